#pragma once
// Center plate: the car body's plate sitting in the bolster's bowl.
//
// Vertical: the plate rim is represented by N points on a circle of radius a_c,
// each a unilateral contact (UnilateralContact.h). N = 2 puts them at ±a_c
// laterally (the planar half car: two rim contacts); N ≥ 4 (multiple of 4) spreads
// them round the rim so the plate can tip about any rim point in roll and pitch.
// Horizontal: a stiff center-pin spring at the bowl center carries lateral (and,
// in 3-D, longitudinal) force between plate and bowl, whether or not the plate
// is seated, so lateral force passes through the pin at bowl height.
// Yaw (3-D only): Coulomb friction torque T_c = μ·N·(2/3)·a_c (uniform pressure
// over the plate), as an elasto-plastic bristle in relative yaw.
#include "contacts/BristleFriction.h"
#include "contacts/DynamicsCache.h"
#include "contacts/UnilateralContact.h"

#include <vector>

namespace rockroll {

struct CenterPlateGeometry {
    SimTK::MobilizedBody carBody;
    SimTK::Vec3 p_CarBodyPlate;  ///< plate center on the car body [m]
    SimTK::MobilizedBody bolster;
    SimTK::Vec3 p_BolsterBowl;   ///< bowl center on the bolster, same height as the plate at rest [m]
    double radius = 0;           ///< a_c [m]
    int rimPoints = 2;           ///< 2 (planar) or a multiple of 4 (3-D)
};

struct CenterPlateLaw {
    UnilateralContactLaw rim;          ///< per rim point
    double pinStiffness = 0;           ///< horizontal center-pin stiffness [N/m]
    double pinDamping = 0;             ///< [N·s/m]
    bool longitudinalPin = false;      ///< also restrain x (3-D)
    double yawFrictionCoefficient = 0; ///< μ; 0 disables yaw friction
    double yawBristleStiffness = 0;    ///< [N·m/rad]
    double yawBristleDamping = 0;      ///< [N·m·s/rad]
};

struct CenterPlateForces {
    std::vector<double> rim;   ///< normal force per rim point [N]
    double vertical = 0;       ///< total [N]
    SimTK::Vec3 pin{0};        ///< pin force on the car body, ground axes [N]
    double yawTorque = 0;      ///< on the car body about ground z [N·m]
    bool yawSlipping = false;
};

class CenterPlateContact : public SimTK::Force::Custom::Implementation {
public:
    CenterPlateContact(const SimTK::GeneralForceSubsystem& forces, CenterPlateGeometry g,
                       CenterPlateLaw law);

    CenterPlateForces calcForces(const SimTK::State& s) const;

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
    /// Elastic energy: rim contacts, pin spring (lateral, and longitudinal in 3-D)
    /// and the yaw bristle.
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;
    /// Power dissipated (energy audit): rim contacts' Hunt–Crossley damping,
    /// pin damping c_pin·|ḋ|², yaw friction (calcBristleDissipation). State
    /// realized to Velocity.
    double calcDissipatedPower(const SimTK::State& s) const;
    void realizeTopology(SimTK::State& s) const override;
    void realizeAcceleration(const SimTK::State& s) const override;

    /// Everything one evaluation gives: computed once per realization in
    /// calcForce and kept in the State (DynamicsCache) for realizeAcceleration,
    /// the energy meter and the recorder.
    struct Evaluation {
        CenterPlateForces forces;
        double dissipatedPower = 0;    ///< [W]
        double yawDeflectionRate = 0;  ///< bristle ẇ [rad/s]
    };

private:
    /// Reads each body's kinematics once for all rim points and the pin.
    void evaluate(const SimTK::State& s, Evaluation& e) const;
    /// The cached evaluation at Dynamics stage and above, else a fresh one in `scratch`.
    const Evaluation& findOrEvaluate(const SimTK::State& s, Evaluation& scratch) const;
    bool hasYawFriction() const { return law_.yawFrictionCoefficient > 0; }
    BristleFrictionLaw makeYawLaw(double normalForce) const;

    const SimTK::GeneralForceSubsystem& forces_;
    CenterPlateGeometry geom_;
    CenterPlateLaw law_;
    std::vector<VerticalPointPair> pairs_;  // rim point on car body above bowl point
    mutable SimTK::ZIndex zYaw_;            // topology-stage index of the yaw bristle
    DynamicsCache<Evaluation> cache_;
};

}  // namespace rockroll
