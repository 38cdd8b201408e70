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
        }
    // The rails' work: vertical through the contacts, lateral by the restraint on
    // the wheel (the rails do not move laterally; ė_i is the tread point's velocity).
    for (int i = 0; i < 2; ++i) out.railInputPower += out.normal[i] * rail.zDot[i] + out.lateral[i] * eDot[i];
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
    // potential. The lateral restraint is outside the audited system (header).
    const RailHeights rail = rails_(s.getTime());
    Real e = 0;
    for (int i = 0; i < 2; ++i)
        e += calcUnilateralContactEnergy(rail.z[i] - wheelset_.findStationLocationInGround(s, p_Tread_[i])[2],
                                         law_.vertical);
    return e;
}

}  // namespace rockroll
