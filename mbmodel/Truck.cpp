#include "mbmodel/Truck.h"
#include "contacts/BristleFriction.h"
#include "contacts/CustomForce.h"
#include "mbmodel/CarSide.h"

#include <cmath>
#include <fmt/format.h>

using SimTK::State; using SimTK::Vec3; using SimTK::Vector; using SimTK::MobilizedBody; using SimTK::Transform;
using SimTK::Rotation; using SimTK::Mat33; using SimTK::Body; using SimTK::MassProperties; using SimTK::Inertia;
using SimTK::Stage; using SimTK::Force; using SimTK::SimbodyMatterSubsystem; using SimTK::GeneralForceSubsystem;
using SimTK::System; using SimTK::Integrator;

namespace rockroll {

namespace {
/// The lift channel of wheelset i's wheel on one side ("wheel_lift_F1_L").
std::string makeWheelLiftName(const std::string& truck, size_t i, int side) {
    return fmt::format("wheel_lift_{}{}_{}", truck, i + 1, kSideName[side]);
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
        const double f = spec_.unsprungMassScale;
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
    cpl.pinDamping = calcBristleDamping(cpl.pinStiffness, mB, car_.lateralContactDampingRatio);
    cpl.longitudinalPin = spec_.threeDimensional;
    if (spec_.threeDimensional && car_.centerPlateFriction > 0) {
        const double staticTorque = car_.centerPlateFriction * spec_.carBodyLoad * (2.0 / 3.0) * cpg.radius;
        cpl.yawFrictionCoefficient = car_.centerPlateFriction;
        cpl.yawBristleStiffness = staticTorque / car_.centerPlateYawBristleAngle;
        cpl.yawBristleDamping = calcBristleDamping(cpl.yawBristleStiffness, car_.yawInertia / 2,
                                                car_.frictionBristleDampingRatio);
    }
    centerPlate_ = &addCustomForce<CenterPlateContact>(forces, forces, cpg, cpl);

    const double kWedgeV = car_.calcVerticalBristleStiffness();
    const double kWedgeH = car_.calcLateralBristleStiffness();
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

        BristleFrictionLaw fv{car_.verticalFriction, kWedgeV, calcBristleDamping(kWedgeV, mB / 2, zeta)};
        BristleFrictionLaw fh{car_.lateralFriction, kWedgeH, calcBristleDamping(kWedgeH, mB / 2, zeta)};
        wedge_[side] = &addCustomForce<FrictionWedge>(forces, forces, makeSuspensionLink(sg), fv, fh);
    }

    for (size_t i = 0; i < wheelsets_.size(); ++i) {
        const WheelsetSpec& ws = spec_.wheelsets[i];
        const double n = ws.lumpedWheelsets;
        const double m = n * (car_.wheelsetWeight + car_.sideFrameWeight) / units::g;
        // Attribution: the weight a scaled-down mass no longer carries, as a constant force.
        if (spec_.unsprungMassScale != 1 && spec_.unsprungGravity)
            Force::ConstantForce(forces, wheelsets_[i], Vec3(0), Vec3(0, 0, -(1 - spec_.unsprungMassScale) * m * units::g));
        WheelRailLaw law;
        law.vertical = {n * scale * car_.wheelRailStiffness, d};
        law.lateralStiffness = n * scale * car_.wheelRailLateralStiffness;
        law.lateralDamping = calcBristleDamping(law.lateralStiffness, m, car_.lateralContactDampingRatio);
        law.settings = spec_.wheelRail;
        law.wheels = n;
        const std::array<Vec3, 2> tread{Vec3(0, car_.gauge / 2, -car_.wheelRadius),
                                        Vec3(0, -car_.gauge / 2, -car_.wheelRadius)};
        wheelRail_.push_back(&addCustomForce<WheelRailContact>(
            forces, forces, wheelsets_[i], tread, std::array<double, 2>{car_.gauge / 2, -car_.gauge / 2}, ws.rails, law));
    }
}

TruckStatics Truck::calcStatics() const {
    TruckStaticLoad load;
    load.carBody = spec_.carBodyLoad;
    load.unsprungWeight = spec_.unsprungGravity;
    return TruckStatics(car_, load);
}

double Truck::calcStaticWheelLoad(int i) const {
    return calcStatics().calcWheelLoad(spec_.wheelsets[i].lumpedWheelsets, int(wheelsets_.size()));
}

double Truck::setStaticState(State& s) const {
    const TruckStatics statics = calcStatics();
    const int bodies = int(wheelsets_.size());
    double seatZ = 0;
    for (int i = 0; i < bodies; ++i) {
        const double delta = statics.calcWheelDeflection(spec_.wheelsets[i].lumpedWheelsets, bodies);
        wheelsets_[i].setOneQ(s, 2, car_.wheelRadius - delta);
        seatZ += (car_.springTopAboveRail - delta) / double(bodies);
    }
    const double bolsterZ = seatZ - statics.getSpringCompression();
    bolster_.setOneQ(s, 2, bolsterZ);
    return bolsterZ + car_.centerPlateAboveSprings - statics.getCenterPlateDeflection();
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

void Truck::declareChannels(ChannelTable<CarSample>& c, int index) const {
    const std::string& T = spec_.label;
    const double lb = units::lbf, in = units::inch;
    using R = ChannelRole;
    auto truck = [index](const CarSample& s) -> const TruckSample& { return s.trucks[index]; };
    c.add(fmt::format("cross_level_{}", T), "in", [=](const CarSample& s) { return truck(s).crossLevel / in; });
    c.add({fmt::format("center_plate_{}", T), "lb", R::CenterPlate, T},
          [=](const CarSample& s) { return truck(s).centerPlate / lb; });
    for (int side : {kLeft, kRight})
        c.add({fmt::format("side_bearing_{}_{}", T, kSideName[side]), "lb", R::SideBearing, T},
              [=](const CarSample& s) { return truck(s).sideBearing[side] / lb; });
    for (int side : {kLeft, kRight}) {
        const char* S = kSideName[side];
        c.add(fmt::format("spring_{}_{}", T, S), "lb", [=](const CarSample& s) { return truck(s).spring[side] / lb; });
        c.add(fmt::format("lateral_spring_{}_{}", T, S), "lb",
              [=](const CarSample& s) { return truck(s).lateralSpring[side] / lb; });
        c.add(fmt::format("wedge_vertical_{}_{}", T, S), "lb",
              [=](const CarSample& s) { return truck(s).wedgeVertical[side].force / lb; });
        c.add(fmt::format("wedge_vertical_slip_{}_{}", T, S), "",
              [=](const CarSample& s) { return truck(s).wedgeVertical[side].slipping ? 1.0 : 0.0; });
        c.add(fmt::format("wedge_lateral_{}_{}", T, S), "lb",
              [=](const CarSample& s) { return truck(s).wedgeLateral[side].force / lb; });
        c.add(fmt::format("wedge_lateral_slip_{}_{}", T, S), "",
              [=](const CarSample& s) { return truck(s).wedgeLateral[side].slipping ? 1.0 : 0.0; });
    }
    c.add(fmt::format("bolster_roll_{}", T), "deg",
          [=](const CarSample& s) { return truck(s).bolsterRoll / units::degree; });
    c.add(fmt::format("bolster_lateral_{}", T), "in", [=](const CarSample& s) { return truck(s).bolsterLateral / in; });
    const bool lumped = wheelsets_.size() == 1;  // one (equivalent) wheelset: its wheels are the truck side's
    for (int side : {kLeft, kRight})
        c.add(fmt::format("wheels_{}_{}", T, kSideName[side]), "lb",
              lumped ? R::TruckSideWheelLoad | R::SingleWheelLoad : R::TruckSideWheelLoad, [=](const CarSample& s) {
                  double sum = 0;
                  for (const auto& w : truck(s).wheels) sum += w.vertical[side];
                  return sum / lb;
              });
    std::vector<ChannelLayout::Wheelset> wheelsets(wheelsets_.size());
    for (size_t i = 0; i < wheelsets_.size(); ++i)
        for (int side : {kLeft, kRight}) {
            if (!lumped)
                c.add(fmt::format("wheel_{}{}_{}", T, i + 1, kSideName[side]), "lb", R::SingleWheelLoad,
                      [=](const CarSample& s) { return truck(s).wheels[i].vertical[side] / lb; });
            const int lift = c.add(makeWheelLiftName(T, i, side), "in", R::WheelLift,
                                   [=](const CarSample& s) { return truck(s).wheels[i].lift[side] / in; });
            (side == kLeft ? wheelsets[i].liftLeft : wheelsets[i].liftRight) = lift;
            if (spec_.wheelRail.lateral == LateralWheelRail::CreepAndFlange)
                wheelsets[i].flange[side] =
                    c.add(fmt::format("flange_{}{}_{}", T, i + 1, kSideName[side]), "lb",
                          [=](const CarSample& s) { return truck(s).wheels[i].flange[side] / lb; });
        }
    for (size_t i = 0; i < wheelsets_.size(); ++i) {
        wheelsets[i].lateral = c.add(fmt::format("wheelset_lateral_{}{}", T, i + 1), "in", R::WheelsetLateral,
                                     [=](const CarSample& s) {
                                         const auto& w = truck(s).wheels[i];
                                         return (w.offset[0] + w.offset[1]) / 2 / in;
                                     });
        c.addWheelset(wheelsets[i]);
    }
}

void Truck::declareFreightChannels(ChannelTable<CarSample>& c, int index,
                                   const std::vector<std::array<double, 2>>& staticLoads) const {
    const std::string& T = spec_.label;
    auto truck = [index](const CarSample& s) -> const TruckSample& { return s.trucks[index]; };
    for (size_t i = 0; i < wheelsets_.size(); ++i) {
        ChannelLayout::Wheelset* layout = c.findWheelset(makeWheelLiftName(T, i, kLeft));
        for (int side : {kLeft, kRight}) {
            const double staticLoad = staticLoads.empty() ? calcStaticWheelLoad(int(i)) : staticLoads[i][size_t(side)];
            c.add(fmt::format("wheel_unloading_{}{}_{}", T, i + 1, kSideName[side]), "ratio",
                  ChannelRole::WheelUnloading, [=](const CarSample& s) {
                      return calcWheelUnloading(truck(s).wheels[i].vertical[side], staticLoad);
                  });
            // One equivalent wheelset: its wheel is the truck side's, and so is its L/V.
            const bool lumped = wheelsets_.size() == 1;
            const int lv = c.add(fmt::format("l_over_v_{}{}_{}", T, i + 1, kSideName[side]), "ratio",
                                 lumped ? ChannelRole::LOverV | ChannelRole::TruckSideLOverV : ChannelRole::LOverV,
                                 [=](const CarSample& s) {
                                     const WheelRailForces& w = truck(s).wheels[i];
                                     return calcLOverV(w.lateral[side], w.vertical[side]);
                                 });
            if (layout) layout->lOverV[side] = lv;
        }
    }
    if (wheelsets_.size() > 1)
        for (int side : {kLeft, kRight})
            c.add(fmt::format("truck_side_l_over_v_{}_{}", T, kSideName[side]), "ratio", ChannelRole::TruckSideLOverV,
                  [=](const CarSample& s) {
                      double lateral = 0, vertical = 0;
                      for (const auto& w : truck(s).wheels) lateral += w.lateral[side], vertical += w.vertical[side];
                      return calcLOverV(lateral, vertical);
                  });
}

TruckSample Truck::calcSample(const State& s) const {
    TruckSample t;
    for (const auto* wr : wheelRail_) {
        t.wheels.push_back(wr->calcForces(s));
        const RailHeights r = wr->getRailHeights(s.getTime());
        t.crossLevel += (r.z[kRight] - r.z[kLeft]) / double(wheelRail_.size());
    }
    t.centerPlate = centerPlate_->calcForces(s).vertical;
    for (int side : {kLeft, kRight}) {
        t.sideBearing[side] = sideBearing_[side]->calcForce(s);
        t.spring[side] = verticalSpring_[side]->calcForce(s);
        t.lateralSpring[side] = lateralSpring_[side]->calcForce(s);
        t.wedgeVertical[side] = wedge_[side]->calcFriction(s, FrictionWedge::Vertical);
        t.wedgeLateral[side] = wedge_[side]->calcFriction(s, FrictionWedge::Lateral);
    }
    t.bolsterRoll = bolster_.getOneQ(s, 0);
    t.bolsterLateral = bolster_.getOneQ(s, 1);
    return t;
}

}  // namespace rockroll
