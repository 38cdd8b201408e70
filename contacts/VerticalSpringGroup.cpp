#include "contacts/VerticalSpringGroup.h"

using namespace SimTK;

namespace rockroll {

void VerticalSpringGroup::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                                    Vector_<Vec3>&, Vector&) const {
    const double P = calcForce(s);
    if (P != 0) link_.applyForceOnBolster(s, Vec3(0, 0, P), bodyForces);
}

Real VerticalSpringGroup::calcPotentialEnergy(const State& s) const {
    const double Z = calcCompression(s);
    if (Z <= 0) return 0;
    const double zLin = std::min(Z, law_.travel);
    double e = 0.5 * law_.rate * zLin * zLin;
    if (Z > law_.travel) {
        const double b = Z - law_.travel;
        e += law_.rate * law_.travel * b + 0.5 * law_.bottomingRate * b * b;
    }
    return e;
}

}  // namespace rockroll
