#pragma once
// The one JSON writer of the program: every JSON file rockroll writes (summary.json,
// validation.json) goes through writeJsonFile, with one fixed format: two-space
// indentation, keys in insertion order, UTF-8 as is, a final newline; written through
// a temporary name and renamed when complete (writeAtomically). JSON printed on
// stdout (--json) stays one line.
#include <filesystem>
#include <nlohmann/json.hpp>

namespace rockroll::app {

void writeJsonFile(const std::filesystem::path& path, const nlohmann::ordered_json& document);

}  // namespace rockroll::app
