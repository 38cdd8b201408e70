#pragma once
// Vertical suspension spring group (one side of one truck), report Fig. 4.
#include "contacts/SpringGroupLaws.h"
#include "contacts/SuspensionLink.h"

namespace rockroll {

/// Force element: the bolster point sits above the seat point; both stations are
/// placed so that Z = z_seat − z_bolster is the compression.
class VerticalSpringGroup : public SimTK::Force::Custom::Implementation {
public:
    VerticalSpringGroup(SuspensionLink link, VerticalSpringLaw law)
        : link_(std::move(link)), law_(law) {}

    double calcCompression(const SimTK::State& s) const { return -link_.calcRelativeLocation(s)[2]; }
    double calcForce(const SimTK::State& s) const { return calcVerticalSpringForce(calcCompression(s), law_); }

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;
    bool dependsOnlyOnPositions() const override { return true; }

private:
    SuspensionLink link_;
    VerticalSpringLaw law_;
};

}  // namespace rockroll
