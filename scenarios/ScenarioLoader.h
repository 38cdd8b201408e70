#pragma once
// Scenario files (TOML): a complete case — car, track, speed, duration, model,
// integrator. Quantities carry units ("0.75 in", "15.5 mph"). Any missing,
// unknown or ill-typed key, or bad unit, is a ScenarioError naming the file,
// the key, the value and what was expected.
#include "bespoke/EomHalfCarModel.h"
#include "bespoke/ReducedHalfCarModel.h"
#include "mbmodel/CarParameters.h"
#include "mbmodel/RockingModel.h"
#include "mbmodel/Simulation.h"
#include "mbmodel/TrackInput.h"

#include <stdexcept>
#include <string>

namespace rockroll {

struct Scenario {
    std::string source;          ///< file path, or "<embedded default>"
    std::string sourceSha256;    ///< SHA-256 of the scenario file's bytes (hex)
    /// [car] parameters given in the file, key → the text given (e.g. "0.25 in").
    std::vector<std::pair<std::string, std::string>> carOverrides;
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
};

class ScenarioError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

Scenario loadScenarioFile(const std::string& path);

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

/// SHA-256 of a byte string, lowercase hex.
std::string calcSha256(std::string_view bytes);
Scenario parseScenario(std::string_view tomlText, const std::string& sourceName);
/// The default case: 70-ton loaded, 0.75 in, 16.5 mph, full car, 20 s (report Figs 8–10).
Scenario getDefaultScenario();

}  // namespace rockroll
