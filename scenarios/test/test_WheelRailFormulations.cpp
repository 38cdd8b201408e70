// The creep and flange wheel–rail contact (docs/model.md, "Wheel–rail contact") in the
// models that have lateral wheel forces, against the report's restraint and against each
// other: each wheel its own L/V, eom and the Simbody half car together, the default case's
// energy balance and no climb.
#include "scenarios/ScenarioRun.h"
#include "tests/TestCases.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace rockroll;

namespace {
Scenario makeCreepCase(const std::string& model, double duration) {
    Scenario sc = test_cases::makeCase(model, 0.75, 16.5, duration);
    sc.wheelRail.lateral = LateralWheelRail::CreepAndFlange;
    return sc;
}
}  // namespace

TEST(WheelRailFormulations, EachWheelOfAWheelsetHasItsOwnLOverV) {
    for (const char* model : {"halfcar", "eom", "fullcar"}) {
        SCOPED_TRACE(model);
        const ScenarioRun run = runScenario(makeCreepCase(model, 6));
        const std::string wheel = std::string(model) == "fullcar" ? "wheel_F1_" : "wheels_F_";
        const std::vector<double> left = test_cases::getColumn(run.result, "l_over_v_F1_L_ratio");
        const std::vector<double> right = test_cases::getColumn(run.result, "l_over_v_F1_R_ratio");
        const std::vector<double> loadL = test_cases::getColumn(run.result, wheel + "L_lb");
        const std::vector<double> loadR = test_cases::getColumn(run.result, wheel + "R_lb");
        // Where the two wheels carry loads 20 % apart and neither creeps at its limit, nearly one
        // creep force (one slip velocity but for the roll rate's share, one coefficient) over two
        // loads: their L/V differ by at least half as much.
        int samples = 0;
        for (size_t i = 0; i < left.size(); ++i) {
            if (loadL[i] <= 0 || loadR[i] <= 0 || std::abs(loadL[i] - loadR[i]) < 0.2 * std::max(loadL[i], loadR[i]))
                continue;
            if (std::max(std::abs(left[i]), std::abs(right[i])) > 0.4 || std::abs(left[i]) < 0.1) continue;
            ++samples;
            const double loads = std::abs(loadL[i] - loadR[i]) / std::max(loadL[i], loadR[i]);
            EXPECT_GT(std::abs(left[i] - right[i]), 0.5 * loads * std::max(std::abs(left[i]), std::abs(right[i]))) << i;
        }
        EXPECT_GT(samples, 10);
        // The single-wheel criterion is evaluated, against Nadal's limit.
        const auto lv = std::find_if(run.summary.criteria.begin(), run.summary.criteria.end(),
                                     [](const Criterion& c) { return c.name == "l_over_v"; });
        ASSERT_NE(lv, run.summary.criteria.end());
        EXPECT_TRUE(lv->evaluated());
        EXPECT_DOUBLE_EQ(lv->limit, calcNadalLimit(75 * units::degree, 0.5));
    }
    // The restraint gives each wheel a share of one force by load: its single-wheel
    // criterion is not evaluated.
    const ScenarioRun restraint = runScenario(test_cases::makeCase("halfcar", 0.75, 16.5, 3));
    for (const Criterion& c : restraint.summary.criteria) {
        if (c.name == "l_over_v") {
            EXPECT_FALSE(c.evaluated());
        }
    }
}

TEST(WheelRailFormulations, EomAndTheHalfCarAgreeWithinOnePercentAndTheDefaultCaseNeitherClimbsNorLeaksEnergy) {
    const ScenarioRun half = runScenario(makeCreepCase("halfcar", 20));
    const ScenarioRun eom = runScenario(makeCreepCase("eom", 20));
    for (const ScenarioRun* r : {&half, &eom}) {
        EXPECT_EQ(r->summary.regime, "severe");
        EXPECT_LE(std::abs(r->summary.energyBalanceError), 0.01);
    }
    auto rel = [](double a, double b) { return std::abs(a - b) / std::abs(b); };
    EXPECT_LT(rel(eom.summary.maxRollDeg, half.summary.maxRollDeg), 0.01);
    EXPECT_LT(rel(eom.summary.maxWheelLoadLb, half.summary.maxWheelLoadLb), 0.01);
    EXPECT_LT(rel(eom.summary.maxSideBearingLoadLb, half.summary.maxSideBearingLoadLb), 0.01);
    EXPECT_LT(rel(eom.summary.maxLOverV, half.summary.maxLOverV), 0.01);
}

TEST(WheelRailFormulations, TheCarsResponseConvergesInTheFlangeStiffness) {
    // Flanges touching (0.1 in of clearance); the flange's stiffness alone ×1 and ×4.
    // The flange's own peak force is an impact's and grows with it (docs/model.md).
    std::vector<RunSummary> s;
    for (double scale : {1.0, 4.0}) {
        Scenario sc = makeCreepCase("eom", 12);
        sc.wheelRail.flangewayClearance = 0.1 * units::inch;
        sc.wheelRail.flangeStiffnessScale = scale;
        const ScenarioRun run = runScenario(sc);
        double flange = 0;
        for (const char* c : {"flange_F1_L_lb", "flange_F1_R_lb"})
            for (double v : test_cases::getColumn(run.result, c)) flange = std::max(flange, v);
        EXPECT_GT(flange, 0.0);
        s.push_back(run.summary);
    }
    auto rel = [](double a, double b) { return std::abs(a - b) / std::abs(b); };
    EXPECT_LT(rel(s[1].maxRollDeg, s[0].maxRollDeg), 0.005);
    EXPECT_LT(rel(s[1].maxWheelLoadLb, s[0].maxWheelLoadLb), 0.01);
    EXPECT_LT(rel(s[1].maxSideBearingLoadLb, s[0].maxSideBearingLoadLb), 0.01);
    EXPECT_LT(rel(s[1].maxLOverV, s[0].maxLOverV), 0.01);
}
