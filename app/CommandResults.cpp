#include "app/CommandResults.h"

#include "app/Provenance.h"
#include "scenarios/ModelRegistry.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <stdexcept>

namespace rockroll::app {

nlohmann::ordered_json toJson(const RunSummary& s) {
    nlohmann::ordered_json j;
    j["model"] = s.model;
    j["car"] = s.car;
    j["speed_mph"] = s.speedMph;
    j["amplitude_in"] = s.amplitudeIn;
    j["duration_s"] = s.durationS;
    j["max_roll_deg"] = s.maxRollDeg;
    j["steady_roll_amplitude_deg"] = s.steadyRollAmplitudeDeg;
    j["peak_to_peak_roll_deg"] = s.peakToPeakRollDeg;
    j["max_wheel_lift_in"] = s.maxWheelLiftIn;
    auto valueOrNull = [](double x) { return std::isnan(x) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(x); };
    j["max_pitch_deg"] = valueOrNull(s.maxPitchDeg);
    j["max_yaw_deg"] = valueOrNull(s.maxYawDeg);
    j["max_car_body_twist_deg"] = valueOrNull(s.maxCarBodyTwistDeg);
    j["max_wheel_load_lb"] = s.maxWheelLoadLb;  // the truck side's two wheels; kept beside its new name for one release
    j["max_truck_side_wheel_load_lb"] = s.maxWheelLoadLb;
    j["max_single_wheel_load_lb"] = valueOrNull(s.maxSingleWheelLoadLb);
    j["wheel_load_basis"] = s.wheelLoadBasis;
    j["min_wheel_load_ratio"] = s.minWheelLoadRatio;
    j["max_side_bearing_load_lb"] = s.maxSideBearingLoadLb;
    j["max_center_plate_load_lb"] = s.maxCenterPlateLoadLb;
    j["raw_max_wheel_load_lb"] = s.rawMaxWheelLoadLb;
    j["raw_min_wheel_load_ratio"] = s.rawMinWheelLoadRatio;
    j["raw_max_side_bearing_load_lb"] = s.rawMaxSideBearingLoadLb;
    j["raw_max_center_plate_load_lb"] = s.rawMaxCenterPlateLoadLb;
    j["static_wheel_load_lb"] = s.staticWheelLoadLb;
    j["static_center_plate_load_lb"] = s.staticCenterPlateLoadLb;
    j["regime"] = s.regime;
    j["stopped_at_s"] = s.stoppedAtS >= 0 ? nlohmann::ordered_json(s.stoppedAtS) : nlohmann::ordered_json(nullptr);
    j["stop_reason"] = s.stopReason.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.stopReason);
    j["center_plate_separation_longest_s"] = s.centerPlateSeparationLongestS;
    j["center_plate_separation_total_s"] = s.centerPlateSeparationTotalS;
    j["wheel_lift_longest_s"] = s.wheelLiftLongestS;
    j["energy_balance_error"] = std::isfinite(s.energyBalanceError) ? nlohmann::ordered_json(s.energyBalanceError)
                                                                    : nlohmann::ordered_json(nullptr);
    j["worst_energy_balance_error"] = std::isfinite(s.worstEnergyBalanceError)
                                          ? nlohmann::ordered_json(s.worstEnergyBalanceError)
                                          : nlohmann::ordered_json(nullptr);
    j["steady"] = {{"window_s", s.steady.windowS},
                   {"cycles", s.steady.cycles},
                   {"max_roll_deg", s.steady.rollDeg},
                   {"max_wheel_lift_in", s.steady.wheelLiftIn},
                   {"max_truck_side_wheel_load_lb", s.steady.truckSideWheelLoadLb},
                   {"max_side_bearing_load_lb", s.steady.sideBearingLoadLb},
                   {"max_center_plate_load_lb", s.steady.centerPlateLoadLb}};
    // Freight channels and criteria (null: the model has no such channel).
    j["max_wheel_unloading"] = valueOrNull(s.maxWheelUnloading);
    j["raw_max_wheel_unloading"] = valueOrNull(s.rawMaxWheelUnloading);
    j["max_l_over_v"] = valueOrNull(s.maxLOverV);
    j["raw_max_l_over_v"] = valueOrNull(s.rawMaxLOverV);
    j["max_truck_side_l_over_v"] = valueOrNull(s.maxTruckSideLOverV);
    j["raw_max_truck_side_l_over_v"] = valueOrNull(s.rawMaxTruckSideLOverV);
    j["max_car_body_vertical_accel_g"] = valueOrNull(s.maxCarBodyVerticalAccelG);
    j["raw_max_car_body_vertical_accel_g"] = valueOrNull(s.rawMaxCarBodyVerticalAccelG);
    j["max_car_body_lateral_accel_g"] = valueOrNull(s.maxCarBodyLateralAccelG);
    j["raw_max_car_body_lateral_accel_g"] = valueOrNull(s.rawMaxCarBodyLateralAccelG);
    j["trucks"] = nlohmann::ordered_json::array();
    for (const TruckLoads& t : s.trucks)
        j["trucks"].push_back({{"truck", t.truck},
                               {"max_center_plate_load_lb", t.maxCenterPlateLoadLb},
                               {"min_center_plate_load_lb", t.minCenterPlateLoadLb},
                               {"max_side_bearing_L_load_lb", t.maxSideBearingLoadLb[0]},
                               {"max_side_bearing_R_load_lb", t.maxSideBearingLoadLb[1]}});
    j["criteria"] = nlohmann::ordered_json::array();
    for (const Criterion& c : s.criteria)
        j["criteria"].push_back({{"name", c.name},
                                 {"value", valueOrNull(c.value)},
                                 {"limit", c.limit},
                                 {"unit", c.unit},
                                 {"pass", c.evaluated() ? nlohmann::ordered_json(c.passes()) : nlohmann::ordered_json(nullptr)}});
    j["criteria_pass"] = s.passesCriteria();
    j["criteria_from_s"] = s.criteriaFromS;
    j["filter"] = s.filter;
    j["sim_time_s"] = s.simTimeS;
    j["wall_time_s"] = s.wallTimeS;
    j["steps"] = s.steps;
    return j;
}

std::string formatCriteriaTable(const RunSummary& s) {
    std::string out = fmt::format("  criteria ({})\n", s.passesCriteria() ? "all evaluated pass" : "FAIL");
    for (const Criterion& c : s.criteria)
        out += c.evaluated() ? fmt::format("    {:<26}{:>10.3f} {:<6} limit {:<8g}{}\n", c.name, c.value, c.unit, c.limit,
                                           c.passes() ? "pass" : "FAIL")
                             : fmt::format("    {:<26}{:>10} {:<6} limit {:<8g}not evaluated (no such channel in this model)\n",
                                           c.name, "-", c.unit, c.limit);
    return out;
}

nlohmann::ordered_json makeRunJson(const ScenarioRun& run, const Scenario& sc, const std::string& command) {
    nlohmann::ordered_json j = toJson(run.summary);
    if (!sc.track.measured.empty()) j["amplitude_in"] = nullptr;  // a measured track has no sine amplitude
    j["provenance"] = makeProvenance(sc, command);
    return j;
}

std::vector<SweepSpec> makeSweepSpecs(const std::vector<Scenario>& bases, const SweepOptions& o) {
    std::vector<SweepSpec> specs;
    for (Scenario base : bases) {
        if (o.model) base.model = *o.model;
        if (o.durationS) base.run.duration = *o.durationS;
        if (o.maxWallS) base.run.limits.maxWallTime = *o.maxWallS;
        std::vector<double> amplitudes = o.amplitudesIn;
        if (amplitudes.empty()) amplitudes.push_back(base.track.amplitude / units::inch);
        for (double a : amplitudes)
            for (const char* dir : {"up", "down"}) {
                if (o.direction != "both" && o.direction != dir) continue;
                SweepSpec s;
                s.scenario = base;
                s.scenario.track.amplitude = a * units::inch;
                s.fromMph = o.fromMph;
                s.toMph = o.toMph;
                s.stepMph = o.stepMph;
                s.direction = std::string(dir) == "up" ? SweepDirection::Up : SweepDirection::Down;
                s.fresh = o.fresh;
                s.rampTime = o.rampS;
                specs.push_back(s);
            }
    }
    return specs;
}

nlohmann::ordered_json makeSweepPointJson(const SweepSpec& spec, const SweepPoint& p, const std::string& command) {
    nlohmann::ordered_json j;
    if (p.failed) {
        j["model"] = spec.scenario.model;
        j["car"] = spec.scenario.car.name;
        j["speed_mph"] = p.speedMph;
        j["amplitude_in"] = spec.scenario.track.amplitude / units::inch;
        j["failed"] = true;
        j["error"] = p.error;
    } else {
        j = toJson(p.summary);
        j["failed"] = false;
    }
    if (!spec.scenario.track.measured.empty()) j["amplitude_in"] = nullptr;  // no sine amplitude
    j["direction"] = p.direction;
    j["start"] = p.start;
    Scenario at = spec.scenario;
    at.speed = p.speedMph * units::mph;
    j["provenance"] = makeProvenance(at, command);
    j["provenance"]["sweep"] = {{"from_mph", spec.fromMph}, {"to_mph", spec.toMph},
                                {"step_mph", spec.stepMph}, {"direction", p.direction},
                                {"fresh", spec.fresh}, {"ramp_time_s", spec.rampTime}};
    return j;
}

nlohmann::ordered_json makeSweepJumpsJson(const std::vector<SweepSpec>& specs,
                                          const std::vector<std::vector<SweepPoint>>& results) {
    nlohmann::ordered_json jumps = nlohmann::ordered_json::array();
    for (size_t i = 0; i < specs.size() && i < results.size(); ++i) {
        const Scenario& sc = specs[i].scenario;
        const SweepJump jump = findSweepJump(results[i], specs[i].direction);
        nlohmann::ordered_json j;
        j["model"] = sc.model;
        j["car"] = sc.car.name;
        // The amplitude as the points' summaries echo it (rounded as given, so the CSV's rows match it).
        double amplitudeIn = sc.track.amplitude / units::inch;
        for (const SweepPoint& p : results[i])
            if (!p.failed) {
                amplitudeIn = p.summary.amplitudeIn;
                break;
            }
        j["amplitude_in"] = sc.track.measured.empty() ? nlohmann::ordered_json(amplitudeIn) : nullptr;
        j["direction"] = specs[i].direction == SweepDirection::Up ? "up" : "down";
        j["jump_speed_mph"] = std::isfinite(jump.speedMph) ? nlohmann::ordered_json(jump.speedMph) : nullptr;
        j["steady_roll_change_deg"] = jump.changeDeg;
        j["steady_roll_change_fraction"] = std::isfinite(jump.changeFraction) ? nlohmann::ordered_json(jump.changeFraction)
                                                                               : nullptr;
        j["largest_change_mph"] = std::isfinite(jump.largestChangeMph) ? nlohmann::ordered_json(jump.largestChangeMph)
                                                                        : nullptr;
        jumps.push_back(std::move(j));
    }
    return jumps;
}

nlohmann::ordered_json makeSweepRecords(const nlohmann::ordered_json& points) {
    nlohmann::ordered_json records = nlohmann::ordered_json::array();
    for (const nlohmann::ordered_json& p : points) {
        // One flat row per speed: the per-truck loads, the criteria and the steady-part
        // maxima become columns named with their truck, criterion or "steady_" and their unit.
        nlohmann::ordered_json r = nlohmann::ordered_json::object();
        for (const auto& [key, value] : p.items()) {
            if (key == "provenance") continue;
            if (key == "trucks" && value.is_array()) {
                for (const auto& t : value)
                    for (const auto& [field, v] : t.items())
                        if (field != "truck") r[fmt::format("truck_{}_{}", t.at("truck").get<std::string>(), field)] = v;
            } else if (key == "criteria" && value.is_array()) {
                for (const auto& c : value) {
                    const std::string name = c.at("name").get<std::string>(), unit = c.at("unit").get<std::string>();
                    r[fmt::format("criterion_{}_{}", name, unit)] = c.at("value");
                    r[fmt::format("criterion_{}_limit_{}", name, unit)] = c.at("limit");
                    r[fmt::format("criterion_{}_pass", name)] = c.at("pass");
                }
            } else if (key == "steady" && value.is_object()) {
                for (const auto& [field, v] : value.items()) r["steady_" + field] = v;
            } else {
                r[key] = value;
            }
        }
        records.push_back(std::move(r));
    }
    return records;
}

nlohmann::ordered_json makeSteadyRecords(const nlohmann::ordered_json& steady) {
    nlohmann::ordered_json records = nlohmann::ordered_json::array();
    const auto& branches = steady.at("branches");
    for (size_t b = 0; b < branches.size(); ++b)
        for (const auto& p : branches[b].at("points")) {
            nlohmann::ordered_json r{{"branch", b}, {"path", branches[b].at("path")},
                                     {"stability", branches[b].at("stability")}};
            for (const auto& [key, value] : p.items()) {
                if (value.is_object()) {  // force harmonics and the twin's maxima: one column each
                    for (const auto& [field, v] : value.items()) r[key + "_" + field] = v;
                } else {
                    r[key] = value;
                }
            }
            records.push_back(std::move(r));
        }
    return records;
}

SteadyResult calcSteady(const Scenario& sc, const SteadyOptions& o) {
    checkScenario(sc);
    if (!(o.toMph > o.fromMph))
        throw ScenarioError(fmt::format("steady: --to-mph {} must exceed --from-mph {}: expected to > from", o.toMph,
                                        o.fromMph));
    if (!sc.track.measured.empty())
        throw ScenarioError(fmt::format("{}: steady needs the rectified-sine track (its describing function takes the "
                                        "sine's fundamental); this scenario has a measured track: expected [track] "
                                        "without file or measured",
                                        sc.source));
    if (sc.wheelRail.lateral != LateralWheelRail::Restraint)
        throw ScenarioError(fmt::format("{}: key 'wheel_rail.lateral' = \"{}\": expected \"restraint\" for steady (the "
                                        "describing function solves the report's formulation, with its lateral "
                                        "restraint)",
                                        sc.source, getLateralWheelRailName(sc.wheelRail.lateral)));
    if (sc.carBody.torsion)
        throw ScenarioError(fmt::format("{}: key 'car_body.torsion' = true: expected false for steady (the describing "
                                        "function solves the report's half car, whose body is rigid)",
                                        sc.source));
    if (sc.car.cgLongitudinalOffset != 0 || sc.car.cgLateralOffset != 0)
        throw ScenarioError(fmt::format("{}: key 'car.{}' = {:g} in: expected 0 for steady (the describing function "
                                        "solves the report's half car, loaded centrally)",
                                        sc.source, sc.car.cgLateralOffset != 0 ? "cg_lateral_offset" : "cg_longitudinal_offset",
                                        (sc.car.cgLateralOffset != 0 ? sc.car.cgLateralOffset : sc.car.cgLongitudinalOffset) /
                                            units::inch));
    SteadyResult r;
    const double C = DescribingFunctionModel::calcFundamentalCrossLevel(sc.track.amplitude, sc.car.wheelbase,
                                                                        sc.track.railLength);
    r.inputAmplitude = C;
    const DescribingFunctionModel model(sc.car, C, sc.track.railLength);
    r.set = model.trace(makeContinuationSettings(o));
    if (r.set.paths.empty())
        throw std::runtime_error(fmt::format("no harmonic-balance solution found at {} mph", o.fromMph));
    r.inputNote = fmt::format(
        "sinusoidal cross-level of amplitude {:.4f} in: the fundamental harmonic 8A/(3 pi) cos(pi wheelbase/L_r) "
        "of the {:.3f} in rectified-sine cross-level averaged over the wheelbase",
        C / units::inch, sc.track.amplitude / units::inch);
    return r;
}

ContinuationSettings makeContinuationSettings(const SteadyOptions& o) {
    ContinuationSettings settings;
    settings.fromMph = o.fromMph;
    settings.toMph = o.toMph;
    settings.stability = o.stabilityMethod == "floquet" ? StabilityMethod::Floquet
                         : o.stabilityMethod == "none"  ? StabilityMethod::None
                                                        : StabilityMethod::FoldRule;
    settings.twinPeriods = o.twinPeriods;
    settings.sweepStepMph = o.sweepStarts ? settings.sweepStepMph : 0;
    return settings;
}

namespace {
nlohmann::ordered_json orNullIfNaN(double x) {
    return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json(nullptr);
}
nlohmann::ordered_json makeHarmonicsJson(const ForceHarmonics& h) {
    return {{"mean_lb", h.meanLb}, {"first_harmonic_lb", h.firstLb}, {"second_harmonic_lb", h.secondLb}};
}
nlohmann::ordered_json makeTwinJson(const TwinMaxima& t) {
    if (!t.computed)
        return {{"periods", t.periods}, {"roll_amplitude_deg", nullptr}, {"persistence", nullptr}, {"landed_on", nullptr},
                {"stayed", nullptr},
                {"max_roll_deg", nullptr}, {"max_truck_side_wheel_load_lb", nullptr},
                {"max_side_bearing_load_lb", nullptr}, {"max_center_plate_load_lb", nullptr}};
    return {{"periods", t.periods},
            {"roll_amplitude_deg", t.rollAmplitudeDeg},
            {"persistence", t.persistence},
            {"landed_on", t.landedOn},
            {"stayed", t.stayed()},
            {"max_roll_deg", t.maxRollDeg},
            {"max_truck_side_wheel_load_lb", t.maxTruckSideWheelLoadLb},
            {"max_side_bearing_load_lb", t.maxSideBearingLoadLb},
            {"max_center_plate_load_lb", t.maxCenterPlateLoadLb}};
}
}  // namespace

nlohmann::ordered_json makeSteadyJson(const SteadyResult& r, const Scenario& sc, const SteadyOptions& o,
                                      const std::string& command) {
    const ContinuationSettings settings = makeContinuationSettings(o);
    nlohmann::ordered_json j;
    j["car"] = sc.car.name;
    j["amplitude_in"] = sc.track.amplitude / units::inch;
    j["input_amplitude_in"] = r.inputAmplitude / units::inch;
    j["input"] = r.inputNote;
    j["model"] = "describing function (half car, report 4.1 simplifications)";
    j["stability"] =
        o.stabilityMethod == "floquet"
            ? fmt::format("every point checked: Floquet multipliers of the time-domain twin's periodic orbit and a "
                          "{}-period persistence run of the twin; a point where they disagree is not labelled",
                          settings.persistencePeriods)
        : o.stabilityMethod == "none"
            ? std::string("not computed")
            : fmt::format("each stretch between folds checked near both ends and in the middle (Floquet multipliers of "
                          "the time-domain twin's periodic orbit and a {}-period persistence run of the twin), bisected "
                          "where checks disagree (at most {} checks a stretch); a point takes its nearest check's label, "
                          "and a check whose Floquet and persistence evidence disagree labels nothing",
                          settings.persistencePeriods, settings.maxChecksPerStretch);
    j["forces"] = "force harmonics: mean and first two harmonic amplitudes of each contact force on the two-harmonic "
                  "motion (exact Fourier coefficients); peak values only from the twin's time history (twin_*), never "
                  "from the two-harmonic series";
    j["twin_maxima"] = settings.twinPeriods > 0
                           ? fmt::format("the time-domain twin run {} forcing periods from each solution; 20 Hz filtered "
                                         "maxima over its last period; stayed: that period solves back onto the solution "
                                         "(or, solving onto none, its roll amplitude is within {:g} % of the solution's)",
                                         settings.twinPeriods, 100 * kPersistenceTolerance)
                           : std::string("not computed (--twin-periods 0)");
    j["starts"] = settings.sweepStepMph > 0
                      ? fmt::format("both ends of the range from rest, and the twin swept down and up in {:g} mph steps "
                                    "({} forcing periods a speed, state carried over), each speed's last period "
                                    "projected on two harmonics and solved",
                                    settings.sweepStepMph, settings.sweepPeriods)
                      : std::string("both ends of the range from rest (no sweep starts)");
    j["provenance"] = makeProvenance(sc, command);
    j["provenance"]["model"] = "describing function";  // the scenario's [run] model is not used here
    j["sweep_starts_tried"] = r.set.sweepStarts.size();
    j["sweep_starts_new"] = std::count_if(r.set.sweepStarts.begin(), r.set.sweepStarts.end(),
                                          [](const TwinSweepStart& t) { return t.newPath; });
    j["paths"] = nlohmann::ordered_json::array();
    for (const auto& p : r.set.paths)
        j["paths"].push_back({{"start", p.start},
                              {"start_mph", p.startMph},
                              {"closed", p.closed},
                              {"points", p.points.size()},
                              {"folds", p.points.empty() ? 0 : p.points.back().foldsBefore}});
    j["stability_changes"] = nlohmann::ordered_json::array();
    for (const auto& c : r.set.changes)
        j["stability_changes"].push_back({{"path", c.path}, {"from_mph", c.fromMph}, {"to_mph", c.toMph}, {"kind", c.kind}});
    j["branches"] = nlohmann::ordered_json::array();
    for (const auto& b : r.set.branches) {
        nlohmann::ordered_json jb;
        jb["path"] = b.path;
        // null, never true, when nothing decided it (--stability none, or no evidence).
        jb["stable"] = b.stability == Stability::NotComputed ? nlohmann::ordered_json(nullptr)
                                                              : nlohmann::ordered_json(b.stability == Stability::Stable);
        jb["stability"] = describeStability(b.stability);
        jb["points"] = nlohmann::ordered_json::array();
        for (const auto& p : b.points)
            jb["points"].push_back({{"speed_mph", p.speedMph},
                                    {"roll_amplitude_deg", p.rollAmplitudeDeg},
                                    {"roll_mean_deg", p.rollMeanDeg},
                                    {"roll_first_harmonic_deg", p.rollFirstDeg},
                                    {"roll_second_harmonic_deg", p.rollSecondDeg},
                                    {"wheel_lift_fraction", p.wheelLiftFraction},
                                    {"wheel_load", makeHarmonicsJson(p.wheelLoad)},
                                    {"side_bearing_load", makeHarmonicsJson(p.sideBearingLoad)},
                                    {"center_plate_load", makeHarmonicsJson(p.centerPlateLoad)},
                                    {"twin", makeTwinJson(p.twin)},
                                    // Kept for one release, empty: they were pointwise peaks of the two-harmonic
                                    // series (docs/bespoke.md, "Forces: harmonics, not peaks"); see twin.
                                    {"max_wheel_load_lb", nullptr},
                                    {"max_side_bearing_load_lb", nullptr},
                                    {"min_center_plate_load_lb", nullptr},
                                    {"folds_before", p.foldsBefore},
                                    {"checked", p.checked},
                                    {"floquet_converged", p.floquetConverged},
                                    {"stability_evidence", p.stabilityEvidence},
                                    {"twin_persistence", std::isfinite(p.twinPersistence) && p.twinPersistence > 0
                                                             ? nlohmann::ordered_json(p.twinPersistence)
                                                             : nlohmann::ordered_json(nullptr)},
                                    {"twin_landed_on", p.twinLandedOn.empty() ? nlohmann::ordered_json(nullptr)
                                                                              : nlohmann::ordered_json(p.twinLandedOn)},
                                    {"max_floquet_multiplier", orNullIfNaN(p.maxFloquetMultiplier)},
                                    {"dominant_multiplier_re", orNullIfNaN(p.checked ? p.dominantMultiplier.real() : NAN)},
                                    {"dominant_multiplier_im", orNullIfNaN(p.checked ? p.dominantMultiplier.imag() : NAN)}});
        j["branches"].push_back(jb);
    }
    return j;
}

const UncoupledEstimate* ModesResult::findEstimate(const Mode& m) const {
    const std::string& base = m.body;
    std::string motion = m.motion;
    if (motion == "sway-roll") motion = m.name.find("lower") != std::string::npos ? "roll" : "sway";
    for (const auto& e : table1)
        if (e.body == base && e.motion == motion) return &e;
    return nullptr;
}

ModesResult calcScenarioModes(const Scenario& sc) {
    const ModelDescriptor* descriptor = ModelRegistry::get().find(sc.model);
    if (!descriptor || !descriptor->isMultibody())
        throw ScenarioError(fmt::format("{}: modes need a Simbody model with truck masses: {}, not \"{}\"", sc.source,
                                        fmt::join(ModelRegistry::get().getMultibodyNames(), " or "), sc.model));
    TrackSpec level = sc.track;
    level.amplitude = 0;
    level.measured.clear();
    ModelOptions options;
    options.speed = sc.speed;
    options.entry = sc.entry;
    options.carBody = sc.carBody;  // the twisting car body has its twist mode
    const auto model = descriptor->makeMultibody(makeModalCar(sc.car), TrackInput(level), options);
    ModesResult r;
    r.modes = calcModes(*model);
    r.table1 = calcTable1Estimates(sc.car);
    return r;
}

nlohmann::ordered_json makeModesJson(const ModesResult& r, const Scenario& sc, const std::string& command) {
    nlohmann::ordered_json j;
    j["model"] = sc.model;
    j["car"] = sc.car.name;
    j["linearization"] = "about static equilibrium, every contact closed, Coulomb friction removed";
    j["provenance"] = makeProvenance(sc, command);
    j["modes"] = nlohmann::ordered_json::array();
    for (const Mode& m : r.modes) {
        nlohmann::ordered_json jm{{"name", m.name},           {"frequency_hz", m.frequencyHz},
                                  {"damping_ratio", m.dampingRatio}, {"body", m.body},
                                  {"motion", m.motion},       {"energy_share", m.energyShare}};
        if (const auto* e = r.findEstimate(m)) {
            jm["table1_formula_hz"] = e->frequencyHz;
            jm["table1_report_hz"] = e->reportHz > 0 ? nlohmann::ordered_json(e->reportHz) : nlohmann::ordered_json(nullptr);
        }
        j["modes"].push_back(jm);
    }
    j["table1"] = nlohmann::ordered_json::array();
    for (const auto& e : r.table1)
        j["table1"].push_back({{"body", e.body}, {"motion", e.motion}, {"formula_hz", e.frequencyHz},
                               {"report_hz", e.reportHz > 0 ? nlohmann::ordered_json(e.reportHz) : nlohmann::ordered_json(nullptr)}});
    return j;
}

}  // namespace rockroll::app
