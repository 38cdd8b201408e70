#pragma once
// What the sub-commands compute, as data: the command line prints it (app/Commands.cpp)
// and the Python module returns it (python/rockroll_module.cpp), through these same
// functions (library rr_report), so both give the same numbers and the same JSON.
#include "app/Commands.h"
#include "app/SummaryJson.h"
#include "bespoke/DescribingFunction.h"
#include "mbmodel/ModalAnalysis.h"
#include "scenarios/ScenarioRun.h"
#include "scenarios/SpeedSweep.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rockroll::app {

/// The summary's criteria as text lines for a terminal: name, value, limit, unit, verdict
/// ("not evaluated" where the model has no such channel).
std::string formatCriteriaTable(const RunSummary& s);

/// summary.json: the summary's keys, then "provenance".
nlohmann::ordered_json makeRunJson(const ScenarioRun& run, const Scenario& sc, const std::string& command);

/// The sweeps `rockroll sweep` runs: for each base scenario (the options' model,
/// duration and wall-time limit applied) every amplitude (default: the scenario's
/// own) in each direction asked for.
std::vector<SweepSpec> makeSweepSpecs(const std::vector<Scenario>& bases, const SweepOptions& o);
/// One point of a sweep as `rockroll sweep --json` prints it (with its provenance).
nlohmann::ordered_json makeSweepPointJson(const SweepSpec& spec, const SweepPoint& p, const std::string& command);

/// The sweep points (makeSweepPointJson) as flat records for sweep.csv: every key but
/// the provenance, which stays in sweep.json.
nlohmann::ordered_json makeSweepRecords(const nlohmann::ordered_json& points);

/// Each sweep's jump (scenarios/SpeedSweep.h findSweepJump), for sweep.json's "jumps":
/// {model, car, amplitude_in (null on measured track), direction, jump_speed_mph (null
/// when none), steady_roll_change_deg}, one per spec in the order of `specs`.
nlohmann::ordered_json makeSweepJumpsJson(const std::vector<SweepSpec>& specs,
                                          const std::vector<std::vector<SweepPoint>>& results);

struct SteadyResult {
    double inputAmplitude = 0;  ///< C: the fundamental of the cross-level [m]
    std::string inputNote;      ///< what the input is, in words
    SteadyStateSet set;         ///< paths, their stretches of one stability, stability changes
};
/// The describing-function steady state of `sc` (its amplitude already set) from
/// o.fromMph to o.toMph with o.stabilityMethod; std::invalid_argument for an empty
/// speed range, std::runtime_error when no solution is found.
SteadyResult calcSteady(const Scenario& sc, const SteadyOptions& o);
/// The continuation settings `rockroll steady` runs with.
ContinuationSettings makeContinuationSettings(const SteadyOptions& o);
/// `rockroll steady --json`.
nlohmann::ordered_json makeSteadyJson(const SteadyResult& r, const Scenario& sc, const SteadyOptions& o,
                                      const std::string& command);

/// Every point of every branch of makeSteadyJson's document as a flat record for
/// steady.csv: the branch's index and stability, then the point's keys.
nlohmann::ordered_json makeSteadyRecords(const nlohmann::ordered_json& steady);

struct ModesResult {
    std::vector<Mode> modes;
    std::vector<UncoupledEstimate> table1;
    /// The Table 1 estimate a mode compares with, or nullptr.
    const UncoupledEstimate* findEstimate(const Mode& m) const;
};
/// The modes of `sc`'s model (halfcar or fullcar; ScenarioError otherwise), linearized
/// about static equilibrium on level track, beside the report's Table 1.
ModesResult calcScenarioModes(const Scenario& sc);
/// `rockroll modes --json`.
nlohmann::ordered_json makeModesJson(const ModesResult& r, const Scenario& sc, const std::string& command);

}  // namespace rockroll::app
