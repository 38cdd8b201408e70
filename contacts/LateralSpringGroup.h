#pragma once
// Lateral suspension spring group with the gib stop at one bolster end.
#include "contacts/SuspensionLink.h"
#include "contacts/UnilateralContact.h"

namespace rockroll {

struct LateralSpringLaw {
    double rate = 0;           ///< K_h [N/m]
    double gibClearance = 0;   ///< c_gib, half the total gib clearance [m]
    double gibRate = 0;        ///< K_gib [N/m]
    double gibDissipation = 0; ///< Hunt–Crossley d of the gib contact [s/m]
};

/// Lateral force resisting relative displacement Y (bolster relative to side frame):
///
///     P = K_h·Y + sign(Y)·f_gib(|Y| − c_gib, d|Y|/dt)
///
/// where f_gib is the unilateral contact law (zero inside the clearance).
double calcLateralSpringForce(double Y, double Ydot, const LateralSpringLaw& law);

class LateralSpringGroup : public SimTK::Force::Custom::Implementation {
public:
    LateralSpringGroup(SuspensionLink link, LateralSpringLaw law)
        : link_(std::move(link)), law_(law) {}

    double calcDisplacement(const SimTK::State& s) const { return link_.calcRelativeLocation(s)[1]; }
    double calcForce(const SimTK::State& s) const;
    bool isGibClosed(const SimTK::State& s) const {
        return std::abs(calcDisplacement(s)) > law_.gibClearance;
    }

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;

private:
    SuspensionLink link_;
    LateralSpringLaw law_;
};

}  // namespace rockroll
