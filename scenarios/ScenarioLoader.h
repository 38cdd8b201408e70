#pragma once
// Scenario files (TOML): a case — car, track, speed, duration, model, integrator —
// each key left out taking its default (scenarios/ScenarioSchema.h, the schema that
// declares every key once; docs/cli.md "Keys and defaults"). Quantities carry units ("0.75 in", "15.5 mph"). An unknown or
// ill-typed key, or bad unit, is a ScenarioError naming the file, the key, the
// value and what was expected.
#include "bespoke/EomHalfCarModel.h"
#include "bespoke/ReducedHalfCarModel.h"
#include "mbmodel/CarParameters.h"
#include "mbmodel/ModelOptions.h"
#include "mbmodel/RunSummary.h"
#include "mbmodel/RunSettings.h"
#include "mbmodel/TrackInput.h"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace rockroll {

struct Scenario {
    std::string source;          ///< file path, or "<embedded default>"
    std::string sourceSha256;    ///< SHA-256 of the scenario file's bytes (hex)
    /// [car] parameters given in the file, key → the text given (e.g. "0.25 in").
    std::vector<std::pair<std::string, std::string>> carOverrides;
    /// Every dotted key the scenario file holds or an override gave ("run.speed",
    /// "integrator.accuracy", "track.measured"), sorted: what the user set, as opposed
    /// to the defaults of the keys left out (docs/cli.md, "Keys and defaults").
    /// A model's unused settings are found among these (getIgnoredSettings).
    std::vector<std::string> settingsSet;
    /// Overrides applied on top of the file (applyScenarioOverrides), in the order given:
    /// full dotted key → the value text given (e.g. {"car.side_bearing_clearance", "0.25 in"}).
    std::vector<std::pair<std::string, std::string>> overrides;
    std::string description;
    CarParameters car;
    TrackSpec track;
    TrackEntry entry = TrackEntry::Lead;
    double speed = 0;            ///< [m/s]
    std::string model;           ///< a ModelRegistry name (the loader accepts only those)
    EomSimplifications eom;      ///< [eom] table: the report's §4.1 simplifications
    RunSettings run;             ///< run.limits: the [limits] table, unresolved (0 = from the car)
    double filterCutoffHz = 20;
    double severeSeparationTime = 0.010;  ///< [limits] severe_separation [s]
    ReducedOptions reduced;            ///< [reduced] table: the reduced model's truck weight
    AttributionSwitches attribution;   ///< [attribution] table: Simbody truck gravity / mass (attribution only)
    WheelRailSettings wheelRail;       ///< [wheel_rail] table: lateral formulation, creep, flange
    CarBodySettings carBody;           ///< [car_body] table: the full car's rigid or twisting car body
    CriteriaLimits criteria;           ///< [criteria] table: limits of the summary's criteria
};

class ScenarioError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The accepted range of one scenario value, declared once in the schema
/// (scenarios/ScenarioSchema.h) or the car parameter table: the loader (files and
/// overrides), the command line's options and checkScenario (the Python module and
/// every run) all test values against it. docs/cli.md, "Accepted ranges", lists them.
struct ValueRange {
    std::string key;               ///< scenario key ("run.speed", "car.roll_damping"), or a command-line option
    units::Dimension dimension;
    double low, high;              ///< [SI]
    bool lowOpen = false, highOpen = false;
    std::string_view unit;         ///< the unit messages print values and limits in ("mph")
    bool integer = false;          ///< whole numbers only

    bool contains(double si) const;
    /// What is accepted: "a speed in [0.1 mph, 150 mph]".
    std::string describe() const;
    /// `si` in the message unit: "500 mph".
    std::string format(double si) const;
};

/// The range of a scenario key ("run.speed", "integrator.accuracy"); every ranged key
/// of the schema has one. std::out_of_range for a key without a declared range.
const ValueRange& getValueRange(std::string_view key);
const std::vector<ValueRange>& getValueRanges();

/// Every value of a resolved scenario (after command-line options or Python keywords
/// changed it) against its declared range and the cross-checks (filter cut-off below
/// half the output rate): ScenarioError naming sc.source, the key, the value and the range.
void checkScenario(const Scenario& sc);

/// The scenario's criteria limits with the derived ones filled in: a single wheel's
/// L/V limit left 0 is Nadal's limit of its [wheel_rail] flange angle and friction.
CriteriaLimits resolveCriteriaLimits(const Scenario& sc);

/// Refuses (ScenarioError) a run whose recorded history would exceed the memory limit
/// (getMemoryLimitBytes, ROCKROLL_MAX_MEMORY_MB), with the estimate.
void checkMemoryEstimate(const Scenario& sc, size_t channels);

/// One `KEY=VALUE` override of a scenario key, applied to the parsed TOML before the
/// scenario is read, so it goes through exactly the validation (and error messages)
/// of the same key written in the file. `key` is a full dotted key
/// ("car.side_bearing_clearance", "run.speed", "description"), or, where the caller
/// allows it, a bare key naming exactly one key of the schema ("side_bearing_clearance").
/// `value` is text: read as a TOML value when it is one (1e-4, true, 4, "quoted"),
/// otherwise as a string (0.25 in, 16.5 mph, halfcar).
struct ScenarioOverride {
    std::string key;
    std::string value;
};

enum class OverrideKeys { FullOnly, AllowBare };

/// "KEY=VALUE" (spaces around either are trimmed); ScenarioError without an '=' or a key.
ScenarioOverride parseScenarioOverride(std::string_view keyEqualsValue);

/// Every key a scenario file accepts as a value, dotted, in schema order: "description",
/// "car.base", "car.<parameter>" (getCarParameterTable()), "track.amplitude", ...
/// ([[track.measured]] rows are not single keys and are not listed.)
const std::vector<std::string>& getScenarioKeys();

/// The full key `key` names among `keys`: itself when it is one of them, or (AllowBare)
/// the one key whose last part it is. ScenarioError naming `key` and listing `keys`
/// when it names none, or naming the candidates when it names several.
std::string resolveScenarioKey(const std::string& key, OverrideKeys mode,
                               const std::vector<std::string>& keys = getScenarioKeys());

/// Parses `tomlText`, applies `overrides` in order (a later one wins), then reads the
/// scenario as parseScenario does; the scenario records them in `overrides`.
Scenario parseScenario(std::string_view tomlText, const std::string& sourceName,
                       const std::vector<ScenarioOverride>& overrides, OverrideKeys mode = OverrideKeys::FullOnly);

Scenario loadScenarioFile(const std::string& path);
Scenario loadScenarioFile(const std::string& path, const std::vector<ScenarioOverride>& overrides,
                          OverrideKeys mode = OverrideKeys::FullOnly);

/// Cars as data (scenarios/cars/*.toml): `name`, `description` and a [parameters]
/// table giving every car parameter as { value = "<number> <unit>", source = "..." }.
/// A scenario takes one with [car] base = "<built-in name>" or file = "<path
/// relative to the scenario>", or defines the whole car inline with name = "...".
CarParameters parseCarFile(std::string_view tomlText, const std::string& sourceName);
CarParameters loadCarFile(const std::string& path);
/// The built-in cars: the files of scenarios/cars/, compiled in by CMake.
std::vector<std::string> getCarNames();
/// A built-in car by name; ScenarioError listing the names when there is none.
CarParameters makeCarParameters(std::string_view carName);

/// The resolved scenario as a complete TOML document: every car parameter, the
/// track, run, integrator, [eom] and [limits] values, each in SI with its unit
/// and printed to round-trip exactly, so parseScenario of it rebuilds a
/// Scenario that runs bit for bit like this one.
std::string formatScenarioToml(const Scenario& sc);

/// Input size limits (docs/cli.md, "Input size limits"): a scenario, car or summary file, and
/// a measured-track CSV (whose rows mbmodel/TrackInput.h kMaxTrackRows also bounds). Larger
/// files are refused before they are read, so time and memory stay bounded.
inline constexpr std::uintmax_t kMaxScenarioFileBytes = std::uintmax_t(16) << 20;

/// The bytes of the regular file `path` (`what` names it in errors: "scenario file"):
/// ScenarioError when it is missing, not a regular file (a folder, a FIFO, /dev/zero) or
/// larger than `maxBytes`.
std::string readInputFile(const std::string& path, const char* what, std::uintmax_t maxBytes = kMaxScenarioFileBytes);

/// SHA-256 of a byte string, lowercase hex.
std::string calcSha256(std::string_view bytes);
Scenario parseScenario(std::string_view tomlText, const std::string& sourceName);
/// The default case: 70-ton loaded, 0.75 in, 16.5 mph, full car, 20 s (report Figs 8–10).
Scenario getDefaultScenario();

}  // namespace rockroll
