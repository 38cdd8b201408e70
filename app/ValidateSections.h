#pragma once
// rockroll validate writes results/REPORT.md as a set of sections, one source file
// each (app/Validate<Section>.cpp), each owning its computation and its prose;
// app/Validate.cpp is the driver that runs them in report order. The report's
// published numbers come from scenarios/reference/mit1976.toml (mbmodel/Mit1976.h),
// the threads from the program's one pool (mbmodel/Parallel.h).
#include "app/Output.h"
#include "bespoke/DescribingFunction.h"
#include "mbmodel/DataFiles.h"
#include "mbmodel/Mit1976.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioRun.h"
#include "scenarios/SpeedSweep.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rockroll::app {

struct Settings {
    bool quick = false;
    std::filesystem::path out;
    int jobs = 2;  ///< threads (validate --jobs)
    double rollLimitDeg = 6, wheelLoadLimit = 0.10;
    std::vector<std::string> sweepModels;      ///< swept on every case
    std::vector<std::string> fullCarSweepCars; ///< cars the full car is also swept on (all their amplitudes)
    double sweepStep = 1, sweepDuration = 20, runDuration = 20;
};

// ---- shared between sections ---------------------------------------------------

/// A case of section 2's sweeps; `figure` names the report's figure of that case.
struct SweepCase {
    std::string car;
    double amplitudeIn, fromMph, toMph;
    std::string figure;
};

struct SweepResult {
    SweepCase c;
    std::string model;
    std::vector<SweepPoint> up, down;
    double jumpUpMph = NAN, jumpDownMph = NAN;
    CriteriaLimits criteria;  ///< the [criteria] of the scenario the sweep ran (section 9 judges by them)
};

/// What section 7 (convergence) measures of the defaults every other section runs with: per quantity (max
/// roll, wheel load, side bearing, center plate; whole-run maxima from rest), the
/// largest relative change over its cases from the default contact stiffness to the
/// stiffest run and from the default accuracy to the tightest. Run before the
/// comparison tables, which print it beside their values.
struct ResidualUncertainty {
    std::array<double, 4> stiffness{NAN, NAN, NAN, NAN}, accuracy{NAN, NAN, NAN, NAN};
    std::string stiffnessStep, accuracyStep;  ///< "×1 → ×8", "1e-4 → 1e-6"
    int cases = 0;
    /// One sentence for a comparison table; empty when section 7 did not run.
    std::string describe() const;
};
/// Describing-function solutions per amplitude (70-ton loaded), sections 3 and 5.
using SteadyByAmplitude = std::map<double, SteadyStateSet>;

/// The report this run replaces (its default-case runs and commit), read before it is overwritten.
struct PreviousReport {
    nlohmann::json defaultRuns;
    std::string commit;
};

// ---- the sections, in report order (file) ------------------------------------------

/// Title, provenance and the quick/full note (ValidateHeader.cpp).
/// Wall and CPU (this process and its threads) minutes of one validate phase.
struct PhaseTime {
    double wallMinutes = 0;
    double cpuMinutes = 0;
};
std::string makeHeader(const Settings& s, const std::string& commit, double minutes,
                       const std::vector<std::pair<std::string, PhaseTime>>& phases);
/// 1. Time histories of the default case (ValidateTimeHistories.cpp).
std::string makeTimeHistorySection(const Settings& s, nlohmann::ordered_json& meta, const ResidualUncertainty& u);
/// What moved since the previous report (ValidateChanges.cpp).
PreviousReport readPreviousReport(const std::filesystem::path& out);
std::string makeChangesSection(const PreviousReport& previous, const nlohmann::ordered_json& meta);
/// 2. Speed sweeps with hysteresis (ValidateSweeps.cpp); their results feed sections 3, 4 and 9.
std::vector<SweepResult> runAllSweeps(const Settings& s);
std::string makeSweepSection(const Settings& s, const std::vector<SweepResult>& sweeps, nlohmann::ordered_json& meta);
/// 3. Table 3 (ValidateTable3.cpp).
std::string makeTable3Section(const Settings& s, const std::vector<SweepResult>& sweeps, const SteadyByAmplitude& steady,
                              const ResidualUncertainty& u, nlohmann::ordered_json& meta);
/// 4. Table 4 (ValidateTable4.cpp).
std::string makeTable4Section(const Settings& s, const std::vector<SweepResult>& sweeps, const ResidualUncertainty& u);
/// 5. Describing function (ValidateDescribingFunction.cpp); traceSteady also feeds section 3.
SteadyByAmplitude traceSteady(const Settings& s);
std::string makeDescribingFunctionSection(const Settings& s, const SteadyByAmplitude& steady,
                                         const std::vector<SweepResult>& sweeps, nlohmann::ordered_json& meta);
/// 6. Modes against Table 1 (ValidateModes.cpp).
std::string makeModesSection();
/// 7. Convergence in contact stiffness and integrator accuracy (ValidateConvergence.cpp).
std::string makeConvergenceSection(const Settings& s, nlohmann::ordered_json& meta, ResidualUncertainty& uncertainty);
/// 8. What the added degrees of freedom change (ValidateAddedDof.cpp): the full car against the half car, its
/// twisting car body, the truck-centre ratio and the federal harmonics track.
std::string makeAddedDofSection(const Settings& s, const std::vector<SweepResult>& sweeps, nlohmann::ordered_json& meta);
/// 9. The freight criteria per sweep (ValidateCriteria.cpp).
std::string makeCriteriaSection(const Settings& s, const std::vector<SweepResult>& sweeps);
/// 10. Attribution of the half car – reduced model difference (ValidateAttribution.cpp).
std::string makeAttributionSection(const Settings& s, nlohmann::ordered_json& meta);
/// 11. Periodic orbits of eom and the half car on the upper branch (ValidateOrbits.cpp).
std::string makeOrbitSection(const Settings& s, const std::vector<SweepResult>& sweeps, const SteadyByAmplitude& steady,
                             nlohmann::ordered_json& meta);
/// 12. The wheel–rail contact: the report's lateral restraint against the creep and flange
/// contact, and the cases closest to flange climb (ValidateWheelRail.cpp).
std::string makeWheelRailSection(const Settings& s, const std::vector<SweepResult>& sweeps, nlohmann::ordered_json& meta);

namespace validate_detail {

/// A row of the report's Table 3 (scenarios/reference/mit1976.toml, `table3`).
struct Table3Row {
    std::string label, car;
    double amplitudeIn, speedMph;
    std::array<double, 5> report;  ///< roll deg, lift in, wheel lb, side bearing lb, center plate lb
    std::string branch;            ///< which branch the report's number is on, in its own words
};
std::vector<Table3Row> loadTable3(const Mit1976& ref);

/// Runs independent jobs on `threads` threads of the program's one pool (mbmodel/Parallel.h),
/// in order of submission; each job stores its result by index. Rethrows the error of the
/// first failed job (in submission order).
void runJobs(const std::vector<std::function<void()>>& jobs, int threads);

/// scenarios/<car>.toml of the source tree.
Scenario loadCarScenario(const std::string& car);

/// The 70-ton loaded car (the embedded default scenario) at amplitude and speed,
/// from rest, recorded at 100 Hz as in section 1.
Scenario makeLoaded70(const std::string& model, double amplitudeIn, double speedMph, double durationS);

/// Relative change from a to b, |b − a| / max(|a|, |b|); 0 when both are below `floor`.
double relativeChange(double a, double b, double floor);

/// "+12 %": ours against the report's, empty when there is nothing to compare.
std::string fmtPct(double ours, double report);

/// One of section 2's sweeps: `car` (its scenario file) at the case's amplitude, on
/// `model`, at validate's sweep step and time per speed, recorded at 100 Hz.
SweepSpec makeSweepSpec(const Settings& s, const Scenario& car, const SweepCase& c, const std::string& model,
                        SweepDirection direction);

/// Sets r's jump speeds from its points (findSweepJump).
void findJumps(SweepResult& r);

/// "X° at V mph": a sweep's largest value of `value` over its points, with its speed. A
/// down sweep that never drops and is largest at its lowest speed has no maximum in the
/// range swept: it "stays on the upper branch to the lowest speed swept".
std::string describeLargest(const SweepResult& r, SweepDirection direction, double (*value)(const RunSummary&));

/// "sweep_<car>_<A>in" key part: "70ton-loaded_0.75in".
std::string caseKey(const SweepCase& c);

/// The time-domain models every comparison table holds: fullcar, halfcar, eom, reduced.
const std::vector<std::string>& getComparedModels();

/// What a branch table's rows are and which statistics it shows (sections 3 and 4).
std::string describeStatistics(const Settings& s);

/// "reduced, halfcar (every case) and fullcar (70ton-loaded)".
std::string describeSweptModels(const Settings& s);

/// Max roll, wheel lift, truck-side wheel load, side bearing, center plate (Tables 3 and
/// 4): the whole-run maxima, or (steady) the maxima over the steady part of the run.
std::array<double, 5> getTableValues(const RunSummary& x);
std::array<double, 5> getSteadyTableValues(const RunSummary& x);

/// One row of a model-against-report comparison: one model, one start, one speed;
/// every cell of the row comes from the one run `summary`.
struct BranchRow {
    std::string model;
    std::string start;                  ///< "from rest" | "up sweep" | "down sweep"
    double speedMph = NAN;              ///< the run's speed (a sweep's point nearest the speed asked for)
    std::optional<RunSummary> summary;  ///< empty: no such run (`missing` says why)
    std::string missing;
};

/// A run from rest at a case of the report's tables.
struct RestRun {
    std::string car;
    double amplitudeIn = 0, speedMph = 0;
    std::string model;
};
/// The runs, from rest for s.runDuration, recorded at 100 Hz, in parallel; results by index.
std::vector<RunSummary> runFromRest(const Settings& s, const std::vector<RestRun>& runs);
/// Calls run(i, scenario of runs[i]) for every run, in parallel (s.jobs threads): each car's
/// scenario file read once, set up as runFromRest runs it (makeRestScenario).
void forEachRestRun(const Settings& s, const std::vector<RestRun>& runs,
                    const std::function<void(size_t, const Scenario&)>& run);
/// `car` (its scenario file) set up as runFromRest runs `r`.
Scenario makeRestScenario(const Settings& s, const Scenario& car, const RestRun& r);
/// Each named car's scenario file, read once (before threads start).
std::map<std::string, Scenario> loadCarScenarios(const std::vector<std::string>& names);

/// Per model, in order: its run from rest (fromRest, the summary of that model's
/// RestRun at this case) and section 2's up- and down-sweep points nearest `mph`
/// (a failed point or a case not swept for the model is a row with `missing` set).
std::vector<BranchRow> collectBranchRows(const std::vector<SweepResult>& sweeps, const std::string& car, double amp,
                                         double mph, const std::vector<std::string>& models,
                                         const std::vector<RunSummary>& fromRest);

/// A column of a branch table: its header, its index into getTableValues and the
/// factor from the summary's unit to the column's.
struct BranchColumn {
    std::string header;
    int index = 0;
    double scale = 1;
    int decimals = 0;
};
/// The rows as a Markdown table, each cell "value (difference from `published`)":
/// the steady-part maxima (steady) or the whole-run maxima; the model, start, speed
/// and regime lead each row.
std::string formatBranchTable(const std::vector<BranchRow>& rows, const std::vector<BranchColumn>& columns,
                              const std::vector<double>& published, bool steady);

/// A describing-function solution at one speed: its two-harmonic roll amplitude
/// (interpolated along its path) and the twin maxima of the nearer traced point.
struct SteadyAt {
    double rollAmplitudeDeg = 0;
    TwinMaxima twin;
    Eigen::VectorXd harmonics;  ///< interpolated along the path: a guess for solve() at this speed
    Stability stability = Stability::NotComputed;  ///< of the nearer traced point
};
/// The largest (stable, when stableOnly) describing-function solution at `mph`.
std::optional<SteadyAt> findSteadyAt(const SteadyStateSet& set, double mph, bool stableOnly);
/// Every describing-function solution at `mph` (any stability), roll amplitudes ascending.
std::vector<SteadyAt> findAllSteadyAt(const SteadyStateSet& set, double mph);

}  // namespace validate_detail
}  // namespace rockroll::app
