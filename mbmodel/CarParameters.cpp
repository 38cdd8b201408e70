#include "mbmodel/CarParameters.h"

#include <array>
#include <fmt/format.h>
#include <stdexcept>

namespace rockroll {

using units::Dimension;

namespace {

const std::vector<CarParameterInfo> kTable = [] {
    using P = CarParameters;
    // The values and their sources are data: scenarios/cars/*.toml.
    auto e = [](const char* key, double P::*m, Dimension d, const char* unit, bool mayBeZero = false,
                bool integer = false) { return CarParameterInfo{key, m, d, unit, mayBeZero, integer, false}; };
    auto offset = [](const char* key, double P::*m) {
        return CarParameterInfo{key, m, Dimension::Length, "in", true, false, true};
    };
    return std::vector<CarParameterInfo>{
        e("body_and_bolsters_weight", &P::bodyAndBolstersWeight, Dimension::Force, "lb"),
        e("wheelset_weight", &P::wheelsetWeight, Dimension::Force, "lb"),
        e("roll_inertia", &P::rollInertia, Dimension::MomentOfInertia, "lb*in*s^2"),
        e("pitch_inertia", &P::pitchInertia, Dimension::MomentOfInertia, "lb*in*s^2"),
        e("yaw_inertia", &P::yawInertia, Dimension::MomentOfInertia, "lb*in*s^2"),
        e("spring_vertical_rate", &P::springVerticalRate, Dimension::Stiffness, "lb/in"),
        e("spring_lateral_rate", &P::springLateralRate, Dimension::Stiffness, "lb/in"),
        e("gib_rate", &P::gibRate, Dimension::Stiffness, "lb/in"),
        e("bottoming_rate", &P::bottomingRate, Dimension::Stiffness, "lb/in"),
        e("vertical_friction", &P::verticalFriction, Dimension::Force, "lb"),
        e("lateral_friction", &P::lateralFriction, Dimension::Force, "lb"),
        e("center_plate_diameter", &P::centerPlateDiameter, Dimension::Length, "in"),
        e("cg_above_center_plate", &P::cgAboveCenterPlate, Dimension::Length, "in"),
        e("center_plate_above_springs", &P::centerPlateAboveSprings, Dimension::Length, "in"),
        e("side_bearing_offset", &P::sideBearingOffset, Dimension::Length, "in"),
        e("side_bearing_above_springs", &P::sideBearingAboveSprings, Dimension::Length, "in"),
        e("spring_top_above_rail", &P::springTopAboveRail, Dimension::Length, "in"),
        e("spring_offset", &P::springOffset, Dimension::Length, "in"),
        e("gib_clearance", &P::gibClearance, Dimension::Length, "in"),
        e("spring_travel", &P::springTravel, Dimension::Length, "in"),
        e("wheelbase", &P::wheelbase, Dimension::Length, "in"),
        e("truck_spacing", &P::truckSpacing, Dimension::Length, "ft"),
        e("gauge", &P::gauge, Dimension::Length, "in"),
        e("bolster_weight", &P::bolsterWeight, Dimension::Force, "lb"),
        e("bolster_roll_inertia", &P::bolsterRollInertia, Dimension::MomentOfInertia, "lb*in*s^2"),
        e("side_frame_weight", &P::sideFrameWeight, Dimension::Force, "lb"),
        e("wheelset_roll_inertia", &P::wheelsetRollInertia, Dimension::MomentOfInertia, "lb*in*s^2"),
        e("wheel_radius", &P::wheelRadius, Dimension::Length, "in"),
        e("side_bearing_clearance", &P::sideBearingClearance, Dimension::Length, "in", true),
        e("wheel_rail_stiffness", &P::wheelRailStiffness, Dimension::Stiffness, "lb/in"),
        e("center_plate_stiffness", &P::centerPlateStiffness, Dimension::Stiffness, "lb/in"),
        e("side_bearing_stiffness", &P::sideBearingStiffness, Dimension::Stiffness, "lb/in"),
        e("contact_stiffness_scale", &P::contactStiffnessScale, Dimension::Dimensionless, ""),
        e("contact_dissipation", &P::contactDissipation, Dimension::InverseSpeed, "s/m", true),
        e("center_pin_stiffness", &P::centerPinStiffness, Dimension::Stiffness, "lb/in"),
        e("wheel_rail_lateral_stiffness", &P::wheelRailLateralStiffness, Dimension::Stiffness, "lb/in"),
        e("lateral_contact_damping_ratio", &P::lateralContactDampingRatio, Dimension::Dimensionless, "", true),
        e("friction_bristle_deflection", &P::frictionBristleDeflection, Dimension::Length, "in"),
        e("friction_bristle_damping_ratio", &P::frictionBristleDampingRatio, Dimension::Dimensionless, "", true),
        e("center_plate_friction", &P::centerPlateFriction, Dimension::Dimensionless, "", true),
        e("center_plate_yaw_bristle_angle", &P::centerPlateYawBristleAngle, Dimension::Angle, "deg"),
        e("center_plate_rim_points", &P::centerPlateRimPoints, Dimension::Dimensionless, "", false, true),
        e("car_body_torsional_stiffness", &P::carBodyTorsionalStiffness, Dimension::AngularStiffness, "lb*in/rad"),
        e("car_body_torsional_damping_ratio", &P::carBodyTorsionalDampingRatio, Dimension::Dimensionless, "", true),
        offset("cg_longitudinal_offset", &P::cgLongitudinalOffset),
        offset("cg_lateral_offset", &P::cgLateralOffset),
    };
}();

}  // namespace

const std::vector<CarParameterInfo>& getCarParameterTable() { return kTable; }

const CarParameterInfo* findCarParameter(std::string_view key) {
    for (const auto& info : kTable)
        if (key == info.key) return &info;
    return nullptr;
}

}  // namespace rockroll
