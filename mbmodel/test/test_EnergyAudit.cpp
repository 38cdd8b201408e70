// Energy audit (docs/model.md, "Energy audit"): the element laws' elastic energy and
// dissipated power, the balance function, and the balance W = ΔE + D of every
// time-domain model on a short severe run.
#include "contacts/BristleFriction.h"
#include "contacts/SpringGroupLaws.h"
#include "contacts/UnilateralContactLaw.h"
#include "contacts/WheelRailContact.h"
#include "mbmodel/Truck.h"
#include "mbmodel/EnergyAudit.h"
#include "scenarios/ScenarioRun.h"
#include "tests/TestCases.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <cmath>

using namespace rockroll;

namespace {
/// Central difference of V at x.
template <class F>
double derivative(F V, double x, double h) {
    return (V(x + h) - V(x - h)) / (2 * h);
}

ChannelLayout layoutOf(const TimeHistory& h) {
    ChannelLayout l;
    l.names.assign(h.names.begin() + 1, h.names.end());
    l.energyStored = l.find("energy_stored_J");
    l.energyInput = l.find("energy_input_J");
    l.energyDissipated = l.find("energy_dissipated_J");
    return l;
}
}  // namespace

// ---- element laws ------------------------------------------------------------

TEST(EnergyLaws, UnilateralContactEnergyGivesTheElasticForce) {
    const UnilateralContactLaw law{2e8, 5};
    for (double delta : {1e-5, 3e-4, 2e-3}) {
        const double dV = derivative([&](double d) { return calcUnilateralContactEnergy(d, law); }, delta, 1e-8);
        // Without rate the force is the elastic part alone: f = dV/dδ.
        EXPECT_NEAR(dV, calcUnilateralNormalForce(delta, 0, law), 1e-6 * law.stiffness * delta) << delta;
    }
    EXPECT_EQ(calcUnilateralContactEnergy(-1e-3, law), 0.0);
    EXPECT_EQ(calcUnilateralContactEnergy(0, law), 0.0);
}

TEST(EnergyLaws, UnilateralContactDissipationIsNonNegativeAndZeroWhenOpen) {
    const UnilateralContactLaw law{2e8, 5};
    for (double delta : {-1e-3, 0.0, 1e-5, 1e-3})
        for (double rate : {-2.0, -0.3, -0.19, -1e-3, 0.0, 1e-3, 0.5}) {
            const double P = calcUnilateralContactDissipation(delta, rate, law);
            EXPECT_GE(P, 0.0) << delta << " " << rate;
            if (delta <= 0) {
                EXPECT_EQ(P, 0.0);
            }
            // Power balance of the element: f·δ̇ = dV/dt + P.
            const double f = calcUnilateralNormalForce(delta, rate, law);
            const double Vdot = (delta > 0 ? law.stiffness * delta : 0.0) * rate;
            EXPECT_NEAR(f * rate, Vdot + P, 1e-9 * (1 + std::abs(f * rate))) << delta << " " << rate;
        }
    // Clamped (separating faster than 1/d): f = 0, the stored energy released is dissipated.
    EXPECT_EQ(calcUnilateralNormalForce(1e-3, -0.3, law), 0.0);
    EXPECT_NEAR(calcUnilateralContactDissipation(1e-3, -0.3, law), 2e8 * 1e-3 * 0.3, 1e-6);
}

TEST(EnergyLaws, VerticalSpringEnergyGivesTheForceOnEverySegment) {
    const VerticalSpringLaw law{3.65e6, 0.0937, 1.16e8};
    for (double Z : {-0.01, 0.001, 0.05, 0.0936, 0.0938, 0.1, 0.12}) {
        const double dV = derivative([&](double z) { return calcVerticalSpringEnergy(z, law); }, Z, 1e-7);
        EXPECT_NEAR(dV, calcVerticalSpringForce(Z, law), 1e-5 * (1 + std::abs(calcVerticalSpringForce(Z, law))))
            << Z;
    }
    EXPECT_EQ(calcVerticalSpringEnergy(-0.01, law), 0.0);
    // Continuous at the bottoming point.
    EXPECT_NEAR(calcVerticalSpringEnergy(law.travel * (1 + 1e-12), law), 0.5 * law.rate * law.travel * law.travel, 1e-3);
}

TEST(EnergyLaws, LateralSpringAndGibEnergyGiveTheForceAndTheGibDissipates) {
    const LateralSpringLaw law{1.55e6, 0.0095, 1.16e8, 5};
    for (double Y : {-0.02, -0.0096, -0.005, 0.0, 0.004, 0.0094, 0.0097, 0.015}) {
        const double dV = derivative([&](double y) { return calcLateralSpringEnergy(y, law); }, Y, 1e-8);
        const double P = calcLateralSpringForce(Y, 0, law);
        EXPECT_NEAR(dV, P, 1e-5 * (1 + std::abs(P))) << Y;
        for (double rate : {-0.5, -0.01, 0.0, 0.02, 0.4}) {
            const double D = calcLateralSpringDissipation(Y, rate, law);
            EXPECT_GE(D, 0.0) << Y << " " << rate;
            if (std::abs(Y) <= law.gibClearance) {
                EXPECT_EQ(D, 0.0) << "gib open";
            }
            // f·Ẏ = dV/dt + P_diss.
            EXPECT_NEAR(calcLateralSpringForce(Y, rate, law) * rate, dV * rate + D,
                        1e-5 * (1 + std::abs(calcLateralSpringForce(Y, rate, law) * rate)));
        }
    }
}

TEST(EnergyLaws, BristleEnergyGivesTheStickForceAndDissipationIsNonNegative) {
    const BristleFrictionLaw law{17800, 17800 / 2.54e-4, 2500};
    const double wMax = law.limit / law.stiffness;
    // In stick at rest the force is the elastic one: −F = dV/dw.
    for (double w : {-0.5 * wMax, 0.1 * wMax, 0.9 * wMax}) {
        const double dV = derivative([&](double x) { return calcBristleEnergy(x, law); }, w, 1e-9);
        EXPECT_NEAR(dV, -calcBristleFriction(w, 0, law).force, 1e-6 * law.limit) << w;
    }
    // Dissipation ≥ 0 everywhere, including the blends, the clamp and an
    // overstretched bristle relaxing, and with no normal load.
    for (double limit : {law.limit, 0.5 * law.limit, 0.0}) {
        BristleFrictionLaw l = law;
        l.limit = limit;
        for (double w = -1.6 * wMax; w <= 1.6 * wMax; w += 0.013 * wMax)
            for (double v : {-0.3, -0.01, -1e-3, -3e-4, 0.0, 2e-4, 7e-4, 2e-3, 0.05, 0.4})
                EXPECT_GE(calcBristleDissipation(w, v, l), -1e-9 * law.limit) << limit << " " << w << " " << v;
    }
    // Sticking without damping: nothing dissipated. Sliding at the limit: F_c·|v|.
    BristleFrictionLaw undamped = law;
    undamped.damping = 0;
    EXPECT_NEAR(calcBristleDissipation(0.5 * wMax, 0.01, undamped), 0.0, 1e-9);
    EXPECT_NEAR(calcBristleDissipation(wMax, 0.05, law), law.limit * 0.05, 1e-9 * law.limit);
    EXPECT_NEAR(calcBristleDissipation(-wMax, -0.05, law), law.limit * 0.05, 1e-9 * law.limit);
}

// ---- balance function ------------------------------------------------------------

TEST(EnergyAudit, BalanceErrorOfAHistory) {
    TimeHistory h;
    h.names = {"t_s", "roll_deg", "energy_stored_J", "energy_input_J", "energy_dissipated_J"};
    h.samples = {{0, 0, 100, 0, 0}, {1, 0, 130, 50, 19}, {2, 0, 120, 80, 62}};
    ChannelLayout none;
    none.names = {"roll_deg"};
    EXPECT_TRUE(std::isnan(calcEnergyBalanceError(h, none)));
    const ChannelLayout l = layoutOf(h);
    // Last sample: W = 80, ΔE = 20, D = 62 → |80 − 20 − 62| / 80.
    EXPECT_DOUBLE_EQ(calcEnergyBalanceError(h, l), 2.0 / 80);
    // t = 1: |50 − 30 − 19| / 50 = 0.02 < 0.025.
    EXPECT_DOUBLE_EQ(calcWorstEnergyBalanceError(h, l), 2.0 / 80);
    h.samples.set(1, {1, 0, 130, 50, 10});  // |50 − 30 − 10| / 50 = 0.2
    EXPECT_DOUBLE_EQ(calcWorstEnergyBalanceError(h, l), 0.2);
    EXPECT_DOUBLE_EQ(calcWorstEnergyBalanceError(h, l, 1.5), 2.0 / 80);
    // Dissipation larger than the input sets the scale.
    h.samples.set(2, {2, 0, 60, 10, 52});  // |10 + 40 − 52| / 52
    EXPECT_DOUBLE_EQ(calcEnergyBalanceError(h, l), 2.0 / 52);
}

// ---- models ------------------------------------------------------------------------

namespace {
// Severe rocking within a few seconds: 1 in cross-level near resonance (the
// default case's 0.75 in needs ~8 s to build up to wheel lift).
Scenario makeSevereCase(const std::string& model, double duration) {
    return test_cases::makeCase(model, 1.0, 16.5, duration);
}

/// `bound`: the summary's end-of-run energy_balance_error (held to 1 %, docs/model.md "Energy audit");
/// `worstBound`: the worst ratio after 0.5 s (docs/model.md "Energy audit").
void expectBalanced(const ScenarioRun& run, const std::string& model, double bound, double worstBound = -1) {
    if (worstBound < 0) worstBound = bound;
    const TimeHistory& h = run.result.history;
    const ChannelLayout l = layoutOf(h);
    ASSERT_GE(l.energyStored, 0) << model;
    const auto& first = h.samples.front();
    EXPECT_EQ(first[l.energyInput + 1], 0.0) << model;
    EXPECT_EQ(first[l.energyDissipated + 1], 0.0) << model;
    const auto& last = h.samples.back();
    const double W = last[l.energyInput + 1], D = last[l.energyDissipated + 1];
    EXPECT_GT(D, 1000.0) << model << ": the run must exchange real energy";  // J
    EXPECT_GT(W, 0.0) << model;
    const double err = calcEnergyBalanceError(h, l), worst = calcWorstEnergyBalanceError(h, l, 0.5);
    EXPECT_LE(err, bound) << model << " W " << W << " D " << D;
    EXPECT_LE(worst, worstBound) << model;
    // Dissipation never decreases (up to the integrator's interpolation between
    // its steps, a polynomial that may dip by a few 1e-5 of D at output times).
    for (size_t k = 1; k < h.samples.size(); ++k) {
        const double before = h.samples[k - 1][l.energyDissipated + 1];
        ASSERT_GE(h.samples[k][l.energyDissipated + 1], before - 1e-4 * before - 1e-6) << model << " sample " << k;
    }
    std::printf("[energy] %s: W = %.1f J, D = %.1f J, error %.5f (worst after 0.5 s %.5f), regime %s\n",
                model.c_str(), W, D, err, worst, run.summary.regime.c_str());
}
}  // namespace

TEST(EnergyAudit, HalfCarAndEomBalanceWithinOnePercentOnASevereRun) {
    // At the default accuracy (1e-4) the end of the run is held to the summary's 1 %. The
    // worst moment is not held here: it is the energy meter's integration error, and on this
    // case the half car's scatters between 0.06 % and 2.5 % when the accuracy moves between
    // 0.9e-4 and 1.1e-4 (docs/model.md "Energy audit"); the next test holds it at 1e-5.
    for (const char* model : {"halfcar", "eom"}) {
        const ScenarioRun run = runScenario(makeSevereCase(model, 4.0));
        EXPECT_NE(run.summary.regime, "light") << model;
        expectBalanced(run, model, 0.01, 1.0);
    }
}

TEST(EnergyAudit, HalfCarAndEomBalanceThroughoutASevereRunAtAccuracy1e5) {
    // Measured worst after 0.5 s at accuracy 0.9e-5, 1e-5 and 1.1e-5: 0.007-0.008 % (half
    // car), 0.001-0.005 % (eom); end of run <= 0.003 %.
    for (const char* model : {"halfcar", "eom"}) {
        Scenario sc = makeSevereCase(model, 4.0);
        sc.run.integrator.accuracy = 1e-5;
        const ScenarioRun run = runScenario(sc);
        EXPECT_NE(run.summary.regime, "light") << model;
        expectBalanced(run, model, 0.001, 0.002);
    }
}

TEST(EnergyAudit, FullCarBalancesWithinOnePercentOnASevereRun) {
    const ScenarioRun run = runScenario(makeSevereCase("fullcar", 4.0));
    expectBalanced(run, "fullcar", 0.01);
}

TEST(EnergyAudit, ContinuedRunCountsItsEnergiesFromItsOwnStart) {
    const Scenario sc = makeSevereCase("halfcar", 1.5);
    const ScenarioRun first = runScenario(sc);
    RunStart start;
    start.from = first.restart;
    start.staticReference = first.staticReference;
    const ScenarioRun next = runScenario(sc, start);
    expectBalanced(next, "halfcar (continued)", 0.01);
}


// ---- wheel–rail lateral restraint --------------------------------------------------

// The load-share restraint F_y,i = −(N_i/ΣN)·(k_y·e_i + c_y·ė_i) is not conservative:
// Σ (N_i/ΣN)·½·k_y·e_i² is no potential of it (the shares change with the loads), and
// a wheelset landing on one wheel after drifting while airborne gets the full restraint
// at once. Booked as an element it cost the 50 in cross-level case 328 kJ of balance.
// The audit books it as the rails' force: the element's power identity
//     power to the wheelset = P_in − dV/dt − P_diss
// must hold at any state, with loads changing and the wheelset rolled (e_L ≠ e_R).
TEST(EnergyAudit, WheelRailContactPowerIdentityWithChangingLoadShares) {
    using namespace SimTK;
    MultibodySystem system;
    SimbodyMatterSubsystem matter(system);
    GeneralForceSubsystem forces(system);
    const double m = 1450, r = 0.4191, g = 0.71755;
    MobilizedBody::Planar ws = makeCrossSectionBody(matter.updGround(), 0, Body::Rigid(MassProperties(m, Vec3(0), Inertia(1160))));
    WheelRailLaw law;
    law.vertical = {8.756e8, 5};
    law.lateralStiffness = 3.5e8;
    law.lateralDamping = 2 * 0.2 * std::sqrt(law.lateralStiffness * m);
    auto rails = [](double t) {
        RailHeights h;
        h.z[0] = 0.01 * std::sin(3 * t);
        h.zDot[0] = 0.03 * std::cos(3 * t);
        return h;
    };
    auto* wr = new WheelRailContact(forces, ws, {Vec3(0, g, -r), Vec3(0, -g, -r)}, {g, -g}, rails, law);
    Force::Custom(forces, wr);
    system.realizeTopology();
    struct Case { double roll, y, z, rollRate, yRate, zRate; };
    // Both wheels down with different loads and rates; one wheel lifted.
    for (const Case c : {Case{0.02, 0.01, r - 2e-4, 0.5, 0.3, -0.02}, Case{-0.03, -0.02, r - 1e-4, -0.4, 0.2, 0.01},
                         Case{0.01, 0.004, r - 1.5e-4, 0.2, -0.1, 0.03}}) {
        State s = system.getDefaultState();
        s.setTime(0.1);
        ws.setOneQ(s, 0, c.roll); ws.setOneQ(s, 1, c.y); ws.setOneQ(s, 2, c.z);
        ws.setOneU(s, 0, c.rollRate); ws.setOneU(s, 1, c.yRate); ws.setOneU(s, 2, c.zRate);
        system.realize(s, Stage::Dynamics);
        const WheelRailForces f = wr->calcForces(s);
        Vector_<SpatialVec> bf(matter.getNumBodies(), SpatialVec(Vec3(0), Vec3(0)));
        Vector_<Vec3> pf;
        Vector mf(s.getNU(), 0.0);
        wr->calcForce(s, bf, pf, mf);
        const SpatialVec V = ws.getBodyVelocity(s);
        const double toBody = ~bf[ws.getMobilizedBodyIndex()][0] * V[0] + ~bf[ws.getMobilizedBodyIndex()][1] * V[1];
        // dV/dt along the motion: t and q advanced, u as it is (V is a function of q and t).
        const double h = 1e-7;
        auto energyAt = [&](double dt) {
            State sh = s;
            sh.setTime(s.getTime() + dt);
            sh.updQ() = s.getQ() + dt * s.getQDot();
            system.realize(sh, Stage::Dynamics);
            return wr->calcPotentialEnergy(sh);
        };
        const double Vdot = (energyAt(h) - energyAt(-h)) / (2 * h);
        const double scale = std::abs(f.railInputPower) + std::abs(Vdot) + f.dissipatedPower;
        EXPECT_GT(std::abs(f.lateral[0] + f.lateral[1]), 1e3) << "the restraint must be loaded";
        EXPECT_NEAR(toBody, f.railInputPower - Vdot - f.dissipatedPower, 1e-5 * scale)
            << "N " << f.normal[0] << " " << f.normal[1];
    }
    // Landing on one wheel (the other up) at a 10 mm lateral offset: no work is done
    // across the instant of touch-down, so the stored energy must not jump (the share-
    // weighted restraint energy jumped by ½·k_y·e² = 17.5 kJ here).
    State s = system.getDefaultState();
    s.setTime(0);  // rails level at t = 0
    ws.setOneQ(s, 0, 0.004);
    ws.setOneQ(s, 1, 0.01);
    auto storedAt = [&](double gap) {
        // Right tread point z = −g·sin θ − r·cos θ; place it `gap` above the rail.
        ws.setOneQ(s, 2, gap + g * std::sin(0.004) + r * std::cos(0.004));
        system.realize(s, Stage::Dynamics);
        return wr->calcPotentialEnergy(s);
    };
    EXPECT_NEAR(storedAt(-1e-9), storedAt(1e-9), 1.0) << "touch-down must not create stored energy";
}
