// The report's published numbers live in one data file, scenarios/reference/mit1976.toml,
// read at run time (mbmodel/Mit1976.h). It must load, every number must carry its unit,
// its source and the report's words that print it, and a few values are checked against
// what the report prints.
#include "mbmodel/Mit1976.h"
#include "mbmodel/ModalAnalysis.h"
#include "scenarios/ScenarioLoader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>

using namespace rockroll;
namespace fs = std::filesystem;

TEST(Mit1976, DataFileLoadsWithUnitSourceAndQuoteForEveryValue) {
    const Mit1976& ref = Mit1976::get();
    EXPECT_EQ(fs::canonical(ref.getFile()),
              fs::canonical(fs::path(ROCKROLL_SOURCE_DIR) / "scenarios" / "reference" / "mit1976.toml"));
    EXPECT_GT(ref.getValues().size(), 60u);
    for (const auto& [key, v] : ref.getValues()) {
        EXPECT_FALSE(v.unit.empty()) << key;
        EXPECT_FALSE(v.source.empty()) << key;
        EXPECT_FALSE(v.page.empty()) << key;
        EXPECT_FALSE(v.quote.empty()) << key << ": no quote of the report's words";
    }
    EXPECT_FALSE(ref.getQuotedTexts().empty());
    for (const auto& [key, t] : ref.getQuotedTexts()) {
        EXPECT_FALSE(t.source.empty()) << key;
        EXPECT_FALSE(t.quote.empty()) << key << ": no quote of the report's words";
    }
    EXPECT_EQ(ref.text("report.title"), "Computational methods to predict railcar response to track cross-level variations");
}

// The quote is the report's words for the number: it prints the value (as the report
// writes it: "90,000", "two" for the §3.1 "factor of almost two").
TEST(Mit1976, EveryQuotePrintsItsValue) {
    const Mit1976& ref = Mit1976::get();
    for (const auto& [key, v] : ref.getValues()) {
        std::vector<std::string> forms{formatPublished(v.value), fmt::format("{:.1f}", v.value), fmt::format("{:.2f}", v.value)};
        if (v.value == std::round(v.value) && std::abs(v.value) >= 1000) {
            std::string s = formatPublished(v.value);
            std::replace(s.begin(), s.end(), ' ', ',');
            forms.push_back(s);
        }
        if (v.value == 2) forms.emplace_back("two");
        bool found = false;
        for (const auto& f : forms)
            found = found || std::regex_search(v.quote, std::regex("(^|[^0-9.,])" + std::regex_replace(f, std::regex("[.]"), "\\.") +
                                                                   "($|[^0-9]|[.,][^0-9]|[.,]$)"));
        EXPECT_TRUE(found) << key << " = " << v.value << " is not in its quote: " << v.quote;
    }
}

// Figure 11 is the 70-ton loaded car at 1.0 in (§3.2: "for the loaded 70 ton car operating
// on track with 1.0 inch cross level amplitude. Figure 11 summarizes ..."); it was once
// attributed the 0.75 in case. Every value attributed to Figure 11 says 1.0 in, and the
// [[sweeps]] case that names Figure 11 is the 1.0 in one.
TEST(Mit1976, Figure11IsThe1InchCase) {
    const Mit1976& ref = Mit1976::get();
    const std::regex figure11("Figures? 11\\b|Figures [0-9, and]*\\b11\\b");
    int attributed = 0;
    for (const auto& [key, v] : ref.getValues())
        if (std::regex_search(v.source, figure11)) {
            ++attributed;
            EXPECT_NE(v.source.find("1.0 in"), std::string::npos) << key << ": " << v.source;
            EXPECT_EQ(v.source.find("0.75 in"), std::string::npos) << key << ": " << v.source;
            EXPECT_EQ(v.source.find("0.5 in"), std::string::npos) << key << ": " << v.source;
        }
    EXPECT_GE(attributed, 8);
    int cases = 0;
    for (size_t i = 0; i < ref.count("sweeps"); ++i) {
        const std::string k = fmt::format("sweeps[{}].", i);
        if (!std::regex_search(ref.text(k + "figures"), std::regex("(^|, )11(,|$)"))) continue;
        ++cases;
        EXPECT_EQ(ref.text(k + "car"), "70ton-loaded");
        EXPECT_EQ(ref(k + "amplitude", "in"), 1.0);
        // Its numbers: up at nearly 14 (to moderate) and 15.5 mph (to severe); down, 9° to 3° at 13.5 mph; light below 11 mph.
        EXPECT_EQ(ref(k + "jump_up_moderate", "mph"), 14);
        EXPECT_EQ(ref.value(k + "jump_up_moderate", "mph").qualifier, "nearly");
        EXPECT_EQ(ref(k + "jump_up_severe", "mph"), 15.5);
        EXPECT_EQ(ref(k + "jump_down", "mph"), 13.5);
        EXPECT_EQ(ref(k + "jump_down_from_roll", "deg"), 9);
        EXPECT_EQ(ref(k + "jump_down_to_roll", "deg"), 3);
        EXPECT_EQ(ref(k + "light_below_down", "mph"), 11);
        EXPECT_EQ(ref(k + "severe_until_speed", "mph"), 20);
        EXPECT_EQ(ref(k + "severe_until_roll", "deg"), 3);
        EXPECT_EQ(ref.text(k + "statistic"), "the maximum car body roll angle occurring in a simulation time history");
    }
    EXPECT_EQ(cases, 1);
    // The report gives no jump speeds for the 70-ton car at 0.75 in (Figures 14 and 17).
    for (size_t i = 0; i < ref.count("sweeps"); ++i) {
        const std::string k = fmt::format("sweeps[{}].", i);
        if (ref.text(k + "car") != "70ton-loaded" || ref(k + "amplitude", "in") != 0.75) continue;
        for (const char* jump : {"jump_up_moderate", "jump_up_severe", "jump_down", "jump_resonance"})
            EXPECT_FALSE(ref.has(k + jump)) << k << jump;
    }
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
    EXPECT_EQ(ref.value("table3[0].max_roll", "deg").source, "Table 3 (Roll Angle [Degrees])");
    EXPECT_EQ(ref.value("table3[0].max_roll", "deg").quote, "Unloaded 70 ton car 0.75 inch cross level 33 3.2 1.9 60,000 54,000 62,000");
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
    // §3.1 ("reaches a maximum value of 90,000 lbs": no hedge) and §4.3.
    EXPECT_EQ(ref.value("section3_1.max_side_bearing_load", "lb").qualifier, "");
    EXPECT_EQ(ref("section3_1.max_side_bearing_load", "lb"), 90000);
    EXPECT_EQ(ref.value("section3_1.max_wheel_lift", "in").qualifier, "approaching");
    EXPECT_EQ(ref("describing_function.jump_up_1_00in", "mph"), 19.5);
    EXPECT_EQ(ref("describing_function.simulation_high_branch_not_below", "mph"), 16);
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
    // `quote` is optional and read; a quoted text refuses an unknown field as a number does.
    const Mit1976 quoted = load("[t]\nx = { value = 3, unit = \"deg\", source = \"Table 3\", page = \"?\", quote = \"3 deg\" }\n"
                                "y = { text = \"severe\", source = \"§3.1\", page = \"?\", quote = \"severe rocking\" }\n");
    EXPECT_EQ(quoted.value("t.x", "deg").quote, "3 deg");
    EXPECT_EQ(quoted.text("t.y"), "severe");
    EXPECT_EQ(quoted.getQuotedTexts().at("t.y").quote, "severe rocking");
    EXPECT_THROW(load("[t]\nx = { value = 3, unit = \"deg\", source = \"Table 3\", page = \"?\", quote = 3 }\n"), std::runtime_error);
    EXPECT_THROW(load("[t]\ny = { text = \"severe\", source = \"§3.1\", page = \"?\", qoute = \"x\" }\n"), std::runtime_error);
}

TEST(Mit1976, PublishedNumbersPrintAsTheReportPrintsThem) {
    EXPECT_EQ(formatPublished(90000), "90 000");
    EXPECT_EQ(formatPublished(100000), "100 000");
    EXPECT_EQ(formatPublished(2), "2");
    EXPECT_EQ(formatPublished(19.5), "19.5");
    EXPECT_EQ(formatPublished(1976), "1976");
}
