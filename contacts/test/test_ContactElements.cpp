// Each force element against its law, inside a small Simbody system.
#include "contacts/CenterPlateContact.h"
#include "contacts/FrictionWedge.h"
#include "contacts/LateralSpringGroup.h"
#include "contacts/SideBearing.h"
#include "contacts/VerticalSpringGroup.h"
#include "contacts/WheelRailContact.h"
#include "mbmodel/Truck.h"

#include <gtest/gtest.h>

using namespace rockroll;
using SimTK::Vec3;

namespace {

/// Ground plus two cross-section bodies (lateral, vertical, roll), no gravity.
struct Rig {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::MobilizedBody upper, lower;
    Rig() {
        SimTK::Body::Rigid body(SimTK::MassProperties(100, Vec3(0), SimTK::Inertia(10)));
        upper = makeCrossSectionBody(matter.updGround(), 0, body);
        lower = makeCrossSectionBody(matter.updGround(), 0, body);
    }
    SimTK::State init() {
        system.realizeTopology();
        SimTK::State s = system.getDefaultState();
        return s;
    }
    static void place(const SimTK::MobilizedBody& b, SimTK::State& s, double y, double z, double roll = 0) {
        b.setOneQ(s, 0, roll);
        b.setOneQ(s, 1, y);
        b.setOneQ(s, 2, z);
    }
    /// Net force on a body (mass 100 kg, no gravity) along y (axis 1) or z (axis 2),
    /// from its acceleration.
    double netForce(const SimTK::State& s, const SimTK::MobilizedBody& b, int axis) {
        system.realize(s, SimTK::Stage::Acceleration);
        return 100 * b.getBodyOriginAcceleration(s)[axis];
    }
};

/// Link at lateral offset y on both bodies (y = 0: through the body origins, so
/// a force along it does not roll the test body).
SuspensionLink linkBetween(const SimTK::MobilizedBody& bolster, const SimTK::MobilizedBody& frame, double y = 1) {
    SuspensionLink l;
    l.bolster = bolster;
    l.p_BolsterPoint = Vec3(0, y, 0);
    l.seat.bodies = {frame};
    l.seat.stations = {Vec3(0, y, 0)};
    return l;
}
}  // namespace

TEST(VerticalSpringGroupLaw, FreeLinearAndBottoming) {
    const VerticalSpringLaw law{1e6, 0.09, 1e8};
    EXPECT_EQ(calcVerticalSpringForce(-0.01, law), 0.0);
    EXPECT_DOUBLE_EQ(calcVerticalSpringForce(0.05, law), 5e4);
    EXPECT_DOUBLE_EQ(calcVerticalSpringForce(0.09, law), 9e4);
    EXPECT_DOUBLE_EQ(calcVerticalSpringForce(0.10, law), 9e4 + 1e8 * 0.01);
    for (double P : {0.0, 3e4, 9e4, 2e6}) EXPECT_NEAR(calcVerticalSpringForce(calcVerticalSpringCompression(P, law), law), P, 1e-6);
}

TEST(VerticalSpringGroup, ElementPushesBolsterUpWhenCompressedAndNothingWhenExtended) {
    Rig rig;
    const VerticalSpringLaw law{1e6, 0.09, 1e8};
    SimTK::Force::Custom(rig.forces, new VerticalSpringGroup(linkBetween(rig.upper, rig.lower), law));
    SimTK::State s = rig.init();
    Rig::place(rig.upper, s, 0, -0.03);  // 30 mm below the free position
    EXPECT_NEAR(rig.netForce(s, rig.upper, 2), 3e4, 1e-6);
    EXPECT_NEAR(rig.netForce(s, rig.lower, 2), -3e4, 1e-6);
    Rig::place(rig.upper, s, 0, +0.01);  // lifted off its springs
    EXPECT_EQ(rig.netForce(s, rig.upper, 2), 0.0);
}

TEST(LateralSpringGroupLaw, LinearInsideClearanceGibBeyond) {
    const LateralSpringLaw law{1.5e6, 0.0095, 1.15e8, 0.0};
    EXPECT_DOUBLE_EQ(calcLateralSpringForce(0.005, 0, law), 1.5e6 * 0.005);
    EXPECT_DOUBLE_EQ(calcLateralSpringForce(-0.005, 0, law), -1.5e6 * 0.005);
    EXPECT_NEAR(calcLateralSpringForce(0.0105, 0, law), 1.5e6 * 0.0105 + 1.15e8 * 0.001, 1e-6);
    EXPECT_NEAR(calcLateralSpringForce(-0.0105, 0, law), -(1.5e6 * 0.0105 + 1.15e8 * 0.001), 1e-6);
}

TEST(SideBearing, OpenUntilClearanceTakenUpThenCompliant) {
    Rig rig;
    const double c = 0.00635, k = 1.75e9;
    auto* sb = new SideBearing({rig.upper, Vec3(0, 0.635, 0), rig.lower, Vec3(0, 0.635, 0), c}, {k, 0});
    SimTK::Force::Custom(rig.forces, sb);
    SimTK::State s = rig.init();
    Rig::place(rig.upper, s, 0, -0.5 * c);  // half the clearance taken up
    rig.system.realize(s, SimTK::Stage::Velocity);
    EXPECT_EQ(sb->calcForce(s), 0.0);
    EXPECT_NEAR(sb->calcGap(s), 0.5 * c, 1e-12);
    Rig::place(rig.upper, s, 0, -c - 1e-4);
    rig.system.realize(s, SimTK::Stage::Velocity);
    EXPECT_NEAR(sb->calcForce(s), k * 1e-4, 1e-3);
    EXPECT_NEAR(rig.netForce(s, rig.upper, 2), k * 1e-4, 1e-3);
}

TEST(CenterPlateContact, PlanarTwoRimPointsShareLoadAndTipOntoOne) {
    Rig rig;
    const double k = 1e9, a = 0.1778;
    auto* cp = new CenterPlateContact(rig.forces, {rig.upper, Vec3(0), rig.lower, Vec3(0), a, 2},
                                      {{k, 0}, 1e8, 0, false, 0, 0, 0});
    SimTK::Force::Custom(rig.forces, cp);
    SimTK::State s = rig.init();
    Rig::place(rig.upper, s, 0, -1e-4);
    rig.system.realize(s, SimTK::Stage::Velocity);
    CenterPlateForces f = cp->calcForces(s);
    ASSERT_EQ(f.rim.size(), 2u);
    EXPECT_NEAR(f.rim[0], k * 1e-4, 1e-3);
    EXPECT_NEAR(f.rim[1], k * 1e-4, 1e-3);
    // Roll the plate +0.01 rad: the left rim (+y) rises 1.8 mm, the right one sinks.
    Rig::place(rig.upper, s, 0, -1e-4, 0.01);
    rig.system.realize(s, SimTK::Stage::Velocity);
    f = cp->calcForces(s);
    EXPECT_EQ(f.rim[0], 0.0);
    EXPECT_NEAR(f.rim[1], k * (1e-4 + a * std::sin(0.01)), 1.0);
    // Lifted clear: no vertical force, the pin still carries lateral force.
    Rig::place(rig.upper, s, 0.001, 0.01);
    rig.system.realize(s, SimTK::Stage::Velocity);
    f = cp->calcForces(s);
    EXPECT_EQ(f.vertical, 0.0);
    EXPECT_NEAR(f.pin[1], -1e8 * 0.001, 1e-6);
}

TEST(CenterPlateContact, RingOfRimPointsTipsAboutAnyRimPoint) {
    // Full 3-D car body on a Free mobilizer over a planar bolster.
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    SimTK::GeneralForceSubsystem forces(system);
    SimTK::Body::Rigid body(SimTK::MassProperties(100, Vec3(0), SimTK::Inertia(10)));
    SimTK::MobilizedBody::Free car(matter.updGround(), body);
    auto bolster = makeCrossSectionBody(matter.updGround(), 0, body);
    auto* cp = new CenterPlateContact(forces, {car, Vec3(0), bolster, Vec3(0), 0.1778, 16},
                                      {{1e8, 0}, 1e8, 0, true, 0, 0, 0});
    SimTK::Force::Custom(forces, cp);
    system.realizeTopology();
    SimTK::State s = system.getDefaultState();
    car.setQToFitTransform(s, SimTK::Transform(SimTK::Rotation(0.01, SimTK::YAxis), Vec3(0, 0, -1e-4)));
    system.realize(s, SimTK::Stage::Velocity);
    const CenterPlateForces f = cp->calcForces(s);
    // Pitch +0.01 rad about y lowers the front (+x) rim and lifts the rear.
    EXPECT_GT(f.rim[0], 0.0);   // φ = 0: front
    EXPECT_EQ(f.rim[8], 0.0);   // φ = 180°: rear
    EXPECT_GT(f.rim[4], 0.0);   // sides still seated at 1e-4 m
    int loaded = 0;
    for (double r : f.rim) loaded += r > 0;
    EXPECT_LT(loaded, 16);
}

TEST(FrictionWedge, SticksWithoutCreepBelowLimitAndSlipsAtIt) {
    for (double fraction : {0.6, 1.3}) {  // 0.6: the step overshoot (ζ = 0.3) stays below the limit
        Rig rig;
        const double Fc = 17800, kb = Fc / 2.54e-4;
        auto* w = new FrictionWedge(rig.forces, linkBetween(rig.upper, rig.matter.updGround(), 0),
                                    {Fc, kb, 2 * 0.3 * std::sqrt(kb * 100)}, {Fc, kb, 2 * 0.3 * std::sqrt(kb * 100)});
        SimTK::Force::Custom(rig.forces, w);
        SimTK::Force::ConstantForce(rig.forces, rig.upper, Vec3(0), Vec3(0, 0, fraction * Fc));
        SimTK::Force::ConstantForce(rig.forces, rig.lower, Vec3(0), Vec3(0, 0, 0));
        SimTK::State s = rig.init();
        SimTK::CPodesIntegrator integ(rig.system);
        integ.setAccuracy(1e-6);
        integ.initialize(s);
        auto advance = [&](double t) {
            while (integ.getTime() < t && !integ.isSimulationOver()) integ.stepTo(t);
        };
        advance(0.5);
        const double z1 = rig.upper.getOneQ(integ.getState(), 2);
        const double v1 = rig.upper.getOneU(integ.getState(), 2);
        advance(1.5);
        const double z2 = rig.upper.getOneQ(integ.getState(), 2);
        const double v2 = rig.upper.getOneU(integ.getState(), 2);
        if (fraction < 1) {
            EXPECT_NEAR(z1, fraction * Fc / kb, 1e-6);
            EXPECT_NEAR(z2, z1, 1e-8) << "creep under a steady force below the Coulomb limit";
            EXPECT_FALSE(w->calcFriction(integ.getState(), FrictionWedge::Vertical).slipping);
        } else {
            EXPECT_NEAR((v2 - v1) / 1.0, (fraction - 1) * Fc / 100, 0.01 * (fraction - 1) * Fc / 100);
            EXPECT_TRUE(w->calcFriction(integ.getState(), FrictionWedge::Vertical).slipping);
            EXPECT_NEAR(w->calcFriction(integ.getState(), FrictionWedge::Vertical).force, -Fc, 1e-6 * Fc);
        }
    }
}

TEST(WheelRailContact, LiftedWheelCarriesNothingAndLateralGoesThroughTheOther) {
    Rig rig;
    const double k = 8.8e8, g = 0.7176, r = 0.419;
    auto* wr = new WheelRailContact(rig.forces, rig.upper, {Vec3(0, g, -r), Vec3(0, -g, -r)}, {g, -g},
                                    [](double) { return RailHeights{}; }, {{k, 0}, 3.5e8, 0, {}, 1});
    SimTK::Force::Custom(rig.forces, wr);
    SimTK::State s = rig.init();
    Rig::place(rig.upper, s, 0, r - 1e-4);
    rig.system.realize(s, SimTK::Stage::Velocity);
    WheelRailForces f = wr->calcForces(s);
    EXPECT_NEAR(f.normal[0], k * 1e-4, 1e-3);
    EXPECT_NEAR(f.normal[1], k * 1e-4, 1e-3);
    EXPECT_EQ(f.lift[0], 0.0);
    // Roll so that the left wheel (+y) lifts about 4 mm; push the wheelset 1 mm left.
    const double roll = 0.006;
    Rig::place(rig.upper, s, 0.001, r - 1e-4, roll);
    rig.system.realize(s, SimTK::Stage::Velocity);
    f = wr->calcForces(s);
    EXPECT_EQ(f.normal[0], 0.0);
    EXPECT_GT(f.lift[0], 0.003);
    EXPECT_GT(f.normal[1], 0.0);
    EXPECT_EQ(f.lateral[0], 0.0);
    EXPECT_LT(f.lateral[1], 0.0);  // restoring, all through the right rail
}

TEST(CenterPlateContact, YawFrictionSticksBelowItsLimitAndSlipsAbove) {
    // A 3-D car body seated (by gravity) on the plate ring of a fixed bowl, twisted
    // by a constant yaw torque. Limit T_c = μ·N·(2/3)·a_c.
    const double m = 1000, g = 9.80665, mu = 0.25, a = 0.1778, Izz = 500;
    const double Tc = mu * m * g * (2.0 / 3.0) * a;
    for (double fraction : {0.5, 1.5}) {
        SimTK::MultibodySystem system;
        SimTK::SimbodyMatterSubsystem matter(system);
        SimTK::GeneralForceSubsystem forces(system);
        SimTK::MobilizedBody::Free car(matter.updGround(),
                                       SimTK::Body::Rigid(SimTK::MassProperties(m, Vec3(0), SimTK::Inertia(Izz))));
        const double kYaw = Tc / 1e-4;
        auto* cp = new CenterPlateContact(forces, {car, Vec3(0), matter.updGround(), Vec3(0), a, 16},
                                          {{1e8 / 16, 0}, 1e8, 2 * 0.5 * std::sqrt(1e8 * m), true, mu, kYaw,
                                           2 * 0.5 * std::sqrt(kYaw * Izz)});
        SimTK::Force::Custom(forces, cp);
        SimTK::Force::UniformGravity(forces, matter, Vec3(0, 0, -g));
        SimTK::Force::ConstantTorque(forces, car, Vec3(0, 0, fraction * Tc));
        system.realizeTopology();
        SimTK::State s = system.getDefaultState();
        car.setQToFitTranslation(s, Vec3(0, 0, -m * g / 1e8));  // seated at rest
        SimTK::CPodesIntegrator integ(system);
        integ.setAccuracy(1e-6);
        integ.initialize(s);
        auto yawAt = [&](double t) {
            while (integ.getTime() < t && !integ.isSimulationOver()) integ.stepTo(t);
            return car.getBodyRotation(integ.getState()).convertRotationToBodyFixedXYZ()[2];
        };
        const double y1 = yawAt(0.5), y2 = yawAt(1.5);
        if (fraction < 1) {
            EXPECT_NEAR(y2, y1, 1e-4 * std::abs(y1)) << "yaw creep below the friction limit";
            EXPECT_LT(std::abs(y1), 1e-4);
        } else {
            EXPECT_GT(y2 - y1, 0.01) << "no slip above the friction limit";
            system.realize(integ.getState(), SimTK::Stage::Velocity);
            EXPECT_NEAR(cp->calcForces(integ.getState()).yawTorque, -Tc, 0.02 * Tc);
        }
    }
}

// The elements keep one evaluation per realization in the State (DynamicsCache.h).
// What they return from it must equal a fresh evaluation, and a change of z, u or
// time must never expose the old value.
TEST(DynamicsCache, CachedEvaluationEqualsFreshAndNeverGoesStale) {
    Rig rig;
    const double Fc = 17800, kb = Fc / 2.54e-4;
    auto* w = new FrictionWedge(rig.forces, linkBetween(rig.upper, rig.lower, 0), {Fc, kb, 50}, {Fc, kb, 50});
    SimTK::Force::Custom(rig.forces, w);
    SimTK::State s = rig.init();
    Rig::place(rig.upper, s, 0, 0.01);
    rig.upper.setOneU(s, 2, 0.2);
    w->setDeflection(s, FrictionWedge::Vertical, 1e-4);

    rig.system.realize(s, SimTK::Stage::Velocity);  // below Dynamics: computed afresh
    const double freshP = w->calcDissipatedPower(s);
    const double freshF = w->calcFriction(s, FrictionWedge::Vertical).force;
    EXPECT_NE(freshP, 0);
    rig.system.realize(s, SimTK::Stage::Acceleration);  // calcForce has stored its evaluation
    EXPECT_EQ(w->calcDissipatedPower(s), freshP);
    EXPECT_EQ(w->calcFriction(s, FrictionWedge::Vertical).force, freshF);

    w->setDeflection(s, FrictionWedge::Vertical, -1e-4);  // z changed: the stored value is stale
    const double afterZ = w->calcFriction(s, FrictionWedge::Vertical).force;
    EXPECT_NE(afterZ, freshF);
    rig.system.realize(s, SimTK::Stage::Acceleration);
    EXPECT_EQ(w->calcFriction(s, FrictionWedge::Vertical).force, afterZ);

    const double beforeU = w->calcDissipatedPower(s);
    rig.upper.setOneU(s, 2, -0.5);  // u changed
    rig.system.realize(s, SimTK::Stage::Velocity);
    const double afterU = w->calcDissipatedPower(s);
    EXPECT_NE(afterU, beforeU);
    rig.system.realize(s, SimTK::Stage::Acceleration);
    EXPECT_EQ(w->calcDissipatedPower(s), afterU);
}

TEST(WheelRailContact, AWheelsetPushedHarderThanMuNSlidesUntilItsFlangeTakesTheLoad) {
    Rig rig;
    const double k = 8.8e8, g = 0.7176, r = 0.419;
    WheelRailLaw law{{k, 5}, 0, 0, {}, 1};
    law.settings.lateral = LateralWheelRail::CreepAndFlange;  // μ 0.5, 75°, 0.375 in clearance
    const double V = 7.0;
    auto* wr = new WheelRailContact(rig.forces, rig.upper, {Vec3(0, g, -r), Vec3(0, -g, -r)}, {g, -g},
                                    [V](double) {
                                        RailHeights h;
                                        h.speed = V;
                                        return h;
                                    },
                                    law);
    SimTK::Force::Custom(rig.forces, wr);
    const double N = 1e5, L = 0.6 * N;  // lateral push above μ·N
    SimTK::Force::ConstantForce(rig.forces, rig.upper, Vec3(0), Vec3(0, L, -N));
    SimTK::State s = rig.init();
    Rig::place(rig.upper, s, 0, r - N / (2 * k));
    Rig::place(rig.lower, s, 0, -1);
    SimTK::RungeKuttaMersonIntegrator integ(rig.system);
    integ.setAccuracy(1e-6);
    SimTK::TimeStepper ts(rig.system, integ);
    ts.initialize(s);
    // Sliding: toward the left rail (+y), its creep forces oppose it, and no flange yet.
    ts.stepTo(0.005);
    rig.system.realize(integ.getState(), SimTK::Stage::Dynamics);
    WheelRailForces f = wr->calcForces(integ.getState());
    EXPECT_GT(rig.upper.getOneU(integ.getState(), 1), 0.0);
    EXPECT_LT(f.creep[0] + f.creep[1], 0.0);
    EXPECT_EQ(f.flange[0], 0.0);
    // At rest against the left flange: the flange carries the push, and its vertical part
    // is the rail's too.
    ts.stepTo(1.0);
    const SimTK::State& end = integ.getState();
    rig.system.realize(end, SimTK::Stage::Dynamics);
    f = wr->calcForces(end);
    EXPECT_NEAR(rig.upper.getOneU(end, 1), 0.0, 1e-4);
    EXPECT_GT(f.offset[0], law.settings.flangewayClearance);
    EXPECT_GT(f.flange[0], 0.0);
    EXPECT_EQ(f.flange[1], 0.0);
    EXPECT_NEAR(f.lateral[0] + f.lateral[1], -L, 1e-3 * L);
    EXPECT_NEAR(f.vertical[0] + f.vertical[1], N, 1e-3 * N);
    // The flange's normal force: its lateral part balances what creep does not.
    EXPECT_NEAR(f.flange[0] * std::sin(law.settings.flangeAngle), L + f.creep[0] + f.creep[1], 1e-3 * L);
    // The left wheel's own L/V is not the right one's.
    EXPECT_GT(std::abs(f.lateral[0] / f.vertical[0] - f.lateral[1] / f.vertical[1]), 0.1);
}
