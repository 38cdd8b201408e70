#include "contacts/CenterPlateContact.h"

#include "contacts/SpringGroupLaws.h"

#include <cmath>
#include <stdexcept>

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

CenterPlateContact::CenterPlateContact(const GeneralForceSubsystem& forces, CenterPlateGeometry g,
                                       CenterPlateLaw law)
    : forces_(forces), geom_(std::move(g)), law_(law) {
    const int n = geom_.rimPoints;
    if (n != 2 && (n < 4 || n % 4 != 0))
        throw std::invalid_argument("CenterPlateContact: rimPoints must be 2 or a multiple of 4");
    for (int k = 0; k < n; ++k) {
        // n = 2: φ = 90°, 270° (left and right rim points).
        const double phi = n == 2 ? Pi / 2 + Pi * k : 2 * Pi * k / n;
        const Vec3 offset(geom_.radius * std::cos(phi), geom_.radius * std::sin(phi), 0);
        pairs_.push_back({geom_.carBody, geom_.p_CarBodyPlate + offset, geom_.bolster,
                          geom_.p_BolsterBowl + offset, 0.0});
    }
}

void CenterPlateContact::realizeTopology(State& s) const {
    if (hasYawFriction()) zYaw_ = forces_.allocateZ(s, Vector(1, 0.0));
    cache_.allocate(forces_, s);
}

BristleFrictionLaw CenterPlateContact::makeYawLaw(double N) const {
    return {law_.yawFrictionCoefficient * N * (2.0 / 3.0) * geom_.radius, law_.yawBristleStiffness,
            law_.yawBristleDamping};
}

void CenterPlateContact::evaluate(const State& s, Evaluation& e) const {
    const BodyKinematics car = BodyKinematics::calc(geom_.carBody, s);
    const BodyKinematics bowl = BodyKinematics::calc(geom_.bolster, s);
    CenterPlateForces& out = e.forces;
    out.rim.resize(pairs_.size());
    out.vertical = 0;
    out.pin = Vec3(0);
    out.yawTorque = 0;
    out.yawSlipping = false;
    double P = 0;
    for (size_t k = 0; k < pairs_.size(); ++k) {
        const double delta = pairs_[k].calcPenetration(car, bowl), rate = pairs_[k].calcPenetrationRate(car, bowl);
        out.rim[k] = calcUnilateralNormalForce(delta, rate, law_.rim);
        out.vertical += out.rim[k];
        P += calcUnilateralContactDissipation(delta, rate, law_.rim);
    }
    const Vec3 d = car.findStationLocationInGround(geom_.p_CarBodyPlate) -
                   bowl.findStationLocationInGround(geom_.p_BolsterBowl);
    const Vec3 v = car.findStationVelocityInGround(geom_.p_CarBodyPlate) -
                   bowl.findStationVelocityInGround(geom_.p_BolsterBowl);
    out.pin[1] = -(law_.pinStiffness * d[1] + law_.pinDamping * v[1]);
    if (law_.longitudinalPin) out.pin[0] = -(law_.pinStiffness * d[0] + law_.pinDamping * v[0]);
    P += calcViscousDissipation(law_.pinDamping, v[1]);
    if (law_.longitudinalPin) P += calcViscousDissipation(law_.pinDamping, v[0]);
    e.yawDeflectionRate = 0;
    if (hasYawFriction()) {
        const double w = forces_.getZ(s)[zYaw_], rate = car.V_GB[0][2] - bowl.V_GB[0][2];
        const BristleFrictionLaw yawLaw = makeYawLaw(out.vertical);
        const BristleFrictionState yaw = calcBristleFriction(w, rate, yawLaw);
        out.yawTorque = yaw.force;
        out.yawSlipping = yaw.slipping;
        e.yawDeflectionRate = yaw.deflectionRate;
        P += calcBristleDissipation(w, rate, yawLaw);
    }
    e.dissipatedPower = P;
}

const CenterPlateContact::Evaluation& CenterPlateContact::findOrEvaluate(const State& s, Evaluation& scratch) const {
    if (const Evaluation* cached = cache_.find(forces_, s)) return *cached;
    evaluate(s, scratch);
    return scratch;
}

CenterPlateForces CenterPlateContact::calcForces(const State& s) const {
    Evaluation scratch;
    return findOrEvaluate(s, scratch).forces;
}

void CenterPlateContact::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                                   Vector_<Vec3>&, Vector&) const {
    Evaluation& e = cache_.upd(forces_, s);
    evaluate(s, e);
    const CenterPlateForces& f = e.forces;
    const BodyPose car = BodyPose::calc(geom_.carBody, s), bowl = BodyPose::calc(geom_.bolster, s);
    for (size_t k = 0; k < pairs_.size(); ++k) pairs_[k].applyNormalForce(car, bowl, f.rim[k], bodyForces);
    car.applyForceToBodyPoint(geom_.p_CarBodyPlate, f.pin, bodyForces);
    bowl.applyForceToBodyPoint(geom_.p_BolsterBowl, -f.pin, bodyForces);
    if (f.yawTorque != 0) {
        geom_.carBody.applyBodyTorque(s, Vec3(0, 0, f.yawTorque), bodyForces);
        geom_.bolster.applyBodyTorque(s, Vec3(0, 0, -f.yawTorque), bodyForces);
    }
}

Real CenterPlateContact::calcPotentialEnergy(const State& s) const {
    const BodyPose car = BodyPose::calc(geom_.carBody, s), bowl = BodyPose::calc(geom_.bolster, s);
    Real e = 0;
    for (const auto& p : pairs_) e += calcUnilateralContactEnergy(p.calcPenetration(car, bowl), law_.rim);
    const Vec3 d = car.findStationLocationInGround(geom_.p_CarBodyPlate) -
                   bowl.findStationLocationInGround(geom_.p_BolsterBowl);
    e += calcLinearSpringEnergy(law_.pinStiffness, d[1]);
    if (law_.longitudinalPin) e += calcLinearSpringEnergy(law_.pinStiffness, d[0]);
    if (hasYawFriction()) e += calcBristleEnergy(forces_.getZ(s)[zYaw_], makeYawLaw(0));
    return e;
}

double CenterPlateContact::calcDissipatedPower(const State& s) const {
    Evaluation scratch;
    return findOrEvaluate(s, scratch).dissipatedPower;
}

void CenterPlateContact::realizeAcceleration(const State& s) const {
    if (!hasYawFriction()) return;
    Evaluation scratch;
    forces_.updZDot(s)[zYaw_] = findOrEvaluate(s, scratch).yawDeflectionRate;
}

}  // namespace rockroll
