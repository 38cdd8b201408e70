// Where rockroll finds its shipped data (mbmodel/DataFiles.h): $ROCKROLL_DATA_DIR first,
// then an installed prefix, then the source tree; a missing file names every path tried.
#include "mbmodel/DataFiles.h"
#include "mbmodel/Mit1976.h"
#include "tests/TestTmp.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace rockroll;
namespace fs = std::filesystem;

namespace {
/// Sets an environment variable for one scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() { old_.empty() ? unsetenv(name_) : setenv(name_, old_.c_str(), 1); }

private:
    const char* name_;
    std::string old_;
};
}  // namespace

TEST(DataFiles, FindsTheSourceTreesFilesInABuildTree) {
    EXPECT_EQ(fs::canonical(findDataFile("scenarios/reference/mit1976.toml")),
              fs::canonical(fs::path(ROCKROLL_SOURCE_DIR) / "scenarios/reference/mit1976.toml"));
    EXPECT_EQ(fs::canonical(findDataFile("python/rockroll_plots/__main__.py")), fs::canonical(fs::path(ROCKROLL_SOURCE_DIR) / "python/rockroll_plots/__main__.py"));
}

TEST(DataFiles, DataDirFromTheEnvironmentComesFirst) {
    const fs::path dir = test::makeTestTempDir();
    fs::create_directories(dir / "scenarios");
    std::ofstream(dir / "scenarios" / "70ton-loaded.toml") << "# a stand-in\n";
    ScopedEnv env("ROCKROLL_DATA_DIR", dir.string());
    ASSERT_EQ(getDataDirs().front(), dir);
    EXPECT_EQ(findDataFile("scenarios/70ton-loaded.toml"), dir / "scenarios" / "70ton-loaded.toml");
    // A file the folder does not hold is still found further down the list.
    EXPECT_EQ(fs::canonical(findDataFile("python/rockroll_plots/__main__.py")), fs::canonical(fs::path(ROCKROLL_SOURCE_DIR) / "python/rockroll_plots/__main__.py"));
}

TEST(DataFiles, AMissingFileNamesEveryPathTried) {
    try {
        findDataFile("scenarios/no-such-car.toml");
        FAIL() << "no error";
    } catch (const DataFileError& e) {  // exit 2 at the command line (app/main.cpp)
        const std::string what = e.what();
        for (const auto& dir : getDataDirs())
            EXPECT_NE(what.find((dir / "scenarios/no-such-car.toml").string()), std::string::npos) << what;
        EXPECT_NE(what.find("ROCKROLL_DATA_DIR"), std::string::npos) << what;
    }
}
