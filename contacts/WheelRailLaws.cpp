#include "contacts/WheelRailLaws.h"

#include <algorithm>
#include <cmath>

namespace rockroll {

const char* getLateralWheelRailName(LateralWheelRail l) {
    return l == LateralWheelRail::Restraint ? "restraint" : "creep_and_flange";
}

const LateralWheelRail* findLateralWheelRail(std::string_view name) {
    static constexpr LateralWheelRail kAll[] = {LateralWheelRail::Restraint, LateralWheelRail::CreepAndFlange};
    for (const LateralWheelRail& l : kAll)
        if (name == getLateralWheelRailName(l)) return &l;
    return nullptr;
}

double calcSaturatedCreepFraction(double beta) {
    if (beta >= 3) return 1;
    return beta - beta * beta / 3 + beta * beta * beta / 27;
}

double calcLateralCreepForce(double slipVelocity, double forwardSpeed, double normalForce, double wheels,
                             const WheelRailSettings& w) {
    if (normalForce <= 0 || slipVelocity == 0) return 0;
    const double creepage = slipVelocity / std::max(std::abs(forwardSpeed), kMinCreepSpeed);
    const double linear = -wheels * w.creepCoefficient * creepage;
    const double limit = w.friction * normalForce;
    if (limit <= 0) return 0;
    const double beta = std::abs(linear) / limit;
    // g(β)/β → 1 as β → 0: the linear force itself.
    return beta < 1e-12 ? linear : linear * calcSaturatedCreepFraction(beta) / beta;
}

namespace {
UnilateralContactLaw makeFlangeLaw(const UnilateralContactLaw& tread, const WheelRailSettings& w) {
    return {tread.stiffness * w.flangeStiffnessScale, tread.dissipation};
}

double calcPenetration(double towardRail, double lift, double sinAngle, double cosAngle, const WheelRailSettings& w) {
    if (lift >= w.flangeHeight) return 0;
    return (towardRail - w.flangewayClearance) * sinAngle - lift * cosAngle;
}
}  // namespace

FlangeForces calcFlangeForces(double towardRail, double towardRailRate, double lift, double liftRate,
                              double forwardSpeed, double wheels, const UnilateralContactLaw& normal,
                              const WheelRailSettings& w) {
    const UnilateralContactLaw flange = makeFlangeLaw(normal, w);
    FlangeForces f;
    const double sg = std::sin(w.flangeAngle), cg = std::cos(w.flangeAngle);
    f.penetration = calcPenetration(towardRail, lift, sg, cg, w);
    if (f.penetration <= 0) return f;
    const double rate = towardRailRate * sg - liftRate * cg;
    f.normal = calcUnilateralNormalForce(f.penetration, rate, flange);
    const double slide = towardRailRate * cg + liftRate * sg;
    f.friction = calcLateralCreepForce(slide, forwardSpeed, f.normal, wheels, w);
    f.towardRail = -f.normal * sg + f.friction * cg;
    f.vertical = f.normal * cg + f.friction * sg;
    f.dissipatedPower = calcUnilateralContactDissipation(f.penetration, rate, flange) - f.friction * slide;
    f.energy = calcUnilateralContactEnergy(f.penetration, flange);
    return f;
}

double calcFlangeEnergy(double towardRail, double lift, const UnilateralContactLaw& normal,
                        const WheelRailSettings& w) {
    const double p = calcPenetration(towardRail, lift, std::sin(w.flangeAngle), std::cos(w.flangeAngle), w);
    return calcUnilateralContactEnergy(p, makeFlangeLaw(normal, w));
}

double calcNadalLimit(double flangeAngle, double friction) {
    const double t = std::tan(flangeAngle);
    return (t - friction) / (1 + friction * t);
}

}  // namespace rockroll
