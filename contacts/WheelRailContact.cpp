#include "contacts/WheelRailContact.h"

#include "contacts/SpringGroupLaws.h"

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

WheelRailForces WheelRailContact::calcForces(const State& s) const {
    if (const WheelRailForces* cached = cache_.find(forces_, s)) return *cached;
    WheelRailForces out;
    evaluate(s, out);
    return out;
}

void WheelRailContact::evaluate(const State& s, WheelRailForces& out) const {
    out = WheelRailForces{};
    const RailHeights rail = rails_(s.getTime());
    const BodyKinematics wheelset = BodyKinematics::calc(wheelset_, s);
    const bool restraint = law_.settings.lateral == LateralWheelRail::Restraint;
    double e[2], eDot[2];
    for (int i = 0; i < 2; ++i) {
        const Vec3 p = wheelset.findStationLocationInGround(p_Tread_[i]);
        const Vec3 v = wheelset.findStationVelocityInGround(p_Tread_[i]);
        const double delta = rail.z[i] - p[2];
        out.normal[i] = calcUnilateralNormalForce(delta, rail.zDot[i] - v[2], law_.vertical);
        out.vertical[i] = out.normal[i];
        out.lift[i] = std::max(0.0, -delta);
        out.dissipatedPower += calcUnilateralContactDissipation(delta, rail.zDot[i] - v[2], law_.vertical);
        e[i] = p[1] - yRail_[i];
        out.offset[i] = e[i];
        eDot[i] = v[1];
        if (restraint) continue;
        // Creep and flange: each wheel its own (the rails do not move laterally).
        out.creep[i] = calcLateralCreepForce(v[1], rail.speed, out.normal[i], law_.wheels, law_.settings);
        out.dissipatedPower -= out.creep[i] * v[1];
        // Toward its own rail: +y for the left wheel (i = 0), −y for the right.
        const double sg = i == 0 ? 1.0 : -1.0;
        const FlangeForces f = calcFlangeForces(sg * e[i], sg * v[1], -delta, v[2] - rail.zDot[i], rail.speed,
                                                law_.wheels, law_.vertical, law_.settings);
        out.flange[i] = f.normal;
        out.vertical[i] += f.vertical;
        out.lateral[i] = out.creep[i] + sg * f.towardRail;
        out.dissipatedPower += f.dissipatedPower;
    }
    if (restraint) {
        const double total = out.normal[0] + out.normal[1];
        if (total > 0)
            for (int i = 0; i < 2; ++i) {
                const double share = out.normal[i] / total;
                out.lateral[i] = -share * (law_.lateralStiffness * e[i] + law_.lateralDamping * eDot[i]);
            }
    }
    // The rails' work: vertical through the contacts; lateral only by the restraint
    // (the rails do not move laterally; ė_i is the tread point's velocity).
    for (int i = 0; i < 2; ++i)
        out.railInputPower += out.vertical[i] * rail.zDot[i] + (restraint ? out.lateral[i] * eDot[i] : 0.0);
}

void WheelRailContact::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                                 Vector_<Vec3>&, Vector&) const {
    WheelRailForces& f = cache_.upd(forces_, s);
    evaluate(s, f);
    const BodyPose wheelset = BodyPose::calc(wheelset_, s);
    for (int i = 0; i < 2; ++i)
        wheelset.applyForceToBodyPoint(p_Tread_[i], Vec3(0, f.lateral[i], f.vertical[i]), bodyForces);
}

Real WheelRailContact::calcPotentialEnergy(const State& s) const {
    // The rails move, so this is the contacts' elastic energy, not a conserved
    // potential. The lateral restraint is outside the audited system (header).
    const RailHeights rail = rails_(s.getTime());
    Real e = 0;
    for (int i = 0; i < 2; ++i) {
        const Vec3 p = wheelset_.findStationLocationInGround(s, p_Tread_[i]);
        e += calcUnilateralContactEnergy(rail.z[i] - p[2], law_.vertical);
        if (law_.settings.lateral == LateralWheelRail::CreepAndFlange) {
            const double sg = i == 0 ? 1.0 : -1.0;
            e += calcFlangeEnergy(sg * (p[1] - yRail_[i]), p[2] - rail.z[i], law_.vertical, law_.settings);
        }
    }
    return e;
}

}  // namespace rockroll
