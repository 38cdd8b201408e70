#include "mbmodel/CarParameters.h"

#include <array>
#include <fmt/format.h>
#include <stdexcept>

namespace rockroll {

using units::Dimension;
namespace u = units;

namespace {

const std::vector<CarParameterInfo> kTable = [] {
    using P = CarParameters;
    auto e = [](const char* key, double P::*m, Dimension d, const char* unit, const char* src,
                bool mayBeZero = false) { return CarParameterInfo{key, m, d, unit, src, mayBeZero}; };
    const char* t2 = "report Table 2";
    const char* b4 = "brief §4";
    const char* as = "assumed (docs/model.md)";
    return std::vector<CarParameterInfo>{
        e("body_and_bolsters_weight", &P::bodyAndBolstersWeight, Dimension::Force, "lb", t2),
        e("wheelset_weight", &P::wheelsetWeight, Dimension::Force, "lb", t2),
        e("roll_inertia", &P::rollInertia, Dimension::MomentOfInertia, "lb*in*s^2", t2),
        e("pitch_inertia", &P::pitchInertia, Dimension::MomentOfInertia, "lb*in*s^2", t2),
        e("yaw_inertia", &P::yawInertia, Dimension::MomentOfInertia, "lb*in*s^2", t2),
        e("spring_vertical_rate", &P::springVerticalRate, Dimension::Stiffness, "lb/in", t2),
        e("spring_lateral_rate", &P::springLateralRate, Dimension::Stiffness, "lb/in", t2),
        e("gib_rate", &P::gibRate, Dimension::Stiffness, "lb/in", t2),
        e("bottoming_rate", &P::bottomingRate, Dimension::Stiffness, "lb/in", t2),
        e("vertical_friction", &P::verticalFriction, Dimension::Force, "lb", t2),
        e("lateral_friction", &P::lateralFriction, Dimension::Force, "lb", t2),
        e("center_plate_diameter", &P::centerPlateDiameter, Dimension::Length, "in", t2),
        e("cg_above_center_plate", &P::cgAboveCenterPlate, Dimension::Length, "in", t2),
        e("center_plate_above_springs", &P::centerPlateAboveSprings, Dimension::Length, "in", t2),
        e("side_bearing_offset", &P::sideBearingOffset, Dimension::Length, "in", t2),
        e("side_bearing_above_springs", &P::sideBearingAboveSprings, Dimension::Length, "in", t2),
        e("spring_top_above_rail", &P::springTopAboveRail, Dimension::Length, "in", t2),
        e("spring_offset", &P::springOffset, Dimension::Length, "in", t2),
        e("gib_clearance", &P::gibClearance, Dimension::Length, "in", t2),
        e("spring_travel", &P::springTravel, Dimension::Length, "in", t2),
        e("wheelbase", &P::wheelbase, Dimension::Length, "in", t2),
        e("truck_spacing", &P::truckSpacing, Dimension::Length, "ft", t2),
        e("gauge", &P::gauge, Dimension::Length, "in", t2),
        e("bolster_weight", &P::bolsterWeight, Dimension::Force, "lb", b4),
        e("bolster_roll_inertia", &P::bolsterRollInertia, Dimension::MomentOfInertia, "lb*in*s^2", b4),
        e("side_frame_weight", &P::sideFrameWeight, Dimension::Force, "lb", b4),
        e("wheelset_roll_inertia", &P::wheelsetRollInertia, Dimension::MomentOfInertia, "lb*in*s^2", as),
        e("wheel_radius", &P::wheelRadius, Dimension::Length, "in", b4),
        e("side_bearing_clearance", &P::sideBearingClearance, Dimension::Length, "in", b4, true),
        e("wheel_rail_stiffness", &P::wheelRailStiffness, Dimension::Stiffness, "lb/in", as),
        e("center_plate_stiffness", &P::centerPlateStiffness, Dimension::Stiffness, "lb/in", as),
        e("side_bearing_stiffness", &P::sideBearingStiffness, Dimension::Stiffness, "lb/in", as),
        e("contact_stiffness_scale", &P::contactStiffnessScale, Dimension::Dimensionless, "", as),
        e("contact_dissipation", &P::contactDissipation, Dimension::Dimensionless, "s/m", as, true),
        e("center_pin_stiffness", &P::centerPinStiffness, Dimension::Stiffness, "lb/in", as),
        e("wheel_rail_lateral_stiffness", &P::wheelRailLateralStiffness, Dimension::Stiffness, "lb/in", as),
        e("lateral_contact_damping_ratio", &P::lateralContactDampingRatio, Dimension::Dimensionless, "", as, true),
        e("friction_bristle_deflection", &P::frictionBristleDeflection, Dimension::Length, "in", as),
        e("friction_bristle_damping_ratio", &P::frictionBristleDampingRatio, Dimension::Dimensionless, "", as, true),
        e("center_plate_friction", &P::centerPlateFriction, Dimension::Dimensionless, "", as, true),
        e("center_plate_yaw_bristle_angle", &P::centerPlateYawBristleAngle, Dimension::Angle, "deg", as),
        e("center_plate_rim_points", &P::centerPlateRimPoints, Dimension::Dimensionless, "", as),
    };
}();

void setAssumedDefaults(CarParameters& p) {
    p.sideBearingClearance = 0.25 * u::inch;
    p.wheelRailStiffness = 5e6 * u::lbfPerInch;
    p.centerPlateStiffness = 2e7 * u::lbfPerInch;
    p.sideBearingStiffness = 1e7 * u::lbfPerInch;
    p.contactStiffnessScale = 1;
    p.contactDissipation = 5;
    p.centerPinStiffness = 2e6 * u::lbfPerInch;
    p.wheelRailLateralStiffness = 2e6 * u::lbfPerInch;
    p.lateralContactDampingRatio = 0.2;
    p.frictionBristleDeflection = 0.01 * u::inch;
    p.frictionBristleDampingRatio = 0.3;
    p.centerPlateFriction = 0.25;
    p.centerPlateYawBristleAngle = 0.01 * u::degree;
    p.centerPlateRimPoints = 16;
}

CarParameters make70Ton(bool loaded) {
    CarParameters p;
    p.name = loaded ? "70ton-loaded" : "70ton-empty";
    p.bodyAndBolstersWeight = (loaded ? 172650 : 66000) * u::lbf;
    p.wheelsetWeight = 6380 * u::lbf;
    p.rollInertia = (loaded ? 1288800 : 346000) * u::lbInS2;
    // Empty car pitch/yaw: 70 t loaded values scaled by weight (brief §3).
    const double scale = loaded ? 1.0 : 66000.0 / 172650.0;
    p.pitchInertia = 16650000 * scale * u::lbInS2;
    p.yawInertia = 16416000 * scale * u::lbInS2;
    p.springVerticalRate = 20840 * u::lbfPerInch;
    p.springLateralRate = 8850 * u::lbfPerInch;
    p.gibRate = 660000 * u::lbfPerInch;
    p.bottomingRate = 660000 * u::lbfPerInch;
    p.verticalFriction = 4000 * u::lbf;
    p.lateralFriction = 4000 * u::lbf;
    p.centerPlateDiameter = 14.0 * u::inch;
    p.cgAboveCenterPlate = (loaded ? 72.5 : 35.0) * u::inch;
    p.centerPlateAboveSprings = 7.875 * u::inch;
    p.sideBearingOffset = 25.0 * u::inch;
    p.sideBearingAboveSprings = 12.1875 * u::inch;
    p.springTopAboveRail = 20.125 * u::inch;
    p.springOffset = 39.0 * u::inch;
    p.gibClearance = 0.375 * u::inch;
    p.springTravel = 3.6875 * u::inch;
    p.wheelbase = 68.0 * u::inch;
    p.truckSpacing = 39.0 * u::foot;
    p.gauge = 56.5 * u::inch;
    p.bolsterWeight = 1160 * u::lbf;
    p.bolsterRollInertia = 4190 * u::lbInS2;
    p.sideFrameWeight = 1000 * u::lbf;
    // K_v·l²/(2π·12.5 Hz)², Table 1's uncoupled wheelset roll frequency.
    p.wheelsetRollInertia = 20550 * u::lbInS2;
    p.wheelRadius = 16.5 * u::inch;
    setAssumedDefaults(p);
    return p;
}

CarParameters make100Ton() {
    CarParameters p = make70Ton(true);
    p.name = "100ton-loaded";
    p.bodyAndBolstersWeight = 243730 * u::lbf;
    p.wheelsetWeight = 8280 * u::lbf;
    p.rollInertia = 1824000 * u::lbInS2;
    p.pitchInertia = 16800000 * u::lbInS2;
    p.yawInertia = 16567000 * u::lbInS2;
    p.springVerticalRate = 22110 * u::lbfPerInch;
    p.springLateralRate = 10200 * u::lbfPerInch;
    p.gibRate = 55000 * u::lbfPerInch;
    p.bottomingRate = 197100 * u::lbfPerInch;
    p.cgAboveCenterPlate = 81.6 * u::inch;
    p.centerPlateAboveSprings = 10.0 * u::inch;
    p.sideBearingAboveSprings = 10.0 * u::inch;
    p.springTopAboveRail = 24.5 * u::inch;
    p.springOffset = 39.52 * u::inch;
    p.truckSpacing = 39.5 * u::foot;
    p.gauge = 56.4 * u::inch;
    p.bolsterWeight = 1360 * u::lbf;
    p.bolsterRollInertia = 5600 * u::lbInS2;
    p.sideFrameWeight = 1300 * u::lbf;
    // K_v·l²/(2π·11.7 Hz)², Table 1's uncoupled wheelset roll frequency.
    p.wheelsetRollInertia = 25560 * u::lbInS2;
    p.wheelRadius = 18.0 * u::inch;
    return p;
}
}  // namespace

const std::vector<CarParameterInfo>& getCarParameterTable() { return kTable; }

const CarParameterInfo* findCarParameter(std::string_view key) {
    for (const auto& info : kTable)
        if (key == info.key) return &info;
    return nullptr;
}

std::vector<std::string> getCarNames() { return {"70ton-loaded", "70ton-empty", "100ton-loaded"}; }

CarParameters makeCarParameters(std::string_view carName) {
    if (carName == "70ton-loaded") return make70Ton(true);
    if (carName == "70ton-empty") return make70Ton(false);
    if (carName == "100ton-loaded") return make100Ton();
    throw std::invalid_argument(fmt::format("unknown car \"{}\"; expected one of: 70ton-loaded, "
                                            "70ton-empty, 100ton-loaded",
                                            carName));
}

}  // namespace rockroll
