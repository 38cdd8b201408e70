#pragma once
// Shared by the libFuzzer harnesses (bench/fuzz/fuzz_*.cpp): readers that take a path
// get the fuzz input written to a file in one temporary folder per process.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace rockroll::fuzz {

/// This process's folder for the files a harness writes (removed by nobody: under /tmp).
inline const std::filesystem::path& getFuzzDir() {
    static const std::filesystem::path dir = [] {
        std::string tmpl = (std::filesystem::temp_directory_path() / "rockroll-fuzz-XXXXXX").string();
        if (!mkdtemp(tmpl.data())) std::abort();
        return std::filesystem::path(tmpl);
    }();
    return dir;
}

/// Writes `bytes` to getFuzzDir()/name and returns that path.
inline std::filesystem::path writeFuzzFile(const std::string& name, std::string_view bytes) {
    const std::filesystem::path p = getFuzzDir() / name;
    std::ofstream(p, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p;
}

/// The part of `text` before the first line that is exactly `marker`, and the rest after it
/// (empty when there is no such line): one input feeds a scenario and the file it names.
inline std::pair<std::string_view, std::string_view> splitAtMarker(std::string_view text, std::string_view marker) {
    std::string line(1, '\n');  // appended char by char: GCC 12 -O2 gives a false -Wrestrict for "\n" + string
    line += marker;
    line += '\n';
    const auto at = text.find(line);
    if (at == std::string_view::npos) return {text, {}};
    return {text.substr(0, at + 1), text.substr(at + line.size())};
}

inline std::string_view asText(const uint8_t* data, size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

}  // namespace rockroll::fuzz
