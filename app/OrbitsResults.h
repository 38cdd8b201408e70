#pragma once
// What `rockroll orbits` computes (docs/orbits.md), shared by the command
// (app/OrbitsCommand.h) and the Python module's rockroll.orbits.
#include "app/OrbitsCommand.h"
#include "scenarios/OrbitContinuation.h"

#include <nlohmann/json.hpp>
#include <string>

namespace rockroll::app {

struct OrbitsResult {
    nlohmann::ordered_json doc;      ///< what orbits.json and --json hold
    nlohmann::ordered_json records;  ///< one flat record per point (orbits.csv)
    OrbitBranch branch;
};
/// The start run or sweep, then the continuation, as `rockroll orbits` computes them
/// (progress lines on stderr unless options.json); command: the provenance's command line.
OrbitsResult calcOrbits(const Scenario& sc, const OrbitsOptions& options, const std::string& command);

/// The shooting settings of the options; ScenarioError for a case that cannot be shot
/// (equal speeds, a track that does not repeat, a model whose state holds a discrete mode).
OrbitSettings checkOrbitsInput(const Scenario& sc, const OrbitsOptions& options);

}  // namespace rockroll::app
