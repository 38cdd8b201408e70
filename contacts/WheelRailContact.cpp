#include "contacts/WheelRailContact.h"

#include "contacts/SpringGroupLaws.h"

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
        out.dissipatedPower += calcUnilateralContactDissipation(delta, rail.zDot[i] - v[2], law_.vertical);
        e[i] = p[1] - yRail_[i];
        out.offset[i] = e[i];
        eDot[i] = v[1];
    }
    const double total = out.normal[0] + out.normal[1];
    if (total > 0)
        for (int i = 0; i < 2; ++i) {
            const double share = out.normal[i] / total;
            out.lateral[i] = -share * (law_.lateralStiffness * e[i] + law_.lateralDamping * eDot[i]);
            out.dissipatedPower += share * calcViscousDissipation(law_.lateralDamping, eDot[i]);
        }
    for (int i = 0; i < 2; ++i) out.railInputPower += out.normal[i] * rail.zDot[i];
    return out;
}

void WheelRailContact::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                                 Vector_<Vec3>&, Vector&) const {
    const WheelRailForces f = calcForces(s);
    for (int i = 0; i < 2; ++i)
        wheelset_.applyForceToBodyPoint(s, p_Tread_[i], Vec3(0, f.lateral[i], f.normal[i]), bodyForces);
}

Real WheelRailContact::calcPotentialEnergy(const State& s) const {
    // The rails move, so this is the contacts' elastic energy, not a conserved
    // potential. The lateral shares depend on the normal forces, hence on
    // velocities: the state must be realized to Velocity.
    const RailHeights rail = rails_(s.getTime());
    Real e = 0;
    double N[2], eLat[2];
    for (int i = 0; i < 2; ++i) {
        const Vec3 p = wheelset_.findStationLocationInGround(s, p_Tread_[i]);
        const double delta = rail.z[i] - p[2];
        e += calcUnilateralContactEnergy(delta, law_.vertical);
        N[i] = calcUnilateralNormalForce(delta, rail.zDot[i] - wheelset_.findStationVelocityInGround(s, p_Tread_[i])[2],
                                         law_.vertical);
        eLat[i] = p[1] - yRail_[i];
    }
    if (N[0] + N[1] > 0)
        for (int i = 0; i < 2; ++i) e += N[i] / (N[0] + N[1]) * calcLinearSpringEnergy(law_.lateralStiffness, eLat[i]);
    return e;
}

}  // namespace rockroll
