// The bare `rockroll` command's table beside the report's §3.1 (app/ReportComparison.h):
// the wheel-force growth is measured over the report's own windows, and every
// published number in the table comes from scenarios/reference/mit1976.toml; and
// validate's sentence of what §3.2 says of each swept case.
#include "app/ReportComparison.h"
#include "mbmodel/Mit1976.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace rockroll;

namespace {
/// Two truck sides' wheel pairs plus a single wheel, sampled at 1 Hz over 0–20 s;
/// the load is `early` before 4 s, `late` in 10–14 s, and larger elsewhere.
TimeHistory makeHistory(double early, double late) {
    TimeHistory h;
    h.names = {"t_s", "wheels_F_L_lb", "wheels_F_R_lb", "wheel_F1_L_lb"};
    for (int t = 0; t <= 20; ++t) {
        const double load = t <= 4 ? early : (t >= 10 && t <= 14) ? late : 5 * late;
        // The single wheel and the other side stay below: only the largest pair counts.
        h.samples.push_back({double(t), load, 0.5 * load, 50 * late});
    }
    return h;
}
}  // namespace

TEST(ReportComparison, WheelLoadGrowthIsLateWindowOverEarlyWindow) {
    EXPECT_DOUBLE_EQ(app::calcWheelLoadGrowth(makeHistory(50000, 95000), 0, 4, 10, 14), 1.9);
    // Not the static load: doubling the early loads halves the ratio.
    EXPECT_DOUBLE_EQ(app::calcWheelLoadGrowth(makeHistory(100000, 95000), 0, 4, 10, 14), 0.95);
    EXPECT_TRUE(std::isnan(app::calcWheelLoadGrowth(makeHistory(0, 95000), 0, 4, 10, 14)));
}

TEST(ReportComparison, PublishedNumbersComeFromTheDataFile) {
    RunSummary s;
    s.regime = "severe";
    s.maxSideBearingLoadLb = 119076;
    s.maxWheelLiftIn = 0.29;
    s.maxWheelLoadLb = 134714;
    const std::string table = app::formatBesideSection3_1(s, makeHistory(50000, 95000));
    const Mit1976& ref = Mit1976::get();
    for (const char* key : {"section3_1.max_side_bearing_load", "section3_1.max_wheel_load"})
        EXPECT_NE(table.find(formatPublished(ref.value(key, "lb"), true)), std::string::npos) << key << "\n" << table;
    EXPECT_NE(table.find(formatPublished(ref.value("section3_1.max_wheel_lift", "in"), true)), std::string::npos) << table;
    EXPECT_NE(table.find("90 000 lb"), std::string::npos) << table;
    EXPECT_EQ(table.find("up to 90 000"), std::string::npos) << table;  // §3.1: "reaches a maximum value of 90,000 lbs"
    EXPECT_NE(table.find("max wheel force 10–14 s / max 0–4 s"), std::string::npos) << table;
    EXPECT_NE(table.find("0.75 in, 16.5 mph"), std::string::npos) << table;
    EXPECT_NE(table.find("almost 2"), std::string::npos) << table;
    EXPECT_NE(table.find("1.90"), std::string::npos) << table;
    EXPECT_NE(table.find("119076 lb"), std::string::npos) << table;
}

// Section 2 compares each swept case with the figure that holds it: the 70-ton loaded car
// at 1.0 in with Figure 11's jump speeds, at 0.75 in (Figures 14 and 17) with none.
TEST(ReportComparison, EachSweptCaseNamesItsFigureAndItsJumpSpeeds) {
    const Mit1976& ref = Mit1976::get();
    const std::string one = app::formatReportSweepCase(ref, "70ton-loaded", 1.0);
    for (const char* part : {"Figures 11, 17", "the maximum car body roll angle occurring in a simulation time history",
                             "jumps up at nearly 14 mph (to moderate) and at 15.5 mph (to severe)",
                             "from 9° to 3° at 13.5 mph", "light rocking below 11 mph", "about 3° at 20 mph"})
        EXPECT_NE(one.find(part), std::string::npos) << part << "\n" << one;
    EXPECT_EQ(one.find("gives no jump speeds"), std::string::npos) << one;
    const std::string threeQuarters = app::formatReportSweepCase(ref, "70ton-loaded", 0.75);
    EXPECT_NE(threeQuarters.find("Figures 14, 17"), std::string::npos) << threeQuarters;
    EXPECT_NE(threeQuarters.find("the report gives no jump speeds"), std::string::npos) << threeQuarters;
    EXPECT_EQ(threeQuarters.find("Figure 11"), std::string::npos) << threeQuarters;
    EXPECT_NE(app::formatReportSweepCase(ref, "70ton-empty", 0.75).find("maximum response at 30 mph"), std::string::npos);
    EXPECT_NE(app::formatReportSweepCase(ref, "100ton-loaded", 0.75).find("a jump resonance at 13 mph"), std::string::npos);
    EXPECT_EQ(app::formatReportSweepCase(ref, "70ton-loaded", 0.6), "");
}
