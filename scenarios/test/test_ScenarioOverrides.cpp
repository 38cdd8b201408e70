// KEY=VALUE overrides of scenario keys (scenarios/ScenarioLoader.h): applied to the
// parsed TOML before the scenario is read, so they meet the file's own validation and
// messages; recorded in the scenario for provenance. (The Python module's load(**kw)
// and a future `--set KEY=VALUE` both go through here.)
#include "scenarios/ScenarioLoader.h"

#include "tests/TestCases.h"

#include <gtest/gtest.h>

#include <functional>
#include <regex>
#include <set>
#include <toml++/toml.h>

using namespace rockroll;

namespace {
const std::string kCase = test_cases::kMinimalScenarioToml;

Scenario withOverrides(std::vector<ScenarioOverride> o, OverrideKeys mode = OverrideKeys::FullOnly,
                       const std::string& text = kCase) {
    return parseScenario(text, "case.toml", o, mode);
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const ScenarioError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(ScenarioOverrides, ParsesKeyEqualsValue) {
    const ScenarioOverride o = parseScenarioOverride(" car.side_bearing_clearance = 0.25 in ");
    EXPECT_EQ(o.key, "car.side_bearing_clearance");
    EXPECT_EQ(o.value, "0.25 in");
    EXPECT_EQ(parseScenarioOverride("description=a=b").value, "a=b");
    EXPECT_NE(errorOf([] { parseScenarioOverride("run.speed"); }).find("expected KEY=VALUE"), std::string::npos);
    EXPECT_NE(errorOf([] { parseScenarioOverride("=3"); }).find("expected KEY=VALUE"), std::string::npos);
}

TEST(ScenarioOverrides, FullKeysSetValuesAsTheFileWould) {
    const Scenario sc = withOverrides({{"car.side_bearing_clearance", "0.25 in"},
                                       {"run.speed", "15 mph"},
                                       {"run.model", "halfcar"},
                                       {"integrator.accuracy", "1e-5"},
                                       {"track.rails", "4"},
                                       {"track.mirror", "true"},
                                       {"description", "\"quoted text\""}});
    const Scenario file = parseScenario(
        "description = \"quoted text\"\n" +
        test_cases::replaceOnce(test_cases::replaceOnce(test_cases::replaceOnce(test_cases::replaceOnce(test_cases::replaceOnce(kCase, "base = \"70ton-loaded\"",
                                                "base = \"70ton-loaded\"\nside_bearing_clearance = \"0.25 in\""),
                                        "\"16.5 mph\"", "\"15 mph\""),
                                "\"fullcar\"", "\"halfcar\""),
                        "1e-4", "1e-5"),
                "rail_length = \"39 ft\"", "rail_length = \"39 ft\"\nrails = 4\nmirror = true"),
        "case.toml");
    EXPECT_EQ(sc.car.sideBearingClearance, file.car.sideBearingClearance);
    EXPECT_EQ(sc.car.sideBearingClearance, 0.25 * 0.0254);
    EXPECT_EQ(sc.speed, file.speed);
    EXPECT_EQ(sc.model, "halfcar");
    EXPECT_EQ(sc.run.integrator.accuracy, 1e-5);
    EXPECT_EQ(sc.track.rails, 4);
    EXPECT_TRUE(sc.track.mirror);
    EXPECT_EQ(sc.description, "quoted text");
    // The resolved scenario is the one the same keys written in the file give.
    EXPECT_EQ(formatScenarioToml(sc), formatScenarioToml(file));
    EXPECT_EQ(sc.carOverrides, (std::vector<std::pair<std::string, std::string>>{{"side_bearing_clearance", "0.25 in"}}));
    ASSERT_EQ(sc.overrides.size(), 7u);
    EXPECT_EQ(sc.overrides[0], (std::pair<std::string, std::string>{"car.side_bearing_clearance", "0.25 in"}));
    EXPECT_EQ(sc.overrides[3], (std::pair<std::string, std::string>{"integrator.accuracy", "1e-5"}));
    EXPECT_TRUE(parseScenario(kCase, "case.toml").overrides.empty());
}

TEST(ScenarioOverrides, ReplaceAValueInTheFileAndCreateAMissingTable) {
    const std::string text = test_cases::replaceOnce(kCase, "base = \"70ton-loaded\"", "base = \"70ton-loaded\"\ngib_clearance = \"1 in\"");
    const Scenario sc = withOverrides({{"car.gib_clearance", "0.5 in"}, {"wheel_rail.flange_height", "1.5 in"},
                                       {"eom.small_angles", "true"}},
                                      OverrideKeys::FullOnly, text);
    EXPECT_EQ(sc.car.gibClearance, 0.5 * 0.0254);
    EXPECT_EQ(sc.wheelRail.flangeHeight, 1.5 * 0.0254);
    EXPECT_TRUE(sc.eom.smallAngles);
    EXPECT_EQ(sc.carOverrides.size(), 1u);  // the file's key, replaced in place
    // A later override of the same key wins.
    EXPECT_EQ(withOverrides({{"run.speed", "10 mph"}, {"run.speed", "12 mph"}}).speed,
              parseScenario(test_cases::replaceOnce(kCase, "16.5 mph", "12 mph"), "case.toml").speed);
}

TEST(ScenarioOverrides, BareKeysOnlyWhereAllowedAndUnambiguous) {
    const Scenario sc = withOverrides({{"side_bearing_clearance", "0.25 in"}, {"speed", "15 mph"}},
                                      OverrideKeys::AllowBare);
    EXPECT_EQ(sc.car.sideBearingClearance, 0.25 * 0.0254);
    ASSERT_EQ(sc.overrides.size(), 2u);
    EXPECT_EQ(sc.overrides[0].first, "car.side_bearing_clearance");  // recorded by its full key
    EXPECT_EQ(sc.overrides[1].first, "run.speed");

    const std::string fullOnly = errorOf([] { withOverrides({{"speed", "15 mph"}}); });
    EXPECT_NE(fullOnly.find("override key 'speed': no such scenario key; accepted keys: description, car.base, "),
              std::string::npos)
        << fullOnly;
    EXPECT_NE(fullOnly.find("run.speed"), std::string::npos) << fullOnly;

    const std::string unknown = errorOf([] { withOverrides({{"side_bearing_clearence", "1 in"}}, OverrideKeys::AllowBare); });
    EXPECT_NE(unknown.find("'side_bearing_clearence'"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("car.side_bearing_clearance"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("or the last part of one of them alone"), std::string::npos) << unknown;

    // Two tables with the same key: the bare key is refused, naming both.
    const std::vector<std::string> keys{"run.speed", "limits.speed", "car.mass"};
    EXPECT_EQ(resolveScenarioKey("mass", OverrideKeys::AllowBare, keys), "car.mass");
    EXPECT_EQ(resolveScenarioKey("limits.speed", OverrideKeys::AllowBare, keys), "limits.speed");
    const std::string ambiguous = errorOf([&] { resolveScenarioKey("speed", OverrideKeys::AllowBare, keys); });
    EXPECT_EQ(ambiguous, "override key 'speed' is ambiguous: it names run.speed and limits.speed; give the full key");
    // In the real schema only 'file' (car.file and track.file) is ambiguous alone; it is refused by name.
    std::set<std::string> leaves;
    for (const auto& k : getScenarioKeys())
        if (k != "track.file") {
            EXPECT_TRUE(leaves.insert(k.substr(k.rfind('.') + 1)).second) << k;
        }
    EXPECT_EQ(errorOf([] { resolveScenarioKey("file", OverrideKeys::AllowBare); }),
              "override key 'file' is ambiguous: it names car.file and track.file; give the full key");
}

TEST(ScenarioOverrides, BadValuesGetTheFilesOwnMessages) {
    // The same message but for the line: the file's error names it ("case.toml:8:"), an override has none.
    auto fileError = [](const std::string& text) {
        const std::string e = errorOf([&] { parseScenario(text, "case.toml"); });
        EXPECT_TRUE(std::regex_search(e, std::regex("^case\\.toml:[0-9]+: key"))) << e;
        return std::regex_replace(e, std::regex("^case\\.toml:[0-9]+: "), "case.toml: ");
    };
    EXPECT_EQ(errorOf([] { withOverrides({{"car.side_bearing_clearance", "-1 in"}}); }),
              fileError(test_cases::replaceOnce(kCase, "base = \"70ton-loaded\"",
                                "base = \"70ton-loaded\"\nside_bearing_clearance = \"-1 in\"")));
    EXPECT_EQ(errorOf([] { withOverrides({{"run.speed", "15"}}); }), fileError(test_cases::replaceOnce(kCase, "\"16.5 mph\"", "15")));
    EXPECT_EQ(errorOf([] { withOverrides({{"run.speed", "15 parsecs"}}); }),
              fileError(test_cases::replaceOnce(kCase, "\"16.5 mph\"", "\"15 parsecs\"")));
    EXPECT_EQ(errorOf([] { withOverrides({{"run.model", "quartercar"}}); }),
              fileError(test_cases::replaceOnce(kCase, "\"fullcar\"", "\"quartercar\"")));
    EXPECT_EQ(errorOf([] { withOverrides({{"track.rails", "-1"}}); }),
              fileError(test_cases::replaceOnce(kCase, "rail_length = \"39 ft\"", "rail_length = \"39 ft\"\nrails = -1")));
    EXPECT_EQ(errorOf([] { withOverrides({{"limits.enabled", "maybe"}}); }),
              fileError(kCase + "[limits]\nenabled = \"maybe\"\n"));
    EXPECT_NE(errorOf([] { withOverrides({{"run.speed", "15"}}); }).find("case.toml: key 'run.speed' = 15: expected"),
              std::string::npos);
    // A table name is not a key; a key inside [[track.measured]] is not one either.
    EXPECT_NE(errorOf([] { withOverrides({{"car", "1"}}); }).find("no such scenario key"), std::string::npos);
    EXPECT_NE(errorOf([] { withOverrides({{"track.measured", "[]"}}); }).find("no such scenario key"), std::string::npos);
}

namespace {
/// The dotted keys of a TOML document's values (tables opened, arrays of tables skipped).
void collectKeys(const toml::table& t, const std::string& prefix, std::set<std::string>& out) {
    for (const auto& [k, v] : t) {
        const std::string key = prefix + std::string(k.str());
        if (const auto* sub = v.as_table()) collectKeys(*sub, key + ".", out);
        else if (!(v.is_array() && v.as_array()->is_array_of_tables())) out.insert(key);
    }
}
}  // namespace

// getScenarioKeys() is a list beside the readers; this keeps the three in step.
TEST(ScenarioOverrides, SchemaIsWhatTheLoaderReadsAndTheWriterWrites) {
    // Every key of the schema is read (a value of the wrong type is refused by name, not
    // as an unknown key).
    for (const std::string& key : getScenarioKeys()) {
        SCOPED_TRACE(key);
        const std::string e = errorOf([&] { withOverrides({{key, "[1, 2]"}}); });
        EXPECT_NE(e.find("key '" + key + "' = [ 1, 2 ]: expected"), std::string::npos) << e;
        EXPECT_EQ(e.find("no such key"), std::string::npos) << e;
    }
    // Every key the writer writes (all of them, with the optional ones set) is in the schema, and back.
    Scenario sc = getDefaultScenario();
    sc.run.limits.wheelsOffTime = 0.5;
    sc.run.limits.rolloverAngle = 0.3;
    sc.criteria.lOverV = 1.1;
    sc.track.measured = {{0, 0, 0}, {1, 0.01, 0}};  // the writer gives taper and repeat with a measured table
    std::set<std::string> written;
    collectKeys(toml::parse(formatScenarioToml(sc)), "", written);
    const std::set<std::string> schema(getScenarioKeys().begin(), getScenarioKeys().end());
    // The writer gives the car inline (car.name and every parameter); car.base and car.file
    // are the two other ways a file names its car. It gives a measured track inline
    // ([[track.measured]]); track.file is the other way to give one.
    written.insert({"car.base", "car.file", "track.file"});
    EXPECT_EQ(written, schema);
}
