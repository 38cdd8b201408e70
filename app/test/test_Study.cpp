// Study files (app/Study.h): points numbered deterministically (grid row-major in the
// file's key order, zip, a seeded Latin hypercube with one sample per stratum), units
// and columns as the study file wrote them, and bad values refused with the study
// file's line, the key, the value and the accepted range.
#include "app/Study.h"
#include "tests/TestTmp.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>

using namespace rockroll;
using namespace rockroll::app;

namespace {
std::string writeStudy(const std::filesystem::path& dir, const std::string& body) {
    const std::filesystem::path file = dir / "study.toml";
    std::ofstream(file) << "scenario = \"" << ROCKROLL_SOURCE_DIR << "/scenarios/70ton-loaded.toml\"\n"
                        << "model = \"reduced\"\n"
                        << body;
    return file.string();
}
std::string refusal(const std::string& file) {
    try {
        loadStudy(file);
    } catch (const ScenarioError& e) {
        return e.what();
    }
    return "accepted";
}
}  // namespace

TEST(Study, GridIsRowMajorInTheFilesKeyOrder) {
    const auto dir = test::makeTestTempDir();
    // run.speed comes first in the file though toml++ sorts keys: the file's order wins.
    const StudyPlan plan = loadStudy(writeStudy(dir, "[vary]\n"
                                                     "\"run.speed\" = { from = \"14 mph\", to = \"15 mph\", step = \"0.5 mph\" }\n"
                                                     "\"car.side_bearing_clearance\" = [\"0.125 in\", \"0.25 in\"]\n"));
    ASSERT_EQ(plan.varied.size(), 2u);
    EXPECT_EQ(plan.varied[0].column, "run.speed_mph");
    EXPECT_EQ(plan.varied[1].column, "car.side_bearing_clearance_in");
    ASSERT_EQ(plan.points.size(), 6u);
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"14 mph", "0.125 in"}, {"14 mph", "0.25 in"}, {"14.5 mph", "0.125 in"},
        {"14.5 mph", "0.25 in"}, {"15 mph", "0.125 in"}, {"15 mph", "0.25 in"}};
    for (size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(plan.points[i][0].text, expected[i].first) << i;
        EXPECT_EQ(plan.points[i][1].text, expected[i].second) << i;
    }
    EXPECT_EQ(plan.points[2][0].shown, 14.5);
    const auto overrides = getPointOverrides(plan, 3);
    ASSERT_EQ(overrides.size(), 3u);  // model, then the two varied keys
    EXPECT_EQ(overrides[0].key, "run.model");
    EXPECT_EQ(overrides[2].value, "0.25 in");
}

TEST(Study, ZipPairsValuesAndNeedsEqualLengths) {
    const auto dir = test::makeTestTempDir();
    const StudyPlan plan = loadStudy(writeStudy(dir, "combine = \"zip\"\n[vary]\n"
                                                     "\"run.speed\" = [\"14 mph\", \"16 mph\"]\n"
                                                     "\"track.amplitude\" = [\"0.5 in\", \"0.75 in\"]\n"));
    ASSERT_EQ(plan.points.size(), 2u);
    EXPECT_EQ(plan.points[1][0].text, "16 mph");
    EXPECT_EQ(plan.points[1][1].text, "0.75 in");
    const std::string e = refusal(writeStudy(dir, "combine = \"zip\"\n[vary]\n\"run.speed\" = [\"14 mph\"]\n"
                                                  "\"track.amplitude\" = [\"0.5 in\", \"0.75 in\"]\n"));
    EXPECT_NE(e.find("as many values"), std::string::npos) << e;
}

TEST(Study, LatinHypercubeIsSeededAndFillsEveryStratum) {
    const auto dir = test::makeTestTempDir();
    auto plan = [&](int seed) {
        return loadStudy(writeStudy(dir, "combine = { latin_hypercube = 8, seed = " + std::to_string(seed) +
                                             " }\n[vary]\n"
                                             "\"run.speed\" = { from = \"12 mph\", to = \"20 mph\" }\n"
                                             "\"car.side_bearing_clearance\" = { from = \"0.1 in\", to = \"0.5 in\" }\n"));
    };
    const StudyPlan a = plan(7), b = plan(7), c = plan(8);
    ASSERT_EQ(a.points.size(), 8u);
    bool differs = false;
    for (size_t k = 0; k < 2; ++k) {
        std::set<int> strata;
        const double from = a.varied[k].from, to = a.varied[k].to;
        for (size_t i = 0; i < 8; ++i) {
            const double x = a.points[i][k].shown.get<double>();
            EXPECT_EQ(a.points[i][k].text, b.points[i][k].text);  // same seed, same points
            differs = differs || a.points[i][k].text != c.points[i][k].text;
            ASSERT_GE(x, from);
            ASSERT_LE(x, to);
            strata.insert(std::min(7, int((x - from) / (to - from) * 8)));
        }
        EXPECT_EQ(strata.size(), 8u) << "one sample in each of the 8 strata of " << a.varied[k].key;
    }
    EXPECT_TRUE(differs) << "another seed gave the same points";
}

TEST(Study, BadValuesNameTheStudyLineKeyValueAndRange) {
    const auto dir = test::makeTestTempDir();
    const std::string speed = refusal(writeStudy(dir, "[vary]\n\"run.speed\" = [\"14 mph\", \"500 mph\"]\n"));
    for (const char* part : {"study.toml:4", "run.speed", "500 mph", "expected", "150 mph"})
        EXPECT_NE(speed.find(part), std::string::npos) << part << " missing from: " << speed;
    const std::string key = refusal(writeStudy(dir, "[vary]\n\"car.no_such_key\" = [1, 2]\n"));
    EXPECT_NE(key.find("study.toml:4"), std::string::npos) << key;
    EXPECT_NE(key.find("no such scenario key"), std::string::npos) << key;
    const std::string units = refusal(writeStudy(dir, "[vary]\n\"track.amplitude\" = [\"0.5 in\", \"12 mm\"]\n"));
    EXPECT_NE(units.find("one unit"), std::string::npos) << units;
    const std::string set = refusal(writeStudy(dir, "[set]\n\"run.duration\" = \"-4 s\"\n[vary]\n\"run.speed\" = [\"14 mph\"]\n"));
    EXPECT_NE(set.find("study.toml:4"), std::string::npos) << set;
    EXPECT_NE(set.find("run.duration"), std::string::npos) << set;
    const std::string range = refusal(writeStudy(dir, "[vary]\n\"run.speed\" = { from = \"14 mph\", to = \"12 mph\", step = \"1 mph\" }\n"));
    EXPECT_NE(range.find("expected to ≥ from"), std::string::npos) << range;
    EXPECT_NE(refusal(writeStudy(dir, "kind = \"walk\"\n[vary]\n\"run.speed\" = [\"14 mph\"]\n")).find("expected \"run\" or \"sweep\""),
              std::string::npos);
    EXPECT_NE(refusal(writeStudy(dir, "[vary]\n")).find("[vary]"), std::string::npos);
}

TEST(Study, RecordsHavePointVariedColumnsStatusThenSummary) {
    nlohmann::ordered_json study = {
        {"study", {{"point_count", 2}}},
        {"varied", {{{"key", "run.speed"}, {"column", "run.speed_mph"}, {"unit", "mph"}, {"values", {14, 15}}}}},
        {"shard", {{"k", 1}, {"n", 1}}},
        {"points",
         {{{"point", 0}, {"values", {{"run.speed_mph", 14}}}, {"status", "ok"}, {"summary", {{"max_roll_deg", 1.5}}}},
          {{"point", 1}, {"values", {{"run.speed_mph", 15}}}, {"status", "failed"}, {"error", "x"}, {"summary", nlohmann::ordered_json::object()}}}}};
    const auto records = makeStudyRecords(study);
    ASSERT_EQ(records.size(), 2u);
    std::vector<std::string> keys;
    for (const auto& [k, v] : records[0].items()) keys.push_back(k);
    EXPECT_EQ(keys, (std::vector<std::string>{"point", "run.speed_mph", "status", "max_roll_deg"}));
    EXPECT_EQ(records[1]["status"], "failed");
}

// A study file and its base scenario are read as every input file is (readInputFile;
// docs/cli.md, "Input size limits"): a folder or a device is refused as not a regular file,
// a file over 16 MiB from its size, each naming the path.
TEST(Study, FilesAreReadWithTheSizeLimitAndRegularFileCheck) {
    namespace fs = std::filesystem;
    const fs::path dir = test::makeTestTempDir();
    fs::create_directory(dir / "folder.toml");
    std::string e = refusal((dir / "folder.toml").string());
    EXPECT_NE(e.find("folder.toml: cannot open study file: not a regular file"), std::string::npos) << e;
    std::ofstream(dir / "huge.toml") << "# padding\n";
    fs::resize_file(dir / "huge.toml", kMaxScenarioFileBytes + 1);
    e = refusal((dir / "huge.toml").string());
    EXPECT_NE(e.find("huge.toml: the study file is 16777217 bytes; expected at most 16777216 bytes"), std::string::npos)
        << e;
    std::ofstream(dir / "on-device.toml") << "scenario = \"/dev/zero\"\n";
    e = refusal((dir / "on-device.toml").string());
    EXPECT_NE(e.find("/dev/zero: cannot open base scenario (key 'scenario' of"), std::string::npos) << e;
    EXPECT_NE(e.find("not a regular file"), std::string::npos) << e;
}

// The keys set that a point's model does not use go into study.json's study info
// (docs/studies.md): the shipped study runs the reduced model on 70ton-loaded.toml,
// whose [integrator] table the reduced model does not use.
TEST(Study, InfoNamesTheSettingsTheModelIgnores) {
    const StudyPlan plan = loadStudy(std::string(ROCKROLL_SOURCE_DIR) + "/scenarios/studies/side-bearing-clearance.toml");
    EXPECT_EQ(plan.ignoredSettings, (std::vector<std::string>{"integrator.accuracy", "integrator.method"}));
    EXPECT_EQ(makeStudyInfo(plan)["ignored_settings"], nlohmann::ordered_json({"integrator.accuracy", "integrator.method"}));
}
