// rockroll steady --stability none: no solution may be reported stable. JSON
// gives "stable": null and "stability": "not computed"; the text table says
// "not computed".
#include "tests/CliRunner.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace {
std::string capture(const std::string& cmd, int& exitCode) {
    std::string out;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return out;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    const int status = pclose(p);
    exitCode = rockroll::test::getExitCode(status);
    return out;
}
const std::string kSteady = std::string(ROCKROLL_BIN) + " steady '" + ROCKROLL_SCENARIO_DIR +
                            "/70ton-loaded.toml' --from-mph 12 --to-mph 14 --stability none";
}  // namespace

TEST(SteadyCommand, StabilityNoneIsNotComputedInJson) {
    int code = -1;
    const std::string out = capture(kSteady + " --json 2>/dev/null", code);
    ASSERT_EQ(code, 0);
    const auto j = nlohmann::json::parse(out);
    EXPECT_EQ(j.at("stability"), "not computed");
    ASSERT_FALSE(j.at("branches").empty());
    for (const auto& b : j.at("branches")) {
        EXPECT_TRUE(b.at("stable").is_null()) << b.at("stable");
        EXPECT_EQ(b.at("stability"), "not computed");
        ASSERT_FALSE(b.at("points").empty());
        for (const auto& p : b.at("points")) EXPECT_EQ(p.at("stability_evidence"), "none");
    }
}

TEST(SteadyCommand, StabilityNoneIsNotComputedInText) {
    int code = -1;
    const std::string out = capture(kSteady + " 2>/dev/null", code);
    ASSERT_EQ(code, 0);
    std::istringstream in(out);
    int rows = 0;
    for (std::string line; std::getline(in, line);) {
        // Table rows start with the speed.
        if (line.size() < 10 || line.find_first_not_of(' ') == std::string::npos ||
            !std::isdigit(static_cast<unsigned char>(line[line.find_first_not_of(' ')])))
            continue;
        ++rows;
        EXPECT_EQ(line.substr(line.size() - 12), "not computed") << line;
    }
    EXPECT_GT(rows, 3) << out;
}

TEST(SteadyCommand, RefusesTheCreepAndFlangeContactItDoesNotSolve) {
    int code = -1;
    const std::string err = capture(kSteady + " --set wheel_rail.lateral=creep_and_flange 2>&1 >/dev/null", code);
    EXPECT_EQ(code, 2) << err;
    EXPECT_NE(err.find("wheel_rail.lateral"), std::string::npos) << err;
    EXPECT_NE(err.find("expected \"restraint\" for steady"), std::string::npos) << err;
}

// The describing function's car is the report's rigid, centrally loaded half car: a twisting
// body or an off-centre load is refused, not echoed and ignored.
TEST(SteadyCommand, RefusesTheFullCarsBodyItDoesNotSolve) {
    for (const std::string& set : {std::string("car_body.torsion=true"), std::string("car.cg_lateral_offset='2 in'"),
                                   std::string("car.cg_longitudinal_offset='-3 in'")}) {
        int code = -1;
        const std::string err = capture(kSteady + " --set " + set + " 2>&1 >/dev/null", code);
        EXPECT_EQ(code, 2) << set << ": " << err;
        EXPECT_NE(err.find(set.substr(0, set.find('='))), std::string::npos) << err;
        EXPECT_NE(err.find("for steady"), std::string::npos) << err;
    }
}
