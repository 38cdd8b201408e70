#include "contacts/UnilateralContact.h"

#include <algorithm>

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

double VerticalPointPair::calcPenetration(const State& s) const {
    const Vec3 p_GU = upper.findStationLocationInGround(s, p_UpperPoint);
    const Vec3 p_GL = lower.findStationLocationInGround(s, p_LowerPoint);
    return p_GL[2] - p_GU[2] - clearance;
}

double VerticalPointPair::calcPenetrationRate(const State& s) const {
    const Vec3 v_GU = upper.findStationVelocityInGround(s, p_UpperPoint);
    const Vec3 v_GL = lower.findStationVelocityInGround(s, p_LowerPoint);
    return v_GL[2] - v_GU[2];
}

void VerticalPointPair::applyNormalForce(const State& s, double f,
                                         Vector_<SpatialVec>& bodyForces) const {
    if (f == 0) return;
    upper.applyForceToBodyPoint(s, p_UpperPoint, Vec3(0, 0, f), bodyForces);
    lower.applyForceToBodyPoint(s, p_LowerPoint, Vec3(0, 0, -f), bodyForces);
}

}  // namespace rockroll
