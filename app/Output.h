#pragma once
// Output helpers shared by the sub-commands: run summaries as JSON (toJson, in
// app/SummaryJson.h, library rr_report), time histories as CSV, and files written
// through a temporary name.
#include "app/SummaryJson.h"
#include "mbmodel/RunSummary.h"
#include "mbmodel/TimeHistory.h"

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace rockroll::app {

/// Writes through a temporary name and renames when complete, so a reader never
/// sees a half-written file.
void writeAtomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

/// The history as CSV (mbmodel/CsvWriter): every channel, or only `columns` in
/// that order (each must exist), with `digits` significant digits.
void writeHistoryCsv(std::ostream& out, const TimeHistory& h, const std::vector<std::string>& columns = {},
                     int digits = 7);

}  // namespace rockroll::app
