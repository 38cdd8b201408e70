#pragma once
// Full-car 3-D model: the car body with vertical, lateral, roll, pitch and yaw
// motion (and a longitudinal coordinate held by the center pins); two trucks,
// each with a bolster and two wheelsets moving laterally, vertically and in
// roll; side frames lumped into the wheelsets they rest on.
#include "mbmodel/RockingModel.h"

namespace rockroll {

/// The full car's twisting car body (car_body.torsion), after the AAR model the report
/// compares with (its Table 4: "flexible car body effects"): two rigid halves joined on the
/// car's longitudinal axis through its CG by a torsional spring K and damper C.
///
/// The split rule (docs/model.md, "Car-body torsion"): the body as a uniform beam of the
/// length that gives its pitch inertia, ℓ = √(12·I_pitch/m). Each half has m/2, its CG at
/// ±ℓ/4, roll inertia I_roll/2, pitch inertia I_pitch/8 (a uniform beam of ℓ/2) and yaw
/// inertia (I_yaw − m·(ℓ/4)²)/2, so the halves together have the car body's mass, CG and
/// inertias. The twist θ (rear half against front, about x) is resisted by
///
///     M = K·θ + C·θ̇,   C = 2ζ·√(K·I_rel),   I_rel = I_roll/4,
///
/// with I_rel the relative roll inertia of the two halves; the free twist frequency is
/// √(K/I_rel)/2π. Energy: ½Kθ² stored (Simbody's potential energy), C·θ̇² dissipated
/// (the energy audit, RockingModel::calcPowers).
struct TwistingCarBody {
    double length = 0;                 ///< ℓ [m]
    double halfMass = 0;               ///< [kg]
    double halfOffset = 0;             ///< ℓ/4, each half's CG from the car's [m]
    double halfRollInertia = 0, halfPitchInertia = 0, halfYawInertia = 0;  ///< about the half's CG [kg·m²]
    double relativeRollInertia = 0;    ///< I_rel [kg·m²]
    double damping = 0;                ///< C [N·m·s/rad]
};
/// The split of `car`'s body; std::invalid_argument when the yaw inertia leaves a half no
/// physical inertia.
TwistingCarBody calcTwistingCarBody(const CarParameters& car);

class FullCarModel : public RockingModel {
public:
    FullCarModel(const CarParameters& car, const TrackInput& track, ModelOptions options);

protected:
    void setCarBodyPose(SimTK::State& s, const std::vector<double>& plateZ) const override;

private:
    double frontHalfOffset_ = 0;  ///< the front half's CG ahead of the car's (twisting body) [m]
    SimTK::Vec3 cgOffset_{0};     ///< the car body's CG from mid-way between the truck centres [m]
};

}  // namespace rockroll
