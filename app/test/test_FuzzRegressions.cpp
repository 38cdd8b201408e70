// Every input that crashed, hung or was handled wrongly by a reader (found by the fuzzers,
// bench/fuzz/run.sh) stays a test: tests/data/fuzz/fuzz_<reader>/* read through the same
// reader as its harness (bench/fuzz/FuzzTargets.h), each refused with a clear bad-input error
// (exit 2 at the command line) that names the input.
#include "bench/fuzz/FuzzTargets.h"
#include "tests/TestTmp.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdlib.h>

namespace fs = std::filesystem;

TEST(FuzzRegressions, EveryFoundInputIsAClearError) {
    const std::map<std::string, std::pair<std::function<std::string(std::string_view)>, std::string>> readers{
        // harness → (reader, what its error must name)
        {"fuzz_scenario", {rockroll::fuzz::readScenarioFile, "scenario.toml"}},
        {"fuzz_scenario_text", {rockroll::fuzz::readScenarioText, "<fuzz>"}},
        {"fuzz_override", {rockroll::fuzz::readOverrides, ""}},
        {"fuzz_track_csv", {rockroll::fuzz::readTrackTable, "<fuzz>"}},
        {"fuzz_car", {rockroll::fuzz::readCar, "<fuzz>"}},
        {"fuzz_summary", {rockroll::fuzz::readSummary, "summary.json"}},
        {"fuzz_mit1976", {rockroll::fuzz::readMit1976, "mit1976.toml"}},
        {"fuzz_journal", {rockroll::fuzz::readJournal, "<fuzz>"}},
        {"fuzz_study", {rockroll::fuzz::readStudy, "study.toml"}},
    };
    // The readers' files (FuzzFiles.h getFuzzDir) go under this test's folder.
    setenv("TMPDIR", rockroll::test::makeTestTempDir().c_str(), 1);
    const fs::path root = fs::path(ROCKROLL_SOURCE_DIR) / "tests" / "data" / "fuzz";
    int inputs = 0;
    for (const auto& dir : fs::directory_iterator(root)) {
        if (!dir.is_directory()) continue;
        const std::string harness = dir.path().filename().string();
        const auto reader = readers.find(harness);
        ASSERT_NE(reader, readers.end()) << "no reader for " << dir.path() << " (a new harness: add it here)";
        for (const auto& file : fs::directory_iterator(dir.path())) {
            SCOPED_TRACE(file.path().string());
            std::ifstream in(file.path(), std::ios::binary);
            std::stringstream bytes;
            bytes << in.rdbuf();
            const std::string error = reader->second.first(bytes.str());
            EXPECT_NE(error, "") << "accepted";
            EXPECT_NE(error.find(reader->second.second), std::string::npos) << error;
            ++inputs;
        }
    }
    EXPECT_GE(inputs, 5);
}
