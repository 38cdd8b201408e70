#include "contacts/FrictionWedge.h"

using namespace SimTK;

namespace rockroll {

namespace {
int axisOf(FrictionWedge::Direction d) { return d == FrictionWedge::Vertical ? 2 : 1; }
}

void FrictionWedge::realizeTopology(State& s) const {
    z0_ = forces_.allocateZ(s, Vector(2, 0.0));
}

double FrictionWedge::getDeflection(const State& s, Direction d) const {
    return forces_.getZ(s)[z0_ + d];
}

void FrictionWedge::setDeflection(State& s, Direction d, double w) const {
    forces_.updZ(s)[z0_ + d] = w;
}

BristleFrictionState FrictionWedge::calcFriction(const State& s, Direction d) const {
    const double v = link_.calcRelativeVelocity(s)[axisOf(d)];
    return calcBristleFriction(getDeflection(s, d), v, law_[d]);
}

void FrictionWedge::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                              Vector_<Vec3>&, Vector&) const {
    Vec3 f(0);
    f[2] = calcFriction(s, Vertical).force;
    f[1] = calcFriction(s, Lateral).force;
    link_.applyForceOnBolster(s, f, bodyForces);
}

Real FrictionWedge::calcPotentialEnergy(const State& s) const {
    Real e = 0;
    for (Direction d : {Vertical, Lateral}) e += calcBristleEnergy(getDeflection(s, d), law_[d]);
    return e;
}

double FrictionWedge::calcDissipatedPower(const State& s) const {
    const Vec3 v = link_.calcRelativeVelocity(s);
    double P = 0;
    for (Direction d : {Vertical, Lateral}) P += calcBristleDissipation(getDeflection(s, d), v[axisOf(d)], law_[d]);
    return P;
}

void FrictionWedge::realizeAcceleration(const State& s) const {
    Vector& zDot = forces_.updZDot(s);
    zDot[z0_ + Vertical] = calcFriction(s, Vertical).deflectionRate;
    zDot[z0_ + Lateral] = calcFriction(s, Lateral).deflectionRate;
}

}  // namespace rockroll
