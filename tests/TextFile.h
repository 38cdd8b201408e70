// A file's whole text, for tests that read back what the program wrote.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace rockroll::test {

/// The bytes of `path` as a string; "" when it cannot be opened (the test's
/// comparison then fails on the content, naming what was expected).
inline std::string readTextFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace rockroll::test
