#pragma once
// Friction wedge at one bolster end: Coulomb friction of constant magnitude,
// vertical and lateral, between bolster and side frame (report eqs 8–10).
// Each direction is an elasto-plastic bristle (BristleFriction.h) whose
// deflection is a continuous state of the force subsystem, so the wedge sticks.
#include "contacts/BristleFriction.h"
#include "contacts/DynamicsCache.h"
#include "contacts/SuspensionLink.h"

namespace rockroll {

class FrictionWedge : public SimTK::Force::Custom::Implementation {
public:
    enum Direction { Vertical = 0, Lateral = 1 };

    FrictionWedge(const SimTK::GeneralForceSubsystem& forces, SuspensionLink link,
                  BristleFrictionLaw vertical, BristleFrictionLaw lateral)
        : forces_(forces), link_(std::move(link)), law_{vertical, lateral} {}

    /// Friction force on the bolster along ground z (Vertical) or y (Lateral).
    BristleFrictionState calcFriction(const SimTK::State& s, Direction d) const;
    double getDeflection(const SimTK::State& s, Direction d) const;
    void setDeflection(SimTK::State& s, Direction d, double w) const;

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
    /// Elastic energy held in the two bristles, ½·k_b·w².
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;
    /// Friction dissipation of both directions (calcBristleDissipation, energy
    /// audit); state realized to Velocity.
    double calcDissipatedPower(const SimTK::State& s) const;

    void realizeTopology(SimTK::State& s) const override;
    void realizeAcceleration(const SimTK::State& s) const override;

    /// Both directions from one relative velocity, computed once per realization
    /// in calcForce and kept in the State (DynamicsCache).
    struct Evaluation {
        BristleFrictionState friction[2];
        double dissipatedPower = 0;  ///< [W]
    };

private:
    void evaluate(const SimTK::State& s, Evaluation& e) const;
    const Evaluation& findOrEvaluate(const SimTK::State& s, Evaluation& scratch) const;

    const SimTK::GeneralForceSubsystem& forces_;
    SuspensionLink link_;
    BristleFrictionLaw law_[2];
    // Topology-stage index of the two bristle states, as Simbody's own elements keep it.
    mutable SimTK::ZIndex z0_;
    DynamicsCache<Evaluation> cache_;
};

}  // namespace rockroll
