// validate, section 8: what the degrees of freedom the 1976 models leave out change. The
// full car against the half car (pitch, yaw, single-wheel loads); the full car's twisting
// car body (FullCarModel.h, TwistingCarBody) from rigid down to flexible; the ratio of truck
// centres to rail length; the off-centre car body (its static loads against the closed form of
// mbmodel/OffCentreStatics.h, and from rest); and the federal "harmonics" track
// (scenarios/federal-harmonics.toml).
#include "app/ValidateSections.h"
#include "mbmodel/CarSide.h"
#include "mbmodel/LowPassFilter.h"
#include "mbmodel/OffCentreStatics.h"
#include "mbmodel/RockingModel.h"
#include "scenarios/ModelRegistry.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rockroll::app {

using namespace validate_detail;

namespace {

/// One configuration of the full car: truck centres over rail length, the car body's
/// torsional stiffness (0: rigid) and its CG's offsets.
struct DofConfig {
    double ratio = 1;
    double stiffnessLbInPerRad = 0;
    double exIn = 0, eyIn = 0;  ///< cg_longitudinal_offset, cg_lateral_offset [in]
    std::string describeStiffness() const {
        return stiffnessLbInPerRad == 0 ? std::string("rigid") : fmt::format("{:.0e}", stiffnessLbInPerRad);
    }
};

/// The 70-ton loaded car in that configuration.
Scenario makeDofScenario(const DofConfig& c) {
    Scenario sc = loadCarScenario("70ton-loaded");
    sc.model = model_names::kFullCar;
    sc.car.truckSpacing = c.ratio * sc.track.railLength;
    sc.carBody.torsion = c.stiffnessLbInPerRad > 0;
    if (sc.carBody.torsion) sc.car.carBodyTorsionalStiffness = c.stiffnessLbInPerRad * units::lbf * units::inch;
    sc.car.cgLongitudinalOffset = c.exIn * units::inch;
    sc.car.cgLateralOffset = c.eyIn * units::inch;
    return sc;
}

/// `x` to `digits` decimals, a value that rounds to zero printed without its sign.
std::string noNegativeZero(double x, int digits) {
    const std::string t = fmt::format("{:.{}f}", x, digits);
    return t.find_first_not_of("-0.") == std::string::npos ? t.substr(t[0] == '-' ? 1 : 0) : t;
}

std::string fmtAngle(double deg) { return std::isfinite(deg) ? fmt::format("{:.3f}", deg) : std::string("—"); }

/// Part 1: the full car beside the half car on the report's cars.
std::string makeHalfCarPart(const Settings& s) {
    struct Case {
        std::string car;
        double amp, mph;
    };
    const std::vector<Case> cases{{"70ton-loaded", 0.75, 16.5}, {"100ton-loaded", 0.75, 13}};
    std::vector<RestRun> runs;
    for (const auto& c : cases)
        for (const char* m : {model_names::kFullCar, model_names::kHalfCar}) runs.push_back({c.car, c.amp, c.mph, m});
    const std::vector<RunSummary> res = runFromRest(s, runs);
    std::string md =
        "### The full car beside the half car\n\nMade by `rockroll run scenarios/<car>.toml --model fullcar|halfcar "
        "--speed-mph V`. The 100-ton car's truck spacing (39.5 ft) differs from the rail length (39 ft), so its two "
        "trucks see slightly different phases and the body pitches and yaws; the full car also gives single-wheel "
        "loads, where the half car's equivalent wheelset lumps two wheels. The lowest wheel load over its static value "
        "is one real wheel's in the full car and one truck side's (two wheels) in the half car; the largest "
        "single-wheel load exists only in the full car.\n\n| case | model | max roll, deg | max pitch, deg | max yaw, "
        "deg | min wheel load / static | taken over | max single-wheel load, lb | max truck-side wheel load (2 wheels), "
        "lb |\n|---|---|---|---|---|---|---|---|---|\n";
    for (size_t i = 0; i < runs.size(); ++i) {
        const RunSummary& x = res[i];
        md += fmt::format("| {} {:.2f} in {:g} mph | {} | {:.2f} | {} | {} | {:.3f} | {} | {} | {:.0f} |\n", runs[i].car,
                          runs[i].amplitudeIn, runs[i].speedMph, runs[i].model, x.maxRollDeg, fmtAngle(x.maxPitchDeg),
                          fmtAngle(x.maxYawDeg), x.minWheelLoadRatio, x.wheelLoadBasis,
                          std::isfinite(x.maxSingleWheelLoadLb) ? fmt::format("{:.0f}", x.maxSingleWheelLoadLb) : "—",
                          x.maxWheelLoadLb);
    }
    return md + "\nThe half car is planar, so its pitch and yaw are zero by construction.\n\n";
}

/// Part 2: each configuration from rest at the default case, with every wheel's unloading.
std::string makeFromRestPart(const Settings& s, const std::vector<DofConfig>& configs, nlohmann::ordered_json& meta) {
    struct Result {
        RunSummary summary;
        std::vector<std::pair<std::string, double>> unloading;  // per wheel: column, filtered max
        std::string error;
    };
    std::vector<Result> out(configs.size());
    std::vector<std::function<void()>> jobs;
    for (size_t i = 0; i < configs.size(); ++i)
        jobs.push_back([&, i] {
            const Scenario sc = makeRestScenario(s, makeDofScenario(configs[i]),
                                                 {"70ton-loaded", 0.75, 16.5, model_names::kFullCar});
            try {
                const ScenarioRun run = runScenario(sc);
                out[i].summary = run.summary;
                const TimeHistory& h = run.result.history;
                const LowPassFilter filter(sc.filterCutoffHz, sc.run.outputRate);
                for (int c : run.channels.wheelUnloading) {
                    std::vector<double> x;
                    for (const auto& row : h.samples) x.push_back(row[size_t(c) + 1]);
                    const std::vector<double> f = filter.apply(x);
                    // A load cannot be negative, so unloading cannot exceed 1; the filter's overshoot can.
                    out[i].unloading.push_back({run.channels.names[size_t(c)], std::min(1.0, *std::max_element(f.begin(), f.end()))});
                }
            } catch (const std::exception& e) {
                out[i].error = e.what();
            }
        });
    runJobs(jobs, s.jobs);
    std::vector<std::string> wheels;
    for (const auto& r : out)
        if (wheels.empty())
            for (const auto& [name, v] : r.unloading) wheels.push_back(name);
    std::string md = fmt::format(
        "### The twisting car body and the truck centres, from rest\n\nThe 70-ton loaded car, 0.75 in, 16.5 mph, full "
        "car from rest, {:g} s: `rockroll run scenarios/70ton-loaded.toml --set car.truck_spacing=\"R·39 ft\" "
        "--set car_body.torsion=true --set car.car_body_torsional_stiffness=\"K lb*in/rad\" --set "
        "car.cg_longitudinal_offset=\"e_x in\" --set car.cg_lateral_offset=\"e_y in\"` (rigid: "
        "`car_body.torsion` left false). R: truck centres over the 39 ft rail; K: the car body's torsional stiffness "
        "(docs/model.md, \"Car-body torsion\"; the car files assume 1e9); e_x, e_y: the body's CG ahead and to the "
        "left (docs/model.md, \"Off-centre lading\"; every wheel's unloading from its own static load). Angles are the largest |value| over the run; "
        "twist is the rear half's roll against the front half's. Each wheel's unloading (columns truck, "
        "wheelset, side: F1_L is the front truck's leading wheelset's left wheel) is its largest (static − load) / "
        "static, 20 Hz filtered (1: the wheel unloads fully).\n\n| R | K, lb·in/rad | e_x, in | e_y, in | regime | "
        "roll, deg | pitch, deg | yaw, deg | twist, deg | min wheel load / static |",
        s.runDuration);
    // wheel_unloading_F1_L_ratio → F1_L
    for (const auto& w : wheels) md += fmt::format(" {} |", w.substr(16, w.rfind("_ratio") - 16));
    md += "\n|---|---|---|---|---|---|---|---|---|---|";
    for (size_t k = 0; k < wheels.size(); ++k) md += "---|";
    md += "\n";
    for (size_t i = 0; i < configs.size(); ++i) {
        const RunSummary& x = out[i].summary;
        md += fmt::format("| {:.2f} | {} | {:g} | {:g} |", configs[i].ratio, configs[i].describeStiffness(),
                          configs[i].exIn, configs[i].eyIn);
        if (!out[i].error.empty()) {
            md += fmt::format(" failed: {} |\n", out[i].error);
            continue;
        }
        md += fmt::format(" {} | {:.2f} | {} | {} | {} | {:.3f} |", x.regime, x.maxRollDeg, fmtAngle(x.maxPitchDeg),
                          fmtAngle(x.maxYawDeg), fmtAngle(x.maxCarBodyTwistDeg), x.minWheelLoadRatio);
        for (const auto& [name, v] : out[i].unloading) md += fmt::format(" {:.3f} |", v);
        md += "\n";
        meta["added_dof"]["from_rest"].push_back(
            {{"truck_centre_ratio", configs[i].ratio},
             {"torsional_stiffness_lb_in_per_rad", configs[i].stiffnessLbInPerRad},
             {"cg_longitudinal_offset_in", configs[i].exIn},
             {"cg_lateral_offset_in", configs[i].eyIn},
             {"max_roll_deg", x.maxRollDeg},
             {"max_car_body_twist_deg", std::isfinite(x.maxCarBodyTwistDeg) ? nlohmann::json(x.maxCarBodyTwistDeg) : nullptr},
             {"min_wheel_load_ratio", x.minWheelLoadRatio}});
    }
    return md + "\n";
}

/// Part 3: each configuration swept up and down, its jump speeds and largest unloading.
std::string makeSweepPart(const Settings& s, const std::vector<DofConfig>& configs, nlohmann::ordered_json& meta) {
    const double from = s.quick ? 14 : 12, to = s.quick ? 18 : 20, step = s.quick ? 2 : 1, duration = s.quick ? 10 : 20;
    std::vector<SweepSpec> specs;
    for (const auto& c : configs)
        for (auto dir : {SweepDirection::Up, SweepDirection::Down}) {
            SweepSpec spec;
            spec.scenario = makeDofScenario(c);
            spec.scenario.track.amplitude = 0.75 * units::inch;
            spec.scenario.run.duration = duration;
            spec.scenario.run.outputRate = 100;
            spec.fromMph = from, spec.toMph = to, spec.stepMph = step;
            spec.direction = dir;
            specs.push_back(spec);
        }
    const auto points = runSweeps(specs, s.jobs);
    std::string md = fmt::format(
        "### Jump speeds against the truck centres and the torsional stiffness\n\nThe same car and amplitude swept up "
        "and down, {:g}–{:g} mph in {:g} mph steps, {:g} s a speed, each speed from the previous one's final state "
        "(section 2's procedure and jump rule). Largest values over both sweeps; the lowest wheel load is one real "
        "wheel's (filtered), at the speed given.\n\n| R | K, lb·in/rad | jump up, mph | jump down, mph | max roll, "
        "deg | max pitch, deg | max yaw, deg | max twist, deg | min wheel load / static | failed points |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n",
        from, to, step, duration);
    auto jump = [](double v) { return std::isfinite(v) ? fmt::format("{:g}", v) : std::string("none"); };
    for (size_t i = 0; i < configs.size(); ++i) {
        SweepResult r;
        r.up = points[2 * i];
        r.down = points[2 * i + 1];
        findJumps(r);
        double roll = 0, pitch = NAN, yaw = NAN, twist = NAN, minRatio = INFINITY, minAt = NAN;
        int failed = 0;
        auto larger = [](double& best, double x) {
            if (std::isfinite(x)) best = std::isfinite(best) ? std::max(best, x) : x;
        };
        for (const auto* l : {&r.up, &r.down})
            for (const auto& p : *l) {
                if (p.failed) {
                    ++failed;
                    continue;
                }
                roll = std::max(roll, p.summary.maxRollDeg);
                larger(pitch, p.summary.maxPitchDeg);
                larger(yaw, p.summary.maxYawDeg);
                larger(twist, p.summary.maxCarBodyTwistDeg);
                if (p.summary.minWheelLoadRatio < minRatio) minRatio = p.summary.minWheelLoadRatio, minAt = p.speedMph;
            }
        md += fmt::format("| {:.2f} | {} | {} | {} | {:.2f} | {} | {} | {} | {:.3f} at {:g} mph | {} |\n", configs[i].ratio,
                          configs[i].describeStiffness(), jump(r.jumpUpMph), jump(r.jumpDownMph), roll, fmtAngle(pitch),
                          fmtAngle(yaw), fmtAngle(twist), minRatio, minAt, failed);
        meta["added_dof"]["sweeps"].push_back(
            {{"truck_centre_ratio", configs[i].ratio},
             {"torsional_stiffness_lb_in_per_rad", configs[i].stiffnessLbInPerRad},
             {"jump_up_mph", std::isfinite(r.jumpUpMph) ? nlohmann::json(r.jumpUpMph) : nullptr},
             {"jump_down_mph", std::isfinite(r.jumpDownMph) ? nlohmann::json(r.jumpDownMph) : nullptr},
             {"min_wheel_load_ratio", minRatio}});
    }
    return md + "\n";
}

/// Part 4: the off-centre car body's static loads: the lever rule, the closed form
/// (mbmodel/OffCentreStatics.h) and the full car's solved static state.
std::string makeOffCentreStaticPart(const Settings& s, nlohmann::ordered_json& meta) {
    struct Case {
        std::string car;
        double ex, ey;  // [in]
    };
    std::vector<Case> cases;
    for (const char* car : {"70ton-loaded", "70ton-empty", "100ton-loaded"})
        for (auto [ex, ey] : s.quick ? std::vector<std::pair<double, double>>{{2, 0}, {0, 2}}
                                     : std::vector<std::pair<double, double>>{{2, 0}, {12, 0}, {24, 0}, {0, 1}, {0, 2}, {0, 4}, {12, 2}})
            cases.push_back({car, ex, ey});
    const std::map<std::string, Scenario> cars = loadCarScenarios({"70ton-loaded", "70ton-empty", "100ton-loaded"});
    std::string md =
        "### Off-centre lading: static loads\n\nEach car's full car with its body's CG moved e_x ahead and e_y to "
        "the left (`--set car.cg_longitudinal_offset=\"e_x in\" --set car.cg_lateral_offset=\"e_y in\"`), its "
        "static state solved (docs/model.md, \"Off-centre lading\"), beside the closed form of "
        "mbmodel/OffCentreStatics.h and the rigid car's lever rule: the front truck's plate W·(½ + e_x/s), and each "
        "wheel of a wheelset (Q + W_B)/4 + W_u/2 ± Q·e_y/(2g). Wheel: the front truck's leading wheelset's left "
        "wheel. Transfer: the load the offset moves onto the front plate, or between the two wheels, over the "
        "lever rule's (1: the lever rule). Closed form valid: every rim point seated and the side bearings "
        "open.\n\n| car | e_x, in | e_y, in | front plate: lever rule, lb | closed form, lb | model, lb | wheel: "
        "lever rule, lb | closed form, lb | model, lb | plate transfer / lever | wheel transfer / lever | body "
        "roll, deg | pitch, deg | closed form valid |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    const double lb = units::lbf;
    for (const Case& c : cases) {
        Scenario sc = cars.at(c.car);
        sc.model = model_names::kFullCar;
        sc.car.cgLongitudinalOffset = c.ex * units::inch;
        sc.car.cgLateralOffset = c.ey * units::inch;
        const CarParameters& car = sc.car;
        const OffCentreStatics cf = calcOffCentreStatics(car);
        const double W = car.getCarBodyWeight(), Q = W * (0.5 + car.cgLongitudinalOffset / car.truckSpacing);
        const double centred = (Q + car.bolsterWeight) / 4 + (car.wheelsetWeight + car.sideFrameWeight) / 2;
        const double leverWheel = centred + Q * car.cgLateralOffset / (2 * car.gauge);
        double plate = NAN, wheel = NAN, rightWheel = NAN, roll = NAN, pitch = NAN;
        std::string error;
        try {
            const auto model = ModelRegistry::get().getModel(sc.model).makeMultibody(
                car, TrackInput(sc.track), ModelOptions{sc.speed, TrackEntry::Lead, TrackMotion{}, AttributionSwitches{},
                                                        sc.wheelRail, sc.carBody});
            const SimTK::State st = model->makeStaticState(false);
            const CarSample sample = model->calcSample(st);
            plate = sample.trucks[0].centerPlate;
            wheel = model->getStaticWheelLoad(0, 0, kLeft);
            rightWheel = model->getStaticWheelLoad(0, 0, kRight);
            roll = sample.angles[0] / units::degree;
            pitch = sample.angles[1] / units::degree;
        } catch (const std::exception& e) {
            error = e.what();
        }
        if (!error.empty()) {
            md += fmt::format("| {} | {:g} | {:g} | failed: {} | | | | | | | | | | |\n", c.car, c.ex, c.ey, error);
            continue;
        }
        auto ratio = [](double moved, double lever) {
            return lever == 0 ? std::string("—") : fmt::format("{:.3f}", moved / lever);
        };
        const double leverSide = Q * car.cgLateralOffset / car.gauge;  // between the wheelset's two wheels
        md += fmt::format("| {} | {:g} | {:g} | {:.0f} | {:.0f} | {:.0f} | {:.0f} | {:.0f} | {:.0f} | {} | {} | {} | {} | "
                          "{} |\n",
                          c.car, c.ex, c.ey, Q / lb, cf.trucks[0].centerPlate / lb, plate / lb, leverWheel / lb,
                          cf.trucks[0].wheel[kLeft] / lb, wheel / lb, ratio(plate - W / 2, Q - W / 2),
                          ratio(wheel - rightWheel, leverSide), noNegativeZero(roll, 4), noNegativeZero(pitch, 4),
                          cf.getIsValid() ? "yes" : "no");
        meta["added_dof"]["off_centre_static"].push_back({{"car", c.car},
                                                          {"cg_longitudinal_offset_in", c.ex},
                                                          {"cg_lateral_offset_in", c.ey},
                                                          {"front_plate_lever_lb", Q / lb},
                                                          {"front_plate_closed_form_lb", cf.trucks[0].centerPlate / lb},
                                                          {"front_plate_model_lb", plate / lb},
                                                          {"wheel_lever_lb", leverWheel / lb},
                                                          {"wheel_closed_form_lb", cf.trucks[0].wheel[kLeft] / lb},
                                                          {"wheel_model_lb", wheel / lb}});
    }
    return md + "\n";
}

/// A measured track that excites the full car's added motions, run by each car.
struct TrackCase {
    std::string file;     ///< scenario file, relative to the data directory
    std::string heading;  ///< the part's heading and text before its table
};

/// Parts 5 and 6: a measured track (the federal harmonics track; rails with their own joint
/// geometry), each car at the speed where section 2's sweeps peak.
std::string makeTrackPart(const Settings& s, const std::vector<SweepResult>& sweeps, const TrackCase& tc) {
    const Scenario track = loadScenarioFile(findDataFile(tc.file).string());
    struct Case {
        std::string car;
        double mph = 0;
        std::string from;
    };
    std::vector<Case> cases;
    for (const char* car : {"70ton-loaded", "70ton-empty", "100ton-loaded"}) {
        // The speed of the largest steady roll on the up sweep (the branch a car reaches from
        // rest, as it does here) of the half car at 0.75 in, else of the model swept.
        const SweepResult* r = nullptr;
        for (const auto& x : sweeps)
            if (x.c.car == car && x.c.amplitudeIn == 0.75 && (!r || x.model == model_names::kHalfCar)) r = &x;
        if (!r) continue;
        const SweepPoint* best = nullptr;
        for (const auto& p : r->up)
            if (!p.failed && (!best || p.summary.steadyRollAmplitudeDeg > best->summary.steadyRollAmplitudeDeg)) best = &p;
        if (best) cases.push_back({car, best->speedMph, fmt::format("{} up sweep", r->model)});
    }
    std::vector<std::pair<Case, bool>> runs;  // (case, twisting body)
    for (const auto& c : cases)
        for (bool torsion : {false, true}) runs.push_back({c, torsion});
    std::vector<RunSummary> out(runs.size());
    std::vector<std::string> errors(runs.size());
    std::vector<std::function<void()>> jobs;
    for (size_t i = 0; i < runs.size(); ++i)
        jobs.push_back([&, i] {
            Scenario sc = track;
            const Scenario car = loadCarScenario(runs[i].first.car);
            sc.car = car.car;
            sc.criteria = car.criteria;
            sc.wheelRail = car.wheelRail;
            sc.speed = runs[i].first.mph * units::mph;
            sc.carBody.torsion = runs[i].second;
            sc.run.outputRate = 100;
            try {
                out[i] = runScenario(sc).summary;
            } catch (const std::exception& e) {
                errors[i] = e.what();
            }
        });
    runJobs(jobs, s.jobs);
    std::string md = tc.heading + fmt::format(
        " Full car from rest, rigid and twisting car body (the car file's K), each car at the speed of the largest "
        "steady roll amplitude of section 2's 0.75 in up sweep (the branch from rest; the half car's, else the model "
        "swept): `rockroll run {} --set car.base=<car> --speed-mph V`. Whole-run values.\n\n", tc.file) +
        "| car | speed, mph | from | car body | regime | max roll, deg | max pitch, deg | max yaw, deg | max twist, deg | min wheel load / static | max single-wheel "
        "load, lb | max wheel lift, in |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (size_t i = 0; i < runs.size(); ++i) {
        const Case& c = runs[i].first;
        const std::string body = runs[i].second ? "twisting" : "rigid";
        if (!errors[i].empty()) {
            md += fmt::format("| {} | {:g} | {} | {} | failed: {} | | | | | | | |\n", c.car, c.mph, c.from, body, errors[i]);
            continue;
        }
        const RunSummary& x = out[i];
        md += fmt::format("| {} | {:g} | {} | {} | {} | {:.2f} | {} | {} | {} | {:.3f} | {:.0f} | {:.3f} |\n", c.car, c.mph,
                          c.from, body, x.regime, x.maxRollDeg, fmtAngle(x.maxPitchDeg), fmtAngle(x.maxYawDeg),
                          fmtAngle(x.maxCarBodyTwistDeg), x.minWheelLoadRatio, x.maxSingleWheelLoadLb, x.maxWheelLiftIn);
    }
    if (cases.empty()) md += "| no car was swept at 0.75 in | | | | | | | | | | | |\n";
    return md + "\n";
}

}  // namespace

std::string makeAddedDofSection(const Settings& s, const std::vector<SweepResult>& sweeps, nlohmann::ordered_json& meta) {
    std::string md = "## 8. What the added degrees of freedom change\n\n";
    md += makeHalfCarPart(s);
    // From rigid to flexible at the report's ratio and at pure twist, and the ratio alone with a rigid body.
    const std::vector<double> stiffnesses = s.quick ? std::vector<double>{0, 1e8} : std::vector<double>{0, 1e9, 1e8};
    const std::vector<double> ratios =
        s.quick ? std::vector<double>{0.5, 1.0} : std::vector<double>{0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    std::vector<DofConfig> configs;
    for (double r : ratios) configs.push_back({r, 0});
    for (double r : {1.0, 0.5})
        for (double k : stiffnesses)
            if (k > 0) configs.push_back({r, k});
    // Off-centre lading, rigid body at the report's ratio: from rest only.
    std::vector<DofConfig> offCentre;
    for (auto [ex, ey] : s.quick ? std::vector<std::pair<double, double>>{{0, 2}}
                                 : std::vector<std::pair<double, double>>{{0, 1}, {0, 2}, {0, -2}, {24, 0}, {24, 2}})
        offCentre.push_back({1.0, 0, ex, ey});
    std::vector<DofConfig> fromRest = configs;
    fromRest.insert(fromRest.end(), offCentre.begin(), offCentre.end());
    md += makeFromRestPart(s, fromRest, meta);
    md += makeSweepPart(s, configs, meta);
    md += makeOffCentreStaticPart(s, meta);
    md += makeTrackPart(s, sweeps, {"scenarios/federal-harmonics.toml",
                                    "### The federal harmonics track\n\nThe 1.25 in limit of 49 CFR 213.63 on jointed "
                                    "track with staggered joints: seven low joints, then level track (docs/cli.md, "
                                    "\"Measured track\")."});
    md += makeTrackPart(s, sweeps, {"scenarios/uneven-joints.toml",
                                    "### Rails with their own joint geometry\n\nJoints 0.75 in deep on the left rail "
                                    "and 0.5 in on the right, each scattered by up to ±25 % by a seeded rule, the "
                                    "right rail's joints 0.35 of a rail after the left's (scripts/make-uneven-joints-"
                                    "track.py; docs/cli.md, \"Measured track\")."});
    return md;
}

}  // namespace rockroll::app
