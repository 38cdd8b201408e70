#include "mbmodel/DataFiles.h"

#include <cstdlib>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <stdexcept>
#include <string>

namespace rockroll {

namespace fs = std::filesystem;

std::vector<fs::path> getDataDirs() {
    std::vector<fs::path> dirs;
    if (const char* env = std::getenv("ROCKROLL_DATA_DIR"); env && *env) dirs.emplace_back(env);
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) dirs.push_back(exe.parent_path().parent_path() / ROCKROLL_INSTALL_DATADIR);
    dirs.emplace_back(ROCKROLL_SOURCE_DIR);
    if (!ec) dirs.push_back(exe.parent_path().parent_path().parent_path());
    return dirs;
}

fs::path findDataFile(const fs::path& relative) {
    std::vector<std::string> tried;
    for (const auto& dir : getDataDirs()) {
        const fs::path p = dir / relative;
        if (fs::is_regular_file(p)) return p;
        tried.push_back(p.string());
    }
    throw DataFileError(fmt::format("{} is in none of: {} (set ROCKROLL_DATA_DIR to the folder that holds it)",
                                         relative.string(), fmt::join(tried, ", ")));
}

}  // namespace rockroll
