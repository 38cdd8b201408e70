#include "bespoke/DescribingFunction.h"

#include "bespoke/EomSimulation.h"
#include "bespoke/StiffIntegrator.h"
#include "contacts/BristleFriction.h"
#include "mbmodel/Parallel.h"
#include "mbmodel/RunSummary.h"
#include "mbmodel/Units.h"

#include <unsupported/Eigen/NonLinearOptimization>

#include <fmt/format.h>

#include <functional>
#include <memory>
#include <set>
#include <cmath>
#include <limits>
#include <numbers>

namespace rockroll {

const char* toString(Stability s) {
    switch (s) {
        case Stability::Stable: return "yes";
        case Stability::Unstable: return "no";
        case Stability::NotComputed: return "not computed";
    }
    return "not computed";
}

const char* describeStability(Stability s) {
    return s == Stability::Stable ? "stable" : s == Stability::Unstable ? "unstable" : "not computed";
}

namespace {
constexpr double kUnknownScale = 1e-3;  // unknowns in mm and mrad
constexpr double kForceScale = 1e4;     // residuals in 10 kN and 10 kN·m
constexpr int kSamples = 720;           // per period, for output maxima
constexpr int kAxisY = 1, kAxisZ = 2;
constexpr double kTwinAccuracy = 1e-4;  // the twin maxima's runs and the sweep starts

/// CVODE BDF on the twin's 22 states at relative accuracy `accuracy` (absolute: eom's).
std::unique_ptr<StiffIntegrator> makeTwinIntegrator(const EomHalfCarModel& twin, double accuracy) {
    using M = EomHalfCarModel;
    return std::make_unique<StiffIntegrator>(
        M::kNumStates,
        [&twin](double t, const double* y, double* yDot) {
            M::State s = Eigen::Map<const M::State>(y), d;
            twin.calcStateDerivative(t, s, d);
            Eigen::Map<M::State> out(yDot);
            out = d;
        },
        accuracy, getEomAbsoluteTolerances(accuracy));
}

/// A point p = (p_y, p_z) of a body rolled by θ (small angles) moves along `axis` by
/// `force`·θ (x_y = y + p_y − θ·p_z, x_z = z + p_z + θ·p_y), and a force f along that axis
/// at p has the moment (force + θ·rolledForce)·f about the body's reference point.
struct RollArms {
    double force = 0, rolledForce = 0;
};
RollArms getRollArms(int axis, const Eigen::Vector2d& p) {
    return axis == kAxisZ ? RollArms{p.x(), -p.y()} : RollArms{-p.y(), -p.x()};
}

PiecewiseLinearLaw makeLinear(double stiffness, double damping) {
    // f = −k·d − c·ḋ
    return {{}, {0.0}, {-stiffness}, -damping};
}

PiecewiseLinearLaw makeCompressionOnly(double stiffness, double clearance) {
    // Penetration δ = −d − clearance; f = k·max(0, δ).
    return {{-clearance}, {-stiffness * clearance, 0.0}, {-stiffness, 0.0}, 0.0};
}

using VectorFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;
/// The residual's Jacobian at x (exact: DescribingFunctionModel::calcResidualJacobian).
using JacobianFunction = std::function<Eigen::MatrixXd(const Eigen::VectorXd&)>;

/// Eigen's HybridNonLinearSolver functor around any residual function.
struct ResidualFunctor {
    VectorFunction f;
    int n = 0;
    JacobianFunction jacobian;
    int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) const {
        fvec = f(x);
        return 0;
    }
    int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) const {
        jac = jacobian(x);
        return 0;
    }
    int inputs() const { return n; }
    int values() const { return n; }
};

std::optional<Eigen::VectorXd> solvePowell(const VectorFunction& f, const JacobianFunction& jacobian, Eigen::VectorXd x,
                                           double tolerance) {
    ResidualFunctor functor{f, int(x.size()), jacobian};
    Eigen::HybridNonLinearSolver<ResidualFunctor> solver(functor);
    solver.parameters.maxfev = 200;
    solver.parameters.xtol = 1e-12;
    solver.diag.setConstant(x.size(), 1.0);
    solver.useExternalScaling = true;
    solver.solve(x);
    const Eigen::VectorXd& r = solver.fvec;  // f at the x it returns (it moves both together)
    if (!r.allFinite() || r.norm() > tolerance) return std::nullopt;
    return x;
}
}  // namespace

DescribingFunctionModel::DescribingFunctionModel(const CarParameters& car, double crossLevelAmplitude,
                                                 double railLength)
    : car_(car), inputAmplitude_(crossLevelAmplitude), railLength_(railLength),
      reference_(car, [](double) { return RailState{}; }, EomSimplifications::describingFunctionTwin()) {
    buildElements();
}

double DescribingFunctionModel::calcFundamentalCrossLevel(double A, double wheelbase, double railLength) {
    return 8 * A / (3 * std::numbers::pi) * std::cos(std::numbers::pi * wheelbase / railLength);
}

double DescribingFunctionModel::calcOmega(double speedMph) const {
    return 2 * std::numbers::pi * speedMph * units::mph / railLength_;
}

void DescribingFunctionModel::buildElements() {
    using M = EomHalfCarModel;
    const auto& g = reference_.getGeometry();
    const auto& L = reference_.getLaws();
    const Eigen::Vector2d zero(0, 0);
    for (int side : {0, 1}) {
        const Eigen::Vector2d rim((side == 0 ? 1 : -1) * g.rimRadius, 0);
        elements_.push_back({kAxisZ, M::CarBody, g.plateOnCarBody + rim, M::Bolster, g.bowlOnBolster + rim, -1,
                             makeCompressionOnly(L.rim.stiffness, 0), "rim"});
        elements_.push_back({kAxisZ, M::CarBody, g.padOnCarBody[side], M::Bolster, g.bearingOnBolster[side], -1,
                             makeCompressionOnly(L.sideBearing.stiffness, L.sideBearingClearance), "side_bearing"});
        elements_.push_back({kAxisZ, M::Bolster, g.springOnBolster[side], M::Wheelset, g.seatOnWheelset[side], -1,
                             makeLinear(L.spring.rate, 0), "spring"});
        const double cLock = calcBristleDamping(L.lateral.rate, reference_.getMass(M::Bolster) / 2,
                                             car_.lateralContactDampingRatio);
        elements_.push_back({kAxisY, M::Bolster, g.springOnBolster[side], M::Wheelset, g.seatOnWheelset[side], -1,
                             makeLinear(L.lateral.rate, cLock), "lateral_lock"});
        elements_.push_back({kAxisZ, M::Bolster, g.springOnBolster[side], M::Wheelset, g.seatOnWheelset[side], -1,
                             ElastoPlasticLaw{L.wedgeVertical.limit, L.wedgeVertical.stiffness}, "wedge"});
        elements_.push_back({kAxisZ, M::Wheelset, g.tread[side], -1, zero, side,
                             makeCompressionOnly(L.wheelVertical.stiffness, 0), "wheel"});
        elements_.push_back({kAxisY, M::Wheelset, g.tread[side], -1, Eigen::Vector2d(g.railY[side], 0), side,
                             makeLinear(0.5 * L.wheelLateralStiffness, 0.5 * L.wheelLateralDamping), "wheel_lateral"});
    }
    elements_.push_back({kAxisY, M::CarBody, g.plateOnCarBody, M::Bolster, g.bowlOnBolster, -1,
                         makeLinear(L.pinStiffness, L.pinDamping), "pin"});
}

std::vector<TrigSeries> DescribingFunctionModel::getPositions(const Eigen::VectorXd& x) const {
    std::vector<TrigSeries> q(EomHalfCarModel::kNumDofs, TrigSeries(kHarmonics));
    for (int j = 0; j < EomHalfCarModel::kNumDofs; ++j) {
        q[j].updMean() = kUnknownScale * x[kCoefficients * j];
        for (int k = 1; k <= kHarmonics; ++k) {
            q[j].updCos(k) = kUnknownScale * x[kCoefficients * j + 2 * k - 1];
            q[j].updSin(k) = kUnknownScale * x[kCoefficients * j + 2 * k];
        }
    }
    return q;
}

TrigSeries DescribingFunctionModel::calcStationSeries(const std::vector<TrigSeries>& q, int body,
                                                      const Eigen::Vector2d& p, int axis) const {
    // Small angles (getRollArms): x_y = y + p_y − θ·p_z,  x_z = z + p_z + θ·p_y.
    const TrigSeries& th = q[3 * body];
    const double arm = getRollArms(axis, p).force;
    if (axis == kAxisY) return q[3 * body + 1] + TrigSeries::constant(p.x()) + th * arm;
    return q[3 * body + 2] + TrigSeries::constant(p.y()) + th * arm;
}

TrigSeries DescribingFunctionModel::calcRailSeries(int side, int axis) const {
    if (axis == kAxisY) return TrigSeries::constant(reference_.getGeometry().railY[side]);
    return TrigSeries::sine(1, (side == 0 ? -0.5 : 0.5) * inputAmplitude_);  // rails at ∓c/2
}

TrigSeries DescribingFunctionModel::calcRelative(const std::vector<TrigSeries>& q, const Element& e) const {
    const TrigSeries a = calcStationSeries(q, e.bodyA, e.pA, e.axis);
    const TrigSeries b = e.bodyB >= 0 ? calcStationSeries(q, e.bodyB, e.pB, e.axis)
                                      : (e.axis == kAxisY ? TrigSeries::constant(e.pB.x()) : calcRailSeries(e.railSide, e.axis));
    return a + b * -1.0;
}

std::vector<TrigSeries> DescribingFunctionModel::calcElementHarmonics(const std::vector<TrigSeries>& q, const Element& e,
                                                                      double omega) const {
    const TrigSeries d = calcRelative(q, e);
    std::vector<TrigSeries> weights{TrigSeries::constant(1), q[3 * e.bodyA]};
    if (e.bodyB >= 0) weights.push_back(q[3 * e.bodyB]);
    return std::visit([&](const auto& law) { return calcForceHarmonics(law, d, omega, weights, kHarmonics); }, e.law);
}

Eigen::VectorXd DescribingFunctionModel::assembleResidual(const std::vector<TrigSeries>& q,
                                                          const std::vector<std::vector<TrigSeries>>& harmonics,
                                                          double omega) const {
    using M = EomHalfCarModel;
    std::vector<TrigSeries> Q(M::kNumDofs, TrigSeries(kHarmonics));
    for (int b = 0; b < M::kNumBodies; ++b) Q[3 * b + 2].updMean() -= reference_.getMass(b) * units::g;

    // Moment of f along `axis` at p on a body rolled by θ (getRollArms):
    //   z: (p_y − θ p_z)·f,   y: −(p_z + θ p_y)·f.
    auto addMoment = [](TrigSeries& Qth, int axis, const Eigen::Vector2d& p, const TrigSeries& f,
                        const TrigSeries& thetaF, double sign) {
        const RollArms a = getRollArms(axis, p);
        Qth += (f * a.force + thetaF * a.rolledForce) * sign;
    };
    for (size_t i = 0; i < elements_.size(); ++i) {
        const Element& e = elements_[i];
        const std::vector<TrigSeries>& H = harmonics[i];
        Q[3 * e.bodyA + e.axis] += H[0];
        addMoment(Q[3 * e.bodyA], e.axis, e.pA, H[0], H[1], +1);
        if (e.bodyB >= 0) {
            Q[3 * e.bodyB + e.axis] += H[0] * -1.0;
            addMoment(Q[3 * e.bodyB], e.axis, e.pB, H[0], H[2], -1);
        }
    }
    Eigen::VectorXd r(kNumUnknowns);
    for (int j = 0; j < M::kNumDofs; ++j) {
        const int body = j / 3;
        const double mass = j % 3 == 0 ? reference_.getInertia(body) : reference_.getMass(body);
        r[kCoefficients * j] = -Q[j].getMean() / kForceScale;
        for (int k = 1; k <= kHarmonics; ++k) {
            const double w2 = (k * omega) * (k * omega);
            r[kCoefficients * j + 2 * k - 1] = (-w2 * mass * q[j].getCos(k) - Q[j].getCos(k)) / kForceScale;
            r[kCoefficients * j + 2 * k] = (-w2 * mass * q[j].getSin(k) - Q[j].getSin(k)) / kForceScale;
        }
    }
    return r;
}

Eigen::VectorXd DescribingFunctionModel::calcResidual(const Eigen::VectorXd& x, double speedMph) const {
    const double omega = calcOmega(speedMph);
    const std::vector<TrigSeries> q = getPositions(x);
    std::vector<std::vector<TrigSeries>> H(elements_.size());
    for (size_t i = 0; i < elements_.size(); ++i) H[i] = calcElementHarmonics(q, elements_[i], omega);
    return assembleResidual(q, H, omega);
}

Eigen::MatrixXd DescribingFunctionModel::calcResidualJacobian(const Eigen::VectorXd& x, double speedMph,
                                                              bool speedColumn) const {
    // R is linear in the element harmonics H_j (through the generalized forces Q) and in
    // the positions (the inertia terms); H_j depends on the unknowns through the
    // element's displacement d and its weights θ_A, θ_B, each linear in the unknowns.
    using M = EomHalfCarModel;
    const double omega = calcOmega(speedMph);
    const std::vector<TrigSeries> q = getPositions(x);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(kNumUnknowns, kNumUnknowns + (speedColumn ? 1 : 0));
    const double omegaPerMph = calcOmega(1.0);
    // Inertia: r_{j,k} = (−(kω)²·M_j·q_{j,k} − Q_{j,k}) / F.
    for (int j = 0; j < M::kNumDofs; ++j) {
        const int body = j / 3;
        const double mass = j % 3 == 0 ? reference_.getInertia(body) : reference_.getMass(body);
        for (int k = 1; k <= kHarmonics; ++k)
            for (int c : {2 * k - 1, 2 * k}) {
                const int row = kCoefficients * j + c;
                J(row, row) = -(k * omega) * (k * omega) * mass * kUnknownScale / kForceScale;
                if (speedColumn)
                    J(row, kNumUnknowns) =
                        -2 * k * k * omega * omegaPerMph * mass * kUnknownScale * x[row] / kForceScale;
            }
    }
    // −∂Q/∂(·)/F into one column from an element's dH_0 (force), dH_1, dH_2 (weighted by θ_A, θ_B),
    // as assembleResidual adds H into Q.
    auto addForce = [&](int column, const Element& e, const TrigSeries& f, const TrigSeries& thetaAF,
                        const TrigSeries* thetaBF, double scale) {
        auto add = [&](int dof, const TrigSeries& s, double factor) {
            for (int c = 0; c < kCoefficients; ++c)
                J(kCoefficients * dof + c, column) -= factor * scale * s.getCoefficient(c) / kForceScale;
        };
        auto addMoment = [&](int body, const Eigen::Vector2d& p, const TrigSeries& thetaF, double sign) {
            const RollArms a = getRollArms(e.axis, p);
            add(3 * body, f, sign * a.force), add(3 * body, thetaF, sign * a.rolledForce);
        };
        add(3 * e.bodyA + e.axis, f, 1);
        addMoment(e.bodyA, e.pA, thetaAF, +1);
        if (e.bodyB >= 0) {
            add(3 * e.bodyB + e.axis, f, -1);
            addMoment(e.bodyB, e.pB, *thetaBF, -1);
        }
    };
    for (const Element& e : elements_) {
        const TrigSeries d = calcRelative(q, e);
        std::vector<TrigSeries> weights{TrigSeries::constant(1), q[3 * e.bodyA]};
        if (e.bodyB >= 0) weights.push_back(q[3 * e.bodyB]);
        const ForceHarmonicsDerivatives D = std::visit(
            [&](const auto& law) { return calcForceHarmonicsDerivatives(law, d, omega, weights, kHarmonics); }, e.law);
        const int nw = int(weights.size());
        // The unknowns that move d (by `arm` per unit of the position's coefficient) and,
        // for a roll, the weight it is.
        struct Mover {
            int dof;
            double arm;
            int weight;  ///< the weight it is: 1 θ_A, 2 θ_B, −1 none
        };
        std::vector<Mover> movers{{3 * e.bodyA + e.axis, 1.0, -1}, {3 * e.bodyA, getRollArms(e.axis, e.pA).force, 1}};
        if (e.bodyB >= 0)
            movers.push_back({3 * e.bodyB + e.axis, -1.0, -1}),
                movers.push_back({3 * e.bodyB, -getRollArms(e.axis, e.pB).force, 2});
        for (const Mover& mv : movers)
            for (int m = 0; m < kCoefficients; ++m) {
                std::array<TrigSeries, 3> dH;
                for (int j = 0; j < nw; ++j) {
                    dH[j] = D.byDisplacement[j][m] * mv.arm;
                    if (j == mv.weight) dH[j] += D.byWeight[m];
                }
                addForce(kCoefficients * mv.dof + m, e, dH[0], dH[1], nw > 2 ? &dH[2] : nullptr, kUnknownScale);
            }
        if (speedColumn)
            addForce(kNumUnknowns, e, D.byOmega[0], D.byOmega[1], nw > 2 ? &D.byOmega[2] : nullptr, omegaPerMph);
    }
    return J;
}

Eigen::VectorXd DescribingFunctionModel::makeStaticGuess() const {
    const EomHalfCarModel::State y = reference_.makeStaticState();
    Eigen::VectorXd x = Eigen::VectorXd::Zero(kNumUnknowns);
    for (int j = 0; j < EomHalfCarModel::kNumDofs; ++j) x[kCoefficients * j] = y[j] / kUnknownScale;
    // Every body rolls with the rails (θ = −c/gauge, c = C·sin τ), about rail height.
    const double theta = -inputAmplitude_ / car_.gauge;
    for (int b = 0; b < EomHalfCarModel::kNumBodies; ++b) {
        x[kCoefficients * (3 * b) + 2] = theta / kUnknownScale;
        x[kCoefficients * (3 * b + 1) + 2] = -theta * y[3 * b + 2] / kUnknownScale;
    }
    return x;
}

std::optional<Eigen::VectorXd> DescribingFunctionModel::solve(double speedMph, const Eigen::VectorXd& guess) const {
    return solvePowell([&](const Eigen::VectorXd& x) { return calcResidual(x, speedMph); },
                       [&](const Eigen::VectorXd& x) { return calcResidualJacobian(x, speedMph, false); }, guess,
                       1e-7);
}

std::optional<Eigen::VectorXd> DescribingFunctionModel::solveFromRest(double speedMph) const {
    // Homotopy in the wedge friction: with F_c = 0 the balance is smooth; the
    // friction is then raised to its value in steps, each from the last solution.
    // (Raising the input amplitude instead fails: a Coulomb element's describing
    // function is singular at zero slip amplitude.)
    std::optional<Eigen::VectorXd> x = makeStaticGuess();
    for (double scale : {0.0, 0.01, 0.03, 0.1, 0.2, 0.4, 0.6, 0.8, 1.0}) {
        CarParameters car = car_;
        car.verticalFriction *= std::max(scale, 1e-6);
        const DescribingFunctionModel step(car, inputAmplitude_, railLength_);
        x = step.solve(speedMph, *x);
        if (!x) return std::nullopt;
    }
    return x;
}

bool TwinMaxima::stayed() const {
    return computed && (landedOn == "this solution" ||
                        (landedOn == "no solution" && std::abs(persistence - 1) <= kPersistenceTolerance));
}

SteadyStatePoint DescribingFunctionModel::describe(const Eigen::VectorXd& x, double speedMph) const {
    const double omega = calcOmega(speedMph);
    const std::vector<TrigSeries> q = getPositions(x);
    SteadyStatePoint p;
    p.speedMph = speedMph;
    p.harmonics = x;
    p.rollMeanDeg = q[0].getMean() / units::degree;
    p.rollFirstDeg = std::hypot(q[0].getCos(1), q[0].getSin(1)) / units::degree;
    p.rollSecondDeg = std::hypot(q[0].getCos(2), q[0].getSin(2)) / units::degree;
    // The force harmonics: exact Fourier coefficients of each law on the two-harmonic
    // motion, the quantities the balance itself uses (calcElementHarmonics).
    auto toHarmonics = [](const TrigSeries& f) {
        return ForceHarmonics{f.getMean() / units::lbf, std::hypot(f.getCos(1), f.getSin(1)) / units::lbf,
                              std::hypot(f.getCos(2), f.getSin(2)) / units::lbf};
    };
    TrigSeries plate(kHarmonics);
    std::vector<size_t> wheels;
    for (size_t i = 0; i < elements_.size(); ++i) {
        const Element& e = elements_[i];
        if (e.name != "wheel" && e.name != "side_bearing" && e.name != "rim") continue;
        const TrigSeries f = calcElementHarmonics(q, e, omega)[0];
        if (e.name == "rim") {
            plate += f;
            continue;
        }
        ForceHarmonics& out = e.name == "wheel" ? p.wheelLoad : p.sideBearingLoad;
        const ForceHarmonics h = toHarmonics(f);
        if (h.firstLb >= out.firstLb) out = h;
        if (e.name == "wheel") wheels.push_back(i);
    }
    p.centerPlateLoad = toHarmonics(plate);
    // Roll amplitude and wheel lift: properties of the two-harmonic motion, sampled.
    static const std::vector<TrigSeries::Angles> samples = [] {
        std::vector<TrigSeries::Angles> a;
        for (int s = 0; s < kSamples; ++s) a.emplace_back(2 * std::numbers::pi * s / kSamples, kHarmonics);
        return a;
    }();
    std::vector<TrigSeries> d;
    for (size_t i : wheels) d.push_back(calcRelative(q, elements_[i]));
    double rollMin = 1e9, rollMax = -1e9;
    int lifted = 0;
    for (const TrigSeries::Angles& tau : samples) {
        const double roll = q[0].evaluate(tau);
        rollMin = std::min(rollMin, roll);
        rollMax = std::max(rollMax, roll);
        bool anyLift = false;
        for (const TrigSeries& di : d) anyLift = anyLift || di.evaluate(tau) >= 0;  // penetration −d ≤ 0
        lifted += anyLift ? 1 : 0;
    }
    p.rollAmplitudeDeg = 0.5 * (rollMax - rollMin) / units::degree;
    p.wheelLiftFraction = double(lifted) / kSamples;
    p.maxFloquetMultiplier = std::numeric_limits<double>::quiet_NaN();
    p.twinPersistence = std::numeric_limits<double>::quiet_NaN();
    return p;
}

TwinMaxima DescribingFunctionModel::calcTwinMaxima(const Eigen::VectorXd& x, double speedMph, int periods) const {
    TwinMaxima out;
    out.periods = periods;
    if (periods <= 0) return out;
    const EomHalfCarModel twin = makeTwin(speedMph);
    const double period = 2 * std::numbers::pi / calcOmega(speedMph);
    RunResult run;
    try {
        // The scenarios' accuracy (1e-4): the accuracy study moves eom's filtered maxima by
        // at most 0.7 % from 1e-4 to 1e-6 (docs/validation.md, section 7).
        run = simulateEom(twin, {periods * period, 500, kTwinAccuracy, RunLimits{}}, makeTwinState(x, speedMph));
    } catch (const NumericalFailure&) {
        return out;
    }
    SummaryOptions o;
    o.forcingPeriod = period;
    o.steadyCycles = 1;
    const RunSummary s = summarizeRun(run, twin.getChannels(), o);
    const int c = run.history.column("roll_deg");
    double lo = 1e9, hi = -1e9;
    for (const auto& row : run.history.samples)
        if (row[0] >= (periods - 1) * period - 1e-9) lo = std::min(lo, row[c]), hi = std::max(hi, row[c]);
    out.computed = true;
    out.rollAmplitudeDeg = 0.5 * (hi - lo);
    out.persistence = out.rollAmplitudeDeg / describe(x, speedMph).rollAmplitudeDeg;
    out.maxRollDeg = s.steady.rollDeg;
    out.maxTruckSideWheelLoadLb = s.steady.truckSideWheelLoadLb;
    out.maxSideBearingLoadLb = s.steady.sideBearingLoadLb;
    out.maxCenterPlateLoadLb = s.steady.centerPlateLoadLb;
    // Where the run went, judged as the persistence check judges it (its last period
    // solved back onto the solution set), so a stable label and these maxima agree.
    try {
        out.landedOn = checkTwinPersistence(x, speedMph, periods).landedOn;
    } catch (const NumericalFailure&) {
        out.landedOn = "twin failed";
    }
    return out;
}

Eigen::VectorXd DescribingFunctionModel::projectTwinState(const EomHalfCarModel::State& y0, double speedMph,
                                                          int periods, EomHalfCarModel::State* end) const {
    using M = EomHalfCarModel;
    const EomHalfCarModel twin = makeTwin(speedMph);
    const double period = 2 * std::numbers::pi / calcOmega(speedMph);
    // A guess for solve(), which then converges on its own.
    const std::unique_ptr<StiffIntegrator> integPtr = makeTwinIntegrator(twin, kTwinAccuracy);
    StiffIntegrator& integ = *integPtr;
    integ.initialize(0, y0.data());
    integ.advanceTo((periods - 1) * period);
    // The last period sampled at K points: the DFT's mean, first and second harmonics.
    constexpr int K = 64;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(kNumUnknowns);
    for (int k = 1; k <= K; ++k) {
        integ.advanceTo((periods - 1 + double(k) / K) * period);
        const double tau = 2 * std::numbers::pi * k / K;
        for (int j = 0; j < M::kNumDofs; ++j) {
            const double qj = integ.getState()[j] / kUnknownScale;
            x[kCoefficients * j] += qj / K;
            for (int h = 1; h <= kHarmonics; ++h) {
                x[kCoefficients * j + 2 * h - 1] += 2.0 / K * qj * std::cos(h * tau);
                x[kCoefficients * j + 2 * h] += 2.0 / K * qj * std::sin(h * tau);
            }
        }
    }
    if (end) *end = M::State(Eigen::Map<const M::State>(integ.getState().data()));
    return x;
}

EomHalfCarModel DescribingFunctionModel::makeTwin(double speedMph) const {
    return EomHalfCarModel(car_, makeSinusoidalCrossLevel(inputAmplitude_, calcOmega(speedMph)),
                           EomSimplifications::describingFunctionTwin());
}

EomHalfCarModel::State DescribingFunctionModel::makeTwinState(const Eigen::VectorXd& x, double speedMph) const {
    using M = EomHalfCarModel;
    const double omega = calcOmega(speedMph);
    const std::vector<TrigSeries> q = getPositions(x);
    M::State y = M::State::Zero();
    for (int j = 0; j < M::kNumDofs; ++j) {
        y[j] = q[j].evaluate(0);
        y[M::kNumDofs + j] = omega * q[j].derivative().evaluate(0);
    }
    // Wedge bristles carry the hysteresis force at τ = 0 (F = −k_b·w).
    int side = 0;
    for (const Element& e : elements_)
        if (const auto* law = std::get_if<ElastoPlasticLaw>(&e.law)) {
            const TrigSeries d = calcRelative(q, e);
            const double f = evaluateHistory(calcElastoPlasticHistory(*law, d), d, 0.0);
            y[2 * M::kNumDofs + 2 * side] = -f / law->stiffness;
            ++side;
        }
    return y;
}

TwinFloquet DescribingFunctionModel::calcTwinFloquet(const Eigen::VectorXd& x, double speedMph) const {
    using M = EomHalfCarModel;
    const EomHalfCarModel twin = makeTwin(speedMph);
    const double period = 2 * std::numbers::pi / calcOmega(speedMph);
    const double accuracy = 1e-7;
    // One period of the twin from y0. Each call has an integrator of its own, started
    // afresh (CVodeReInit would reset one as well), so a flow depends on y0 alone and the
    // monodromy's columns can run in parallel with the same bits as one after another.
    auto flow = [&](const M::State& y0) {
        const std::unique_ptr<StiffIntegrator> integ = makeTwinIntegrator(twin, accuracy);
        integ->initialize(0, y0.data());
        integ->advanceTo(period);
        return M::State(Eigen::Map<const M::State>(integ->getState().data()));
    };
    // Perturbations well above the integration error (relative 1e-7 of ~0.5 m)
    // and well below the motion: positions 10 µm, rates 0.1 mm/s, bristles 0.1 µm.
    M::State step;
    for (int i = 0; i < M::kNumStates; ++i) step[i] = i < M::kNumDofs ? 1e-5 : (i < 2 * M::kNumDofs ? 1e-4 : 1e-7);
    // The columns are independent one-period flows: nested in a parallel job (validate's
    // amplitudes, the fold rule's stretches) they share the enclosing pool's threads.
    // A column that fails throws out of parallelFor as one after another would.
    auto monodromyAt = [&](const M::State& y0, const M::State& base) {
        Eigen::MatrixXd Phi(M::kNumStates, M::kNumStates);
        parallelFor(M::kNumStates, 0, [&](size_t i) {
            M::State yp = y0;
            yp[i] += step[i];
            Phi.col(i) = (flow(yp) - base) / step[i];
        });
        return Phi;
    };
    // Shooting: Newton on φ_T(y) = y from the harmonic solution's state, so the
    // multipliers are those of the twin's own periodic orbit.
    TwinFloquet out;
    M::State y = makeTwinState(x, speedMph);
    M::State base = flow(y);
    // Newton with Broyden's rank-one updates of the monodromy between iterations (one
    // flow an iteration instead of 23); a fresh finite-difference monodromy on the orbit
    // found gives the multipliers.
    Eigen::MatrixXd Phi = monodromyAt(y, base);
    bool moved = false;
    for (int it = 0; it < 12; ++it) {
        const M::State r = base - y;
        out.mismatch = r.cwiseQuotient(step).cwiseAbs().maxCoeff();
        // Within a few perturbation steps (tens of µm against mm of motion): a sticking
        // wedge's anchor is neutral (μ = 1), so a family of orbits exists and Newton
        // cannot pin that direction down exactly.
        if (out.mismatch < 5) {
            out.converged = true;
            break;
        }
        const Eigen::MatrixXd A = Phi - Eigen::MatrixXd::Identity(M::kNumStates, M::kNumStates);
        // Least squares: sticking wedges are neutral (μ = 1). Steps are capped at
        // 1000 perturbation steps (10 mm); a growing mismatch ends the search.
        M::State delta = A.completeOrthogonalDecomposition().solve(-r);
        const double size = delta.cwiseQuotient(step).cwiseAbs().maxCoeff();
        if (size > 1000) delta *= 1000 / size;
        const M::State yNext = y + delta;
        M::State baseNext;
        try {
            baseNext = flow(yNext);
        } catch (const NumericalFailure&) {
            break;
        }
        const M::State rNext = baseNext - yNext;
        if (rNext.cwiseQuotient(step).cwiseAbs().maxCoeff() > 10 * out.mismatch) break;
        // Broyden: (Φ − I) δ must reproduce the change of the mismatch.
        Phi += ((rNext - r) - A * delta) * delta.transpose() / delta.squaredNorm();
        y = yNext;
        base = baseNext;
        moved = true;
    }
    if (!out.converged) {
        // Multipliers of an approximate monodromy off the orbit would read as evidence.
        out.maxMultiplier = std::numeric_limits<double>::quiet_NaN();
        out.dominant = {out.maxMultiplier, 0.0};
        return out;
    }
    if (moved) Phi = monodromyAt(y, base);
    const Eigen::VectorXcd mu = Phi.eigenvalues();
    Eigen::Index largest = 0;
    out.maxMultiplier = mu.cwiseAbs().maxCoeff(&largest);
    out.dominant = mu[largest];
    // The orbit found must be this solution's, not a neighbouring branch's.
    const RunResult one = simulateEom(twin, {period, 400, accuracy, RunLimits{}}, y);
    const int c = one.history.column("roll_deg");
    double lo = 1e9, hi = -1e9;
    for (const auto& row : one.history.samples) lo = std::min(lo, row[c]), hi = std::max(hi, row[c]);
    out.rollAmplitudeDeg = 0.5 * (hi - lo);
    const double ratio = out.rollAmplitudeDeg / describe(x, speedMph).rollAmplitudeDeg;
    if (ratio < 0.75 || ratio > 1.0 / 0.75) out.converged = false;
    return out;
}

double DescribingFunctionModel::calcTwinPersistence(const Eigen::VectorXd& x, double speedMph, int periods) const {
    const EomHalfCarModel twin = makeTwin(speedMph);
    const double period = 2 * std::numbers::pi / calcOmega(speedMph);
    const RunResult r = simulateEom(twin, {periods * period, 200, 1e-6, RunLimits{}}, makeTwinState(x, speedMph));
    const int c = r.history.column("roll_deg");
    double lo = 1e9, hi = -1e9;
    for (const auto& row : r.history.samples)
        if (row[0] >= (periods - 1) * period) lo = std::min(lo, row[c]), hi = std::max(hi, row[c]);
    return 0.5 * (hi - lo) / describe(x, speedMph).rollAmplitudeDeg;
}

namespace {
/// Two solutions are the same when their harmonics (means left out) differ by at most
/// `relative` of the larger harmonic plus `absolute` (mm, mrad).
bool isSameSolution(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double relative, double absolute) {
    double d = 0, size = 0;
    for (int i = 0; i < a.size(); ++i)
        if (i % DescribingFunctionModel::kCoefficients != 0)
            d = std::max(d, std::abs(a[i] - b[i])), size = std::max(size, std::abs(a[i]));
    return d <= relative * size + absolute;
}
}  // namespace

TwinPersistence DescribingFunctionModel::checkTwinPersistence(const Eigen::VectorXd& x, double speedMph,
                                                              int periods) const {
    TwinPersistence out;
    const Eigen::VectorXd landed = projectTwinState(makeTwinState(x, speedMph), speedMph, periods);
    const double roll = describe(x, speedMph).rollAmplitudeDeg;
    out.ratio = describe(landed, speedMph).rollAmplitudeDeg / roll;
    if (const auto back = solve(speedMph, landed)) {
        out.landedRollDeg = describe(*back, speedMph).rollAmplitudeDeg;
        // 2 %: far below the gap between neighbouring solutions at one speed (tens of %).
        out.stayed = isSameSolution(*back, x, 0.02, 0.02);
        out.landedOn = out.stayed ? "this solution" : "another solution";
    } else {
        out.landedOn = "no solution";
    }
    return out;
}

SteadyStateSet DescribingFunctionModel::trace(const ContinuationSettings& s) const {
    // Unknowns u = [x (45, mm and mrad), V (mph)]; residual R(x, V) = 0 plus the
    // arclength condition t·(u − u_pred) = 0, t the unit tangent (null vector of ∂R/∂u).
    const int n = kNumUnknowns;
    auto residualOf = [this](const Eigen::VectorXd& u) { return calcResidual(u.head(kNumUnknowns), u[kNumUnknowns]); };
    auto jacobianOf = [this](const Eigen::VectorXd& u) {
        return calcResidualJacobian(u.head(kNumUnknowns), u[kNumUnknowns], true);
    };
    // The tangent at u; J receives ∂R/∂u there, the corrector's Jacobian on the next step.
    auto tangentAt = [&](const Eigen::VectorXd& u, const Eigen::VectorXd& previous, Eigen::MatrixXd& J) {
        J = jacobianOf(u);
        Eigen::MatrixXd A(n + 1, n + 1);
        A.topRows(n) = J;
        A.row(n) = previous.transpose();
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 1);
        rhs[n] = 1;
        Eigen::VectorXd t = A.partialPivLu().solve(rhs);
        return Eigen::VectorXd(t / t.norm());
    };
    const auto outside = [&](double v) { return v > s.toMph + 1e-9 || v < s.fromMph - 1e-9; };

    // The corrector: Newton's method on [R(v); t·(v − u_pred)] = 0 from the predicted point,
    // holding ∂R/∂u at u (the tangent's) while the steps contract by half or more (chord
    // iterations; the arclength row is exact) and taking it at the iterate where they do
    // not. Converged when ‖R‖ ≤ 1e-9 and the last step moved v by at most 1e-10 of its
    // size; nullopt (the step Δs is then halved) after 30 residuals without that.
    auto correctByNewton = [&](const auto& residual, const Eigen::VectorXd& predicted, const Eigen::VectorXd& t,
                               const Eigen::MatrixXd& Ju) -> std::optional<Eigen::VectorXd> {
        Eigen::MatrixXd A(n + 1, n + 1);
        A.topRows(n) = Ju;
        A.row(n) = t.transpose();
        Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
        Eigen::VectorXd v = predicted, r = residual(v);
        int evaluations = 1;
        double previousStep = std::numeric_limits<double>::infinity();
        while (evaluations < 30) {
            const Eigen::VectorXd delta = lu.solve(-r);
            if (!delta.allFinite()) return std::nullopt;  // a singular matrix
            v += delta;
            r = residual(v);
            ++evaluations;
            if (!r.allFinite()) return std::nullopt;
            const double step = delta.norm();
            if (r.norm() <= 1e-9 && step <= 1e-10 * v.norm()) return v;
            if (step > 0.5 * previousStep) {
                A.topRows(n) = jacobianOf(v);
                lu.compute(A);
            }
            previousStep = step;
        }
        return std::nullopt;
    };

    // One direction of the continuation from u along t: the points after u, up to and
    // including the first one outside the range; `closed` when it comes back to `origin`.
    auto continueFrom = [&](Eigen::VectorXd u, Eigen::VectorXd t, Eigen::MatrixXd Ju, const Eigen::VectorXd& origin,
                            bool& closed) {
        std::vector<Eigen::VectorXd> out;
        double ds = s.initialStep, travelled = 0;
        while (int(out.size()) < s.maxPoints) {
            const Eigen::VectorXd predicted = u + ds * t;
            const auto arclengthResidual = [&](const Eigen::VectorXd& v) {
                Eigen::VectorXd r(n + 1);
                r.head(n) = residualOf(v);
                r[n] = t.dot(v - predicted);
                return r;
            };
            const std::optional<Eigen::VectorXd> corrected =
                correctByNewton(arclengthResidual, predicted, t, Ju);
            if (!corrected || (corrected->segment(0, n) - u.head(n)).norm() > 20 * ds + 1) {
                ds *= 0.5;
                if (ds < s.minStep) break;
                continue;
            }
            travelled += (*corrected - u).norm();
            u = *corrected;
            t = tangentAt(u, t, Ju);
            out.push_back(u);
            if (outside(u[n])) break;
            // Back at the start after going round: a closed curve of solutions (an isola).
            if (travelled > 4 * s.maxStep && (u - origin).norm() < std::max(2 * ds, 0.5)) {
                closed = true;
                break;
            }
            ds = std::min(s.maxStep, ds * 1.5);
        }
        return out;
    };

    SteadyStateSet set;
    Eigen::VectorXd e = Eigen::VectorXd::Zero(n + 1);
    e[n] = 1;
    // A path through the solution x at speedMph, continued towards higher speed
    // (direction +1), lower (−1) or both (0).
    auto makePath = [&](const Eigen::VectorXd& x, double speedMph, int direction, std::string start) {
        Eigen::VectorXd u0(n + 1);
        u0 << x, speedMph;
        SteadyStatePath path;
        path.start = std::move(start);
        path.startMph = speedMph;
        std::vector<Eigen::VectorXd> us{u0};
        Eigen::MatrixXd J0;
        const Eigen::VectorXd t0 = tangentAt(u0, direction < 0 ? Eigen::VectorXd(-e) : e, J0);
        bool closed = false;
        const std::vector<Eigen::VectorXd> ahead = continueFrom(u0, t0, J0, u0, closed);
        us.insert(us.end(), ahead.begin(), ahead.end());
        if (direction == 0 && !closed) {
            bool unused = false;
            std::vector<Eigen::VectorXd> behind = continueFrom(u0, -t0, J0, u0, unused);
            us.insert(us.begin(), behind.rbegin(), behind.rend());
        }
        path.closed = closed;
        for (const auto& u : us) path.points.push_back(describe(u.head(n), u[n]));
        // Folds: where the speed along the path turns back.
        auto& pts = path.points;
        for (size_t i = 1; i < pts.size(); ++i) {
            pts[i].foldsBefore = pts[i - 1].foldsBefore;
            if (i >= 2 && (pts[i].speedMph - pts[i - 1].speedMph) * (pts[i - 1].speedMph - pts[i - 2].speedMph) < 0)
                ++pts[i].foldsBefore;
        }
        return path;
    };
    // Whether a solution lies on a path already traced: within 10 % (plus 0.05 mm or
    // mrad) of the path's harmonics interpolated to its speed, means left out.
    auto isKnown = [&](const Eigen::VectorXd& x, double speedMph) {
        auto distance = [&](const Eigen::VectorXd& a) { return isSameSolution(x, a, 0.1, 0.05); };
        for (const auto& path : set.paths)
            for (size_t i = 0; i < path.points.size(); ++i) {
                const SteadyStatePoint& a = path.points[i];
                if (std::abs(a.speedMph - speedMph) < 1e-6 && distance(a.harmonics)) return true;
                if (i + 1 == path.points.size()) continue;
                const SteadyStatePoint& b = path.points[i + 1];
                if ((a.speedMph - speedMph) * (b.speedMph - speedMph) >= 0 || a.speedMph == b.speedMph) continue;
                const double f = (speedMph - a.speedMph) / (b.speedMph - a.speedMph);
                if (distance(a.harmonics + f * (b.harmonics - a.harmonics))) return true;
            }
        return false;
    };

    // Starts: the two ends of the range, from rest.
    if (const auto x = solveFromRest(s.fromMph))
        set.paths.push_back(makePath(*x, s.fromMph, +1, fmt::format("rest at {:g} mph", s.fromMph)));
    if (const auto x = solveFromRest(s.toMph); x && !isKnown(*x, s.toMph))
        set.paths.push_back(makePath(*x, s.toMph, -1, fmt::format("rest at {:g} mph", s.toMph)));
    // Starts from the twin's own sweeps, down and up, each speed's last period projected.
    if (s.sweepStepMph > 0 && s.sweepPeriods > 0) {
        struct Candidate {
            TwinSweepStart record;
            std::optional<Eigen::VectorXd> x;
        };
        std::vector<std::vector<Candidate>> sweeps(2);
        const int count = int(std::floor((s.toMph - s.fromMph) / s.sweepStepMph + 1e-9)) + 1;
        parallelFor(2, 0, [&](size_t dir) {
            EomHalfCarModel::State y = reference_.makeStaticState();
            for (int k = 0; k < count; ++k) {
                const double v = dir == 0 ? s.toMph - k * s.sweepStepMph : s.fromMph + k * s.sweepStepMph;
                Candidate c;
                c.record.speedMph = v;
                c.record.direction = dir == 0 ? "down" : "up";
                try {
                    EomHalfCarModel::State end;
                    // Whole periods: the input's phase carries over to the next speed.
                    c.x = projectTwinState(y, v, s.sweepPeriods, &end);
                    y = end;
                } catch (const NumericalFailure&) {
                    break;  // the rest of this sweep has no state to start from
                }
                c.record.twinRollAmplitudeDeg = describe(*c.x, v).rollAmplitudeDeg;
                sweeps[dir].push_back(std::move(c));
            }
        });
        std::vector<Candidate> all;
        for (auto& sw : sweeps) all.insert(all.end(), sw.begin(), sw.end());
        parallelFor(all.size(), 0, [&](size_t i) { all[i].x = solve(all[i].record.speedMph, *all[i].x); });
        for (Candidate& c : all) {
            c.record.solved = c.x.has_value();
            if (c.x) c.record.solvedRollAmplitudeDeg = describe(*c.x, c.record.speedMph).rollAmplitudeDeg;
            if (c.x && !isKnown(*c.x, c.record.speedMph)) {
                c.record.newPath = true;
                set.paths.push_back(makePath(*c.x, c.record.speedMph, 0,
                                             fmt::format("twin {} sweep at {:g} mph", c.record.direction,
                                                         c.record.speedMph)));
            }
            set.sweepStarts.push_back(c.record);
        }
    }
    for (size_t k = 0; k < set.paths.size(); ++k)
        for (auto& p : set.paths[k].points) p.path = int(k);

    // Stability.
    auto check = [this, &s](SteadyStatePoint& p) {
        p.checked = true;
        std::optional<bool> floquetStable, stays;
        try {
            const TwinFloquet f = calcTwinFloquet(p.harmonics, p.speedMph);
            p.maxFloquetMultiplier = f.maxMultiplier;
            p.dominantMultiplier = f.dominant;
            p.floquetConverged = f.converged;
            // A sticking wedge contributes μ = 1 exactly; the finite-difference
            // monodromy puts a few percent of noise on it (1.00–1.05 seen).
            if (f.converged) floquetStable = f.maxMultiplier < 1.1;
        } catch (const NumericalFailure&) {
            p.floquetConverged = false;
        }
        try {
            const TwinPersistence t = checkTwinPersistence(p.harmonics, p.speedMph, s.persistencePeriods);
            p.twinPersistence = t.ratio;
            p.twinLandedOn = t.landedOn;
            // A last period that solves onto no solution says neither (the ansatz does
            // not hold the twin's motion there).
            if (t.landedOn != "no solution") stays = t.stayed;
        } catch (const NumericalFailure&) {
            p.twinLandedOn = "twin failed";
        }
        if (!stays && floquetStable) {
            p.stabilityEvidence = "floquet (persistence inconclusive)";
            p.stability = *floquetStable ? Stability::Stable : Stability::Unstable;
        } else if (!stays) {
            p.stabilityEvidence = "none";
            p.stability = Stability::NotComputed;
        } else if (floquetStable && *floquetStable != *stays) {
            p.stabilityEvidence = "floquet, persistence disagree";
            p.stability = Stability::NotComputed;
        } else {
            p.stabilityEvidence = floquetStable ? "floquet+persistence" : "persistence";
            p.stability = *stays ? Stability::Stable : Stability::Unstable;
        }
    };
    std::vector<SteadyStatePoint*> all;
    for (auto& path : set.paths)
        for (auto& p : path.points) all.push_back(&p);
    if (s.stability == StabilityMethod::Floquet) {
        parallelFor(all.size(), 0, [&](size_t i) { check(*all[i]); });
    } else if (s.stability == StabilityMethod::FoldRule) {
        // Each stretch between folds: checks near both ends (a tenth in from the fold,
        // where one multiplier is +1) and in the middle; a pair of neighbouring checks
        // that disagree is bisected until they are neighbouring points or the stretch
        // has used its checks. Every point then takes its nearest check's label.
        struct Stretch {
            std::vector<SteadyStatePoint>* points;
            size_t first, last;
            std::set<size_t> checks;
        };
        std::vector<Stretch> stretches;
        for (auto& path : set.paths)
            for (size_t i = 0; i < path.points.size();) {
                size_t j = i;
                while (j + 1 < path.points.size() && path.points[j + 1].foldsBefore == path.points[i].foldsBefore) ++j;
                const size_t inset = (j - i + 5) / 10;
                stretches.push_back({&path.points, i, j, {i + inset, (i + j) / 2, j - inset}});
                i = j + 1;
            }
        std::vector<std::pair<size_t, size_t>> pending;  // (stretch, point)
        for (size_t k = 0; k < stretches.size(); ++k)
            for (size_t i : stretches[k].checks) pending.push_back({k, i});
        while (!pending.empty()) {
            parallelFor(pending.size(), 0, [&](size_t m) { check((*stretches[pending[m].first].points)[pending[m].second]); });
            pending.clear();
            for (size_t k = 0; k < stretches.size(); ++k) {
                Stretch& st = stretches[k];
                std::vector<size_t> c(st.checks.begin(), st.checks.end());
                for (size_t m = 0; m + 1 < c.size() && int(st.checks.size()) < s.maxChecksPerStretch; ++m)
                    if ((*st.points)[c[m]].stability != (*st.points)[c[m + 1]].stability && c[m + 1] - c[m] > 1) {
                        const size_t mid = (c[m] + c[m + 1]) / 2;
                        st.checks.insert(mid);
                        pending.push_back({k, mid});
                    }
            }
        }
        for (const Stretch& st : stretches) {
            const std::vector<size_t> c(st.checks.begin(), st.checks.end());
            for (size_t i = st.first; i <= st.last; ++i) {
                SteadyStatePoint& p = (*st.points)[i];
                if (p.checked) continue;
                size_t nearest = c.front();
                for (size_t k : c)
                    if ((k > i ? k - i : i - k) < (nearest > i ? nearest - i : i - nearest)) nearest = k;
                p.stability = (*st.points)[nearest].stability;
                p.stabilityEvidence = "interpolated";
            }
            for (size_t m = 0; m + 1 < c.size(); ++m) {
                const SteadyStatePoint &a = (*st.points)[c[m]], &b = (*st.points)[c[m + 1]];
                if (a.stability == b.stability || a.stability == Stability::NotComputed ||
                    b.stability == Stability::NotComputed)
                    continue;
                const SteadyStatePoint& unstable = a.stability == Stability::Unstable ? a : b;
                const std::complex<double> mu = unstable.dominantMultiplier;
                const std::string kind = !unstable.floquetConverged || !std::isfinite(mu.real()) ? "not classified"
                                         : std::abs(mu.imag()) > 1e-3 * std::abs(mu)          ? "complex pair"
                                         : mu.real() > 0 ? "real multiplier through +1"
                                                         : "period doubling (-1)";
                set.changes.push_back({a.path, a.speedMph, b.speedMph, kind});
            }
        }
    }

    // Peak values from the twin's time history: at each path's ends, each checked point,
    // and every point twinSpacingMph or 5 % of roll amplitude on from the last one run.
    if (s.twinPeriods > 0) {
        std::vector<SteadyStatePoint*> run;
        for (auto& path : set.paths) {
            const SteadyStatePoint* last = nullptr;
            for (size_t i = 0; i < path.points.size(); ++i) {
                SteadyStatePoint& p = path.points[i];
                if (!last || p.checked || i + 1 == path.points.size() ||
                    std::abs(p.speedMph - last->speedMph) >= s.twinSpacingMph ||
                    std::abs(p.rollAmplitudeDeg - last->rollAmplitudeDeg) >= 0.05 * last->rollAmplitudeDeg) {
                    run.push_back(&p);
                    last = &p;
                }
            }
        }
        parallelFor(run.size(), 0, [&](size_t i) {
            run[i]->twin = calcTwinMaxima(run[i]->harmonics, run[i]->speedMph, s.twinPeriods);
        });
    }

    for (const auto& path : set.paths)
        for (const auto& p : path.points) {
            auto& b = set.branches;
            if (b.empty() || b.back().path != p.path || b.back().stability != p.stability)
                b.push_back({p.stability, p.path, {}});
            b.back().points.push_back(p);
        }
    return set;
}

}  // namespace rockroll
