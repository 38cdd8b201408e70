#include "contacts/VerticalSpringGroup.h"

using namespace SimTK;

namespace rockroll {

void VerticalSpringGroup::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                                    Vector_<Vec3>&, Vector&) const {
    const double P = calcForce(s);
    if (P != 0) link_.applyForceOnBolster(s, Vec3(0, 0, P), bodyForces);
}

Real VerticalSpringGroup::calcPotentialEnergy(const State& s) const {
    return calcVerticalSpringEnergy(calcCompression(s), law_);
}

}  // namespace rockroll
