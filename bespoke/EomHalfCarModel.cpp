#include "bespoke/EomHalfCarModel.h"

#include "contacts/BristleFriction.h"
#include "mbmodel/CarSide.h"
#include "mbmodel/TrackInput.h"
#include "mbmodel/Units.h"

#include <cmath>
#include <limits>
#include <fmt/format.h>

namespace rockroll {

namespace {
constexpr int kWedgeVertical = 0, kWedgeLateral = 1;  // + 2·side

using Vec2 = Eigen::Vector2d;
}  // namespace

EomHalfCarModel::EomHalfCarModel(const CarParameters& car, RailStateFunction rails, EomSimplifications simp,
                                 WheelRailSettings wheelRail)
    : car_(car), rails_(std::move(rails)), simp_(simp), wheelRail_(wheelRail) {
    const double g = units::g;
    mass_ = {car.getCarBodyWeight() / 2 / g, car.bolsterWeight / g, 2 * (car.wheelsetWeight + car.sideFrameWeight) / g};
    inertia_ = {car.rollInertia / 2, car.bolsterRollInertia, 2 * car.wheelsetRollInertia};

    const double h = car.cgAboveCenterPlate, R = car.wheelRadius;
    geom_.plateOnCarBody = Vec2(0, -h);
    geom_.bowlOnBolster = Vec2(0, car.centerPlateAboveSprings);
    geom_.rimRadius = car.centerPlateDiameter / 2;
    for (int side : {0, 1}) {
        const double sg = kSideSign[side];
        geom_.padOnCarBody[side] = Vec2(sg * car.sideBearingOffset, -h + car.sideBearingAboveSprings - car.centerPlateAboveSprings);
        geom_.bearingOnBolster[side] = Vec2(sg * car.sideBearingOffset, car.sideBearingAboveSprings);
        geom_.springOnBolster[side] = Vec2(sg * car.springOffset, 0);
        geom_.seatOnWheelset[side] = Vec2(sg * car.springOffset, car.springTopAboveRail - R);
        geom_.tread[side] = Vec2(sg * car.gauge / 2, -R);
        geom_.railY[side] = sg * car.gauge / 2;
    }

    const double scale = car.contactStiffnessScale;
    const double d = simp.elasticContacts ? 0.0 : car.contactDissipation;
    const double mB = mass_[Bolster];
    laws_.rim = {scale * car.centerPlateStiffness / 2, d};
    laws_.sideBearing = {scale * car.sideBearingStiffness, d};
    laws_.sideBearingClearance = car.sideBearingClearance;
    laws_.wheelVertical = {2 * scale * car.wheelRailStiffness, d};
    laws_.spring = {car.springVerticalRate, car.springTravel, car.bottomingRate};
    laws_.lateral = {car.springLateralRate, car.gibClearance, car.gibRate, d};
    laws_.pinStiffness = scale * car.centerPinStiffness;
    laws_.pinDamping = calcBristleDamping(laws_.pinStiffness, mB, car.lateralContactDampingRatio);
    laws_.wheelLateralStiffness = 2 * scale * car.wheelRailLateralStiffness;
    laws_.wheelLateralDamping = calcBristleDamping(laws_.wheelLateralStiffness, mass_[Wheelset], car.lateralContactDampingRatio);
    const double kV = car.calcVerticalBristleStiffness();
    const double kH = car.calcLateralBristleStiffness();
    const double zeta = car.frictionBristleDampingRatio;
    laws_.wedgeVertical = {car.verticalFriction, kV, calcBristleDamping(kV, mB / 2, zeta)};
    laws_.wedgeLateral = {car.lateralFriction, kH, calcBristleDamping(kH, mB / 2, zeta)};
    if (simp.lockBolsterLateral) {
        // A stiff, damped lateral link per bolster end (half the center pin's
        // stiffness each) replaces spring group, gib and lateral wedge.
        laws_.lateral = {scale * car.centerPinStiffness / 2, 0, 0, 0};
        laws_.wedgeLateral.limit = 0;
    }
    declareChannels();
    staticCarBodyZ_ = makeStaticState()[3 * CarBody + 2];
}

double EomHalfCarModel::calcSpringForce(double Z) const {
    return simp_.linearSprings ? laws_.spring.rate * Z : calcVerticalSpringForce(Z, laws_.spring);
}

double EomHalfCarModel::calcSpringEnergy(double Z) const {
    return simp_.linearSprings ? calcLinearSpringEnergy(laws_.spring.rate, Z) : calcVerticalSpringEnergy(Z, laws_.spring);
}

double EomHalfCarModel::calcLockedLinkDamping() const {
    return calcBristleDamping(laws_.lateral.rate, mass_[Bolster] / 2, car_.lateralContactDampingRatio);
}

TruckStatics EomHalfCarModel::calcTruckStatics() const {
    TruckStaticLoad load;
    load.carBody = car_.getCarBodyWeight() / 2;
    load.linearSprings = simp_.linearSprings;
    return TruckStatics(car_, load);
}

double EomHalfCarModel::calcStaticWheelLoad() const {
    return calcTruckStatics().getTruckSideWheelLoad();  // per wheel of the equivalent wheelset
}

EomHalfCarModel::State EomHalfCarModel::makeStaticState() const {
    const CarParameters& c = car_;
    const TruckStatics statics = calcTruckStatics();
    const double delta = statics.calcWheelDeflection(2, 1);
    const double bolsterZ = c.springTopAboveRail - delta - statics.getSpringCompression();
    const double plateZ = bolsterZ + c.centerPlateAboveSprings - statics.getCenterPlateDeflection();
    State y = State::Zero();
    y[3 * Wheelset + 2] = c.wheelRadius - delta;
    y[3 * Bolster + 2] = bolsterZ;
    y[3 * CarBody + 2] = plateZ + c.cgAboveCenterPlate;
    return y;
}

EomHalfCarModel::Point EomHalfCarModel::findStation(const State& y, int body, const Vec2& p) const {
    const double th = y[3 * body], thDot = y[kNumDofs + 3 * body];
    const Vec2 origin(y[3 * body + 1], y[3 * body + 2]);
    const Vec2 originVel(y[kNumDofs + 3 * body + 1], y[kNumDofs + 3 * body + 2]);
    Point pt;
    if (simp_.smallAngles) {
        pt.r = Vec2(p.x() - th * p.y(), p.y() + th * p.x());
        pt.v = originVel + thDot * Vec2(-p.y(), p.x());
    } else {
        const double c = std::cos(th), s = std::sin(th);
        pt.r = Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y());
        pt.v = originVel + thDot * Vec2(-pt.r.y(), pt.r.x());
    }
    pt.x = origin + pt.r;
    return pt;
}

void EomHalfCarModel::applyForce(Forces& f, int body, const Point& at, const Vec2& F) {
    f.generalized[3 * body] += at.r.x() * F.y() - at.r.y() * F.x();
    f.generalized[3 * body + 1] += F.x();
    f.generalized[3 * body + 2] += F.y();
}

EomHalfCarModel::Forces EomHalfCarModel::calcForces(double t, const State& y) const {
    Forces f;
    const Geometry& g = geom_;
    // Center plate: rim contacts and pin.
    for (int side : {0, 1}) {
        const Vec2 rim(kSideSign[side] * g.rimRadius, 0);
        const Point up = findStation(y, CarBody, g.plateOnCarBody + rim);
        const Point lo = findStation(y, Bolster, g.bowlOnBolster + rim);
        f.rim[side] = calcUnilateralNormalForce(lo.x.y() - up.x.y(), lo.v.y() - up.v.y(), laws_.rim);
        f.dissipatedPower += calcUnilateralContactDissipation(lo.x.y() - up.x.y(), lo.v.y() - up.v.y(), laws_.rim);
        f.elasticEnergy += calcUnilateralContactEnergy(lo.x.y() - up.x.y(), laws_.rim);
        applyForce(f, CarBody, up, Vec2(0, f.rim[side]));
        applyForce(f, Bolster, lo, Vec2(0, -f.rim[side]));
    }
    {
        const Point plate = findStation(y, CarBody, g.plateOnCarBody);
        const Point bowl = findStation(y, Bolster, g.bowlOnBolster);
        f.pin = -(laws_.pinStiffness * (plate.x.x() - bowl.x.x()) + laws_.pinDamping * (plate.v.x() - bowl.v.x()));
        f.dissipatedPower += calcViscousDissipation(laws_.pinDamping, plate.v.x() - bowl.v.x());
        f.elasticEnergy += calcLinearSpringEnergy(laws_.pinStiffness, plate.x.x() - bowl.x.x());
        applyForce(f, CarBody, plate, Vec2(f.pin, 0));
        applyForce(f, Bolster, bowl, Vec2(-f.pin, 0));
    }
    for (int side : {0, 1}) {
        // Side bearing.
        const Point pad = findStation(y, CarBody, g.padOnCarBody[side]);
        const Point brg = findStation(y, Bolster, g.bearingOnBolster[side]);
        f.sideBearing[side] = calcUnilateralNormalForce(brg.x.y() - pad.x.y() - laws_.sideBearingClearance,
                                                        brg.v.y() - pad.v.y(), laws_.sideBearing);
        f.dissipatedPower += calcUnilateralContactDissipation(brg.x.y() - pad.x.y() - laws_.sideBearingClearance,
                                                              brg.v.y() - pad.v.y(), laws_.sideBearing);
        f.elasticEnergy += calcUnilateralContactEnergy(brg.x.y() - pad.x.y() - laws_.sideBearingClearance, laws_.sideBearing);
        applyForce(f, CarBody, pad, Vec2(0, f.sideBearing[side]));
        applyForce(f, Bolster, brg, Vec2(0, -f.sideBearing[side]));

        // Suspension: springs and wedges between bolster end and side-frame seat.
        const Point b = findStation(y, Bolster, g.springOnBolster[side]);
        const Point s = findStation(y, Wheelset, g.seatOnWheelset[side]);
        const Vec2 rel = b.x - s.x, relVel = b.v - s.v;
        f.spring[side] = calcSpringForce(-rel.y());
        f.elasticEnergy += calcSpringEnergy(-rel.y());
        if (simp_.lockBolsterLateral) {
            const double c = calcLockedLinkDamping();
            f.lateralSpring[side] = laws_.lateral.rate * rel.x() + c * relVel.x();
            f.dissipatedPower += calcViscousDissipation(c, relVel.x());
            f.elasticEnergy += calcLinearSpringEnergy(laws_.lateral.rate, rel.x());
        } else {
            f.lateralSpring[side] = calcLateralSpringForce(rel.x(), relVel.x(), laws_.lateral);
            f.dissipatedPower += calcLateralSpringDissipation(rel.x(), relVel.x(), laws_.lateral);
            f.elasticEnergy += calcLateralSpringEnergy(rel.x(), laws_.lateral);
        }
        const int iv = 2 * side + kWedgeVertical, ih = 2 * side + kWedgeLateral;
        f.wedge[iv] = calcBristleFriction(y[2 * kNumDofs + iv], relVel.y(), laws_.wedgeVertical);
        f.wedge[ih] = calcBristleFriction(y[2 * kNumDofs + ih], relVel.x(), laws_.wedgeLateral);
        f.dissipatedPower += calcBristleDissipation(y[2 * kNumDofs + iv], relVel.y(), laws_.wedgeVertical) +
                             calcBristleDissipation(y[2 * kNumDofs + ih], relVel.x(), laws_.wedgeLateral);
        f.elasticEnergy += calcBristleEnergy(y[2 * kNumDofs + iv], laws_.wedgeVertical) +
                           calcBristleEnergy(y[2 * kNumDofs + ih], laws_.wedgeLateral);
        const Vec2 onBolster(-f.lateralSpring[side] + f.wedge[ih].force, f.spring[side] + f.wedge[iv].force);
        applyForce(f, Bolster, b, onBolster);
        applyForce(f, Wheelset, s, -onBolster);
    }
    // Wheel–rail.
    const RailState rail = rails_(t);
    std::array<Point, 2> tread;
    for (int side : {0, 1}) {
        tread[side] = findStation(y, Wheelset, g.tread[side]);
        const double delta = rail.z[side] - tread[side].x.y();
        f.wheel[side] = calcUnilateralNormalForce(delta, rail.zDot[side] - tread[side].v.y(), laws_.wheelVertical);
        f.dissipatedPower += calcUnilateralContactDissipation(delta, rail.zDot[side] - tread[side].v.y(), laws_.wheelVertical);
        f.railInputPower += f.wheel[side] * rail.zDot[side];
        f.elasticEnergy += calcUnilateralContactEnergy(delta, laws_.wheelVertical);
        f.wheelLift[side] = std::max(0.0, -delta);
    }
    if (wheelRail_.lateral == LateralWheelRail::CreepAndFlange) {
        // Each side its own creep and flange (WheelRailContact.h), two wheels lumped.
        for (int side : {0, 1}) {
            const double sg = side == 0 ? 1.0 : -1.0;
            const double e = tread[side].x.x() - g.railY[side], v = tread[side].v.x();
            f.wheelOffset[side] = e;
            const double creep = calcLateralCreepForce(v, rail.speed, f.wheel[side], 2, wheelRail_);
            f.dissipatedPower -= creep * v;
            const FlangeForces fl = calcFlangeForces(sg * e, sg * v, tread[side].x.y() - rail.z[side],
                                                     tread[side].v.y() - rail.zDot[side], rail.speed, 2,
                                                     laws_.wheelVertical, wheelRail_);
            f.wheelFlange[side] = fl.normal;
            f.wheel[side] += fl.vertical;
            f.wheelLateral[side] = creep + sg * fl.towardRail;
            f.dissipatedPower += fl.dissipatedPower;
            f.elasticEnergy += fl.energy;
            f.railInputPower += fl.vertical * rail.zDot[side];
            applyForce(f, Wheelset, tread[side], Vec2(f.wheelLateral[side], f.wheel[side]));
        }
    } else {
        const double total = f.wheel[0] + f.wheel[1];
        for (int side : {0, 1}) {
            const double share = simp_.equalLateralShares ? 0.5 : (total > 0 ? f.wheel[side] / total : 0.0);
            const double e = tread[side].x.x() - g.railY[side];
            f.wheelOffset[side] = e;
            f.wheelLateral[side] =
                -share * (laws_.wheelLateralStiffness * e + laws_.wheelLateralDamping * tread[side].v.x());
            // Energy audit: the restraint is the rails' lateral reaction, an external
            // force (not conservative with load shares; WheelRailContact.h): its work
            // on the wheel is rail input, and it stores and dissipates nothing.
            f.railInputPower += f.wheelLateral[side] * tread[side].v.x();
            applyForce(f, Wheelset, tread[side], Vec2(f.wheelLateral[side], f.wheel[side]));
        }
    }
    for (int b = 0; b < kNumBodies; ++b) f.generalized[3 * b + 2] -= mass_[b] * units::g;
    return f;
}

void EomHalfCarModel::calcStateDerivative(double t, const State& y, State& yDot) const {
    const Forces f = calcForces(t, y);
    yDot.head<kNumDofs>() = y.segment<kNumDofs>(kNumDofs);
    for (int b = 0; b < kNumBodies; ++b) {
        yDot[kNumDofs + 3 * b] = f.generalized[3 * b] / inertia_[b];
        yDot[kNumDofs + 3 * b + 1] = f.generalized[3 * b + 1] / mass_[b];
        yDot[kNumDofs + 3 * b + 2] = f.generalized[3 * b + 2] / mass_[b];
    }
    for (int i = 0; i < kNumBristles; ++i) yDot[2 * kNumDofs + i] = f.wedge[i].deflectionRate;
}

double EomHalfCarModel::calcStoredEnergy(double t, const State& y) const {
    double E = calcForces(t, y).elasticEnergy;
    for (int b = 0; b < kNumBodies; ++b) {
        const double thDot = y[kNumDofs + 3 * b], yDot = y[kNumDofs + 3 * b + 1], zDot = y[kNumDofs + 3 * b + 2];
        E += 0.5 * inertia_[b] * thDot * thDot + 0.5 * mass_[b] * (yDot * yDot + zDot * zDot);
        E += mass_[b] * units::g * y[3 * b + 2];
    }
    return E;
}

void EomHalfCarModel::calcEnergyRates(double t, const State& y, double* rates) const {
    const Forces f = calcForces(t, y);
    rates[0] = f.railInputPower;
    rates[1] = f.dissipatedPower;
}

void EomHalfCarModel::declareChannels() {
    ChannelTable<Sample>& c = channels_;
    const double lb = units::lbf, in = units::inch, deg = units::degree;
    declareHalfCarBodyChannels(c);
    for (int side : {0, 1}) {
        const char* S = kSideName[side];
        const int iv = 2 * side + kWedgeVertical, ih = 2 * side + kWedgeLateral;
        c.add(fmt::format("spring_F_{}", S), "lb", [=](const Sample& s) { return s.forces.spring[side] / lb; });
        c.add(fmt::format("lateral_spring_F_{}", S), "lb",
              [=](const Sample& s) { return s.forces.lateralSpring[side] / lb; });
        c.add(fmt::format("wedge_vertical_F_{}", S), "lb", [=](const Sample& s) { return s.forces.wedge[iv].force / lb; });
        c.add(fmt::format("wedge_vertical_slip_F_{}", S), "",
              [=](const Sample& s) { return s.forces.wedge[iv].slipping ? 1.0 : 0.0; });
        c.add(fmt::format("wedge_lateral_F_{}", S), "lb", [=](const Sample& s) { return s.forces.wedge[ih].force / lb; });
        c.add(fmt::format("wedge_lateral_slip_F_{}", S), "",
              [=](const Sample& s) { return s.forces.wedge[ih].slipping ? 1.0 : 0.0; });
    }
    c.add("bolster_roll_F", "deg", [=](const Sample& s) { return s.y[3 * Bolster] / deg; });
    c.add("bolster_lateral_F", "in", [=](const Sample& s) { return s.y[3 * Bolster + 1] / in; });
    declareEquivalentWheelsetChannels(c, true, wheelRail_.lateral == LateralWheelRail::CreepAndFlange);
    declareEnergyChannels(c);
    // With equal lateral shares a lifted wheel still carries half the lateral restraint,
    // so its L/V would be ±infinity: a value of the simplification, not of the wheel. Such
    // a model records no L/V (not evaluated, as the reduced model). Before this, the
    // runaway check stopped every run that lifted a wheel, among them the describing
    // function's twin orbits (its stability evidence on the wheel-lift stretches).
    declareHalfCarFreightChannels(c, calcStaticWheelLoad(), !simp_.equalLateralShares);
}

EomHalfCarModel::Sample EomHalfCarModel::calcSample(double t, const State& y, const double* energyIntegrals) const {
    Sample s;
    s.forces = calcForces(t, y);
    s.y = y;
    const Forces& f = s.forces;
    const RailState rail = rails_(t);
    s.roll = y[3 * CarBody];
    s.verticalFromStatic = y[3 * CarBody + 2] - staticCarBodyZ_;
    s.lateral = y[3 * CarBody + 1];
    s.crossLevel = rail.z[1] - rail.z[0];
    s.centerPlate = f.rim[0] + f.rim[1];
    for (int side : {0, 1}) {
        s.sideBearing[side] = f.sideBearing[side];
        s.wheel[side] = f.wheel[side];
        s.wheelLift[side] = f.wheelLift[side];
        s.wheelOffset[side] = f.wheelOffset[side];
        s.wheelLateral[side] = f.wheelLateral[side];
        s.wheelFlange[side] = f.wheelFlange[side];
    }
    // The car body's accelerations, as calcStateDerivative forms them.
    s.verticalAccel = f.generalized[3 * CarBody + 2] / mass_[CarBody];
    s.lateralAccel = f.generalized[3 * CarBody + 1] / mass_[CarBody];
    s.energyStored = calcStoredEnergy(t, y);
    s.energyInput = energyIntegrals ? energyIntegrals[0] : std::numeric_limits<double>::quiet_NaN();
    s.energyDissipated = energyIntegrals ? energyIntegrals[1] : std::numeric_limits<double>::quiet_NaN();
    return s;
}

void EomHalfCarModel::calcChannels(double t, const State& y, std::vector<double>& out,
                                   const double* energyIntegrals) const {
    channels_.evaluate(calcSample(t, y, energyIntegrals), out);
}

std::vector<std::string> EomHalfCarModel::getStateNames() const {
    std::vector<std::string> names;
    const char* bodies[] = {"car_body", "bolster", "wheelset"};
    const char* coords[] = {"roll", "y", "z"};
    for (const char* rate : {"", "_rate"})
        for (const char* b : bodies)
            for (const char* q : coords) names.push_back(fmt::format("{}_{}{}", b, q, rate));
    for (int side : {0, 1})
        for (const char* dir : {"vertical", "lateral"}) names.push_back(fmt::format("wedge_{}_{}_w", dir, kSideName[side]));
    return names;
}

RailStateFunction makeEquivalentWheelsetInput(const TrackInput& track, const TrackMotion& motion, double wheelbase) {
    return [track, motion, wheelbase](double t) {
        RailState r;
        const double s = motion.calcDistance(t), V = motion.calcSpeed(t);
        r.speed = V;
        for (double s0 : {0.0, -wheelbase}) {
            const RailPoint p = track.calcRails(s + s0);
            for (int i = 0; i < 2; ++i) {
                r.z[i] += 0.5 * p.z[i];
                r.zDot[i] += 0.5 * p.slope[i] * V;
            }
        }
        return r;
    };
}

RailStateFunction makeSinusoidalCrossLevel(double amplitude, double omega) {
    return [amplitude, omega](double t) {
        const double c = amplitude * std::sin(omega * t), cDot = amplitude * omega * std::cos(omega * t);
        RailState r;
        r.z = {-c / 2, c / 2};  // cross-level = right − left
        r.zDot = {-cDot / 2, cDot / 2};
        return r;
    };
}

}  // namespace rockroll
