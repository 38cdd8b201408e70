#include "contacts/WheelRailContact.h"

#include "contacts/SpringGroupLaws.h"

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

WheelRailForces WheelRailContact::calcForces(const State& s) const {
    if (const WheelRailForces* cached = cache_.find(wheelset_.getMatterSubsystem(), s)) return *cached;
    WheelRailForces out;
    evaluate(s, out);
    return out;
}

void WheelRailContact::evaluate(const State& s, WheelRailForces& out) const {
    out = WheelRailForces{};
    const RailHeights rail = rails_(s.getTime());
    const BodyKinematics wheelset = BodyKinematics::calc(wheelset_, s);
    double e[2], eDot[2];
    for (int i = 0; i < 2; ++i) {
        const Vec3 p = wheelset.findStationLocationInGround(p_Tread_[i]);
        const Vec3 v = wheelset.findStationVelocityInGround(p_Tread_[i]);
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
}

void WheelRailContact::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                                 Vector_<Vec3>&, Vector&) const {
    WheelRailForces& f = cache_.upd(wheelset_.getMatterSubsystem(), s);
    evaluate(s, f);
    const BodyPose wheelset = BodyPose::calc(wheelset_, s);
    for (int i = 0; i < 2; ++i)
        wheelset.applyForceToBodyPoint(p_Tread_[i], Vec3(0, f.lateral[i], f.normal[i]), bodyForces);
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
