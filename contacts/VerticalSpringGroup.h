#pragma once
// Vertical suspension spring group (one side of one truck), report Fig. 4.
#include "contacts/SuspensionLink.h"

namespace rockroll {

struct VerticalSpringLaw {
    double rate = 0;            ///< K_v [N/m]
    double travel = 0;          ///< free height to bottomed [m]
    double bottomingRate = 0;   ///< K_bottom [N/m]
};

/// Spring force for compression Z (positive = shorter than free height):
///
///     P = 0                                  Z < 0   (bolster off its springs)
///     P = K_v·Z                              0 ≤ Z ≤ travel
///     P = K_v·travel + K_bottom·(Z − travel) Z > travel (coils solid)
double calcVerticalSpringForce(double compression, const VerticalSpringLaw& law);

/// Inverse of calcVerticalSpringForce for P ≥ 0 (used to place the static state).
double calcVerticalSpringCompression(double force, const VerticalSpringLaw& law);

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
