// rockroll validate: the committed report names the commit it came from, and
// the quick run regenerates a complete report.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace {
std::string readFile(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}
const std::string kSource = std::string(ROCKROLL_SCENARIO_DIR) + "/..";
}  // namespace

TEST(Validate, CommittedReportNamesAnExistingCommit) {
    const std::string report = readFile(kSource + "/results/REPORT.md");
    ASSERT_FALSE(report.empty()) << "results/REPORT.md is missing";
    std::smatch m;
    ASSERT_TRUE(std::regex_search(report, m, std::regex("Generated from commit ([0-9a-f]{40})")))
        << "REPORT.md does not name its commit";
    EXPECT_EQ(report.find("uncommitted changes"), std::string::npos) << "generated from a dirty tree";
    const std::string cmd = "git -C '" + kSource + "' cat-file -e " + m[1].str() + "^{commit} 2>/dev/null";
    if (std::system(("git -C '" + kSource + "' rev-parse 2>/dev/null").c_str()) == 0)
        EXPECT_EQ(std::system(cmd.c_str()), 0) << "commit " << m[1] << " is not in this repository";
}

TEST(Validate, QuickRunWritesAReportWithEverySection) {
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "rockroll_validate_quick";
    std::filesystem::remove_all(out);
    const std::string cmd = std::string(ROCKROLL_BIN) + " validate --quick --out '" + out.string() + "' > /dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string report = readFile((out / "REPORT.md").string());
    for (const char* section : {"Time histories", "Roll against speed", "Table 3", "Table 4", "Describing-function",
                                "Modes", "Convergence", "degrees of freedom", "criteria", "Attribution"})
        EXPECT_NE(report.find(section), std::string::npos) << section;
    // The quick attribution and convergence sections produce their tables.
    for (const char* table : {"| half car: `truck_gravity = false` |", "| reduced: `truck_weight = true` |",
                              "| half car: `truck_mass_scale = 0.01` |", "**Pass or fail per case**",
                              "| halfcar severe (16.5 mph) | severe |"})
        EXPECT_NE(report.find(table), std::string::npos) << table;
    EXPECT_NE(report.find("Generated from commit"), std::string::npos);
    for (const char* file : {"timehistory.png", "sweep_70ton-loaded_0.75in.png", "steady_70ton-loaded_0.75in.png",
                             "sweep_70ton-loaded_0.75in_reduced.csv", "validation.json"})
        EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
    // Nothing half-written is left behind.
    for (const auto& e : std::filesystem::directory_iterator(out))
        EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
}
