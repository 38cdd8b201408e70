// validate, section 12: the wheel–rail contact. The report's lateral restraint beside
// the creep and flange contact (contacts/WheelRailLaws.h; docs/model.md, "Wheel–rail
// contact") on the report's Table 3 cases and on section 2's half-car sweeps, and the
// speeds and amplitudes at which the full car with creep and flanges comes closest to
// flange climb (the run monitor's rules, mbmodel/RunLimits.h).
#include "app/Progress.h"
#include "app/ValidateSections.h"
#include "mbmodel/CsvWriter.h"
#include "mbmodel/RunLimits.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <limits>

namespace rockroll::app {

using namespace validate_detail;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const std::vector<LateralWheelRail> kFormulations{LateralWheelRail::Restraint, LateralWheelRail::CreepAndFlange};
/// The models with lateral wheel forces (the reduced model has none).
const std::vector<std::string> kLateralModels{model_names::kFullCar, model_names::kHalfCar, model_names::kEom};

/// How near one run came to flange climb, from its recorded history (100 Hz) by the
/// run monitor's own definitions (RunGuard::check): a wheel is in flange contact while
/// its flange force is positive, and its L/V toward its own rail is the monitor's.
struct ClimbMeasure {
    /// The largest L/V toward its own rail a wheel held for longer than the climb time
    /// (the minimum over the shortest such stretch), with or without flange contact.
    double heldLOverV = kNaN;
    std::string heldWheel;  ///< its L/V channel
    /// The same through unbroken flange contact: the climb rule fires when it passes
    /// Nadal's limit. NaN: no wheel stayed in flange contact that long.
    double heldLOverVInFlangeContact = kNaN;
    std::string heldInFlangeContactWheel;  ///< its flange channel
    double flangeContactS = 0;        ///< longest unbroken flange contact of any wheel [s]
    double maxFlangeForceLb = 0;      ///< largest flange normal force of any wheel (raw) [lb]
    double maxLiftInContactIn = 0;    ///< largest lift of a wheel while its own flange touches [in]
    double maxWheelsetLateralIn = 0;  ///< largest |lateral displacement| of any wheelset [in]
};

/// The largest value of `value` held over the shortest stretch of rows, all satisfying
/// `holds`, that lasts longer than `duration` (rows[i][0] is the time); NaN: none.
template <class Value, class Holds>
double calcHeldMaximum(const SampleTable& rows, double duration, Value value, Holds holds) {
    double best = kNaN;
    for (size_t i = 0; i < rows.size(); ++i) {
        if (!holds(i)) continue;
        double low = value(i);
        for (size_t j = i + 1; j < rows.size() && holds(j); ++j) {
            low = std::min(low, value(j));
            if (rows[j][0] - rows[i][0] > duration) {
                if (std::isnan(best) || low > best) best = low;
                break;
            }
        }
    }
    return best;
}

ClimbMeasure measureClimb(const ScenarioRun& run, double climbTime) {
    ClimbMeasure m;
    const auto& rows = run.result.history.samples;
    const ChannelLayout& layout = run.channels;
    auto at = [&](size_t i, int channel) { return rows[i][size_t(channel) + 1]; };
    auto keepLarger = [](double& best, std::string& bestName, double v, const std::string& name) {
        if (std::isfinite(v) && (std::isnan(best) || v > best)) best = v, bestName = name;
    };
    for (const auto& ws : layout.wheelsets) {
        if (ws.lateral >= 0)
            for (size_t i = 0; i < rows.size(); ++i)
                m.maxWheelsetLateralIn = std::max(m.maxWheelsetLateralIn, std::abs(at(i, ws.lateral)));
        for (int side : {0, 1}) {
            const int f = ws.flange[side], lv = ws.lOverV[side], lift = side == 0 ? ws.liftLeft : ws.liftRight;
            if (f < 0 || lv < 0) continue;
            auto inContact = [&](size_t i) { return at(i, f) > 0; };
            auto toward = [&](size_t i) { return side == 0 ? -at(i, lv) : at(i, lv); };
            keepLarger(m.heldLOverV, m.heldWheel, calcHeldMaximum(rows, climbTime, toward, [](size_t) { return true; }),
                       layout.names[size_t(lv)]);
            keepLarger(m.heldLOverVInFlangeContact, m.heldInFlangeContactWheel,
                       calcHeldMaximum(rows, climbTime, toward, inContact), layout.names[size_t(f)]);
            double since = kNaN;
            for (size_t i = 0; i < rows.size(); ++i) {
                m.maxFlangeForceLb = std::max(m.maxFlangeForceLb, at(i, f));
                if (!inContact(i)) {
                    since = kNaN;
                    continue;
                }
                if (std::isnan(since)) since = rows[i][0];
                m.flangeContactS = std::max(m.flangeContactS, rows[i][0] - since);
                if (lift >= 0) m.maxLiftInContactIn = std::max(m.maxLiftInContactIn, at(i, lift));
            }
        }
    }
    return m;
}

/// One run of the section: its summary and climb measure, or why it failed.
struct WheelRailRun {
    std::string car, model;
    LateralWheelRail lateral = LateralWheelRail::Restraint;
    double amplitudeIn = 0, speedMph = 0;
    bool failed = false;
    std::string error;
    RunSummary summary;
    ClimbMeasure climb;
    double nadalLimit = kNaN;
};

WheelRailRun makeRun(const std::string& car, const std::string& model, LateralWheelRail lateral, double amplitudeIn,
                     double speedMph) {
    WheelRailRun r;
    r.car = car, r.model = model, r.lateral = lateral, r.amplitudeIn = amplitudeIn, r.speedMph = speedMph;
    return r;
}

std::vector<WheelRailRun> runAll(const Settings& s, std::vector<WheelRailRun> runs) {
    std::vector<RestRun> rest;
    for (const auto& r : runs) rest.push_back({r.car, r.amplitudeIn, r.speedMph, r.model});
    forEachRestRun(s, rest, [&](size_t i, const Scenario& car) {
        WheelRailRun& r = runs[i];
        Scenario sc = car;
        sc.wheelRail.lateral = r.lateral;
        if (r.lateral == LateralWheelRail::CreepAndFlange)
            r.nadalLimit = calcNadalLimit(sc.wheelRail.flangeAngle, sc.wheelRail.friction);
        try {
            const ScenarioRun run = runScenario(sc);
            r.summary = run.summary;
            r.climb = measureClimb(run, resolveRunLimits(sc.run.limits, sc.car, sc.wheelRail).flangeClimbTime);
        } catch (const std::exception& e) {
            r.failed = true;
            r.error = e.what();
        }
    });
    return runs;
}

std::string fmtValue(double v, int decimals) {
    return std::isfinite(v) ? fmt::format("{:.{}f}", v, decimals) : std::string("n/e");
}

CsvCell cell(double v, int decimals) { return std::isfinite(v) ? CsvCell::fixed(v, decimals) : CsvCell::empty(); }

/// Part A: each Table 3 case, each model with lateral wheel forces, both formulations.
std::string makeTable3Part(const Settings& s, const std::vector<WheelRailRun>& runs, nlohmann::ordered_json& meta) {
    std::string md = fmt::format(
        "### The report's Table 3 cases, from rest\n\n"
        "One run per row: `rockroll run scenarios/<car>.toml --model M --amplitude-in A --speed-mph V --duration-s {:g} "
        "--set wheel_rail.lateral=L`, recorded at 100 Hz; the two rows of a model differ in `wheel_rail.lateral` alone. "
        "Whole-run maxima from t = 0 (20 Hz filtered, as in section 3), and the steady roll (the largest |roll| over the "
        "steady part, section 3's statistic). Wheel load: one truck side's two wheels. Minimum wheel load ratio: the "
        "lowest single wheel's (full car) or truck side's (half-car models) load over its static load. L/V: filtered "
        "maxima; single wheel (its own lateral force over its own vertical force) and truck side (ΣL/ΣV of one side of "
        "one truck); with the restraint both wheels of a wheelset carry the same L/V (docs/model.md, \"Wheel–rail "
        "contact\"). Energy: the balance error at the end of the run. The reduced model has no lateral wheel force and "
        "is not in this table.\n\n",
        s.runDuration);
    const std::string head =
        "| model | lateral | regime | roll, deg | steady roll, deg | wheel lift, in | wheel load (2 wheels, 1 side), lb | "
        "min wheel load ratio | side bearing, lb | single-wheel L/V | truck-side L/V | energy error, % |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& row : loadTable3(Mit1976::get())) {
        bool any = false;
        std::string table;
        for (const auto& r : runs) {
            if (r.car != row.car || r.amplitudeIn != row.amplitudeIn || r.speedMph != row.speedMph) continue;
            any = true;
            const std::string lateral = getLateralWheelRailName(r.lateral);
            if (r.failed) {
                table += fmt::format("| {} | {} | failed: {} | | | | | | | | | |\n", r.model, lateral, r.error);
                continue;
            }
            const RunSummary& x = r.summary;
            std::string regime = x.regime;
            if (x.stoppedAtS >= 0) regime += fmt::format(" at {:.2f} s: {}", x.stoppedAtS, x.stopReason);
            table += fmt::format("| {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.0f} | {:.3f} | {:.0f} | {} | {} | {} |\n",
                                 r.model, lateral, regime, x.maxRollDeg, x.steady.rollDeg, x.maxWheelLiftIn,
                                 x.maxWheelLoadLb, x.minWheelLoadRatio, x.maxSideBearingLoadLb, fmtValue(x.maxLOverV, 3),
                                 fmtValue(x.maxTruckSideLOverV, 3), fmtValue(100 * x.energyBalanceError, 2));
            meta["wheel_rail"]["table3"].push_back(
                {{"condition", row.label}, {"model", r.model}, {"lateral", lateral}, {"speed_mph", r.speedMph},
                 {"regime", x.regime}, {"max_roll_deg", x.maxRollDeg}, {"steady_roll_deg", x.steady.rollDeg},
                 {"max_single_wheel_l_over_v", std::isfinite(x.maxLOverV) ? nlohmann::json(x.maxLOverV) : nullptr}});
        }
        if (any) md += fmt::format("**{} at {:g} mph**\n\n", row.label, row.speedMph) + head + table + "\n";
    }
    writeAtomically(s.out / "wheel_rail_table3.csv", [&](std::ostream& o) {
        CsvWriter csv(o, {"car", "amplitude_in", "speed_mph", "model", "lateral", "failed", "regime", "max_roll_deg",
                          "steady_max_roll_deg", "max_wheel_lift_in", "max_wheel_load_lb", "min_wheel_load_ratio",
                          "max_side_bearing_load_lb", "max_single_wheel_l_over_v", "max_truck_side_l_over_v",
                          "energy_balance_error"});
        for (const auto& r : runs) {
            const RunSummary& x = r.summary;
            const CsvCell none = CsvCell::empty();
            if (r.failed) {
                csv.writeRow({r.car, r.amplitudeIn, r.speedMph, r.model, getLateralWheelRailName(r.lateral), 1, "failed",
                              none, none, none, none, none, none, none, none, none});
                continue;
            }
            csv.writeRow({r.car, r.amplitudeIn, r.speedMph, r.model, getLateralWheelRailName(r.lateral), 0, x.regime,
                          cell(x.maxRollDeg, 4), cell(x.steady.rollDeg, 4), cell(x.maxWheelLiftIn, 4),
                          cell(x.maxWheelLoadLb, 0), cell(x.minWheelLoadRatio, 4), cell(x.maxSideBearingLoadLb, 0),
                          cell(x.maxLOverV, 4), cell(x.maxTruckSideLOverV, 4), cell(x.energyBalanceError, 6)});
        }
    });
    meta["wheel_rail"]["files"].push_back({{"file", "wheel_rail_table3.csv"}});
    return md;
}

/// Part B: eom's sweeps of section 2 (the cheaper twin of the half car) beside the same sweeps with creep and flanges.
std::string makeSweepPart(const Settings& s, const std::vector<SweepResult>& sweeps, nlohmann::ordered_json& meta) {
    std::vector<const SweepResult*> restraint;
    for (const auto& r : sweeps)
        if (r.model == model_names::kEom) restraint.push_back(&r);
    std::string md = "### Jump speeds of eom, swept up and down\n\n";
    if (restraint.empty())
        return md + "Not run: this validate run does not sweep eom (section 2); the full run does.\n\n";
    std::vector<SweepSpec> specs;
    std::vector<SweepResult> creep;
    for (const SweepResult* r : restraint) {
        Scenario car = loadCarScenario(r->c.car);
        car.wheelRail.lateral = LateralWheelRail::CreepAndFlange;
        SweepResult c;
        c.c = r->c;
        c.model = r->model;
        creep.push_back(c);
        for (auto dir : {SweepDirection::Up, SweepDirection::Down}) specs.push_back(makeSweepSpec(s, car, r->c, r->model, dir));
    }
    size_t total = 0;
    for (const auto& sp : specs) total += getSweepSpeeds(sp).size();
    SweepProgress progress("validate: wheel-rail sweeps", total);
    const auto points = runSweeps(specs, s.jobs, [&progress](const SweepPoint& p) { progress(p); });
    for (size_t i = 0; i < creep.size(); ++i) {
        creep[i].up = points[2 * i];
        creep[i].down = points[2 * i + 1];
        findJumps(creep[i]);
    }
    md += fmt::format(
        "Section 2's sweeps of eom, the equation-of-motion twin of the half car (restraint), beside the same sweeps with `--set wheel_rail.lateral=creep_and_flange` "
        "({:g} mph steps, {:g} s per speed, each speed starting from the previous one's final state); jumps by section "
        "2's rule, the largest steady roll amplitude of each sweep with its speed.\n\n"
        "| car | A, in | lateral | jump up, mph | jump down, mph | largest steady roll, up | largest steady roll, down | failed points |\n"
        "|---|---|---|---|---|---|---|---|\n",
        s.sweepStep, s.sweepDuration);
    auto jump = [](double v) { return std::isfinite(v) ? fmt::format("{:g}", v) : std::string("none"); };
    auto steadyRoll = [](const RunSummary& x) { return x.steadyRollAmplitudeDeg; };
    for (size_t i = 0; i < creep.size(); ++i)
        for (const SweepResult* r : std::array<const SweepResult*, 2>{restraint[i], &creep[i]}) {
            const std::string lateral = r == restraint[i] ? "restraint" : "creep_and_flange";
            int failed = 0;
            for (const auto* l : {&r->up, &r->down})
                for (const auto& p : *l) failed += p.failed ? 1 : 0;
            md += fmt::format("| {} | {:.2f} | {} | {} | {} | {} | {} | {} |\n", r->c.car, r->c.amplitudeIn, lateral,
                              jump(r->jumpUpMph), jump(r->jumpDownMph), describeLargest(*r, SweepDirection::Up, steadyRoll),
                              describeLargest(*r, SweepDirection::Down, steadyRoll), failed);
            meta["wheel_rail"]["sweeps"].push_back({{"car", r->c.car},
                                                    {"amplitude_in", r->c.amplitudeIn},
                                                    {"model", r->model},
                                                    {"lateral", lateral},
                                                    {"jump_up_mph", std::isfinite(r->jumpUpMph) ? nlohmann::json(r->jumpUpMph) : nullptr},
                                                    {"jump_down_mph", std::isfinite(r->jumpDownMph) ? nlohmann::json(r->jumpDownMph) : nullptr}});
        }
    return md + "\n";
}

/// A car's grid of the flange-climb search.
struct ClimbGrid {
    std::string car;
    std::vector<double> amplitudesIn;
    double fromMph, toMph, stepMph;
    std::vector<double> getSpeeds() const {
        std::vector<double> v;
        for (int k = 0; fromMph + k * stepMph <= toMph + 1e-9; ++k) v.push_back(fromMph + k * stepMph);
        return v;
    }
};

/// Part C: the full car with creep and flanges on a grid of speeds and amplitudes.
std::string makeClimbPart(const Settings& s, const std::vector<ClimbGrid>& grids, const std::vector<WheelRailRun>& runs) {
    std::string md = fmt::format(
        "### Where the full car comes closest to flange climb\n\n"
        "The full car with `--set wheel_rail.lateral=creep_and_flange` from rest, {:g} s, 100 Hz, at every speed "
        "and amplitude of the grid; the wheel–rail data are each car file's. Flange climb is the run monitor's rule "
        "(docs/model.md, \"Run limits\"): a wheel in flange contact whose L/V toward its own rail stays above "
        "Nadal's limit longer than the climb time, or a wheel lifted above the flange height toward its rail past "
        "the flangeway clearance. Each cell gives, over Nadal's limit, the largest L/V a wheel held toward its own "
        "rail for longer than the climb time (**L/V margin**) and, after \"f\", the same through unbroken flange "
        "contact (the **climb margin**: 1 climbs), when a flange stayed in contact that long; a run the monitor "
        "stopped shows its regime in bold. `wheel_rail_flange_climb.csv` holds every run's measures.\n\n",
        s.runDuration);
    auto margin = [](const WheelRailRun& r, double held) { return std::isfinite(held) ? held / r.nadalLimit : kNaN; };
    auto lvMargin = [&](const WheelRailRun& r) { return margin(r, r.climb.heldLOverV); };
    auto climbMargin = [&](const WheelRailRun& r) { return margin(r, r.climb.heldLOverVInFlangeContact); };
    for (const auto& g : grids) {
        const WheelRailSettings w = loadCarScenario(g.car).wheelRail;
        const std::vector<double> speeds = g.getSpeeds();
        md += fmt::format("**{}**: Nadal's limit {:.3f} (flange angle {:g}°, μ = {:g}), climb time {:g} s, flange "
                          "height {:g} in, flangeway clearance {:g} in. Rows: amplitude, in; columns: speed, mph.\n\n"
                          "| A, in |",
                          g.car, calcNadalLimit(w.flangeAngle, w.friction), w.flangeAngle / units::degree, w.friction,
                          RunLimits{}.flangeClimbTime, w.flangeHeight / units::inch, w.flangewayClearance / units::inch);
        for (double v : speeds) md += fmt::format(" {:g} |", v);
        md += "\n|---|";
        for (size_t k = 0; k < speeds.size(); ++k) md += "---|";
        md += "\n";
        const WheelRailRun* closest = nullptr;
        // The closest: a stopped run first, then the largest climb margin, then the largest L/V margin.
        auto rank = [&](const WheelRailRun& x) {
            const double c = climbMargin(x), l = lvMargin(x);
            return std::array<double, 3>{x.summary.stoppedAtS >= 0 ? 1.0 : 0.0, std::isfinite(c) ? c : -1.0,
                                         std::isfinite(l) ? l : -1.0};
        };
        for (double a : g.amplitudesIn) {
            md += fmt::format("| {:.2f} |", a);
            for (double v : speeds) {
                const WheelRailRun* r = nullptr;
                for (const auto& x : runs)
                    if (x.car == g.car && x.amplitudeIn == a && std::abs(x.speedMph - v) < 1e-9) r = &x;
                if (!r) {
                    md += " |";
                    continue;
                }
                if (r->failed) {
                    md += " failed |";
                    continue;
                }
                if (r->summary.stoppedAtS >= 0) md += fmt::format(" **{}** |", r->summary.regime);
                else if (std::isfinite(climbMargin(*r))) md += fmt::format(" {} f {:.2f} |", fmtValue(lvMargin(*r), 2), climbMargin(*r));
                else md += fmt::format(" {} |", fmtValue(lvMargin(*r), 2));
                if (!closest || rank(*r) > rank(*closest)) closest = r;
            }
            md += "\n";
        }
        if (closest) {
            const ClimbMeasure& c = closest->climb;
            const RunSummary& x = closest->summary;
            auto named = [](double v, const std::string& wheel) {
                return fmtValue(v, 2) + (wheel.empty() ? std::string() : " (" + wheel + ")");
            };
            md += fmt::format(
                "\nClosest: {:.2f} in at {:g} mph — {}; climb margin {}; L/V margin {}; longest unbroken flange contact "
                "{:.2f} s; largest flange force {:.0f} lb; largest lift of a wheel in flange contact {:.3f} in; largest "
                "wheelset lateral displacement {:.3f} in; largest single-wheel L/V (filtered) {}; lowest wheel load "
                "ratio {:.3f}; roll {:.2f}°.\n\n",
                closest->amplitudeIn, closest->speedMph,
                x.stoppedAtS >= 0 ? fmt::format("{} at {:.2f} s: {}", x.regime, x.stoppedAtS, x.stopReason) : x.regime,
                named(climbMargin(*closest), c.heldInFlangeContactWheel), named(lvMargin(*closest), c.heldWheel),
                c.flangeContactS, c.maxFlangeForceLb, c.maxLiftInContactIn, c.maxWheelsetLateralIn,
                fmtValue(x.maxLOverV, 3), x.minWheelLoadRatio, x.maxRollDeg);
        }
    }
    int failed = 0;
    for (const auto& r : runs) failed += r.failed ? 1 : 0;
    for (const auto& r : runs)
        if (r.failed) md += fmt::format("- failed: {} {:.2f} in {:g} mph: {}\n", r.car, r.amplitudeIn, r.speedMph, r.error);
    if (failed) md += "\n";
    writeAtomically(s.out / "wheel_rail_flange_climb.csv", [&](std::ostream& o) {
        CsvWriter csv(o, {"car", "amplitude_in", "speed_mph", "failed", "regime", "stopped_at_s", "stop_reason",
                          "nadal_limit", "held_l_over_v", "l_over_v_margin", "held_l_over_v_wheel",
                          "held_l_over_v_in_flange_contact", "climb_margin", "held_in_flange_contact_wheel",
                          "longest_flange_contact_s", "max_flange_force_lb", "max_lift_in_flange_contact_in",
                          "max_wheelset_lateral_in", "max_single_wheel_l_over_v", "min_wheel_load_ratio", "max_roll_deg"});
        const CsvCell none = CsvCell::empty();
        for (const auto& r : runs) {
            if (r.failed) {
                csv.writeRow({r.car, r.amplitudeIn, r.speedMph, 1, "failed", none, r.error, cell(r.nadalLimit, 4), none,
                              none, "", none, none, "", none, none, none, none, none, none, none});
                continue;
            }
            const RunSummary& x = r.summary;
            const ClimbMeasure& c = r.climb;
            csv.writeRow({r.car, r.amplitudeIn, r.speedMph, 0, x.regime, x.stoppedAtS >= 0 ? cell(x.stoppedAtS, 3) : none,
                          x.stopReason, cell(r.nadalLimit, 4), cell(c.heldLOverV, 4), cell(lvMargin(r), 4), c.heldWheel,
                          cell(c.heldLOverVInFlangeContact, 4), cell(climbMargin(r), 4), c.heldInFlangeContactWheel,
                          cell(c.flangeContactS, 3), cell(c.maxFlangeForceLb, 0), cell(c.maxLiftInContactIn, 4),
                          cell(c.maxWheelsetLateralIn, 4), cell(x.maxLOverV, 4), cell(x.minWheelLoadRatio, 4),
                          cell(x.maxRollDeg, 4)});
        }
    });
    return md;
}

}  // namespace

std::string makeWheelRailSection(const Settings& s, const std::vector<SweepResult>& sweeps, nlohmann::ordered_json& meta) {
    std::string md =
        "## 12. The wheel–rail contact: the report's lateral restraint against creep and flange\n\n"
        "Every other section holds each wheelset laterally as the report does (`wheel_rail.lateral = \"restraint\"`, a "
        "stiff two-way spring at rail-head height whose force the two wheels share by load). The creep and flange "
        "contact (`\"creep_and_flange\"`: Shen–Hedrick–Elkins saturating lateral creep per wheel, the flangeway "
        "clearance and a one-sided flange at the flange angle; docs/model.md, \"Wheel–rail contact\") is measured "
        "against it here, on the same cases, by changing that one setting.\n\n";
    // Part A and the grid of part C run together, one pool.
    const std::vector<Table3Row> table3 = loadTable3(Mit1976::get());
    std::vector<WheelRailRun> runs;
    for (const auto& row : table3) {
        if (s.quick && !(row.car == "70ton-loaded" && row.amplitudeIn == 0.75)) continue;
        for (const std::string& model : kLateralModels)
            for (LateralWheelRail l : kFormulations)
                runs.push_back(makeRun(row.car, model, l, row.amplitudeIn, row.speedMph));
    }
    const size_t table3Runs = runs.size();
    std::vector<ClimbGrid> grids;
    if (s.quick) {
        grids.push_back({"70ton-loaded", {0.75}, 14, 18, 2});
    } else {
        const std::vector<double> amplitudes{0.5, 0.75, 1.0, 1.25};
        grids.push_back({"70ton-loaded", amplitudes, 10, 22, 1});
        grids.push_back({"70ton-empty", amplitudes, 24, 40, 1});
        grids.push_back({"100ton-loaded", amplitudes, 8, 18, 1});
    }
    for (const auto& g : grids)
        for (double a : g.amplitudesIn)
            for (double v : g.getSpeeds()) runs.push_back(makeRun(g.car, model_names::kFullCar, LateralWheelRail::CreepAndFlange, a, v));
    const std::vector<WheelRailRun> done = runAll(s, runs);
    md += makeTable3Part(s, {done.begin(), done.begin() + long(table3Runs)}, meta);
    md += makeSweepPart(s, sweeps, meta);
    md += makeClimbPart(s, grids, {done.begin() + long(table3Runs), done.end()});
    meta["wheel_rail"]["files"].push_back({{"file", "wheel_rail_flange_climb.csv"}});
    return md;
}

}  // namespace rockroll::app
