#include "contacts/VerticalSpringGroup.h"

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

void VerticalSpringGroup::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                                    Vector_<Vec3>&, Vector&) const {
    const double P = calcForce(s);
    if (P != 0) link_.applyForceOnBolster(s, Vec3(0, 0, P), bodyForces);
}

Real VerticalSpringGroup::calcPotentialEnergy(const State& s) const {
    return calcVerticalSpringEnergy(calcCompression(s), law_);
}

}  // namespace rockroll
