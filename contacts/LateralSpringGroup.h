#pragma once
// Lateral suspension spring group with the gib stop at one bolster end.
#include "contacts/SpringGroupLaws.h"
#include "contacts/SuspensionLink.h"
#include "contacts/UnilateralContact.h"

namespace rockroll {

class LateralSpringGroup : public SimTK::Force::Custom::Implementation {
public:
    LateralSpringGroup(SuspensionLink link, LateralSpringLaw law)
        : link_(std::move(link)), law_(law) {}

    double calcDisplacement(const SimTK::State& s) const { return link_.calcRelativeLocation(s)[1]; }
    double calcForce(const SimTK::State& s) const;

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;
    /// Gib contact dissipation (energy audit); state realized to Velocity.
    double calcDissipatedPower(const SimTK::State& s) const {
        return calcLateralSpringDissipation(calcDisplacement(s), link_.calcRelativeVelocity(s)[1], law_);
    }

private:
    SuspensionLink link_;
    LateralSpringLaw law_;
};

}  // namespace rockroll
