// The compiled part of the Python package `rockroll` (python/rockroll/__init__.py wraps
// it): scenarios, runs, sweeps, steady states and modes through the same library
// functions the command line uses (app/CommandResults.h, scenarios/), returning data.
// Every model run releases the GIL, so Python threads run models in parallel.
#include "app/BuildInfo.h"
#include "app/CommandResults.h"
#include "app/OrbitsResults.h"
#include "mbmodel/Parallel.h"
#include "app/Provenance.h"
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/TimeHistory.h"
#include "mbmodel/Units.h"
#include "scenarios/ScenarioLoader.h"
#include "scenarios/ScenarioRun.h"
#include "scenarios/SpeedSweep.h"

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace rockroll;

namespace {

/// How many model runs are inside their GIL-released section now, and the most ever
/// at once (the test that threads run concurrently reads it).
std::atomic<int> gRunning{0}, gPeak{0};

/// Counts one model run while it lives, with the GIL released for it.
class ReleasedRun {
public:
    ReleasedRun() {
        const int now = ++gRunning;
        int peak = gPeak.load();
        while (now > peak && !gPeak.compare_exchange_weak(peak, now)) {
        }
    }
    ~ReleasedRun() { --gRunning; }
    ReleasedRun(const ReleasedRun&) = delete;
    ReleasedRun& operator=(const ReleasedRun&) = delete;

private:
    py::gil_scoped_release release_;
};

/// JSON (as the command line prints it) → the same structure in Python objects;
/// objects keep their key order.
py::object toPython(const nlohmann::ordered_json& j) {
    switch (j.type()) {
        case nlohmann::ordered_json::value_t::null: return py::none();
        case nlohmann::ordered_json::value_t::boolean: return py::bool_(j.get<bool>());
        case nlohmann::ordered_json::value_t::number_integer: return py::int_(j.get<std::int64_t>());
        case nlohmann::ordered_json::value_t::number_unsigned: return py::int_(j.get<std::uint64_t>());
        case nlohmann::ordered_json::value_t::number_float: return py::float_(j.get<double>());
        case nlohmann::ordered_json::value_t::string: return py::str(j.get<std::string>());
        case nlohmann::ordered_json::value_t::array: {
            py::list out;
            for (const auto& v : j) out.append(toPython(v));
            return out;  // moved implicitly (C++20)
        }
        case nlohmann::ordered_json::value_t::object: {
            py::dict out;
            for (const auto& [k, v] : j.items()) out[py::str(k)] = toPython(v);
            return out;
        }
        default: throw std::runtime_error("unexpected JSON value (binary or discarded)");
    }
}

std::vector<ScenarioOverride> toOverrides(const std::vector<std::pair<std::string, std::string>>& kv) {
    std::vector<ScenarioOverride> out;
    for (const auto& [k, v] : kv) out.push_back({k, v});
    return out;
}

/// The time history as a rows × channels float64 array (t_s first).
py::array_t<double> toArray(const TimeHistory& h) {
    const size_t rows = h.samples.size(), cols = h.names.size();
    py::array_t<double> a({rows, cols});
    if (rows > 0 && h.samples.getWidth() != cols)
        throw std::runtime_error("history rows with the wrong number of channels");
    if (rows > 0) std::memcpy(a.mutable_data(), h.samples.data(), rows * cols * sizeof(double));
    return a;
}

double positive(double v, const char* name) {
    if (!(v > 0)) throw py::value_error(std::string(name) + " must be a positive number");
    return v;
}

/// ChannelRole's flags by name, for the channel table the module returns.
const std::vector<std::pair<ChannelRole, const char*>> kRoleNames{
    {ChannelRole::Roll, "roll"},
    {ChannelRole::CenterPlate, "center_plate"},
    {ChannelRole::SideBearing, "side_bearing"},
    {ChannelRole::TruckSideWheelLoad, "truck_side_wheel_load"},
    {ChannelRole::SingleWheelLoad, "single_wheel_load"},
    {ChannelRole::WheelLift, "wheel_lift"},
    {ChannelRole::WheelsetLateral, "wheelset_lateral"},
    {ChannelRole::WheelUnloading, "wheel_unloading"},
    {ChannelRole::LOverV, "l_over_v"},
    {ChannelRole::TruckSideLOverV, "truck_side_l_over_v"},
    {ChannelRole::CarBodyVerticalAccel, "car_body_vertical_accel"},
    {ChannelRole::CarBodyLateralAccel, "car_body_lateral_accel"},
    {ChannelRole::EnergyStored, "energy_stored"},
    {ChannelRole::EnergyInput, "energy_input"},
    {ChannelRole::EnergyDissipated, "energy_dissipated"},
};

/// The history's columns as the model's channel table declares them (mbmodel/ChannelLayout.h):
/// one dict per column {name, quantity, unit, roles, truck}, time first (TimeHistory: "t_s",
/// then the channels). std::logic_error when the history's columns are not the table's.
py::list toChannelTable(const TimeHistory& h, const ChannelLayout& layout) {
    if (h.names.size() != layout.channels.size() + 1 || h.names.front() != "t_s")
        throw std::logic_error("the history's columns are not t_s followed by the model's channel table");
    py::list table;
    auto entry = [&](const std::string& name, const ChannelInfo& c) {
        py::list roles;
        for (const auto& [role, roleName] : kRoleNames)
            if (hasRole(c.roles, role)) roles.append(roleName);
        py::dict d;
        d["name"] = name, d["quantity"] = c.quantity, d["unit"] = c.unit, d["roles"] = roles, d["truck"] = c.truck;
        table.append(d);
    };
    entry(h.names.front(), ChannelInfo{"t", "s", ChannelRole::None, ""});
    for (size_t i = 0; i < layout.channels.size(); ++i) {
        if (h.names[i + 1] != layout.channels[i].getColumn())
            throw std::logic_error("history column " + h.names[i + 1] + " is not the channel table's " +
                                   layout.channels[i].getColumn());
        entry(h.names[i + 1], layout.channels[i]);
    }
    return table;
}

}  // namespace

PYBIND11_MODULE(_rockroll, m) {
    m.doc() = "rockroll's compiled core; use the package `rockroll`.";
    m.attr("__version__") = kVersion;
    m.attr("git_commit") = kGitCommit;
    m.def("version_string", &app::getVersionString, "rockroll version, git commit and Simbody build");

    // Errors carry the command line's messages; ScenarioError is bad input (a ValueError),
    // NumericalFailure a failed integration (a RuntimeError, with the time it failed at).
    // The types are module attributes for the life of the process; one extra reference
    // each keeps them valid in the translator without a static py::object to destroy at exit.
    static PyObject* scenarioError = py::exception<ScenarioError>(m, "ScenarioError", PyExc_ValueError).inc_ref().ptr();
    static PyObject* numericalFailure =
        py::exception<NumericalFailure>(m, "NumericalFailure", PyExc_RuntimeError).inc_ref().ptr();
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const ScenarioError& e) {
            PyErr_SetString(scenarioError, e.what());
        } catch (const NumericalFailure& e) {
            py::object error = py::reinterpret_borrow<py::object>(numericalFailure)(e.what());
            error.attr("time_s") = e.getTime();
            PyErr_SetObject(numericalFailure, error.ptr());
        }
    });

    py::class_<Scenario>(m, "Scenario", "A complete case: car, track, speed, duration, model, integrator.")
        .def_readonly("source", &Scenario::source, "the scenario file")
        .def_readonly("sha256", &Scenario::sourceSha256, "SHA-256 of the scenario file's bytes")
        .def_readonly("description", &Scenario::description)
        .def_readonly("model", &Scenario::model, "halfcar | fullcar | eom | reduced")
        .def_property_readonly("car", [](const Scenario& sc) { return sc.car.name; }, "the base car")
        .def_property_readonly("speed_mph", [](const Scenario& sc) { return sc.speed / units::mph; })
        .def_property_readonly("amplitude_in", [](const Scenario& sc) { return sc.track.amplitude / units::inch; },
                               "cross-level amplitude A")
        .def_property_readonly("duration_s", [](const Scenario& sc) { return sc.run.duration; })
        .def_property_readonly(
            "overrides",
            [](const Scenario& sc) {
                py::list out;
                for (const auto& [k, v] : sc.overrides) out.append(py::make_tuple(k, v));
                return out;
            },
            "(full key, value text) of every override applied to the file, in order")
        .def_property_readonly(
            "car_overrides",
            [](const Scenario& sc) {
                py::dict out;
                for (const auto& [k, v] : sc.carOverrides) out[py::str(k)] = v;
                return out;
            },
            "[car] parameters set in the file or by an override: key → the text given")
        .def("to_toml", &formatScenarioToml,
             "the resolved scenario as a complete TOML document (every value in SI, exactly)")
        .def("__repr__", [](const Scenario& sc) {
            std::string o;
            for (const auto& [k, v] : sc.overrides) o += (o.empty() ? "" : ", ") + k + "=" + v;
            return "<rockroll.Scenario " + sc.source + ": " + sc.car.name + ", " + sc.model + ", " +
                   std::to_string(sc.speed / units::mph) + " mph" + (o.empty() ? "" : ", overrides: " + o) + ">";
        });

    m.def("scenario_keys", &getScenarioKeys, "every key a scenario file (and an override) accepts, dotted");
    m.def(
        "_load",
        [](const std::string& path, const std::vector<std::pair<std::string, std::string>>& overrides) {
            return loadScenarioFile(path, toOverrides(overrides), OverrideKeys::AllowBare);
        },
        py::arg("path"), py::arg("overrides"));
    m.def("_default_scenario", &getDefaultScenario);
    m.def("_from_summary", &app::loadScenarioFromSummary, py::arg("path"));

    m.def(
        "_run",
        [](Scenario sc, std::optional<std::string> model, std::optional<double> speedMph,
           std::optional<double> durationS, std::optional<double> amplitudeIn, std::optional<double> maxWallS,
           const std::string& command) {
            // As `rockroll run` applies its options (app/Commands.cpp, runCommand).
            if (model) sc.model = *model;
            if (speedMph) sc.speed = positive(*speedMph, "speed_mph") * units::mph;
            if (amplitudeIn) {
                if (!(*amplitudeIn >= 0)) throw py::value_error("amplitude_in must be a number >= 0");
                sc.track.amplitude = *amplitudeIn * units::inch;
            }
            if (durationS) sc.run.duration = positive(*durationS, "duration_s");
            if (maxWallS) sc.run.limits.maxWallTime = positive(*maxWallS, "max_wall_s");
            ScenarioRun run;
            {
                ReleasedRun released;
                run = runScenario(sc);
            }
            py::dict out;
            out["summary"] = toPython(app::makeRunJson(run, sc, command));
            out["names"] = run.result.history.names;
            out["data"] = toArray(run.result.history);
            out["channels"] = toChannelTable(run.result.history, run.channels);
            out["stop"] = run.result.stop ? py::object(py::str(run.result.stop->regime)) : py::object(py::none());
            return out;
        },
        py::arg("scenario"), py::arg("model"), py::arg("speed_mph"), py::arg("duration_s"), py::arg("amplitude_in"),
        py::arg("max_wall_s"), py::arg("command"));

    m.def(
        "_sweep",
        [](const std::vector<Scenario>& scenarios, std::optional<std::string> model,
           std::vector<double> amplitudesIn, double fromMph, double toMph, double stepMph, const std::string& direction,
           std::optional<double> durationS, int jobs, std::optional<double> maxWallS, bool fresh,
           const std::string& command) {
            app::SweepOptions o;  // the options of `rockroll sweep`
            o.model = model;
            o.amplitudesIn = std::move(amplitudesIn);
            o.fromMph = fromMph;
            o.toMph = toMph;
            o.stepMph = stepMph;
            o.direction = direction;
            o.durationS = durationS;
            o.jobs = jobs;
            o.maxWallS = maxWallS;
            o.fresh = fresh;
            const std::vector<SweepSpec> specs = app::makeSweepSpecs(scenarios, o);
            std::vector<std::vector<SweepPoint>> results;
            {
                ReleasedRun released;
                const int threads = resolveJobCount(o.jobs);
                results = runSweeps(specs, threads);
            }
            py::list out;
            for (size_t i = 0; i < specs.size(); ++i)
                for (const SweepPoint& p : results[i]) out.append(toPython(app::makeSweepPointJson(specs[i], p, command)));
            return out;
        },
        py::arg("scenarios"), py::arg("model"), py::arg("amplitude_in"), py::arg("from_mph"), py::arg("to_mph"),
        py::arg("step_mph"), py::arg("direction"), py::arg("duration_s"), py::arg("jobs"), py::arg("max_wall_s"),
        py::arg("fresh"), py::arg("command"));

    m.def(
        "_steady",
        [](Scenario sc, std::optional<double> amplitudeIn, double fromMph, double toMph, const std::string& stability,
           int twinPeriods, bool sweepStarts, const std::string& command) {
            app::SteadyOptions o;  // the options of `rockroll steady`
            o.scenario = sc.source;
            o.amplitudeIn = amplitudeIn;
            o.fromMph = fromMph;
            o.toMph = toMph;
            o.stabilityMethod = stability;
            o.twinPeriods = twinPeriods;
            o.sweepStarts = sweepStarts;
            if (o.amplitudeIn) sc.track.amplitude = *o.amplitudeIn * units::inch;
            app::SteadyResult r;
            {
                ReleasedRun released;
                r = app::calcSteady(sc, o);
            }
            return toPython(app::makeSteadyJson(r, sc, o, command));
        },
        py::arg("scenario"), py::arg("amplitude_in"), py::arg("from_mph"), py::arg("to_mph"), py::arg("stability"),
        py::arg("twin_periods"), py::arg("sweep_starts"), py::arg("command"));

    m.def(
        "_orbits",
        [](Scenario sc, std::optional<std::string> model, std::optional<double> amplitudeIn, double fromMph,
           double toMph, double stepMph, double startDurationS, std::optional<double> startSweepFromMph,
           double startRampS, double accuracy, int refinements, int newtonSteps, int settlePeriods, bool iterate,
           double fdStepScale, int jobs,
           const std::string& command) {
            app::OrbitsOptions o;  // the options of `rockroll orbits`
            o.scenario = sc.source;
            o.model = model;
            o.amplitudeIn = amplitudeIn;
            o.fromMph = fromMph, o.toMph = toMph, o.stepMph = stepMph;
            o.startDurationS = startDurationS;
            o.startSweepFromMph = startSweepFromMph;
            o.startRampS = startRampS;
            o.accuracy = accuracy;
            o.refinements = refinements;
            o.newtonSteps = newtonSteps;
            o.settlePeriods = settlePeriods;
            o.iterate = iterate;
            o.fdStepScale = fdStepScale;
            o.jobs = jobs;
            o.json = true;  // no progress lines
            if (model) sc.model = *model;
            if (amplitudeIn) {
                if (!sc.track.measured.empty())
                    throw ScenarioError(fmt::format("amplitude_in: {} has a measured track, which has no rectified-sine "
                                                    "amplitude; expected amplitude_in=None",
                                                    sc.source));
                sc.track.amplitude = *amplitudeIn * units::inch;
            }
            app::OrbitsResult r;
            {
                ReleasedRun released;
                r = app::calcOrbits(sc, o, command);
            }
            return toPython(r.doc);
        },
        py::arg("scenario"), py::arg("model"), py::arg("amplitude_in"), py::arg("from_mph"), py::arg("to_mph"),
        py::arg("step_mph"), py::arg("start_duration_s"), py::arg("start_sweep_from_mph"), py::arg("start_speed_ramp_s"),
        py::arg("accuracy"), py::arg("refinements"), py::arg("newton_steps"), py::arg("settle_periods"), py::arg("iterate"),
        py::arg("fd_step_scale"),
        py::arg("jobs"), py::arg("command"));

    m.def(
        "_modes",
        [](Scenario sc, std::optional<std::string> model, const std::string& command) {
            if (model) sc.model = *model;
            app::ModesResult r;
            {
                ReleasedRun released;
                r = app::calcScenarioModes(sc);
            }
            return toPython(app::makeModesJson(r, sc, command));
        },
        py::arg("scenario"), py::arg("model"), py::arg("command"));

    m.def(
        "_concurrency",
        [] { return py::make_tuple(gRunning.load(), gPeak.load()); },
        "(model runs now running with the GIL released, the most at once since _reset_concurrency)");
    m.def("_reset_concurrency", [] { gPeak = gRunning.load(); });
}
