#include "bespoke/DescribingFunction.h"

#include "bespoke/EomSimulation.h"
#include "bespoke/StiffIntegrator.h"
#include "contacts/BristleFriction.h"
#include "mbmodel/Parallel.h"
#include "mbmodel/Units.h"

#include <unsupported/Eigen/NonLinearOptimization>

#include <functional>
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

namespace {
constexpr double kUnknownScale = 1e-3;  // unknowns in mm and mrad
constexpr double kForceScale = 1e4;     // residuals in 10 kN and 10 kN·m
constexpr int kSamples = 720;           // per period, for output maxima
constexpr int kAxisY = 1, kAxisZ = 2;

PiecewiseLinearLaw makeLinear(double stiffness, double damping) {
    // f = −k·d − c·ḋ
    return {{}, {0.0}, {-stiffness}, -damping};
}

PiecewiseLinearLaw makeCompressionOnly(double stiffness, double clearance) {
    // Penetration δ = −d − clearance; f = k·max(0, δ).
    return {{-clearance}, {-stiffness * clearance, 0.0}, {-stiffness, 0.0}, 0.0};
}

using VectorFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;
/// A forward-difference Jacobian, column i with the step 1e-6·max(1, |x_i|) (see
/// calcForwardJacobian); a model may compute the same columns faster.
using JacobianFunction = std::function<Eigen::MatrixXd(const Eigen::VectorXd&)>;

/// Forward differences with a step of 1e-6 of max(1, |x_i|) in the scaled
/// unknowns: MINPACK's own step (relative to |x_i|) collapses on harmonics
/// that are exactly zero and then sees only round-off in the switching times.
Eigen::MatrixXd calcJacobian(const VectorFunction& f, const Eigen::VectorXd& x, int rows) {
    Eigen::MatrixXd J(rows, x.size());
    const Eigen::VectorXd f0 = f(x);
    for (int i = 0; i < x.size(); ++i) {
        Eigen::VectorXd xp = x;
        const double h = 1e-6 * std::max(1.0, std::abs(x[i]));
        xp[i] += h;
        J.col(i) = (f(xp) - f0) / h;
    }
    return J;
}

/// Eigen's HybridNonLinearSolver functor around any residual function.
struct ResidualFunctor {
    VectorFunction f;
    int n = 0;
    JacobianFunction jacobian;  ///< the same forward differences, faster; empty: calcJacobian
    int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) const {
        fvec = f(x);
        return 0;
    }
    int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) const {
        jac = jacobian ? jacobian(x) : calcJacobian(f, x, n);
        return 0;
    }
    int inputs() const { return n; }
    int values() const { return n; }
};

std::optional<Eigen::VectorXd> solvePowell(const VectorFunction& f, Eigen::VectorXd x, double tolerance,
                                           int* evaluations = nullptr, const JacobianFunction& jacobian = {}) {
    ResidualFunctor functor{f, int(x.size()), jacobian};
    Eigen::HybridNonLinearSolver<ResidualFunctor> solver(functor);
    solver.parameters.maxfev = 200;
    solver.parameters.xtol = 1e-12;
    solver.diag.setConstant(x.size(), 1.0);
    solver.useExternalScaling = true;
    solver.solve(x);
    if (evaluations) *evaluations = int(solver.nfev);
    const Eigen::VectorXd r = f(x);
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
    // Small angles: x_y = y + p_y − θ·p_z,  x_z = z + p_z + θ·p_y.
    const TrigSeries& th = q[3 * body];
    if (axis == kAxisY) return q[3 * body + 1] + TrigSeries::constant(p.x()) + th * (-p.y());
    return q[3 * body + 2] + TrigSeries::constant(p.y()) + th * p.x();
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

bool DescribingFunctionModel::movesElement(int unknown, const Element& e) {
    const int dof = unknown / kCoefficients, body = dof / 3, coordinate = dof % 3;  // 0 roll, 1 y, 2 z
    // The element reads its bodies' rolls (arms and weights) and the coordinate along its axis.
    return (e.bodyA == body || e.bodyB == body) && (coordinate == 0 || coordinate == e.axis);
}

Eigen::VectorXd DescribingFunctionModel::assembleResidual(const std::vector<TrigSeries>& q,
                                                          const std::vector<std::vector<TrigSeries>>& harmonics,
                                                          double omega) const {
    using M = EomHalfCarModel;
    std::vector<TrigSeries> Q(M::kNumDofs, TrigSeries(kHarmonics));
    for (int b = 0; b < M::kNumBodies; ++b) Q[3 * b + 2].updMean() -= reference_.getMass(b) * units::g;

    // Moment of f along `axis` at p on a body rolled by θ (small angles):
    //   z: (p_y − θ p_z)·f,   y: −(p_z + θ p_y)·f.
    auto addMoment = [](TrigSeries& Qth, int axis, const Eigen::Vector2d& p, const TrigSeries& f,
                        const TrigSeries& thetaF, double sign) {
        if (axis == kAxisZ) Qth += (f * p.x() + thetaF * -p.y()) * sign;
        else Qth += (f * -p.y() + thetaF * -p.x()) * sign;
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
    // calcJacobian's columns, bit for bit (same steps, same sums), but a column
    // re-evaluates only the elements its unknown moves (about 2/5 of them).
    const double omega = calcOmega(speedMph);
    const std::vector<TrigSeries> q = getPositions(x);
    std::vector<std::vector<TrigSeries>> H(elements_.size());
    for (size_t i = 0; i < elements_.size(); ++i) H[i] = calcElementHarmonics(q, elements_[i], omega);
    const Eigen::VectorXd f0 = assembleResidual(q, H, omega);
    Eigen::MatrixXd J(kNumUnknowns, kNumUnknowns + (speedColumn ? 1 : 0));
    std::vector<std::vector<TrigSeries>> Hp = H;
    for (int i = 0; i < kNumUnknowns; ++i) {
        Eigen::VectorXd xp = x;
        const double h = 1e-6 * std::max(1.0, std::abs(x[i]));
        xp[i] += h;
        const std::vector<TrigSeries> qp = getPositions(xp);
        for (size_t k = 0; k < elements_.size(); ++k)
            if (movesElement(i, elements_[k])) Hp[k] = calcElementHarmonics(qp, elements_[k], omega);
        J.col(i) = (assembleResidual(qp, Hp, omega) - f0) / h;
        for (size_t k = 0; k < elements_.size(); ++k)
            if (movesElement(i, elements_[k])) Hp[k] = H[k];
    }
    if (speedColumn) {
        const double h = 1e-6 * std::max(1.0, std::abs(speedMph));
        J.col(kNumUnknowns) = (calcResidual(x, speedMph + h) - f0) / h;
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
    return solvePowell([&](const Eigen::VectorXd& x) { return calcResidual(x, speedMph); }, guess, 1e-7, nullptr,
                       [&](const Eigen::VectorXd& x) { return calcResidualJacobian(x, speedMph, false); });
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

SteadyStatePoint DescribingFunctionModel::describe(const Eigen::VectorXd& x, double speedMph) const {
    const double omega = calcOmega(speedMph);
    const std::vector<TrigSeries> q = getPositions(x);
    SteadyStatePoint p;
    p.speedMph = speedMph;
    p.harmonics = x;
    double rollMin = 1e9, rollMax = -1e9, minPlate = 1e300;
    int lifted = 0;
    std::vector<TrigSeries> d(elements_.size()), rate(elements_.size());
    for (size_t i = 0; i < elements_.size(); ++i) {
        d[i] = calcRelative(q, elements_[i]);
        rate[i] = d[i].derivative() * omega;
    }
    // sin kτ, cos kτ of every sample, once (evaluate(Angles) is bit-identical to evaluate(τ)).
    static const std::vector<TrigSeries::Angles> samples = [] {
        std::vector<TrigSeries::Angles> a;
        for (int s = 0; s < kSamples; ++s) a.emplace_back(2 * std::numbers::pi * s / kSamples, kHarmonics);
        return a;
    }();
    enum class Role { Other, Wheel, SideBearing, Rim };
    std::vector<Role> role(elements_.size(), Role::Other);
    for (size_t i = 0; i < elements_.size(); ++i)
        role[i] = elements_[i].name == "wheel"          ? Role::Wheel
                  : elements_[i].name == "side_bearing" ? Role::SideBearing
                  : elements_[i].name == "rim"          ? Role::Rim
                                                        : Role::Other;
    for (int s = 0; s < kSamples; ++s) {
        const TrigSeries::Angles& tau = samples[s];
        const double roll = q[0].evaluate(tau);
        rollMin = std::min(rollMin, roll);
        rollMax = std::max(rollMax, roll);
        double plate = 0;
        bool anyLift = false;
        for (size_t i = 0; i < elements_.size(); ++i) {
            const Element& e = elements_[i];
            const auto* law = std::get_if<PiecewiseLinearLaw>(&e.law);
            if (!law) continue;
            const double f = law->evaluate(d[i].evaluate(tau), rate[i].evaluate(tau));
            if (role[i] == Role::Wheel) {
                p.maxWheelLoadLb = std::max(p.maxWheelLoadLb, f / units::lbf);
                anyLift = anyLift || f <= 0;
            } else if (role[i] == Role::SideBearing) {
                p.maxSideBearingLoadLb = std::max(p.maxSideBearingLoadLb, f / units::lbf);
            } else if (role[i] == Role::Rim) {
                plate += f;
            }
        }
        minPlate = std::min(minPlate, plate);
        lifted += anyLift ? 1 : 0;
    }
    p.rollAmplitudeDeg = 0.5 * (rollMax - rollMin) / units::degree;
    p.wheelLiftFraction = double(lifted) / kSamples;
    p.minCenterPlateLoadLb = minPlate / units::lbf;
    p.maxFloquetMultiplier = std::numeric_limits<double>::quiet_NaN();
    return p;
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
            const double f = evaluateHistory(calcElastoPlasticHistory(*law, calcRelative(q, e)), 0.0);
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
        StiffIntegrator integ(
            M::kNumStates,
            [&twin](double t, const double* y, double* yDot) {
                M::State s = Eigen::Map<const M::State>(y), d;
                twin.calcStateDerivative(t, s, d);
                Eigen::Map<M::State> out(yDot);
                out = d;
            },
            accuracy, getEomAbsoluteTolerances(accuracy));
        integ.initialize(0, y0.data());
        integ.advanceTo(period);
        return M::State(Eigen::Map<const M::State>(integ.getState().data()));
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
    Eigen::MatrixXd Phi = monodromyAt(y, base);
    for (int it = 0; it < 8; ++it) {
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
        if ((baseNext - yNext).cwiseQuotient(step).cwiseAbs().maxCoeff() > 10 * out.mismatch) break;
        y = yNext;
        base = baseNext;
        Phi = monodromyAt(y, base);
    }
    out.maxMultiplier = Phi.eigenvalues().cwiseAbs().maxCoeff();
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

std::vector<SteadyStateBranch> DescribingFunctionModel::trace(const ContinuationSettings& s) const {
    // Unknowns u = [x (45, mm and mrad), V (mph)]; residual R(x, V) = 0 plus the
    // arclength condition t·(u − u_pred) = 0, t the unit tangent (null vector of ∂R/∂u).
    const int n = kNumUnknowns;
    auto residualOf = [this](const Eigen::VectorXd& u) { return calcResidual(u.head(kNumUnknowns), u[kNumUnknowns]); };
    auto jacobianOf = [this](const Eigen::VectorXd& u) {  // calcJacobian(residualOf, u, n), faster
        return calcResidualJacobian(u.head(kNumUnknowns), u[kNumUnknowns], true);
    };
    auto tangentAt = [&](const Eigen::VectorXd& u, const Eigen::VectorXd& previous) {
        const Eigen::MatrixXd J = jacobianOf(u);
        Eigen::MatrixXd A(n + 1, n + 1);
        A.topRows(n) = J;
        A.row(n) = previous.transpose();
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 1);
        rhs[n] = 1;
        Eigen::VectorXd t = A.fullPivLu().solve(rhs);
        return Eigen::VectorXd(t / t.norm());
    };

    std::vector<SteadyStatePoint> points;
    const std::optional<Eigen::VectorXd> start = solveFromRest(s.fromMph);
    if (!start) return {};
    Eigen::VectorXd u(n + 1);
    u << *start, s.fromMph;
    Eigen::VectorXd e = Eigen::VectorXd::Zero(n + 1);
    e[n] = 1;
    Eigen::VectorXd t = tangentAt(u, e);
    points.push_back(describe(u.head(n), u[n]));
    double ds = s.initialStep;
    while (int(points.size()) < s.maxPoints) {
        const Eigen::VectorXd predicted = u + ds * t;
        int evaluations = 0;
        const auto corrected = solvePowell(
            [&](const Eigen::VectorXd& v) {
                Eigen::VectorXd r(n + 1);
                r.head(n) = residualOf(v);
                r[n] = t.dot(v - predicted);
                return r;
            },
            predicted, 1e-7, &evaluations, [&](const Eigen::VectorXd& v) {
                Eigen::MatrixXd J(n + 1, n + 1);
                J.topRows(n) = jacobianOf(v);
                const double c0 = t.dot(v - predicted);
                for (int i = 0; i <= n; ++i) {  // the arclength row by the same differences
                    Eigen::VectorXd vp = v;
                    const double h = 1e-6 * std::max(1.0, std::abs(v[i]));
                    vp[i] += h;
                    J(n, i) = (t.dot(vp - predicted) - c0) / h;
                }
                return J;
            });
        if (!corrected || (corrected->segment(0, n) - u.head(n)).norm() > 20 * ds + 1) {
            ds *= 0.5;
            if (ds < s.minStep) break;
            continue;
        }
        u = *corrected;
        t = tangentAt(u, t);
        points.push_back(describe(u.head(n), u[n]));
        if (u[n] > s.toMph || u[n] < s.fromMph - 1e-9) break;
        if (evaluations < 8 * (n + 2)) ds = std::min(s.maxStep, ds * 1.5);
    }

    // Folds: where the speed along the path turns back.
    for (size_t i = 1; i < points.size(); ++i) {
        points[i].foldsBefore = points[i - 1].foldsBefore;
        if (i >= 2 && (points[i].speedMph - points[i - 1].speedMph) * (points[i - 1].speedMph - points[i - 2].speedMph) < 0)
            ++points[i].foldsBefore;
    }
    auto applyFloquet = [this](SteadyStatePoint& p) {
        try {
            const TwinFloquet f = calcTwinFloquet(p.harmonics, p.speedMph);
            p.maxFloquetMultiplier = f.maxMultiplier;
            p.floquetConverged = f.converged;
            // A sticking wedge contributes μ = 1 exactly; the finite-difference
            // monodromy puts a few percent of noise on it (1.00–1.05 seen).
            p.stability = f.maxMultiplier < 1.1 ? Stability::Stable : Stability::Unstable;
            p.stabilityEvidence = "floquet";
        } catch (const NumericalFailure&) {
            p.floquetConverged = false;
        }
        if (!p.floquetConverged) {
            // No periodic orbit of the twin found near the harmonic solution: does
            // the twin, started on it, stay there for 10 periods?
            try {
                p.twinPersistence = calcTwinPersistence(p.harmonics, p.speedMph, 10);
                // The describing function itself is ~10 % off near resonance (0.68° against
                // the twin's 0.76° at 15.7 mph); a drift beyond 15 % in 10 periods is not staying.
                p.stability = std::abs(p.twinPersistence - 1) < 0.15 ? Stability::Stable : Stability::Unstable;
                p.stabilityEvidence = "persistence";
            } catch (const NumericalFailure&) {
                p.stabilityEvidence = "none";
                p.stability = Stability::NotComputed;
            }
        }
    };
    // Nested in a parallel job (validate), the enclosing pool's threads; else one per core.
    auto runParallel = [](size_t count, const std::function<void(size_t)>& job) { parallelFor(count, 0, job); };
    if (s.stability == StabilityMethod::Floquet) {
        runParallel(points.size(), [&](size_t i) { applyFloquet(points[i]); });
    } else if (s.stability == StabilityMethod::FoldRule && !points.empty()) {
        // Stability can change only at bifurcations; along a traced path the
        // generic ones are the folds. Each stretch between folds is checked by
        // Floquet (twin orbit) at its middle point and marked as a whole; where
        // the shooting does not converge, stability flips from the stretch before.
        const int stretches = points.back().foldsBefore + 1;
        std::vector<size_t> probe(stretches);
        for (int k = 0; k < stretches; ++k) {
            std::vector<size_t> members;
            for (size_t i = 0; i < points.size(); ++i)
                if (points[i].foldsBefore == k) members.push_back(i);
            probe[k] = members[members.size() / 2];
        }
        runParallel(probe.size(), [&](size_t k) { applyFloquet(points[probe[k]]); });
        // Without evidence and without a decided stretch before it to flip from,
        // a stretch stays not computed (it used to be assumed stable).
        std::vector<Stability> stable(stretches, Stability::NotComputed);
        auto flip = [](Stability x) {
            return x == Stability::Stable     ? Stability::Unstable
                   : x == Stability::Unstable ? Stability::Stable
                                              : Stability::NotComputed;
        };
        for (int k = 0; k < stretches; ++k) {
            const SteadyStatePoint& p = points[probe[k]];
            stable[k] = p.stabilityEvidence != "none" ? p.stability
                        : k == 0                     ? Stability::NotComputed
                                                     : flip(stable[k - 1]);
        }
        for (auto& p : points) p.stability = stable[p.foldsBefore];
    }
    std::vector<SteadyStateBranch> branches;
    for (const auto& p : points) {
        if (branches.empty() || branches.back().stability != p.stability) branches.push_back({p.stability, {}});
        branches.back().points.push_back(p);
    }
    return branches;
}

}  // namespace rockroll
