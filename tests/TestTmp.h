#pragma once
// Every file a test writes goes into its own folder under the build tree
// (ROCKROLL_TEST_TMP, build/test_tmp), never into the working directory or the
// source tree.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace rockroll::test {

/// ROCKROLL_TEST_TMP/<suite>.<test>[/<sub>], emptied and created. Parameterized
/// names have their '/' replaced by '_'.
inline std::filesystem::path makeTestTempDir(const std::string& sub = "") {
    namespace fs = std::filesystem;
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "no_test";
    for (char& c : name)
        if (c == '/') c = '_';
    fs::path dir = fs::path(ROCKROLL_TEST_TMP) / name;
    if (!sub.empty()) dir /= sub;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

}  // namespace rockroll::test
