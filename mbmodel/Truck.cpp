#include "mbmodel/Truck.h"
#include "contacts/CustomForce.h"

#include <cmath>
#include <fmt/format.h>

using SimTK::State; using SimTK::Vec3; using SimTK::Vector; using SimTK::MobilizedBody; using SimTK::Transform;
using SimTK::Rotation; using SimTK::Mat33; using SimTK::Body; using SimTK::MassProperties; using SimTK::Inertia;
using SimTK::Stage; using SimTK::Force; using SimTK::SimbodyMatterSubsystem; using SimTK::GeneralForceSubsystem;
using SimTK::System; using SimTK::Integrator;

namespace rockroll {

namespace {
constexpr int kLeft = 0, kRight = 1;
constexpr double kSideSign[2] = {+1.0, -1.0};
constexpr const char* kSideName[2] = {"L", "R"};

double criticalDamping(double stiffness, double mass, double ratio) {
    return 2 * ratio * std::sqrt(stiffness * mass);
}
}  // namespace

MobilizedBody::Planar makeCrossSectionBody(MobilizedBody& ground, double x, const Body::Rigid& body) {
    // Frame F: x_F = y_G, y_F = z_G, z_F = x_G, so the Planar mobilizer's
    // rotation about z_F is roll about the track axis and its translations are y, z.
    const Rotation R_GF(Mat33(0, 0, 1, 1, 0, 0, 0, 1, 0), true);
    return MobilizedBody::Planar(ground, Transform(R_GF, Vec3(x, 0, 0)), body, Transform(R_GF));
}

Truck::Truck(SimbodyMatterSubsystem& matter, GeneralForceSubsystem& forces, const MobilizedBody& carBody,
             const Vec3& p_CarBodyPlate, const CarParameters& car, TruckSpec spec)
    : car_(car), spec_(std::move(spec)) {
    addBodies(matter);
    addElements(forces, carBody, p_CarBodyPlate);
}

void Truck::addBodies(SimbodyMatterSubsystem& matter) {
    MobilizedBody& ground = matter.updGround();
    const double mB = car_.bolsterWeight / units::g;
    const double IB = car_.bolsterRollInertia;
    bolster_ = makeCrossSectionBody(ground, spec_.x, Body::Rigid(MassProperties(mB, Vec3(0), Inertia(IB))));
    for (const WheelsetSpec& ws : spec_.wheelsets) {
        const double n = ws.lumpedWheelsets;
        const double m = n * (car_.wheelsetWeight + car_.sideFrameWeight) / units::g;
        const double I = n * car_.wheelsetRollInertia;
        const double f = spec_.wheelsetMassScale;
        wheelsets_.push_back(
            makeCrossSectionBody(ground, ws.x, Body::Rigid(MassProperties(f * m, Vec3(0), Inertia(f * I)))));
    }
}

SuspensionLink Truck::makeSuspensionLink(double sideSign) const {
    SuspensionLink link;
    link.bolster = bolster_;
    link.p_BolsterPoint = Vec3(0, sideSign * car_.springOffset, 0);
    for (const auto& ws : wheelsets_) {
        link.seat.bodies.push_back(ws);
        link.seat.stations.push_back(
            Vec3(0, sideSign * car_.springOffset, car_.springTopAboveRail - car_.wheelRadius));
    }
    return link;
}

void Truck::addElements(GeneralForceSubsystem& forces, const MobilizedBody& carBody, const Vec3& p_CarBodyPlate) {
    const double scale = car_.contactStiffnessScale;
    const double d = car_.contactDissipation;
    const double mB = car_.bolsterWeight / units::g;

    // Center plate.
    CenterPlateGeometry cpg{carBody, p_CarBodyPlate, bolster_, Vec3(0, 0, car_.centerPlateAboveSprings),
                            car_.centerPlateDiameter / 2,
                            spec_.threeDimensional ? int(std::lround(car_.centerPlateRimPoints)) : 2};
    CenterPlateLaw cpl;
    cpl.rim = {scale * car_.centerPlateStiffness / cpg.rimPoints, d};
    cpl.pinStiffness = scale * car_.centerPinStiffness;
    cpl.pinDamping = criticalDamping(cpl.pinStiffness, mB, car_.lateralContactDampingRatio);
    cpl.longitudinalPin = spec_.threeDimensional;
    if (spec_.threeDimensional && car_.centerPlateFriction > 0) {
        const double staticTorque = car_.centerPlateFriction * spec_.carBodyLoad * (2.0 / 3.0) * cpg.radius;
        cpl.yawFrictionCoefficient = car_.centerPlateFriction;
        cpl.yawBristleStiffness = staticTorque / car_.centerPlateYawBristleAngle;
        cpl.yawBristleDamping = criticalDamping(cpl.yawBristleStiffness, car_.yawInertia / 2,
                                                car_.frictionBristleDampingRatio);
    }
    centerPlate_ = &addCustomForce<CenterPlateContact>(forces, forces, cpg, cpl);

    const double kWedgeV = car_.verticalFriction / car_.frictionBristleDeflection;
    const double kWedgeH = car_.lateralFriction / car_.frictionBristleDeflection;
    const double zeta = car_.frictionBristleDampingRatio;
    for (int side : {kLeft, kRight}) {
        const double sg = kSideSign[side];
        // Side bearing: pad on the car body, bearing top on the bolster, nominally
        // at the same height; the clearance is the gap.
        VerticalPointPair sb{carBody,
                             p_CarBodyPlate + Vec3(0, sg * car_.sideBearingOffset,
                                                   car_.sideBearingAboveSprings - car_.centerPlateAboveSprings),
                             bolster_, Vec3(0, sg * car_.sideBearingOffset, car_.sideBearingAboveSprings),
                             car_.sideBearingClearance};
        sideBearing_[side] = &addCustomForce<SideBearing>(forces, sb, UnilateralContactLaw{scale * car_.sideBearingStiffness, d});

        verticalSpring_[side] = &addCustomForce<VerticalSpringGroup>(
            forces, makeSuspensionLink(sg),
            VerticalSpringLaw{car_.springVerticalRate, car_.springTravel, car_.bottomingRate});

        lateralSpring_[side] = &addCustomForce<LateralSpringGroup>(
            forces, makeSuspensionLink(sg),
            LateralSpringLaw{car_.springLateralRate, car_.gibClearance, car_.gibRate, d});

        BristleFrictionLaw fv{car_.verticalFriction, kWedgeV, criticalDamping(kWedgeV, mB / 2, zeta)};
        BristleFrictionLaw fh{car_.lateralFriction, kWedgeH, criticalDamping(kWedgeH, mB / 2, zeta)};
        wedge_[side] = &addCustomForce<FrictionWedge>(forces, forces, makeSuspensionLink(sg), fv, fh);
    }

    for (size_t i = 0; i < wheelsets_.size(); ++i) {
        const WheelsetSpec& ws = spec_.wheelsets[i];
        const double n = ws.lumpedWheelsets;
        const double m = n * (car_.wheelsetWeight + car_.sideFrameWeight) / units::g;
        // Attribution: the weight a scaled-down mass no longer carries, as a constant force.
        if (spec_.wheelsetMassScale != 1 && spec_.wheelsetGravity)
            Force::ConstantForce(forces, wheelsets_[i], Vec3(0), Vec3(0, 0, -(1 - spec_.wheelsetMassScale) * m * units::g));
        WheelRailLaw law;
        law.vertical = {n * scale * car_.wheelRailStiffness, d};
        law.lateralStiffness = n * scale * car_.wheelRailLateralStiffness;
        law.lateralDamping = criticalDamping(law.lateralStiffness, m, car_.lateralContactDampingRatio);
        const std::array<Vec3, 2> tread{Vec3(0, car_.gauge / 2, -car_.wheelRadius),
                                        Vec3(0, -car_.gauge / 2, -car_.wheelRadius)};
        wheelRail_.push_back(&addCustomForce<WheelRailContact>(
            forces, wheelsets_[i], tread, std::array<double, 2>{car_.gauge / 2, -car_.gauge / 2}, ws.rails, law));
    }
}

double Truck::calcStaticWheelLoad(int i) const {
    const double springLoad = (spec_.carBodyLoad + car_.bolsterWeight) / 2;
    const double n = spec_.wheelsets[i].lumpedWheelsets;
    const double ownWeight = spec_.wheelsetGravity ? n * (car_.wheelsetWeight + car_.sideFrameWeight) / 2 : 0;
    return springLoad / double(wheelsets_.size()) + ownWeight;
}

double Truck::setStaticState(State& s) const {
    double seatZ = 0;
    for (size_t i = 0; i < wheelsets_.size(); ++i) {
        const double n = spec_.wheelsets[i].lumpedWheelsets;
        const double delta = calcStaticWheelLoad(int(i)) / (n * car_.contactStiffnessScale * car_.wheelRailStiffness);
        wheelsets_[i].setOneQ(s, 2, car_.wheelRadius - delta);
        seatZ += (car_.springTopAboveRail - delta) / double(wheelsets_.size());
    }
    const double springLoad = (spec_.carBodyLoad + car_.bolsterWeight) / 2;
    const double Z = calcVerticalSpringCompression(
        springLoad, {car_.springVerticalRate, car_.springTravel, car_.bottomingRate});
    const double bolsterZ = seatZ - Z;
    bolster_.setOneQ(s, 2, bolsterZ);
    const double plateDelta = spec_.carBodyLoad / (car_.contactStiffnessScale * car_.centerPlateStiffness);
    return bolsterZ + car_.centerPlateAboveSprings - plateDelta;
}

TruckPowers Truck::calcPowers(const State& s) const {
    TruckPowers p;
    p.dissipated = centerPlate_->calcDissipatedPower(s);
    for (int side : {kLeft, kRight})
        p.dissipated += sideBearing_[side]->calcDissipatedPower(s) + lateralSpring_[side]->calcDissipatedPower(s) +
                        wedge_[side]->calcDissipatedPower(s);
    for (const auto* wr : wheelRail_) {
        const WheelRailForces f = wr->calcForces(s);
        p.railInput += f.railInputPower;
        p.dissipated += f.dissipatedPower;
    }
    return p;
}

void Truck::declareChannels(ChannelLayout& c) const {
    const std::string& T = spec_.label;
    c.add(fmt::format("cross_level_{}_in", T));
    c.centerPlate.push_back(c.add(fmt::format("center_plate_{}_lb", T)));
    for (int side : {kLeft, kRight})
        c.sideBearing.push_back(c.add(fmt::format("side_bearing_{}_{}_lb", T, kSideName[side])));
    for (int side : {kLeft, kRight}) {
        const char* S = kSideName[side];
        c.add(fmt::format("spring_{}_{}_lb", T, S));
        c.add(fmt::format("lateral_spring_{}_{}_lb", T, S));
        c.add(fmt::format("wedge_vertical_{}_{}_lb", T, S));
        c.add(fmt::format("wedge_vertical_slip_{}_{}", T, S));
        c.add(fmt::format("wedge_lateral_{}_{}_lb", T, S));
        c.add(fmt::format("wedge_lateral_slip_{}_{}", T, S));
    }
    c.add(fmt::format("bolster_roll_{}_deg", T));
    c.add(fmt::format("bolster_lateral_{}_in", T));
    for (int side : {kLeft, kRight}) {
        const int idx = c.add(fmt::format("wheels_{}_{}_lb", T, kSideName[side]));
        c.truckSideWheelLoad.push_back(idx);
        if (wheelsets_.size() == 1) c.singleWheelLoad.push_back(idx);
    }
    for (size_t i = 0; i < wheelsets_.size(); ++i)
        for (int side : {kLeft, kRight}) {
            if (wheelsets_.size() > 1)
                c.singleWheelLoad.push_back(c.add(fmt::format("wheel_{}{}_{}_lb", T, i + 1, kSideName[side])));
            c.wheelLift.push_back(c.add(fmt::format("wheel_lift_{}{}_{}_in", T, i + 1, kSideName[side])));
        }
    for (size_t i = 0; i < wheelsets_.size(); ++i) {
        ChannelLayout::Wheelset w;
        w.liftLeft = c.find(fmt::format("wheel_lift_{}{}_{}_in", T, i + 1, kSideName[kLeft]));
        w.liftRight = c.find(fmt::format("wheel_lift_{}{}_{}_in", T, i + 1, kSideName[kRight]));
        w.lateral = c.add(fmt::format("wheelset_lateral_{}{}_in", T, i + 1));
        c.wheelsets.push_back(w);
    }
}

double* Truck::calcChannels(const State& s, double* out) const {
    const double lb = units::lbf, in = units::inch;
    double cross = 0;
    std::vector<WheelRailForces> wheel;
    for (const auto* wr : wheelRail_) {
        wheel.push_back(wr->calcForces(s));
        const RailHeights r = wr->getRailHeights(s.getTime());
        cross += (r.z[kRight] - r.z[kLeft]) / double(wheelRail_.size());
    }
    *out++ = cross / in;
    *out++ = centerPlate_->calcForces(s).vertical / lb;
    for (int side : {kLeft, kRight}) *out++ = sideBearing_[side]->calcForce(s) / lb;
    for (int side : {kLeft, kRight}) {
        *out++ = verticalSpring_[side]->calcForce(s) / lb;
        *out++ = lateralSpring_[side]->calcForce(s) / lb;
        const BristleFrictionState v = wedge_[side]->calcFriction(s, FrictionWedge::Vertical);
        const BristleFrictionState h = wedge_[side]->calcFriction(s, FrictionWedge::Lateral);
        *out++ = v.force / lb;
        *out++ = v.slipping ? 1 : 0;
        *out++ = h.force / lb;
        *out++ = h.slipping ? 1 : 0;
    }
    *out++ = bolster_.getOneQ(s, 0) / units::degree;
    *out++ = bolster_.getOneQ(s, 1) / in;
    for (int side : {kLeft, kRight}) {
        double sum = 0;
        for (const auto& w : wheel) sum += w.normal[side];
        *out++ = sum / lb;
    }
    for (size_t i = 0; i < wheel.size(); ++i)
        for (int side : {kLeft, kRight}) {
            if (wheel.size() > 1) *out++ = wheel[i].normal[side] / lb;
            *out++ = wheel[i].lift[side] / in;
        }
    for (const auto& w : wheel) *out++ = (w.offset[0] + w.offset[1]) / 2 / in;
    return out;
}

}  // namespace rockroll
