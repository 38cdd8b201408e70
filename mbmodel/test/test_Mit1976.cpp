// The report's published numbers live in one data file, scenarios/reference/mit1976.toml,
// read at run time (mbmodel/Mit1976.h). It must load, every number must carry its unit
// and source, and a few values are checked against what the report prints.
#include "mbmodel/Mit1976.h"
#include "mbmodel/ModalAnalysis.h"
#include "scenarios/ScenarioLoader.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace rockroll;
namespace fs = std::filesystem;

TEST(Mit1976, DataFileLoadsWithUnitAndSourceForEveryValue) {
    const Mit1976& ref = Mit1976::get();
    EXPECT_EQ(fs::canonical(ref.getFile()),
              fs::canonical(fs::path(ROCKROLL_SOURCE_DIR) / "scenarios" / "reference" / "mit1976.toml"));
    EXPECT_GT(ref.getValues().size(), 60u);
    for (const auto& [key, v] : ref.getValues()) {
        EXPECT_FALSE(v.unit.empty()) << key;
        EXPECT_FALSE(v.source.empty()) << key;
        EXPECT_FALSE(v.page.empty()) << key;
    }
    EXPECT_EQ(ref.text("report.title"), "Computational methods to predict railcar response to track cross level variations");
}

TEST(Mit1976, ValuesAreWhatTheReportPrints) {
    const Mit1976& ref = Mit1976::get();
    // Table 3, loaded 70 ton at 0.75 in and 15.5 mph.
    ASSERT_EQ(ref.count("table3"), 5u);
    EXPECT_EQ(ref.text("table3[1].label"), "Loaded 70 ton, 0.75 in");
    EXPECT_EQ(ref("table3[1].speed", "mph"), 15.5);
    EXPECT_EQ(ref("table3[1].max_roll", "deg"), 7.5);
    EXPECT_EQ(ref("table3[1].max_center_plate_load", "lb"), 118000);
    EXPECT_EQ(ref("table3[4].max_wheel_lift", "in"), 3.3);
    EXPECT_EQ(ref.value("table3[0].max_roll", "deg").source, "Table 3");
    // Table 4: AAR against the report's reduced model, in 10³ lb.
    EXPECT_EQ(ref("table4.aar_max_roll", "deg"), 6.3);
    EXPECT_EQ(ref("table4.reduced_max_wheel_load", "kip"), 119);
    EXPECT_EQ(ref("table4.aar_max_side_bearing_load", "kip"), 92);
    // Table 1, and calcTable1Estimates reads it.
    EXPECT_EQ(ref("table1.70ton-loaded.car_body_roll", "Hz"), 0.88);
    EXPECT_EQ(ref("table1.100ton-loaded.wheelset_sway", "Hz"), 6.94);
    EXPECT_FALSE(ref.has("table1.70ton-empty.bolster_heave"));
    for (const auto& e : calcTable1Estimates(makeCarParameters("70ton-loaded")))
        if (e.body == "bolster" && e.motion == "heave") {
            EXPECT_EQ(e.reportHz, 26.5);
        }
    for (const auto& e : calcTable1Estimates(makeCarParameters("70ton-empty")))
        if (e.body == "bolster") {
            EXPECT_EQ(e.reportHz, 0);
        }
    // §3.1 and Figure 11.
    EXPECT_EQ(ref.value("section3_1.max_side_bearing_load", "lb").qualifier, "up to");
    EXPECT_EQ(ref("section3_1.max_side_bearing_load", "lb"), 90000);
    EXPECT_EQ(ref("sweeps.loaded70_jump_up_from", "mph"), 16);
    EXPECT_EQ(ref("sweeps.loaded70_jump_up_to", "mph"), 17);
    EXPECT_EQ(ref("describing_function.jump_up_1_00in", "mph"), 19.5);
}

TEST(Mit1976, RefusesWrongUnitsMissingKeysAndBareNumbers) {
    const Mit1976& ref = Mit1976::get();
    EXPECT_THROW(ref("table3[1].max_roll", "rad"), std::runtime_error);
    EXPECT_THROW(ref("table3[9].max_roll", "deg"), std::runtime_error);
    EXPECT_THROW(ref.text("no.such.text"), std::runtime_error);
    const fs::path dir = fs::path(ROCKROLL_TEST_TMP) / "mit1976";
    fs::create_directories(dir);
    auto load = [&](const std::string& text) {
        std::ofstream(dir / "x.toml") << text;
        return Mit1976(dir / "x.toml");
    };
    EXPECT_THROW(load("[t]\nx = 3.2\n"), std::runtime_error);  // no unit, no source
    EXPECT_THROW(load("[t]\nx = { value = 3.2, unit = \"deg\" }\n"), std::runtime_error);
    EXPECT_THROW(load("[t]\nx = { value = 3.2, unit = \"deg\", source = \"Table 3\", page = \"?\", units = \"x\" }\n"),
                 std::runtime_error);
    EXPECT_THROW(load("[t\n"), std::runtime_error);
    EXPECT_EQ(load("[t]\nx = { value = 3, unit = \"deg\", source = \"Table 3\", page = \"12\" }\n")("t.x", "deg"), 3);
}

TEST(Mit1976, PublishedNumbersPrintAsTheReportPrintsThem) {
    EXPECT_EQ(formatPublished(90000), "90 000");
    EXPECT_EQ(formatPublished(100000), "100 000");
    EXPECT_EQ(formatPublished(2), "2");
    EXPECT_EQ(formatPublished(19.5), "19.5");
    EXPECT_EQ(formatPublished(1976), "1976");
}
