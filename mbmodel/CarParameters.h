#pragma once
// Parameters of one freight car, SI, and the table of their keys, dimensions and
// display units (getCarParameterTable()). The values of each car, with their
// sources (report Table 2, derived from its Table 1, or assumed; docs/model.md §5),
// are data: scenarios/cars/*.toml.
#include "mbmodel/Units.h"

#include <string_view>
#include <string>
#include <vector>

namespace rockroll {

struct CarParameters {
    std::string name;
    // --- report Table 2 ---------------------------------------------------------
    double bodyAndBolstersWeight = 0;   ///< car body + 2 bolsters [N]
    double wheelsetWeight = 0;          ///< each wheelset [N]
    double rollInertia = 0;             ///< whole car body about its CG [kg·m²]
    double pitchInertia = 0;            ///< [kg·m²]
    double yawInertia = 0;              ///< [kg·m²]
    double springVerticalRate = 0;      ///< one spring group [N/m]
    double springLateralRate = 0;       ///< one spring group [N/m]
    double gibRate = 0;                 ///< one bolster end [N/m]
    double bottomingRate = 0;           ///< one spring group [N/m]
    double verticalFriction = 0;        ///< Coulomb force, one bolster end [N]
    double lateralFriction = 0;         ///< Coulomb force, one bolster end [N]
    double centerPlateDiameter = 0;     ///< [m]
    double cgAboveCenterPlate = 0;      ///< [m]
    double centerPlateAboveSprings = 0; ///< [m]
    double sideBearingOffset = 0;       ///< from center line [m]
    double sideBearingAboveSprings = 0; ///< [m]
    double springTopAboveRail = 0;      ///< uncompressed [m]
    double springOffset = 0;            ///< spring group from center line [m]
    double gibClearance = 0;            ///< half the total [m]
    double springTravel = 0;            ///< free height to bottomed [m]
    double wheelbase = 0;               ///< [m]
    double truckSpacing = 0;            ///< truck centers [m]
    double gauge = 0;                   ///< [m]
    // --- not in the report: derived from its Table 1 or assumed (docs/model.md §5) ---
    double bolsterWeight = 0;           ///< [N]
    double bolsterRollInertia = 0;      ///< [kg·m²]
    double sideFrameWeight = 0;         ///< each [N], lumped with the wheelsets
    double wheelsetRollInertia = 0;     ///< each wheelset with its side-frame share [kg·m²]
    double wheelRadius = 0;             ///< [m]
    double sideBearingClearance = 0;    ///< per side [m]
    // --- contact and friction modelling (assumed; docs/model.md) -----------------
    double wheelRailStiffness = 0;          ///< vertical, per wheel [N/m]
    double centerPlateStiffness = 0;        ///< vertical, whole plate [N/m]
    double sideBearingStiffness = 0;        ///< [N/m]
    double contactStiffnessScale = 1;       ///< multiplies the three above and the gib rate's contact part
    double contactDissipation = 0;          ///< Hunt–Crossley d [s/m]
    double centerPinStiffness = 0;          ///< horizontal [N/m]
    double wheelRailLateralStiffness = 0;   ///< per wheelset [N/m]
    double lateralContactDampingRatio = 0;  ///< pin and wheel–rail lateral, ζ
    double frictionBristleDeflection = 0;   ///< wedge deflection at the Coulomb limit [m]
    double frictionBristleDampingRatio = 0; ///< ζ against a bolster end mass
    double centerPlateFriction = 0;         ///< μ for yaw friction (full car)
    double centerPlateYawBristleAngle = 0;  ///< yaw at the friction limit [rad]
    double centerPlateRimPoints = 0;        ///< rim contact points in the full car
    // --- the full car's flexible car body (car_body.torsion; docs/model.md, "Car-body torsion") ---
    double carBodyTorsionalStiffness = 0;   ///< between the two halves, about the longitudinal axis [N·m/rad]
    double carBodyTorsionalDampingRatio = 0;///< ζ of the two halves' relative twist, against I_roll/4
    // --- off-centre lading (full car; docs/model.md, "Off-centre lading") ----------
    double cgLongitudinalOffset = 0;        ///< car body's CG ahead of mid-way between the truck centres [m]
    double cgLateralOffset = 0;             ///< car body's CG to the left of the car's centre line [m]

    double getCarBodyWeight() const { return bodyAndBolstersWeight - 2 * bolsterWeight; }
    /// A friction wedge's bristle stiffness [N/m]: its friction force at the Coulomb limit
    /// over the deflection it takes to get there (contacts/BristleFriction.h).
    double calcVerticalBristleStiffness() const { return verticalFriction / frictionBristleDeflection; }
    double calcLateralBristleStiffness() const { return lateralFriction / frictionBristleDeflection; }
};

/// One overridable parameter.
struct CarParameterInfo {
    const char* key;           ///< scenario key, snake_case
    double CarParameters::*member;
    units::Dimension dimension;
    const char* displayUnit;   ///< unit used in docs and printouts
    bool mayBeZero = false;    ///< zero is meaningful (no clearance, no damping, no friction)
    bool integer = false;      ///< a count: whole numbers only (center_plate_rim_points)
    bool isSigned = false;     ///< any finite value, negative included (an offset)
};

const std::vector<CarParameterInfo>& getCarParameterTable();
const CarParameterInfo* findCarParameter(std::string_view key);

// The cars themselves are data: scenarios/cars/*.toml, read by scenarios/ScenarioLoader.h
// (makeCarParameters, loadCarFile).

}  // namespace rockroll
