#include "contacts/CenterPlateContact.h"

#include "contacts/SpringGroupLaws.h"

#include <cmath>
#include <stdexcept>

using namespace SimTK;

namespace rockroll {

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
}

Vec3 CenterPlateContact::calcPinDeflection(const State& s) const {
    return geom_.carBody.findStationLocationInGround(s, geom_.p_CarBodyPlate) -
           geom_.bolster.findStationLocationInGround(s, geom_.p_BolsterBowl);
}

Vec3 CenterPlateContact::calcPinVelocity(const State& s) const {
    return geom_.carBody.findStationVelocityInGround(s, geom_.p_CarBodyPlate) -
           geom_.bolster.findStationVelocityInGround(s, geom_.p_BolsterBowl);
}

BristleFrictionLaw CenterPlateContact::makeYawLaw(double N) const {
    return {law_.yawFrictionCoefficient * N * (2.0 / 3.0) * geom_.radius, law_.yawBristleStiffness,
            law_.yawBristleDamping};
}

namespace {
double relativeYawRate(const State& s, const CenterPlateGeometry& g) {
    return g.carBody.getBodyAngularVelocity(s)[2] - g.bolster.getBodyAngularVelocity(s)[2];
}
}  // namespace

BristleFrictionState CenterPlateContact::calcYawFriction(const State& s, double N) const {
    return calcBristleFriction(forces_.getZ(s)[zYaw_], relativeYawRate(s, geom_), makeYawLaw(N));
}

CenterPlateForces CenterPlateContact::calcForces(const State& s) const {
    CenterPlateForces out;
    out.rim.resize(pairs_.size());
    for (size_t k = 0; k < pairs_.size(); ++k) {
        out.rim[k] = calcUnilateralNormalForce(pairs_[k].calcPenetration(s),
                                               pairs_[k].calcPenetrationRate(s), law_.rim);
        out.vertical += out.rim[k];
    }
    const Vec3 d = calcPinDeflection(s);
    const Vec3 v = calcPinVelocity(s);
    out.pin[1] = -(law_.pinStiffness * d[1] + law_.pinDamping * v[1]);
    if (law_.longitudinalPin) out.pin[0] = -(law_.pinStiffness * d[0] + law_.pinDamping * v[0]);
    if (hasYawFriction()) {
        const BristleFrictionState yaw = calcYawFriction(s, out.vertical);
        out.yawTorque = yaw.force;
        out.yawSlipping = yaw.slipping;
    }
    return out;
}

void CenterPlateContact::calcForce(const State& s, Vector_<SpatialVec>& bodyForces,
                                   Vector_<Vec3>&, Vector&) const {
    const CenterPlateForces f = calcForces(s);
    for (size_t k = 0; k < pairs_.size(); ++k) pairs_[k].applyNormalForce(s, f.rim[k], bodyForces);
    geom_.carBody.applyForceToBodyPoint(s, geom_.p_CarBodyPlate, f.pin, bodyForces);
    geom_.bolster.applyForceToBodyPoint(s, geom_.p_BolsterBowl, -f.pin, bodyForces);
    if (f.yawTorque != 0) {
        geom_.carBody.applyBodyTorque(s, Vec3(0, 0, f.yawTorque), bodyForces);
        geom_.bolster.applyBodyTorque(s, Vec3(0, 0, -f.yawTorque), bodyForces);
    }
}

Real CenterPlateContact::calcPotentialEnergy(const State& s) const {
    Real e = 0;
    for (const auto& p : pairs_) e += calcUnilateralContactEnergy(p.calcPenetration(s), law_.rim);
    const Vec3 d = calcPinDeflection(s);
    e += calcLinearSpringEnergy(law_.pinStiffness, d[1]);
    if (law_.longitudinalPin) e += calcLinearSpringEnergy(law_.pinStiffness, d[0]);
    if (hasYawFriction()) e += calcBristleEnergy(forces_.getZ(s)[zYaw_], makeYawLaw(0));
    return e;
}

double CenterPlateContact::calcDissipatedPower(const State& s) const {
    double P = 0, N = 0;
    for (const auto& p : pairs_) {
        const double delta = p.calcPenetration(s), rate = p.calcPenetrationRate(s);
        P += calcUnilateralContactDissipation(delta, rate, law_.rim);
        N += calcUnilateralNormalForce(delta, rate, law_.rim);
    }
    const Vec3 v = calcPinVelocity(s);
    P += calcViscousDissipation(law_.pinDamping, v[1]);
    if (law_.longitudinalPin) P += calcViscousDissipation(law_.pinDamping, v[0]);
    if (hasYawFriction()) P += calcBristleDissipation(forces_.getZ(s)[zYaw_], relativeYawRate(s, geom_), makeYawLaw(N));
    return P;
}

void CenterPlateContact::realizeAcceleration(const State& s) const {
    if (!hasYawFriction()) return;
    double N = 0;
    for (const auto& p : pairs_)
        N += calcUnilateralNormalForce(p.calcPenetration(s), p.calcPenetrationRate(s), law_.rim);
    forces_.updZDot(s)[zYaw_] = calcYawFriction(s, N).deflectionRate;
}

}  // namespace rockroll
