// The hand-written equation-of-motion half car: static equilibrium, mirror
// symmetry, and agreement with the Simbody half car (the formulation check).
#include "bespoke/EomSimulation.h"
#include "mbmodel/TrackInput.h"
#include "scenarios/ScenarioRun.h"
#include "tests/TestCases.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockroll;

using test_cases::makeCase;

namespace {
std::vector<double> column(const RunResult& r, const std::string& name) { return test_cases::getColumn(r, name); }
double peakAbs(const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}
}  // namespace

TEST(EomHalfCar, StaticStateIsEquilibriumAndLoadsAreWeightShares) {
    for (const char* carName : {"70ton-loaded", "70ton-empty", "100ton-loaded"})
        for (bool simplified : {false, true}) {
            const CarParameters car = makeCarParameters(carName);
            const EomHalfCarModel m(car, [](double) { return RailState{}; },
                                    simplified ? EomSimplifications::describingFunctionTwin() : EomSimplifications{});
            const EomHalfCarModel::State y = m.makeStaticState();
            EomHalfCarModel::State yDot;
            m.calcStateDerivative(0, y, yDot);
            for (int i = 0; i < EomHalfCarModel::kNumStates; ++i) EXPECT_NEAR(yDot[i], 0.0, 1e-7) << carName << " " << i;
            const EomHalfCarModel::Forces f = m.calcForces(0, y);
            const double carBodyLoad = car.getCarBodyWeight() / 2;
            EXPECT_NEAR(f.rim[0] + f.rim[1], carBodyLoad, 1e-6 * carBodyLoad);
            EXPECT_NEAR(f.spring[0], (carBodyLoad + car.bolsterWeight) / 2, 1e-6 * carBodyLoad);
            const double wheel = (carBodyLoad + car.bolsterWeight) / 2 + car.wheelsetWeight + car.sideFrameWeight;
            EXPECT_NEAR(f.wheel[0], wheel, 1e-6 * wheel);
            EXPECT_NEAR(f.wheel[1], wheel, 1e-6 * wheel);
            EXPECT_EQ(f.sideBearing[0], 0.0);
        }
}

TEST(EomHalfCar, MirroredInputGivesMirroredRoll) {
    Scenario sc = makeCase("eom", 0.75, 16.5, 6);
    const RunResult a = runScenario(sc).result;
    sc.track.mirror = !sc.track.mirror;
    const RunResult b = runScenario(sc).result;
    const auto ra = column(a, "roll_deg"), rb = column(b, "roll_deg");
    const double peak = peakAbs(ra);
    ASSERT_GT(peak, 1.0);
    for (size_t i = 0; i < ra.size(); ++i) ASSERT_NEAR(ra[i], -rb[i], 2e-3 * peak) << "sample " << i;
}

// On a light-rocking case (0.5 in, 12 mph, 30 s) the roll histories of
// the hand-written model and the Simbody half car agree within 1 % of their peak
// at every output time.
TEST(EomHalfCar, ReproducesSimbodyHalfCarRollHistory) {
    const RunResult eom = runScenario(makeCase("eom", 0.5, 12, 30)).result;
    const RunResult simbody = runScenario(makeCase("halfcar", 0.5, 12, 30)).result;
    const auto a = column(eom, "roll_deg"), b = column(simbody, "roll_deg");
    ASSERT_EQ(a.size(), b.size());
    const double peak = peakAbs(b);
    ASSERT_GT(peak, 0.2);
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    EXPECT_LT(worst, 0.01 * peak) << "worst roll difference " << worst << " deg, peak " << peak << " deg";
}

// The same check in severe rocking (side bearings, wheel lift), where every
// contact opens and closes.
TEST(EomHalfCar, ReproducesSimbodyHalfCarInSevereRocking) {
    const RunResult eom = runScenario(makeCase("eom", 0.75, 16.5, 12)).result;
    const RunResult simbody = runScenario(makeCase("halfcar", 0.75, 16.5, 12)).result;
    const auto a = column(eom, "roll_deg"), b = column(simbody, "roll_deg");
    const double peak = peakAbs(b);
    ASSERT_GT(peak, 4.0);
    for (size_t i = 0; i < a.size(); ++i) ASSERT_NEAR(a[i], b[i], 0.01 * peak) << "sample " << i;
    EXPECT_GT(peakAbs(column(eom, "wheel_lift_F1_L_in")) + peakAbs(column(eom, "wheel_lift_F1_R_in")), 0.0);
}

TEST(EomHalfCar, SimplificationsAreReadFromTheScenario) {
    const std::string base = R"(
[car]
base = "70ton-loaded"
[track]
amplitude = "0.5 in"
rail_length = "39 ft"
[run]
speed = "12 mph"
duration = "1 s"
model = "eom"
[integrator]
method = "cpodes"
accuracy = 1e-4
[eom]
)";
    const Scenario sc = parseScenario(base + "linear_springs = true\nsmall_angles = true\n", "inline");
    EXPECT_TRUE(sc.eom.linearSprings);
    EXPECT_TRUE(sc.eom.smallAngles);
    EXPECT_FALSE(sc.eom.lockBolsterLateral);
    EXPECT_THROW(parseScenario(base + "linear_spring = true\n", "inline"), ScenarioError);  // misspelt key
}
