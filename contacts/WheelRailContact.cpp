#include "contacts/WheelRailContact.h"

using namespace SimTK;

namespace rockroll {

WheelRailForces WheelRailContact::calcForces(const State& s) const {
    WheelRailForces out;
    const RailHeights rail = rails_(s.getTime());
    double e[2], eDot[2];
    for (int i = 0; i < 2; ++i) {
        const Vec3 p = wheelset_.findStationLocationInGround(s, p_Tread_[i]);
        const Vec3 v = wheelset_.findStationVelocityInGround(s, p_Tread_[i]);
        const double delta = rail.z[i] - p[2];
        out.normal[i] = calcUnilateralNormalForce(delta, rail.zDot[i] - v[2], law_.vertical);
        out.lift[i] = std::max(0.0, -delta);
        e[i] = p[1] - yRail_[i];
        out.offset[i] = e[i];
        eDot[i] = v[1];
    }
    const double total = out.normal[0] + out.normal[1];
    if (total > 0)
        for (int i = 0; i < 2; ++i)
            out.lateral[i] = -(out.normal[i] / total) *
                             (law_.lateralStiffness * e[i] + law_.lateralDamping * eDot[i]);
    return out;
}

void WheelRailContact::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                                 Vector_<Vec3>&, Vector&) const {
    const WheelRailForces f = calcForces(s);
    for (int i = 0; i < 2; ++i)
        wheelset_.applyForceToBodyPoint(s, p_Tread_[i], Vec3(0, f.lateral[i], f.normal[i]), bodyForces);
}

Real WheelRailContact::calcPotentialEnergy(const State& s) const {
    // Only the vertical springs store energy; the rails move, so this is the
    // contacts' elastic energy, not a conserved potential.
    const RailHeights rail = rails_(s.getTime());
    Real e = 0;
    for (int i = 0; i < 2; ++i) {
        const double delta = rail.z[i] - wheelset_.findStationLocationInGround(s, p_Tread_[i])[2];
        if (delta > 0) e += 0.5 * law_.vertical.stiffness * delta * delta;
    }
    return e;
}

}  // namespace rockroll
