// The scenario schema (scenarios/ScenarioSchema.h): each key declared once, and its
// default the one the docs give and the settings structs start from.
#include "scenarios/ScenarioSchema.h"

#include "scenarios/ScenarioLoader.h"

#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <set>

using namespace rockroll;

// The docs' table "Keys and defaults" gives each scalar key's default as the schema spells it.
TEST(ScenarioSchema, EachDefaultIsTheDocumentedOne) {
    std::ifstream in(std::string(ROCKROLL_SOURCE_DIR) + "/docs/cli.md");
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t section = all.find("#### Which model uses which key");
    ASSERT_NE(section, std::string::npos);
    const std::string doc = all.substr(section);
    int checked = 0;
    for (const ScenarioField& f : getScenarioSchema()) {
        if (f.kind == FieldKind::Structured || f.zeroIsDerived) continue;  // the docs say how those are derived
        const size_t at = doc.find(std::string("| `") + f.key + "` | ");
        ASSERT_NE(at, std::string::npos) << f.key;
        const std::string line = doc.substr(at, doc.find('\n', at) - at);
        const bool quoted = f.kind == FieldKind::Choice ||
                            (f.kind == FieldKind::Quantity && f.dimension != units::Dimension::Dimensionless);
        const std::string spelt = quoted ? fmt::format("`\"{}\"`", f.defaultText) : fmt::format("`{}`", f.defaultText);
        EXPECT_NE(line.find(spelt), std::string::npos) << f.key << ": expected " << spelt << " in " << line;
        ++checked;
    }
    EXPECT_GT(checked, 30);
}

// Where a settings struct has a default of its own (RunLimits, CriteriaLimits, ...), a
// scenario that leaves the key out gets that same value from the schema's default.
TEST(ScenarioSchema, DefaultsAreTheSettingsStructsOwn) {
    const Scenario constructed;
    const Scenario empty = parseScenario("", "empty.toml");
    int compared = 0;
    for (const ScenarioField& f : getScenarioSchema()) {
        switch (f.kind) {
            case FieldKind::Quantity:
            case FieldKind::Integer:
                if (f.getNumber(constructed) != 0 || f.zeroIsDerived) {
                    EXPECT_EQ(f.getNumber(empty), f.getNumber(constructed)) << f.key;
                    ++compared;
                }
                break;
            case FieldKind::Flag:
                EXPECT_EQ(f.getFlag(empty), f.getFlag(constructed)) << f.key;
                ++compared;
                break;
            case FieldKind::Choice:
                if (!f.getText(constructed).empty()) {
                    EXPECT_EQ(f.getText(empty), f.getText(constructed)) << f.key;
                    ++compared;
                }
                break;
            case FieldKind::Structured: break;
        }
    }
    EXPECT_GT(compared, 25);
}

// Every key once; each key's table and name split at its last dot.
TEST(ScenarioSchema, EachKeyIsDeclaredOnce) {
    std::set<std::string> seen;
    for (const ScenarioField& f : getScenarioSchema()) EXPECT_TRUE(seen.insert(f.key).second) << f.key;
    const ScenarioField* speed = findScenarioField("run.speed");
    ASSERT_NE(speed, nullptr);
    EXPECT_EQ(speed->getTable(), "run");
    EXPECT_EQ(speed->getName(), "speed");
    EXPECT_EQ(findScenarioField("description")->getTable(), "");
    EXPECT_EQ(findScenarioField("run.speedy"), nullptr);
    const std::set<std::string> keys(getScenarioKeys().begin(), getScenarioKeys().end());
    EXPECT_EQ(keys.size(), getScenarioKeys().size());
    for (const ScenarioField& f : getScenarioSchema()) EXPECT_TRUE(keys.count(f.key)) << f.key;
}

// A renamed key is refused with its new name, in a file and as an override.
TEST(ScenarioSchema, ARenamedKeyIsRefusedWithItsNewName) {
    try {
        parseScenario("[attribution]\ntruck_gravity = false\n", "old.toml");
        ADD_FAILURE() << "accepted";
    } catch (const ScenarioError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("old.toml:2: key 'attribution.truck_gravity'"), std::string::npos) << m;
        EXPECT_NE(m.find("'attribution.unsprung_gravity'"), std::string::npos) << m;
    }
    try {
        parseScenario("", "old.toml", {{"attribution.truck_mass_scale", "0.5"}});
        ADD_FAILURE() << "accepted";
    } catch (const ScenarioError& e) {
        EXPECT_NE(std::string(e.what()).find("'attribution.unsprung_mass_scale'"), std::string::npos) << e.what();
    }
    EXPECT_EQ(findRenamedKey("run.speed"), nullptr);
}
