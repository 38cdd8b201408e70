#pragma once
// What every summary carries so it can be rerun: the resolved scenario (every
// parameter with its value and unit, and the complete TOML that rebuilds it),
// the scenario file's SHA-256, rockroll's version and git commit, the model and
// the integrator with its tolerances.
#include "scenarios/ScenarioLoader.h"

#include <nlohmann/json.hpp>
#include <string>

namespace rockroll::app {

/// `command`: the command line that produced the result.
nlohmann::ordered_json makeProvenance(const Scenario& sc, const std::string& command);

/// The scenario a summary.json's provenance describes; ScenarioError naming the
/// file and what is missing when it has none.
Scenario loadScenarioFromSummary(const std::string& summaryPath);
/// The same with `overrides` (--set) applied on top, recorded after the summary's own.
Scenario loadScenarioFromSummaryWithOverrides(const std::string& summaryPath,
                                              const std::vector<ScenarioOverride>& overrides);

std::string getVersionString();

/// The program's command line, set once by main.
void setCommandLine(int argc, char** argv);
const std::string& getCommandLine();  ///< "rockroll 0.9.0 (commit …)"

}  // namespace rockroll::app
