// The reduced (massless-truck) model: static equilibrium, each mode's equations
// against a direct force and moment balance, the wedges' stick and slip, and the
// mode search.
#include "bespoke/ReducedHalfCarModel.h"
#include "mbmodel/Units.h"
#include "scenarios/ScenarioRun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <map>
#include <random>
#include <set>

using namespace rockroll;

namespace {
const CarParameters& getCar() {
    static const CarParameters car = makeCarParameters("70ton-loaded");
    return car;
}
ReducedHalfCarModel makeLevelModel() {
    return ReducedHalfCarModel(getCar(), [](double) { return RailState{}; });
}
constexpr double kSide[2] = {+1.0, -1.0};

/// The bits of a double: tells −0 from +0 (and NaNs apart), which == does not.
std::uint64_t getBits(double v) {
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
}

/// Every field of two truck solutions, compared bit for bit.
/// violation: also compare the violation (a consistent mode's may differ below kConsistentViolation).
void expectBitIdentical(const TruckSolution& a, const TruckSolution& b, bool violation = true) {
    EXPECT_TRUE(a.mode == b.mode) << a.mode.describe() << " / " << b.mode.describe();
    EXPECT_EQ(a.consistent, b.consistent);
    auto same = [](double x, double y) { EXPECT_EQ(getBits(x), getBits(y)) << x << " / " << y; };
    if (violation) same(a.violation, b.violation);
    for (double TruckSolution::*f : {&TruckSolution::zBolster, &TruckSolution::rollBolster, &TruckSolution::zWheelset,
                                     &TruckSolution::rollWheelset, &TruckSolution::yBolster, &TruckSolution::pinForce,
                                     &TruckSolution::lateral, &TruckSolution::lateralFriction,
                                     &TruckSolution::lateralAnchor})
        same(a.*f, b.*f);
    for (int i : {0, 1}) {
        same(a.rim[i], b.rim[i]);
        same(a.sideBearing[i], b.sideBearing[i]);
        same(a.wheel[i], b.wheel[i]);
        same(a.friction[i], b.friction[i]);
        same(a.spring[i], b.spring[i]);
        same(a.compression[i], b.compression[i]);
        same(a.wheelLift[i], b.wheelLift[i]);
        same(a.wedgeAnchor[i], b.wedgeAnchor[i]);
    }
}
}  // namespace

TEST(ReducedModel, StaticStateIsConsistentTwoPointEquilibrium) {
    const ReducedHalfCarModel m = makeLevelModel();
    const auto y = m.makeStaticState();
    const auto e = m.evaluate(0, y, m.makeStaticMemory());
    EXPECT_TRUE(e.truck.consistent);
    EXPECT_EQ(e.truck.mode.support, CarBodySupport::TwoPointCenterPlate);
    EXPECT_EQ(e.truck.mode.wheels, WheelContact::Both);
    const double half = m.getMass() * units::g / 2;
    for (int i : {0, 1}) {
        EXPECT_NEAR(e.truck.rim[i], half, 1e-6 * half);
        EXPECT_NEAR(e.truck.wheel[i], half, 1e-6 * half);
        EXPECT_NEAR(e.truck.spring[i], half, 1e-6 * half);
        EXPECT_NEAR(e.truck.friction[i], 0.0, 1e-6);
        EXPECT_EQ(e.truck.sideBearing[i], 0.0);
    }
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(e.derivative[k], 0.0, 1e-9);
}

TEST(ReducedModel, ZeroAmplitudeRunStaysStatic) {
    Scenario sc = getDefaultScenario();
    sc.model = "reduced";
    sc.track.amplitude = 0;
    sc.run.duration = 3;
    const RunSummary s = runScenario(sc).summary;
    EXPECT_NEAR(s.maxRollDeg, 0.0, 1e-9);
    EXPECT_NEAR(s.rawMaxWheelLoadLb, s.staticWheelLoadLb, 1e-6 * s.staticWheelLoadLb);
}

// Every support and wheel mode, solved at a rolled, displaced car body: the
// solution's forces must balance the bolster and the wheelset when summed
// directly from the geometry, and every closed contact must have zero gap.
TEST(ReducedModel, EveryModeSatisfiesADirectForceAndMomentBalance) {
    const ReducedHalfCarModel m = makeLevelModel();
    const TruckGeometry& g = m.getTruckGeometry();
    auto y = m.makeStaticState();
    y[0] = 0.03, y[1] = 0.004, y[2] -= 0.01;
    auto mem = m.makeStaticMemory();
    mem.wedgeAnchor = {0.05, 0.055};
    TruckInputs in = m.makeTruckInputs(0.1, y, mem);
    in.railZ = {0.004, -0.003};
    int solved = 0;
    for (const TruckMode& mode : enumerateTruckModes()) {
        const TruckSolution s = solveTruckMode(g, in, mode);
        if (s.violation >= 1e300) continue;  // singular mode (e.g. bolster free on free springs)
        ++solved;
        // Bolster: vertical forces and moment about its origin (small angles, nominal arms).
        double Fz = 0, M = 0, Fy = -s.pinForce - s.lateralFriction;
        for (int i : {0, 1}) {
            const double load = s.spring[i] + s.friction[i];
            Fz += -s.rim[i] - s.sideBearing[i] + load;
            M += -kSide[i] * g.a_c * s.rim[i] - kSide[i] * g.a_s * s.sideBearing[i] + kSide[i] * g.l_s * load;
        }
        M += g.cpAboveSprings * s.pinForce;
        const double Y = s.lateral;
        const bool gibModeClosed = mode.gib != GibContact::Open;
        Fy -= 2 * (g.Kh * Y + (gibModeClosed ? g.Kgib * (mode.gib == GibContact::Positive ? Y - g.gibClearance
                                                                                             : Y + g.gibClearance)
                                             : 0.0));
        ASSERT_NEAR(Fz, 0.0, 1e-6 * 1e5) << mode.describe();
        ASSERT_NEAR(M, 0.0, 1e-6 * 1e5) << mode.describe();
        ASSERT_NEAR(Fy, 0.0, 1e-6 * 1e5) << mode.describe();
        // Wheelset.
        double Wz = s.wheel[0] + s.wheel[1], WM = g.halfGauge * (s.wheel[0] - s.wheel[1]);
        for (int i : {0, 1}) {
            Wz -= s.spring[i] + s.friction[i];
            WM -= kSide[i] * g.l_s * (s.spring[i] + s.friction[i]);
        }
        WM += g.springTopAboveRail * s.pinForce;
        ASSERT_NEAR(Wz, 0.0, 1e-6 * 1e5) << mode.describe();
        ASSERT_NEAR(WM, 0.0, 1e-6 * 1e5) << mode.describe();
        // Closed contacts have zero gap; lifted wheels carry nothing.
        for (int i : {0, 1}) {
            const double rimGap = in.rimZ[i] - (s.zBolster + g.cpAboveSprings + s.rollBolster * kSide[i] * g.a_c);
            const bool rimClosed = mode.support == CarBodySupport::TwoPointCenterPlate ||
                                   ((mode.support == CarBodySupport::CornerLeft ||
                                     mode.support == CarBodySupport::SideBearingAndCornerLeft) && i == 0) ||
                                   ((mode.support == CarBodySupport::CornerRight ||
                                     mode.support == CarBodySupport::SideBearingAndCornerRight) && i == 1);
            if (rimClosed) ASSERT_NEAR(rimGap, 0.0, 1e-9) << mode.describe();
            else ASSERT_NEAR(s.rim[i], 0.0, 1e-6) << mode.describe();
            const bool lifted = (mode.wheels == WheelContact::LiftLeft && i == 0) ||
                                (mode.wheels == WheelContact::LiftRight && i == 1);
            if (lifted) ASSERT_NEAR(s.wheel[i], 0.0, 1e-6);
            else ASSERT_NEAR(s.zWheelset - g.wheelRadius + s.rollWheelset * kSide[i] * g.halfGauge, in.railZ[i], 1e-9);
            switch (mode.wedge[i]) {
            case WedgeState::SlipUp: ASSERT_NEAR(s.friction[i], -g.Fv, 1e-9 * g.Fv); break;
            case WedgeState::SlipDown: ASSERT_NEAR(s.friction[i], g.Fv, 1e-9 * g.Fv); break;
            case WedgeState::Stick:
                ASSERT_NEAR(s.friction[i], g.kBristle * (s.compression[i] - in.wedgeAnchor[i]), 1e-6 * g.Fv);
                break;
            }
        }
    }
    EXPECT_GT(solved, 10000);
}

// A wedge under a slowly growing, then reversing, load: it sticks (its force
// follows the bristle, its anchor stays) until the force reaches F_V, slides at
// ±F_V with a moving anchor, and sticks again at the reversal.
TEST(ReducedModel, WedgeSticksThenSlipsThenSticksAgainAtReversal) {
    const ReducedHalfCarModel m = makeLevelModel();
    const TruckGeometry& g = m.getTruckGeometry();
    auto y = m.makeStaticState();
    auto mem = m.makeStaticMemory();
    std::vector<double> friction;
    std::vector<WedgeState> state;
    auto stepTo = [&](double dz) {
        auto yy = y;
        yy[2] += dz;  // car body pushed down (dz < 0) compresses the springs
        const auto e = m.evaluate(0, yy, mem);
        ASSERT_TRUE(e.truck.consistent);
        mem.mode = e.truck.mode;
        mem.compression = e.truck.compression;
        mem.wedgeAnchor = e.truck.wedgeAnchor;
        friction.push_back(e.truck.friction[0]);
        state.push_back(e.truck.mode.wedge[0]);
    };
    for (int k = 1; k <= 40; ++k) stepTo(-2e-5 * k);       // down 0.8 mm
    for (int k = 39; k >= 20; --k) stepTo(-2e-5 * k);      // back up 0.4 mm
    // Sticks first: Φ = k_b (Z − Z_a) grows with the compression.
    EXPECT_EQ(state[0], WedgeState::Stick);
    EXPECT_NEAR(friction[0], g.kBristle * 2e-5, 1e-6 * g.Fv);
    // Reaches the limit and slides down at +F_V.
    EXPECT_EQ(state[39], WedgeState::SlipDown);
    EXPECT_NEAR(friction[39], g.Fv, 1e-9 * g.Fv);
    for (double f : friction) EXPECT_LE(std::abs(f), g.Fv * (1 + 1e-9));
    // At the reversal it sticks again and unloads along the bristle.
    EXPECT_EQ(state[40], WedgeState::Stick);
    EXPECT_NEAR(friction[40], g.Fv - g.kBristle * 2e-5, 1e-6 * g.Fv);
}

TEST(ReducedModel, ModeSearchEnumeratesEveryModeOnceAndFindsConsistentModes) {
    const auto modes = enumerateTruckModes();
    EXPECT_EQ(modes.size(), 8u * 3 * 9 * 9 * 9);
    std::set<std::string> names;
    for (const auto& m : modes) names.insert(m.describe());
    EXPECT_EQ(names.size(), modes.size());
    EXPECT_EQ(modes.front().support, CarBodySupport::TwoPointCenterPlate);
    EXPECT_EQ(findNeighbourModes(modes.front()).size(), 7u + 2 * 7);  // support, and 7 three-way choices
    // Heavy roll to the left: the search leaves two-point contact for the left side bearing.
    const ReducedHalfCarModel m = makeLevelModel();
    auto y = m.makeStaticState();
    y[0] = -0.06;  // left side down
    const auto e = m.evaluate(0, y, m.makeStaticMemory());
    EXPECT_TRUE(e.truck.consistent) << e.truck.mode.describe();
    EXPECT_GT(e.truck.sideBearing[0], 0.0) << e.truck.mode.describe();
    EXPECT_EQ(e.truck.rim[1], 0.0);
}

// The reduced model rocks into the severe regime on the default case, as the
// report's own reduced simulation did (its §3.1).
TEST(ReducedModel, DefaultCaseReachesSideBearingsAndWheelLift) {
    Scenario sc = getDefaultScenario();
    sc.model = "reduced";
    sc.run.duration = 12;
    const RunSummary s = runScenario(sc).summary;
    EXPECT_EQ(s.regime, "severe");
    EXPECT_GT(s.maxWheelLiftIn, 0.1);
    EXPECT_GT(s.maxSideBearingLoadLb, 0.0);
}

// The mode search with cached per-mode factorizations (TruckModeCache, what the
// model uses) returns bit for bit what the same search returns when every mode's
// system is assembled and factored afresh (solveTruckMode): the matrix depends on
// the mode and the geometry only, the inputs on the right-hand side alone.
TEST(ReducedModel, CachedModeSearchIsBitIdenticalToTheDirectSolve) {
    const ReducedHalfCarModel m = makeLevelModel();
    const TruckGeometry& g = m.getTruckGeometry();
    const auto modes = enumerateTruckModes();
    std::map<int, int> classOf;  // getIndex(getMatrixClass(m)) -> getClassIndex
    std::set<int> classIndices;
    for (size_t i = 0; i < modes.size(); ++i) {
        ASSERT_EQ(TruckModeCache::getIndex(modes[i]), int(i));
        const int matrixClass = TruckModeCache::getIndex(TruckModeCache::getMatrixClass(modes[i]));
        const int classIndex = TruckModeCache::getClassIndex(int(i));
        ASSERT_GE(classIndex, 0);
        ASSERT_LT(classIndex, TruckModeCache::kClassCount);
        const auto [at, inserted] = classOf.emplace(matrixClass, classIndex);
        ASSERT_EQ(at->second, classIndex) << modes[i].describe();  // one index per class
        if (inserted) {
            ASSERT_TRUE(classIndices.insert(classIndex).second) << modes[i].describe();  // one class per index
        }
    }
    EXPECT_EQ(int(classIndices.size()), TruckModeCache::kClassCount);
    auto direct = [&](const TruckInputs& in, const TruckMode& previous) {  // findTruckEquilibrium's order
        TruckSolution best = solveTruckMode(g, in, previous);
        if (best.consistent) return best;
        std::vector<TruckMode> order = findNeighbourModes(previous);
        for (const TruckMode& n : findNeighbourModes(previous))
            for (const TruckMode& k : findNeighbourModes(n))
                if (!(k == previous)) order.push_back(k);
        order.insert(order.end(), modes.begin(), modes.end());
        for (const TruckMode& k : order) {
            TruckSolution s = solveTruckMode(g, in, k);
            if (s.consistent) return s;
            if (s.violation < best.violation) best = s;
        }
        return best;
    };
    TruckMode far;  // no contact, a wheel lifted, springs free and bottomed: forces the full enumeration
    far.support = CarBodySupport::None, far.wheels = WheelContact::LiftLeft;
    far.spring = {SpringSegment::Free, SpringSegment::Bottomed};
    far.lateralWedge = WedgeState::SlipDown, far.gib = GibContact::Positive;
    const TruckModeCache cache(g);
    int searches = 0;
    for (double roll : {0.0, 0.01, -0.03, 0.06})
        for (double lateral : {0.0, 0.004}) {
            auto y = m.makeStaticState();
            y[0] = roll, y[1] = lateral, y[2] -= 0.005;
            auto mem = m.makeStaticMemory();
            TruckInputs in = m.makeTruckInputs(0.1, y, mem);
            in.railZ = {0.004, -0.003};
            for (const TruckMode& previous : {mem.mode, far}) {
                const TruckSolution a = findTruckEquilibrium(in, previous, cache), b = direct(in, previous);
                ++searches;
                expectBitIdentical(a, b);
            }
        }
    EXPECT_EQ(searches, 16);
}

// Every mode solved with the cache's factorization (one per matrix class: modes that
// differ only in a slip's direction or the gib's side share it) and the sparse
// substitution gives bit for bit what assembling and factoring that mode's own system
// and substituting through every entry of the factors gives.
TEST(ReducedModel, CachedSolveOfEveryModeIsBitIdenticalToTheDirectSolve) {
    const ReducedHalfCarModel m = makeLevelModel();
    const TruckGeometry& g = m.getTruckGeometry();
    const TruckModeCache cache(g);
    const auto modes = enumerateTruckModes();
    long shared = 0;
    for (const TruckMode& mode : modes) shared += TruckModeCache::getMatrixClass(mode) == mode ? 0 : 1;
    EXPECT_EQ(long(modes.size()) - shared, 8 * 3 * 9 * 2 * 2 * 2 * 2);  // stick or slip ×3, gibs open or in contact
    int consistent = 0;
    for (double roll : {0.0, 0.02, -0.05}) {
        auto y = m.makeStaticState();
        y[0] = roll, y[1] = 0.003, y[2] -= 0.004;
        auto mem = m.makeStaticMemory();
        mem.compression[0] += 0.002, mem.wedgeAnchor[1] -= 0.001, mem.lateralDeflection = 0.004;
        TruckInputs in = m.makeTruckInputs(0.1, y, mem);
        in.railZ = {0.003, -0.002};
        for (const TruckMode& mode : modes) {
            const TruckSolution a = solveTruckMode(in, mode, cache),
                                b = solveTruckMode(g, in, mode, TruckSubstitution::Dense);
            expectBitIdentical(a, b);
            if (::testing::Test::HasFailure()) FAIL() << mode.describe();
            consistent += a.consistent ? 1 : 0;
        }
    }
    EXPECT_GT(consistent, 0);
}

// The search's order decides its answer: along a rocking run some states have more
// than one consistent mode, with different wedge states and different forces.
TEST(ReducedModel, SeveralModesCanBeConsistentAtOneState) {
    const ReducedHalfCarModel m(getCar(), [](double t) {
        const double w = 2 * M_PI * 1.3, a = 1.0 * units::inch * std::sin(w * t), v = 1.0 * units::inch * w * std::cos(w * t);
        return RailState{{a, -a}, {v, -v}};
    });
    const TruckModeCache& cache = *TruckModeCache::getShared(m.getTruckGeometry());
    const auto modes = enumerateTruckModes();
    auto y = m.makeStaticState();
    auto mem = m.makeStaticMemory();
    const double h = ReducedHalfCarModel::kStep;
    int states = 0, several = 0;
    double largestForceGap = 0;
    for (int k = 0; k < 600; ++k) {
        const double t = k * h;
        const auto e = m.evaluate(t, y, mem);
        if (k % 10 == 0) {
            const TruckInputs in = m.makeTruckInputs(t, y, mem);
            std::vector<TruckSolution> consistent;
            for (const TruckMode& mode : modes) {
                const TruckSolution s = solveTruckMode(in, mode, cache);
                if (s.consistent) consistent.push_back(s);
            }
            ++states;
            if (consistent.size() > 1) {
                ++several;
                for (const TruckSolution& s : consistent)
                    for (int i : {0, 1})
                        largestForceGap = std::max(largestForceGap, std::abs(s.wheel[i] - consistent[0].wheel[i]));
            }
        }
        const auto k2 = m.evaluate(t + h / 2, y + h / 2 * e.derivative, mem).derivative;
        const auto k3 = m.evaluate(t + h / 2, y + h / 2 * k2, mem).derivative;
        const auto k4 = m.evaluate(t + h, y + h * k3, mem).derivative;
        y += h / 6 * (e.derivative + 2 * k2 + 2 * k3 + k4);
        mem = ReducedHalfCarModel::makeMemoryAfter(m.evaluate(t + h, y, mem).truck);
    }
    EXPECT_EQ(states, 60);
    EXPECT_GT(several, 0) << "no state with two consistent modes";
    EXPECT_GT(largestForceGap, 1.0 * units::lbf) << "the consistent modes agree on the wheel loads";
    std::printf("states with more than one consistent mode: %d of %d; wheel loads up to %.0f N apart\n", several, states,
                largestForceGap);
}

// Models of one geometry share one cache; another geometry gets its own.
TEST(ReducedModel, ModelsOfOneTruckGeometryShareTheirModeCache) {
    const TruckGeometry g = makeLevelModel().getTruckGeometry();
    TruckGeometry stiffer = g;
    stiffer.Kv *= 1.01;
    const auto a = TruckModeCache::getShared(g), b = TruckModeCache::getShared(g), c = TruckModeCache::getShared(stiffer);
    EXPECT_EQ(a.get(), b.get());
    EXPECT_NE(a.get(), c.get());
    EXPECT_EQ(c->getGeometry().Kv, stiffer.Kv);
    EXPECT_EQ(a->getGeometry().Kv, g.Kv);
}

namespace {
/// Truck inputs far and near the static state (rolled, shifted, lifted car body; rails
/// apart; remembered compressions, anchors and lateral deflections moved), from a fixed seed.
std::vector<TruckInputs> makeScatteredInputs(const ReducedHalfCarModel& m, int count, unsigned seed) {
    std::mt19937 rng(seed);
    auto uniform = [&rng](double lo, double hi) { return lo + (hi - lo) * double(rng() - rng.min()) / double(rng.max() - rng.min()); };
    std::vector<TruckInputs> out;
    for (int k = 0; k < count; ++k) {
        const double scale = k % 2 == 0 ? 1.0 : 0.1;  // every other one near the static state
        auto y = m.makeStaticState();
        y[0] = scale * uniform(-0.08, 0.08), y[1] = scale * uniform(-0.02, 0.02), y[2] += scale * uniform(-0.03, 0.03);
        auto mem = m.makeStaticMemory();
        for (int i : {0, 1}) {
            mem.compression[i] += scale * uniform(-0.02, 0.02);
            mem.wedgeAnchor[i] = mem.compression[i] + scale * uniform(-0.002, 0.002);
        }
        mem.lateralDeflection = scale * uniform(-0.02, 0.02);
        mem.lateralAnchor = mem.lateralDeflection + scale * uniform(-0.002, 0.002);
        TruckInputs in = m.makeTruckInputs(0.1, y, mem);
        in.railZ = {scale * uniform(-0.02, 0.02), scale * uniform(-0.02, 0.02)};
        out.push_back(in);
    }
    return out;
}

/// Cross-level rocking at 1.3 Hz, 1 in: side bearings, lift and slipping wedges.
ReducedHalfCarModel makeRockingModel() {
    return ReducedHalfCarModel(getCar(), [](double t) {
        const double w = 2 * M_PI * 1.3, a = 1.0 * units::inch * std::sin(w * t), v = 1.0 * units::inch * w * std::cos(w * t);
        return RailState{{a, -a}, {v, -v}};
    });
}

/// One RK4 step from (t, y) whose first stage is e, with the memory fixed over the step, as
/// simulateReduced steps.
ReducedHalfCarModel::State stepWithFixedMemory(const ReducedHalfCarModel& m, double t, const ReducedHalfCarModel::State& y,
                                               const ReducedHalfCarModel::TruckMemory& mem,
                                               const ReducedHalfCarModel::Evaluation& e) {
    const double h = ReducedHalfCarModel::kStep;
    const auto k2 = m.evaluate(t + h / 2, y + h / 2 * e.derivative, mem).derivative;
    const auto k3 = m.evaluate(t + h / 2, y + h / 2 * k2, mem).derivative;
    const auto k4 = m.evaluate(t + h, y + h * k3, mem).derivative;
    return y + h / 6 * (e.derivative + 2 * k2 + 2 * k3 + k4);
}
}  // namespace

// The search skips a mode when calcChoiceBound already rules it out, which is only
// sound if the bound never exceeds the violation the mode's solve gives. Checked for
// every mode at scattered states; the bound must also rule out many modes, or the
// skip would be pointless.
TEST(ReducedModel, ChoiceBoundsNeverExceedTheViolation) {
    const ReducedHalfCarModel m = makeLevelModel();
    const TruckGeometry& g = m.getTruckGeometry();
    const auto modes = enumerateTruckModes();
    long positive = 0, checked = 0;
    for (const TruckInputs& in : makeScatteredInputs(m, 12, 7)) {
        for (const TruckMode& mode : modes) {
            const double bound = calcChoiceBound(g, in, mode);
            const TruckSolution s = solveTruckMode(g, in, mode);
            ++checked;
            if (bound > 0) ++positive;
            ASSERT_LE(bound, s.violation) << mode.describe();
        }
    }
    EXPECT_GT(positive, checked / 2) << "the bound rules out too few modes to matter";
}

// The pruned search returns the exhaustive search's solution, bit for bit, whatever
// the previous mode, including searches that reach the enumeration of every mode.
TEST(ReducedModel, PrunedModeSearchIsBitIdenticalToTheExhaustiveSearch) {
    const ReducedHalfCarModel m = makeLevelModel();
    const TruckModeCache cache(m.getTruckGeometry());
    const auto modes = enumerateTruckModes();
    const auto inputs = makeScatteredInputs(m, 120, 11);
    TruckSearchCounts screened, pruned, exhaustive;
    for (size_t k = 0; k < inputs.size(); ++k) {
        const TruckMode& previous = modes[(k * 7919) % modes.size()];
        const TruckSolution a = findTruckEquilibrium(inputs[k], previous, cache, &screened);
        const TruckSolution b =
            findTruckEquilibrium(inputs[k], previous, cache, &pruned, TruckSearchPruning::ChoiceBounds);
        const TruckSolution c =
            findTruckEquilibrium(inputs[k], previous, cache, &exhaustive, TruckSearchPruning::Exhaustive);
        expectBitIdentical(a, c);
        expectBitIdentical(b, c);
    }
    EXPECT_EQ(pruned.searches, exhaustive.searches);
    EXPECT_EQ(pruned.enumerations, exhaustive.enumerations);
    EXPECT_EQ(screened.enumerations, exhaustive.enumerations);
    EXPECT_GT(exhaustive.enumerations, 10);  // the states reach the full enumeration
    EXPECT_EQ(exhaustive.skipped, 0);
    EXPECT_EQ(pruned.screened, 0);
    EXPECT_LT(pruned.solves, exhaustive.solves / 4);  // the bounds and the repeats save real work
    EXPECT_EQ(screened.skipped, pruned.skipped);      // the screen comes after the bounds
    EXPECT_EQ(pruned.kinematic, 0);
    EXPECT_GT(screened.kinematic, 0);  // the kinematic bounds come before the screen
    EXPECT_EQ(screened.solves + screened.kinematic + screened.screened, pruned.solves);
    EXPECT_LT(screened.solves, pruned.solves / 4);  // the screen saves most of the rest
}

// The screen tries first the check "q ≥ 0" that last failed for a mode
// (TruckModeCache::getScreenHint). The hint orders its work, never its answer: the same
// searches give the same solutions, bit for bit, and the same counts (how many modes the
// screen ruled out) with a fresh cache, with one whose hints earlier searches set, and
// with one whose every hint is set by hand to some check "q ≥ 0", mostly not the one that fails.
TEST(ReducedModel, ScreenHintsOrderTheWorkNotTheAnswer) {
    const ReducedHalfCarModel m = makeLevelModel();
    const TruckGeometry& g = m.getTruckGeometry();
    const auto modes = enumerateTruckModes();
    const TruckModeCache fresh(g), warmed(g), forced(g);
    for (const TruckInputs& in : makeScatteredInputs(m, 40, 3))  // other states set the warmed cache's hints
        for (int k = 0; k < 3; ++k) findTruckEquilibrium(in, modes[size_t(k * 1931) % modes.size()], warmed);
    const int atLeastZero[12] = {0, 1, 2, 3, 4, 5, 9, 10, 11, 12, 13, 14};  // forces, gaps, lifts
    for (int i = 0; i < TruckModeCache::kModeCount; ++i) forced.setScreenHint(i, atLeastZero[i % 12]);
    int hinted = 0;
    for (int i = 0; i < TruckModeCache::kModeCount; ++i) hinted += warmed.getScreenHint(i) >= 0 ? 1 : 0;
    EXPECT_GT(hinted, 100) << "the warming searches set too few hints to test";
    TruckSearchCounts a, b, c;
    const auto inputs = makeScatteredInputs(m, 80, 13);
    for (size_t k = 0; k < inputs.size(); ++k) {
        const TruckMode& previous = modes[(k * 7919) % modes.size()];
        const TruckSolution x = findTruckEquilibrium(inputs[k], previous, fresh, &a);
        expectBitIdentical(findTruckEquilibrium(inputs[k], previous, warmed, &b), x);
        expectBitIdentical(findTruckEquilibrium(inputs[k], previous, forced, &c), x);
    }
    EXPECT_GT(a.screened, 1000);
    for (const TruckSearchCounts* n : {&b, &c}) {
        EXPECT_EQ(n->solves, a.solves);
        EXPECT_EQ(n->screened, a.screened);
        EXPECT_EQ(n->kinematic, a.kinematic);
        EXPECT_EQ(n->skipped, a.skipped);
        EXPECT_EQ(n->enumerations, a.enumerations);
    }
    // A quantity no mode checks as "q ≥ 0" is kept as no hint.
    forced.setScreenHint(0, 6);
    EXPECT_EQ(forced.getScreenHint(0), -1);
}

// The screen's error bound covers the difference between the screened quantity and the
// solved one: every mode with an invertible matrix, at scattered states. Two parts: the
// rows' single-precision rounding (kScreenRowRounding), a proven bound, and the rest
// (kScreenRelativeError of the size of each quantity's terms, and a floor for the
// solve's rounding), which must cover what remains with a margin of 100. Measured before
// the rows were single precision, the rest alone: the relative part up to 1.2e-14
// (lengths), the forces up to 4e-8 N where their terms are small (an open contact's zero
// force); the largest difference was 4e-4 of its bound.
TEST(ReducedModel, ScreenErrorBoundCoversTheSolve) {
    const ReducedHalfCarModel m = makeLevelModel();
    const TruckModeCache cache(m.getTruckGeometry());
    const auto modes = enumerateTruckModes();
    double worst = 0;       // largest (|screened − solved| − row rounding bound) / the rest of the bound
    double worstWhole = 0;  // largest |screened − solved| / error bound
    long compared = 0;
    for (const TruckInputs& in : makeScatteredInputs(m, 6, 5))
        for (const TruckMode& mode : modes) {
            const TruckCheckedQuantities q = calcCheckedQuantities(in, mode, cache);
            for (size_t i = 0; i < q.solved.size(); ++i) {
                ASSERT_TRUE(std::isfinite(q.solved[i]) && std::isfinite(q.screened[i])) << mode.describe();
                const double difference = std::abs(q.screened[i] - q.solved[i]);
                ASSERT_LE(difference, q.screenError[i]) << mode.describe() << ", quantity " << i;
                const double rest = q.screenError[i] - q.screenRowRounding[i];
                const double r = std::max(0.0, difference - q.screenRowRounding[i]) / rest;
                worst = std::max(worst, r);
                worstWhole = std::max(worstWhole, difference / q.screenError[i]);
                ++compared;
            }
        }
    EXPECT_GT(compared, 6L * 17496 * 18 / 2);  // most matrices are invertible
    EXPECT_LT(worst, 0.01) << "largest (|screened - solved| - row rounding bound) / the rest of the bound";
    std::printf("screen: largest |screened - solved| = %.3g of its error bound; beyond the rows' rounding bound, "
                "%.3g of the rest (%ld quantities)\n", worstWhole, worst, compared);
}

// The first pass also leaves out a mode whose closed contacts and wheels on the rails leave
// one degree of freedom t (θ_w with a wheel lifted, θ_b with one closed contact) when its
// kinematic checks, affine in t, ask t to lie in intervals that do not meet
// (calcOneParameterKinematics). That is sound only if each checked quantity, evaluated along
// the family at the solve's own t, equals the solved quantity to well within its margin:
// checked for every such mode of three cars at scattered states whose solved |t| ≤ 1 rad
// (the margins are taken there; a mode is ruled out only when one of its intervals confines
// t to it).
TEST(ReducedModel, OneParameterFamiliesMatchTheSolve) {
    double worst = 0;  // largest |solved − along the family| / margin
    long compared = 0, beyond = 0;
    for (const char* carName : {"70ton-loaded", "100ton-loaded", "70ton-empty"}) {
        const ReducedHalfCarModel m(makeCarParameters(carName), [](double) { return RailState{}; });
        const TruckGeometry& g = m.getTruckGeometry();
        const TruckModeCache cache(g);
        for (const TruckInputs& in : makeScatteredInputs(m, 6, 13))
            for (const TruckMode& mode : enumerateTruckModes()) {
                if (!calcOneParameterKinematics(g, in, mode, 0)) continue;
                const TruckSolution s = solveTruckMode(in, mode, cache);
                if (s.violation == 1e300) continue;  // a singular mode: never consistent
                const auto along0 = calcOneParameterKinematics(g, in, mode, 0);
                const double t = along0->wheelsetRoll ? s.rollWheelset : s.rollBolster;
                if (!(std::abs(t) <= 1)) {
                    ++beyond;
                    continue;
                }
                const OneParameterKinematics along = *calcOneParameterKinematics(g, in, mode, t);
                const TruckCheckedQuantities q = calcCheckedQuantities(in, mode, cache);
                ASSERT_FALSE(along.atLeastZero.empty());
                for (size_t j = 0; j < along.atLeastZero.size(); ++j) {
                    worst = std::max(worst, std::abs(q.solved[size_t(along.atLeastZeroQuantity[j])] - along.atLeastZero[j]) /
                                                along.atLeastZeroMargin[j]);
                    ++compared;
                }
                for (int i : {0, 1}) {
                    worst = std::max(worst, std::abs(s.compression[size_t(i)] - along.compression[size_t(i)]) /
                                                along.compressionMargin[size_t(i)]);
                    ++compared;
                }
            }
    }
    EXPECT_GT(compared, 3L * 6 * 17496 / 3);
    EXPECT_LT(worst, 0.01) << "largest |solved - along the family| / margin";
    std::printf("one-parameter families: largest |solved - along the family| = %.3g of the margin (%ld quantities, "
                "%ld modes with |t| > 1 rad)\n", worst, compared, beyond);
}

// What the kinematic bounds rule out is not consistent: every mode, at scattered states and
// along a rocking run's states, with the solve's own verdict. The bounds must rule out many
// modes of the one-parameter families, or they would not be worth their cost.
TEST(ReducedModel, KinematicBoundsRuleOutOnlyInconsistentModes) {
    const ReducedHalfCarModel m = makeLevelModel();
    const TruckGeometry& g = m.getTruckGeometry();
    const TruckModeCache cache(g);
    std::vector<TruckInputs> inputs = makeScatteredInputs(m, 8, 17);
    // States of a rocking run (makeRockingModel).
    const ReducedHalfCarModel rocking = makeRockingModel();
    auto y = rocking.makeStaticState();
    auto mem = rocking.makeStaticMemory();
    for (int k = 0; k < 800; ++k) {
        const double t = k * ReducedHalfCarModel::kStep;
        const auto e = rocking.evaluate(t, y, mem);
        if (k % 40 == 39) inputs.push_back(rocking.makeTruckInputs(t, y, mem));
        y = stepWithFixedMemory(rocking, t, y, mem, e);
        mem = ReducedHalfCarModel::makeMemoryAfter(e.truck);
    }
    long ruledOut = 0, family = 0;
    for (const TruckInputs& in : inputs)
        for (const TruckMode& mode : enumerateTruckModes()) {
            if (!isRuledOutByKinematics(g, in, mode)) continue;
            ++ruledOut;
            if (calcOneParameterKinematics(g, in, mode, 0)) ++family;
            const TruckSolution s = solveTruckMode(in, mode, cache);
            ASSERT_FALSE(s.consistent) << mode.describe();
            ASSERT_GT(s.violation, kConsistentViolation) << mode.describe();
        }
    EXPECT_GT(family, ruledOut / 4) << "the one-parameter families rule out too few modes to matter";
    std::printf("kinematic bounds: %ld modes ruled out (%ld in one-parameter families), none consistent\n", ruledOut,
                family);
}

// The run reuses an accepted evaluation whose mode is consistent as the next step's
// first stage (simulateReduced): evaluating again at the same time and state with the
// memory that evaluation set must give the same evaluation, bit for bit, through stick
// and slip of the wedges and changes of mode.
// The search's first pass leaves out, unsolved, a mode whose spring, wedge or open-gap
// check fails on the compressions its closed contacts and wheels fix
// (calcKinematicCompressions), beyond a margin. That is sound only if a solve of the mode
// gives the same compressions and bolster position to well within the margin: checked for
// every such mode of three cars at scattered states.
TEST(ReducedModel, KinematicCompressionsMatchTheSolve) {
    double worst = 0;  // largest |solved − kinematic| / margin
    long compared = 0;
    for (const char* carName : {"70ton-loaded", "100ton-loaded", "70ton-empty"}) {
        const ReducedHalfCarModel m(makeCarParameters(carName), [](double) { return RailState{}; });
        const TruckGeometry& g = m.getTruckGeometry();
        const TruckModeCache cache(g);
        for (const TruckInputs& in : makeScatteredInputs(m, 8, 11))
            for (const TruckMode& mode : enumerateTruckModes()) {
                const auto kinematic = calcKinematicCompressions(g, in, mode.support);
                if (!kinematic || mode.wheels != WheelContact::Both) continue;
                const TruckSolution s = solveTruckMode(in, mode, cache);
                if (s.violation == 1e300) continue;  // a singular mode: never consistent
                for (int i : {0, 1}) {
                    const KinematicCompressions& k = *kinematic;
                    worst = std::max(worst, std::abs(s.compression[size_t(i)] - k.value[size_t(i)]) / k.margin[size_t(i)]);
                    ++compared;
                }
                const double margin = 1e-9 * std::abs(kinematic->zBolster) + 1e-12;
                worst = std::max(worst, std::abs(s.zBolster - kinematic->zBolster) / margin);
                worst = std::max(worst, std::abs(s.rollBolster - kinematic->rollBolster) / margin);
            }
        EXPECT_FALSE(calcKinematicCompressions(g, TruckInputs{}, CarBodySupport::CornerLeft).has_value());
    }
    EXPECT_GT(compared, 3L * 8 * 3 * 9 * 9 * 9 * 2 / 2);
    EXPECT_LT(worst, 0.01) << "largest |solved - kinematic| / margin";
    std::printf("kinematic compressions: largest |solved - kinematic| = %.3g of the margin (%ld)\n", worst, compared);
}

TEST(ReducedModel, ReusedFirstStageIsTheEvaluationItReplaces) {
    const ReducedHalfCarModel m = makeRockingModel();
    auto y = m.makeStaticState();
    auto mem = m.makeStaticMemory();
    const double h = ReducedHalfCarModel::kStep;
    int compared = 0, slipping = 0, modeChanges = 0;
    for (int k = 0; k < 1200; ++k) {
        const double t = k * h;
        const ReducedHalfCarModel::Evaluation e = m.evaluate(t, y, mem);
        const ReducedHalfCarModel::TruckMemory after = ReducedHalfCarModel::makeMemoryAfter(e.truck);
        if (e.truck.consistent) {
            const ReducedHalfCarModel::Evaluation again = m.evaluate(t, y, after);
            expectBitIdentical(again.truck, e.truck, false);
            for (int i = 0; i < 6; ++i) ASSERT_EQ(again.derivative[i], e.derivative[i]) << "t = " << t;
            ASSERT_EQ(again.railInputPower, e.railInputPower);
            ++compared;
            if (e.truck.mode.wedge[0] != WedgeState::Stick || e.truck.mode.wedge[1] != WedgeState::Stick) ++slipping;
        }
        if (!(e.truck.mode == mem.mode)) ++modeChanges;
        y = stepWithFixedMemory(m, t, y, mem, e);
        mem = after;
    }
    EXPECT_GT(compared, 1100);
    EXPECT_GT(slipping, 50);
    EXPECT_GT(modeChanges, 20);
}

// A duration that is not a whole number of 5 ms steps ends with one shorter step, at
// the duration exactly; the whole steps before it are the same steps, bit for bit.
TEST(ReducedModel, ARunEndsAtItsDurationWithOneShorterStep) {
    // Cross-level rocking at 1.5 Hz, 0.25 in.
    const ReducedHalfCarModel m(getCar(), [](double t) {
        const double w = 2 * M_PI * 1.5, a = 0.25 * units::inch * std::sin(w * t), v = 0.25 * units::inch * w * std::cos(w * t);
        return RailState{{a, -a}, {v, -v}};
    });
    const RunResult whole = simulateReduced(m, 1.0);
    const RunResult longer = simulateReduced(m, 1.0 + 0.0013);
    ASSERT_EQ(whole.history.samples.size(), 201u);
    ASSERT_EQ(longer.history.samples.size(), 202u);
    EXPECT_DOUBLE_EQ(longer.simTime, 1.0013);
    EXPECT_DOUBLE_EQ(longer.history.samples.back()[0], 1.0013);
    for (size_t i = 0; i < whole.history.samples.size(); ++i)
        EXPECT_EQ(toVector(whole.history.samples[i]), toVector(longer.history.samples[i]));
    // The short step moves the state by about its share of a step, not a whole step.
    const double rollStep = longer.finalState[0] - whole.finalState[0];
    EXPECT_LT(std::abs(rollStep), std::abs(whole.finalState[3]) * 0.0013 * 1.5 + 1e-12);
    EXPECT_GT(std::abs(rollStep), 0.0);
}

// A state whose truck-mode entries are not whole numbers in their enumerations' ranges
// is refused by name, never cast into an invalid mode.
TEST(ReducedModel, AStateWithAnInvalidTruckModeIsRefused) {
    const ReducedHalfCarModel m = makeLevelModel();
    std::vector<double> y = m.calcStaticState();
    for (double bad : {0.5, -1.0, 8.0}) {
        std::vector<double> z = y;
        z[6] = bad;
        try {
            simulateReduced(m, 0.01, nullptr, z);
            ADD_FAILURE() << "accepted " << bad;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("truck-mode enumeration"), std::string::npos) << e.what();
        }
    }
    EXPECT_NO_THROW(simulateReduced(m, 0.01, nullptr, y));
}
