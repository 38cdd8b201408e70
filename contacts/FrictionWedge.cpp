#include "contacts/FrictionWedge.h"

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

namespace {
int axisOf(FrictionWedge::Direction d) { return d == FrictionWedge::Vertical ? 2 : 1; }
}

void FrictionWedge::realizeTopology(State& s) const {
    z0_ = forces_.allocateZ(s, Vector(2, 0.0));
    cache_.allocate(forces_, s);
}

double FrictionWedge::getDeflection(const State& s, Direction d) const {
    return forces_.getZ(s)[z0_ + d];
}

void FrictionWedge::setDeflection(State& s, Direction d, double w) const {
    forces_.updZ(s)[z0_ + d] = w;
}

void FrictionWedge::evaluate(const State& s, Evaluation& e) const {
    const Vec3 v = link_.calcRelativeVelocity(s);
    double P = 0;
    for (Direction d : {Vertical, Lateral}) {
        const double w = getDeflection(s, d);
        e.friction[d] = calcBristleFriction(w, v[axisOf(d)], law_[d]);
        P += calcBristleDissipation(w, v[axisOf(d)], law_[d]);
    }
    e.dissipatedPower = P;
}

const FrictionWedge::Evaluation& FrictionWedge::findOrEvaluate(const State& s, Evaluation& scratch) const {
    if (const Evaluation* cached = cache_.find(forces_, s)) return *cached;
    evaluate(s, scratch);
    return scratch;
}

BristleFrictionState FrictionWedge::calcFriction(const State& s, Direction d) const {
    Evaluation scratch;
    return findOrEvaluate(s, scratch).friction[d];
}

void FrictionWedge::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                              Vector_<Vec3>&, Vector&) const {
    Evaluation& e = cache_.upd(forces_, s);
    evaluate(s, e);
    Vec3 f(0);
    f[2] = e.friction[Vertical].force;
    f[1] = e.friction[Lateral].force;
    link_.applyForceOnBolster(s, f, bodyForces);
}

Real FrictionWedge::calcPotentialEnergy(const State& s) const {
    Real e = 0;
    for (Direction d : {Vertical, Lateral}) e += calcBristleEnergy(getDeflection(s, d), law_[d]);
    return e;
}

double FrictionWedge::calcDissipatedPower(const State& s) const {
    Evaluation scratch;
    return findOrEvaluate(s, scratch).dissipatedPower;
}

void FrictionWedge::realizeAcceleration(const State& s) const {
    Evaluation scratch;
    const Evaluation& e = findOrEvaluate(s, scratch);
    Vector& zDot = forces_.updZDot(s);
    zDot[z0_ + Vertical] = e.friction[Vertical].deflectionRate;
    zDot[z0_ + Lateral] = e.friction[Lateral].deflectionRate;
}

}  // namespace rockroll
