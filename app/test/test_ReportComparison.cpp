// The bare `rockroll` command's table beside the report's §3.1 (app/ReportComparison.h):
// the wheel-force growth is measured over the report's own windows, and every
// published number in the table comes from scenarios/reference/mit1976.toml.
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
    EXPECT_NE(table.find("up to 90 000 lb"), std::string::npos) << table;
    EXPECT_NE(table.find("almost 2"), std::string::npos) << table;
    EXPECT_NE(table.find("1.90"), std::string::npos) << table;
    EXPECT_NE(table.find("119076 lb"), std::string::npos) << table;
}
