#pragma once
// A run summary as JSON: the keys of summary.json (and of `rockroll run --json`), shared by
// the command line and the Python module (library rr_report).
#include "mbmodel/RunSummary.h"

#include <nlohmann/json.hpp>

namespace rockroll::app {

/// The summary's own keys (without provenance), in summary.json's order.
nlohmann::ordered_json toJson(const RunSummary& s);

}  // namespace rockroll::app
