#include "contacts/SuspensionLink.h"

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

Vec3 SideFrameSeat::findLocationInGround(const State& s) const {
    Vec3 sum(0);
    for (size_t i = 0; i < bodies.size(); ++i)
        sum += bodies[i].findStationLocationInGround(s, stations[i]);
    return sum / double(bodies.size());
}

Vec3 SideFrameSeat::findVelocityInGround(const State& s) const {
    Vec3 sum(0);
    for (size_t i = 0; i < bodies.size(); ++i)
        sum += bodies[i].findStationVelocityInGround(s, stations[i]);
    return sum / double(bodies.size());
}

void SideFrameSeat::applyForce(const State& s, const Vec3& f_G,
                               Vector_<SpatialVec>& bodyForces) const {
    const Vec3 share = f_G / double(bodies.size());
    for (size_t i = 0; i < bodies.size(); ++i)
        bodies[i].applyForceToBodyPoint(s, stations[i], share, bodyForces);
}

}  // namespace rockroll
