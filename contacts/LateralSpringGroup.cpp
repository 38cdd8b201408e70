#include "contacts/LateralSpringGroup.h"

#include <cmath>

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

double LateralSpringGroup::calcForce(const State& s) const {
    return calcLateralSpringForce(calcDisplacement(s), link_.calcRelativeVelocity(s)[1], law_);
}

void LateralSpringGroup::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                                   Vector_<Vec3>&, Vector&) const {
    const double P = calcForce(s);
    link_.applyForceOnBolster(s, Vec3(0, -P, 0), bodyForces);
}

Real LateralSpringGroup::calcPotentialEnergy(const State& s) const {
    return calcLateralSpringEnergy(calcDisplacement(s), law_);
}

}  // namespace rockroll
