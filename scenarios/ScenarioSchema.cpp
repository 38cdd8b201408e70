#include "scenarios/ScenarioSchema.h"

#include "mbmodel/RunSettings.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioLoader.h"

#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rockroll {

std::string ScenarioField::getTable() const {
    const std::string_view k(key);
    const size_t dot = k.rfind('.');
    return dot == std::string_view::npos ? std::string() : std::string(k.substr(0, dot));
}

std::string ScenarioField::getName() const {
    const std::string_view k(key);
    const size_t dot = k.rfind('.');
    return std::string(dot == std::string_view::npos ? k : k.substr(dot + 1));
}

namespace {
using units::Dimension;

// A number member of the Scenario, read and written in SI.
#define RR_NUMBER(expr)                                              \
    .getNumber = [](const Scenario& s) { return double(s.expr); }, \
    .setNumber = [](Scenario& s, double v) { s.expr = decltype(s.expr)(v); }
#define RR_FLAG(expr)                                         \
    .getFlag = [](const Scenario& s) { return bool(s.expr); }, \
    .setFlag = [](Scenario& s, bool v) { s.expr = v; }

ScenarioField quantity(const char* key, Dimension dim, const char* unit, double low, double high, bool lowOpen,
                       bool highOpen, const char* defaultText, ScenarioField access) {
    access.key = key;
    access.kind = FieldKind::Quantity;
    access.dimension = dim;
    access.unit = unit;
    access.low = low, access.high = high, access.lowOpen = lowOpen, access.highOpen = highOpen;
    access.defaultText = defaultText;
    return access;
}
ScenarioField flag(const char* key, const char* defaultText, ScenarioField access) {
    access.key = key;
    access.kind = FieldKind::Flag;
    access.defaultText = defaultText;
    return access;
}
ScenarioField structured(const char* key, const char* defaultText) {
    ScenarioField f{};
    f.key = key;
    f.kind = FieldKind::Structured;
    f.defaultText = defaultText;
    return f;
}

/// The schema. The cross-level amplitude limit, 3 in, is four times the largest
/// amplitude the 1976 report studies (0.75 in; 1 in in Table 3). Duration, output rate
/// and accuracy are bounded so that no run waits forever.
std::vector<ScenarioField> makeSchema() {
    constexpr double in = units::inch;
    std::vector<ScenarioField> f;
    f.push_back(structured("description", "none"));
    f.push_back(structured("car.base", "70ton-loaded"));
    f.push_back(structured("car.file", "none"));
    f.push_back(structured("car.name", "the car's own name"));
    // [track]. A measured track (file or rows) makes the amplitude's default 0 in.
    f.push_back(quantity("track.amplitude", Dimension::Length, "in", 0, 3 * in, false, false, "0.75 in",
                         {RR_NUMBER(track.amplitude)}));
    f.push_back(quantity("track.rail_length", Dimension::Length, "m", 1, 100, false, false, "39 ft",
                         {RR_NUMBER(track.railLength)}));
    {
        ScenarioField rails = quantity("track.rails", Dimension::Dimensionless, "", 0, 1e5, false, false, "0",
                                       {RR_NUMBER(track.rails)});
        rails.kind = FieldKind::Integer;
        f.push_back(rails);
    }
    f.push_back(flag("track.mirror", "false", {RR_FLAG(track.mirror)}));
    {
        ScenarioField entry{};
        entry.key = "track.entry";
        entry.kind = FieldKind::Choice;
        entry.defaultText = "lead";
        entry.getText = [](const Scenario& s) {
            return std::string(s.entry == TrackEntry::Lead ? "lead" : "synchronized");
        };
        entry.setText = [](Scenario& s, const std::string& v) {
            s.entry = v == "lead" ? TrackEntry::Lead : TrackEntry::Synchronized;
        };
        entry.getChoices = [] { return std::vector<std::string>{"lead", "synchronized"}; };
        f.push_back(entry);
    }
    f.push_back(structured("track.file", "none"));
    f.push_back(structured("track.taper", kDefaultTaperText));
    f.push_back(structured("track.repeat", "false"));
    // [run]
    f.push_back(quantity("run.speed", Dimension::Speed, "mph", 0.1 * units::mph, 150 * units::mph, false, false,
                         "16.5 mph", {RR_NUMBER(speed)}));
    f.push_back(quantity("run.duration", Dimension::Time, "s", 0.05, 3600, false, false, "20 s",
                         {RR_NUMBER(run.duration)}));
    {
        ScenarioField model{};
        model.key = "run.model";
        model.kind = FieldKind::Choice;
        model.defaultText = "fullcar";
        model.getText = [](const Scenario& s) { return s.model; };
        model.setText = [](Scenario& s, const std::string& v) { s.model = v; };
        model.getChoices = [] { return ModelRegistry::get().getNames(); };
        f.push_back(model);
    }
    f.push_back(quantity("run.output_rate", Dimension::Frequency, "Hz", 1, 1e5, false, false, "500 Hz",
                         {RR_NUMBER(run.outputRate)}));
    f.push_back(quantity("run.filter_cutoff", Dimension::Frequency, "Hz", 0, 5e4, true, true, "20 Hz",
                         {RR_NUMBER(filterCutoffHz)}));
    // [integrator]
    {
        ScenarioField method{};
        method.key = "integrator.method";
        method.kind = FieldKind::Choice;
        method.defaultText = "cpodes";
        method.getText = [](const Scenario& s) { return s.run.integrator.method; };
        method.setText = [](Scenario& s, const std::string& v) { s.run.integrator.method = v; };
        method.getChoices = [] { return getIntegratorNames(); };
        f.push_back(method);
    }
    f.push_back(quantity("integrator.accuracy", Dimension::Dimensionless, "", 1e-10, 1e-1, false, false, "1e-4",
                         {RR_NUMBER(run.integrator.accuracy)}));
    f.push_back(quantity("integrator.max_step", Dimension::Time, "s", 0, 1, false, false, "0 s",
                         {RR_NUMBER(run.integrator.maxStepSize)}));
    // [eom]: the report's §4.1 simplifications, each on its own.
    f.push_back(flag("eom.linear_springs", "false", {RR_FLAG(eom.linearSprings)}));
    f.push_back(flag("eom.lock_bolster_lateral", "false", {RR_FLAG(eom.lockBolsterLateral)}));
    f.push_back(flag("eom.elastic_contacts", "false", {RR_FLAG(eom.elasticContacts)}));
    f.push_back(flag("eom.equal_lateral_shares", "false", {RR_FLAG(eom.equalLateralShares)}));
    f.push_back(flag("eom.small_angles", "false", {RR_FLAG(eom.smallAngles)}));
    // [limits]: the run monitor's physical limits (mbmodel/RunLimits.h) and the severe-regime duration.
    f.push_back(flag("limits.enabled", "true", {RR_FLAG(run.limits.enabled)}));
    f.push_back(quantity("limits.flange_climb_time", Dimension::Time, "s", 0, 10, true, false, "0.05 s",
                         {RR_NUMBER(run.limits.flangeClimbTime)}));
    {
        // 0: the flanges' free-flight time; 0: the car's static rollover angle.
        ScenarioField off = quantity("limits.wheels_off_time", Dimension::Time, "s", 0, 10, true, false, "0 s",
                                     {RR_NUMBER(run.limits.wheelsOffTime)});
        off.zeroIsDerived = true;
        f.push_back(off);
        ScenarioField roll = quantity("limits.rollover_angle", Dimension::Angle, "deg", 0, 90 * units::degree, true,
                                      false, "0 deg", {RR_NUMBER(run.limits.rolloverAngle)});
        roll.zeroIsDerived = true;
        f.push_back(roll);
    }
    f.push_back(quantity("limits.energy_runaway_fraction", Dimension::Dimensionless, "", 0, 100, true, false, "0.5",
                         {RR_NUMBER(run.limits.energyRunawayFraction)}));
    f.push_back(quantity("limits.max_wall_time", Dimension::Time, "s", 0, 7 * 86400, true, false, "3600 s",
                         {RR_NUMBER(run.limits.maxWallTime)}));
    f.push_back(quantity("limits.severe_separation", Dimension::Time, "s", 0, 1, false, false, "0.01 s",
                         {RR_NUMBER(severeSeparationTime)}));
    // [wheel_rail]: the lateral wheel–rail formulation and its data (contacts/WheelRailLaws.h;
    // defaults and sources: docs/model.md, "Wheel–rail contact").
    {
        ScenarioField lateral{};
        lateral.key = "wheel_rail.lateral";
        lateral.kind = FieldKind::Choice;
        lateral.defaultText = "restraint";
        lateral.getText = [](const Scenario& s) { return std::string(getLateralWheelRailName(s.wheelRail.lateral)); };
        lateral.setText = [](Scenario& s, const std::string& v) { s.wheelRail.lateral = *findLateralWheelRail(v); };
        lateral.getChoices = [] {
            return std::vector<std::string>{getLateralWheelRailName(LateralWheelRail::Restraint),
                                            getLateralWheelRailName(LateralWheelRail::CreepAndFlange)};
        };
        f.push_back(lateral);
    }
    f.push_back(quantity("wheel_rail.friction", Dimension::Dimensionless, "", 0, 1, true, false, "0.5",
                         {RR_NUMBER(wheelRail.friction)}));
    f.push_back(quantity("wheel_rail.creep_coefficient", Dimension::Force, "N", 1e4, 1e9, false, false, "1e7 N",
                         {RR_NUMBER(wheelRail.creepCoefficient)}));
    f.push_back(quantity("wheel_rail.flange_angle", Dimension::Angle, "deg", 45 * units::degree, 89 * units::degree,
                         false, false, "75 deg", {RR_NUMBER(wheelRail.flangeAngle)}));
    f.push_back(quantity("wheel_rail.flangeway_clearance", Dimension::Length, "in", 0, 3 * in, false, false,
                         "0.375 in", {RR_NUMBER(wheelRail.flangewayClearance)}));
    f.push_back(quantity("wheel_rail.flange_height", Dimension::Length, "in", 0, 3 * in, true, false, "1 in",
                         {RR_NUMBER(wheelRail.flangeHeight)}));
    f.push_back(quantity("wheel_rail.flange_stiffness_scale", Dimension::Dimensionless, "", 0.01, 100, false, false,
                         "1", {RR_NUMBER(wheelRail.flangeStiffnessScale)}));
    // [car_body]: the full car's car body (docs/model.md, "Car-body torsion").
    f.push_back(flag("car_body.torsion", "false", {RR_FLAG(carBody.torsion)}));
    // [reduced], [attribution]
    f.push_back(flag("reduced.truck_weight", "false", {RR_FLAG(reduced.truckWeight)}));
    f.push_back(flag("attribution.unsprung_gravity", "true", {RR_FLAG(attribution.unsprungGravity)}));
    f.push_back(quantity("attribution.unsprung_mass_scale", Dimension::Dimensionless, "", 0.001, 1, false, false, "1",
                         {RR_NUMBER(attribution.unsprungMassScale)}));
    // [criteria]: limits of the summary's freight criteria (mbmodel/RunSummary.h, CriteriaLimits).
    {
        // Kept in degrees, rounded so the echo has no conversion round-off.
        ScenarioField roll{};
        roll.getNumber = [](const Scenario& s) { return s.criteria.rollPeakToPeakDeg * units::degree; };
        roll.setNumber = [](Scenario& s, double v) {
            s.criteria.rollPeakToPeakDeg = std::round(v / units::degree * 1e9) / 1e9;
        };
        roll.formatValue = [](const Scenario& s) { return fmt::format("{} deg", s.criteria.rollPeakToPeakDeg); };
        f.push_back(quantity("criteria.roll_peak_to_peak", Dimension::Angle, "deg", 0, 90 * units::degree, true, false,
                             "6 deg", roll));
    }
    f.push_back(quantity("criteria.wheel_unloading", Dimension::Dimensionless, "", 0, 1, true, false, "0.9",
                         {RR_NUMBER(criteria.wheelUnloading)}));
    {
        // 0: Nadal's limit of [wheel_rail] flange_angle and friction.
        ScenarioField lv = quantity("criteria.l_over_v", Dimension::Dimensionless, "", 0, 10, true, false, "0",
                                    {RR_NUMBER(criteria.lOverV)});
        lv.zeroIsDerived = true;
        f.push_back(lv);
    }
    f.push_back(quantity("criteria.truck_side_l_over_v", Dimension::Dimensionless, "", 0, 10, true, false, "0.5",
                         {RR_NUMBER(criteria.truckSideLOverV)}));
    f.push_back(quantity("criteria.car_body_vertical_accel_g", Dimension::Dimensionless, "", 0, 10, true, false, "0.9",
                         {RR_NUMBER(criteria.carBodyVerticalAccelG)}));
    f.push_back(quantity("criteria.car_body_lateral_accel_g", Dimension::Dimensionless, "", 0, 10, true, false, "0.75",
                         {RR_NUMBER(criteria.carBodyLateralAccelG)}));
    return f;
}
#undef RR_NUMBER
#undef RR_FLAG
}  // namespace

const std::vector<ScenarioField>& getScenarioSchema() {
    static const std::vector<ScenarioField> schema = makeSchema();
    return schema;
}

const char* findRenamedKey(std::string_view oldKey) {
    static const std::pair<const char*, const char*> renamed[] = {
        {"attribution.truck_gravity", "attribution.unsprung_gravity"},
        {"attribution.truck_mass_scale", "attribution.unsprung_mass_scale"},
        {"limits.flange_height", "wheel_rail.flange_height"},
        {"limits.flange_clearance", "wheel_rail.flangeway_clearance"}};
    for (const auto& [from, to] : renamed)
        if (oldKey == from) return to;
    return nullptr;
}

const ScenarioField* findScenarioField(std::string_view key) {
    for (const ScenarioField& f : getScenarioSchema())
        if (key == f.key) return &f;
    return nullptr;
}

}  // namespace rockroll
