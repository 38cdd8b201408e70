#include "bespoke/ReducedHalfCarModel.h"

#include "bespoke/StiffIntegrator.h"
#include "contacts/SpringGroupLaws.h"
#include "mbmodel/CarSide.h"
#include "mbmodel/Units.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <fmt/format.h>

namespace rockroll {

namespace {
}  // namespace

ReducedHalfCarModel::ReducedHalfCarModel(const CarParameters& car, RailStateFunction rails, ReducedOptions options)
    : car_(car), rails_(std::move(rails)), truck_(car) {
    if (options.truckWeight) {
        truckWeight_ = TruckWeight::Carried;
        truck_.bolsterWeight = car.bolsterWeight;
        truck_.wheelsetWeight = 2 * (car.wheelsetWeight + car.sideFrameWeight);
    }
    modeCache_ = TruckModeCache::getShared(truck_);
    mass_ = car.getCarBodyWeight() / 2 / units::g;
    inertia_ = car.rollInertia / 2;
    staticZ_ = makeStaticState()[2];
    declareChannels();
}

TruckStatics ReducedHalfCarModel::calcTruckStatics() const {
    TruckStaticLoad load;
    load.carBody = mass_ * units::g;
    load.weight = truckWeight_;
    return TruckStatics(car_, load);
}

ReducedHalfCarModel::State ReducedHalfCarModel::makeStaticState() const {
    // Rigid rails and center plate: no contact deflections.
    State y = State::Zero();
    y[2] = truck_.springTopAboveRail - calcTruckStatics().getSpringCompression() + truck_.cpAboveSprings +
           car_.cgAboveCenterPlate;
    return y;
}

ReducedHalfCarModel::TruckMemory ReducedHalfCarModel::makeStaticMemory() const {
    TruckMemory m;
    const double Z = calcTruckStatics().getSpringCompression();
    m.compression = {Z, Z};
    m.wedgeAnchor = {Z, Z};
    return m;
}

TruckInputs ReducedHalfCarModel::makeTruckInputs(double t, const State& y, const TruckMemory& mem) const {
    return makeTruckInputs(rails_(t), y, mem);
}

TruckInputs ReducedHalfCarModel::makeTruckInputs(const RailState& rail, const State& y, const TruckMemory& mem) const {
    const double h = car_.cgAboveCenterPlate, padAbovePlate = truck_.sbAboveSprings - truck_.cpAboveSprings;
    TruckInputs in;
    for (int i : {0, 1}) {
        in.rimZ[i] = y[2] - h + y[0] * kSideSign[i] * truck_.a_c;
        in.padZ[i] = y[2] - h + padAbovePlate + y[0] * kSideSign[i] * truck_.a_s;
        in.railZ[i] = rail.z[i];
    }
    in.plateY = y[1] + y[0] * h;  // small angles: y + p_y − θ·p_z with p = (0, −h)
    in.lateralOld = mem.lateralDeflection;
    in.lateralAnchor = mem.lateralAnchor;
    in.compressionOld = mem.compression;
    in.wedgeAnchor = mem.wedgeAnchor;
    return in;
}

ReducedHalfCarModel::Evaluation ReducedHalfCarModel::evaluate(double t, const State& y, const TruckMemory& mem,
                                                              TruckSearchCounts* counts) const {
    return evaluate(rails_(t), y, mem, counts);
}

ReducedHalfCarModel::Evaluation ReducedHalfCarModel::evaluate(const RailState& rail, const State& y,
                                                              const TruckMemory& mem, TruckSearchCounts* counts) const {
    Evaluation e;
    e.rail = rail;
    e.truck = findTruckEquilibrium(makeTruckInputs(e.rail, y, mem), mem.mode, *modeCache_, counts);
    const double pin = e.truck.pinForce;
    const double h = car_.cgAboveCenterPlate, padAbovePlate = truck_.sbAboveSprings - truck_.cpAboveSprings;
    double Fz = -mass_ * units::g, M = h * pin;
    for (int i : {0, 1}) {
        const double Fc = e.truck.rim[i], Fs = e.truck.sideBearing[i];
        Fz += Fc + Fs;
        M += Fc * (kSideSign[i] * truck_.a_c + y[0] * h) + Fs * (kSideSign[i] * truck_.a_s - y[0] * (padAbovePlate - h));
    }
    e.derivative.head<3>() = y.tail<3>();
    e.derivative[3] = M / inertia_;
    e.derivative[4] = pin / mass_;
    e.derivative[5] = Fz / mass_;
    for (int i : {0, 1}) e.railInputPower += e.truck.wheel[i] * e.rail.zDot[i];
    return e;
}

void ReducedHalfCarModel::declareChannels() {
    ChannelTable<Sample>& c = channels_;
    const double lb = units::lbf, deg = units::degree;
    declareHalfCarBodyChannels(c);
    for (int side : {0, 1}) {
        c.add(fmt::format("spring_F_{}", kSideName[side]), "lb", [=](const Sample& s) { return s.truck.spring[side] / lb; });
        c.add(fmt::format("wedge_vertical_F_{}", kSideName[side]), "lb",
              [=](const Sample& s) { return s.truck.friction[side] / lb; });
    }
    c.add("center_pin_F", "lb", [=](const Sample& s) { return s.truck.pinForce / lb; });
    c.add("bolster_roll_F", "deg", [=](const Sample& s) { return s.truck.rollBolster / deg; });
    c.add("wheelset_roll_F", "deg", [=](const Sample& s) { return s.truck.rollWheelset / deg; });
    declareEquivalentWheelsetChannels(c, false);
    // 0 two-point … 7 no contact (TruckEquilibrium.h)
    c.add("truck_support_mode", "", [](const Sample& s) { return double(int(s.truck.mode.support)); });
    c.add("truck_mode_consistent", "", [](const Sample& s) { return s.truck.consistent ? 1.0 : 0.0; });
    declareEnergyChannels(c);
    // The massless truck's wheelset is held laterally by construction: no lateral wheel forces, no L/V.
    declareHalfCarFreightChannels(c, calcStaticWheelLoad(), false);
}

double ReducedHalfCarModel::calcStaticWheelLoad() const {
    const TruckMemory memory = makeStaticMemory();
    TruckInputs in = makeTruckInputs(0, makeStaticState(), memory);
    in.railZ = {0, 0};
    return findTruckEquilibrium(in, memory.mode, *modeCache_).wheel[0];
}

ReducedHalfCarModel::Sample ReducedHalfCarModel::calcSample(double /*t: e.rail is at t*/, const State& y, const Evaluation& e,
                                                            const double* energyIntegrals) const {
    Sample s;
    s.truck = e.truck;
    const RailState& rail = e.rail;  // at t
    s.roll = y[0];
    s.verticalFromStatic = y[2] - staticZ_;
    s.lateral = y[1];
    s.crossLevel = rail.z[1] - rail.z[0];
    s.centerPlate = e.truck.rim[0] + e.truck.rim[1];
    for (int side : {0, 1}) {
        s.sideBearing[side] = e.truck.sideBearing[side];
        s.wheel[side] = e.truck.wheel[side];
        s.wheelLift[side] = e.truck.wheelLift[side];
    }
    s.verticalAccel = e.derivative[5];
    s.lateralAccel = e.derivative[4];
    s.energyStored = calcStoredEnergy(y, e.truck);
    s.energyInput = energyIntegrals ? energyIntegrals[0] : std::numeric_limits<double>::quiet_NaN();
    s.energyDissipated = energyIntegrals ? energyIntegrals[1] : std::numeric_limits<double>::quiet_NaN();
    return s;
}

double ReducedHalfCarModel::calcStoredEnergy(const State& y, const TruckSolution& s) const {
    const TruckGeometry& g = truck_;
    double E = 0.5 * inertia_ * y[3] * y[3] + 0.5 * mass_ * (y[4] * y[4] + y[5] * y[5]) + mass_ * units::g * y[2];
    for (int i : {0, 1}) {
        E += calcVerticalSpringEnergy(s.compression[i], {g.Kv, g.travel, g.Kb});
        E += s.friction[i] * s.friction[i] / (2 * g.kBristle);  // Φ = k_b·(Z − Z_a)
    }
    E += 2 * calcLateralSpringEnergy(s.lateral, {g.Kh, g.gibClearance, g.Kgib, 0});  // both bolster ends
    E += s.lateralFriction * s.lateralFriction / (4 * g.kBristleLateral);       // Φ_H = 2·k_bH·(Y − Y_a)
    E += s.pinForce * s.pinForce / (2 * g.kPin);                                 // F_h = −k_pin·d
    return E;
}

double ReducedHalfCarModel::calcSliderDissipation(const TruckMemory& before, const TruckSolution& after) {
    double D = std::abs(after.lateralFriction) * std::abs(after.lateralAnchor - before.lateralAnchor);
    for (int i : {0, 1}) D += std::abs(after.friction[i]) * std::abs(after.wedgeAnchor[i] - before.wedgeAnchor[i]);
    return D;
}

ReducedHalfCarModel::TruckMemory ReducedHalfCarModel::makeMemoryAfter(const TruckSolution& accepted) {
    TruckMemory m;
    m.mode = accepted.mode;
    m.compression = accepted.compression;
    m.wedgeAnchor = accepted.wedgeAnchor;
    m.lateralDeflection = accepted.lateral;
    m.lateralAnchor = accepted.lateralAnchor;
    m.rollBolster = accepted.rollBolster;
    m.rollWheelset = accepted.rollWheelset;
    return m;
}

void ReducedHalfCarModel::calcChannels(double t, const State& y, const Evaluation& e, std::vector<double>& out,
                                       const double* energyIntegrals) const {
    channels_.evaluate(calcSample(t, y, e, energyIntegrals), out);
}

namespace {
using Memory = ReducedHalfCarModel::TruckMemory;
constexpr int kFlatSize = 6 + 16;  // car body state, then the truck memory

std::vector<double> flatten(const ReducedHalfCarModel::State& y, const Memory& m) {
    return {y[0], y[1], y[2], y[3], y[4], y[5],
            double(int(m.mode.support)), double(int(m.mode.wheels)), double(int(m.mode.wedge[0])),
            double(int(m.mode.wedge[1])), double(int(m.mode.spring[0])), double(int(m.mode.spring[1])),
            double(int(m.mode.lateralWedge)), double(int(m.mode.gib)), m.compression[0], m.compression[1],
            m.wedgeAnchor[0], m.wedgeAnchor[1], m.lateralDeflection, m.lateralAnchor, m.rollBolster, m.rollWheelset};
}

void unflatten(const std::vector<double>& f, ReducedHalfCarModel::State& y, Memory& m) {
    if (int(f.size()) != kFlatSize)
        throw std::invalid_argument("reduced model: initial state has the wrong size");
    // The mode's enumerations: whole numbers in their ranges (a state from elsewhere is checked, not trusted).
    const int counts[8] = {8, 3, 3, 3, 3, 3, 3, 3};
    for (int i = 0; i < 8; ++i) {
        const double v = f[size_t(6 + i)];
        if (!(v >= 0 && v < counts[i] && v == std::floor(v)))
            throw std::invalid_argument(fmt::format("reduced model: initial state entry {} (a truck-mode enumeration) "
                                                    "is {}; expected a whole number in [0, {}]",
                                                    6 + i, v, counts[i] - 1));
    }
    for (int i = 0; i < 6; ++i) y[i] = f[i];
    m.mode.support = CarBodySupport(int(f[6]));
    m.mode.wheels = WheelContact(int(f[7]));
    m.mode.wedge = {WedgeState(int(f[8])), WedgeState(int(f[9]))};
    m.mode.spring = {SpringSegment(int(f[10])), SpringSegment(int(f[11]))};
    m.mode.lateralWedge = WedgeState(int(f[12]));
    m.mode.gib = GibContact(int(f[13]));
    m.compression = {f[14], f[15]};
    m.wedgeAnchor = {f[16], f[17]};
    m.lateralDeflection = f[18];
    m.lateralAnchor = f[19];
    m.rollBolster = f[20];
    m.rollWheelset = f[21];
}
}  // namespace

std::vector<double> ReducedHalfCarModel::calcStaticState() const {
    return flatten(makeStaticState(), makeStaticMemory());
}

RunResult simulateReduced(const ReducedHalfCarModel& model, double duration, ReducedRunStatistics* stats,
                          const std::vector<double>& initial, const RunLimits& limits) {
    using State = ReducedHalfCarModel::State;
    const auto wall0 = std::chrono::steady_clock::now();
    const double h = ReducedHalfCarModel::kStep;
    State y = model.makeStaticState();
    ReducedHalfCarModel::TruckMemory mem = model.makeStaticMemory();
    if (!initial.empty()) unflatten(initial, y, mem);
    RunResult result;
    result.history.names = {"t_s"};
    for (const auto& n : model.getChannels().names) result.history.names.push_back(n);
    std::vector<double> row;
    ReducedRunStatistics st;
    RunGuard guard(model.getChannels(), limits);
    double energy[2] = {0, 0};  // energy audit: rail work (RK4-weighted stage powers), slider dissipation
    // The accepted evaluation, at (tAccepted, y) with the memory before it. When its
    // mode is consistent, the next step's first stage at the same time and state (with
    // the memory it set) solves that mode first with the same right-hand side (a stick
    // row's anchor did not move; a slip row holds ±F_V) and finds it consistent (a
    // slipping wedge's Z − Z_old is now 0): the same evaluation, bit for bit (test
    // ReducedModel.ReusedFirstStageIsTheEvaluationItReplaces).
    ReducedHalfCarModel::Evaluation accepted;
    double tAccepted = std::numeric_limits<double>::quiet_NaN();
    // The rails at the last time asked for: a step's two midpoint stages share one
    // time, and its last stage the time of the evaluation it then accepts (the same
    // RailState when the times are equal, bit for bit).
    double railTime = std::numeric_limits<double>::quiet_NaN();
    RailState rail;
    auto getRails = [&](double t) -> const RailState& {
        if (!(t == railTime)) rail = model.calcRails(t), railTime = t;
        return rail;
    };
    auto accept = [&](double t) {
        accepted = model.evaluate(getRails(t), y, mem, &st.modes);
        tAccepted = t;
        const ReducedHalfCarModel::Evaluation& e = accepted;
        energy[1] += ReducedHalfCarModel::calcSliderDissipation(mem, e.truck);
        mem = ReducedHalfCarModel::makeMemoryAfter(e.truck);
        if (!e.truck.consistent) ++st.inconsistentSteps;
        model.calcChannels(t, y, e, row, energy);
        return result.history.samples.append(t, row);
    };
    // Whole steps of Δt, then one shorter step to end at `duration` exactly when it is
    // not a whole number of steps (a periodic orbit's map runs over T = L / V).
    const long n = long(std::floor(duration / h + 1e-9));
    const double last = duration - double(n) * h;
    const long total = last > 1e-9 * h ? n + 1 : n;
    result.history.reserveSamples(total + 1);
    guard.check(accept(0), result);
    long k = 0;
    for (; k < total && !result.stop; ++k) {
        const double t = double(k) * h, dt = k < n ? h : last;
        const ReducedHalfCarModel::Evaluation e1 =
            t == tAccepted && accepted.truck.consistent ? accepted : model.evaluate(getRails(t), y, mem, &st.modes);
        const ReducedHalfCarModel::Evaluation e2 =
            model.evaluate(getRails(t + dt / 2), y + dt / 2 * e1.derivative, mem, &st.modes);
        const ReducedHalfCarModel::Evaluation e3 =
            model.evaluate(getRails(t + dt / 2), y + dt / 2 * e2.derivative, mem, &st.modes);
        const ReducedHalfCarModel::Evaluation e4 = model.evaluate(getRails(t + dt), y + dt * e3.derivative, mem, &st.modes);
        y += dt / 6 * (e1.derivative + 2 * e2.derivative + 2 * e3.derivative + e4.derivative);
        energy[0] += dt / 6 * (e1.railInputPower + 2 * e2.railInputPower + 2 * e3.railInputPower + e4.railInputPower);
        const double tNext = k < n ? t + h : duration;
        if (!y.allFinite()) {
            throw NumericalFailure(fmt::format(
                "reduced model: state became non-finite at t = {:.4f} s (truck mode: {})\nroll {} rad, y {} m, z {} m",
                tNext, mem.mode.describe(), y[0], y[1], y[2]), tNext);
        }
        guard.check(accept(tNext), result);
        ++st.steps;
    }
    result.steps = st.steps;
    result.finalState = flatten(y, mem);
    result.realizations = 4 * st.steps + st.steps + 1;
    result.simTime = k > n ? duration : double(k) * h;
    result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    if (stats) *stats = st;
    return result;
}

}  // namespace rockroll
