#pragma once
// Wheel–rail contact of one wheelset (two wheels, or two truck sides of n lumped wheels).
//
// Vertical, per wheel i: a unilateral compliant contact between the wheel's
// tread point and its rail top, δ_i = z_rail,i(t) − z_tread,i,
// N_i = f_unilateral(δ_i, δ̇_i): the wheel may lift off.
//
// Lateral, by WheelRailSettings::lateral (contacts/WheelRailLaws.h):
//
// Restraint (the 1976 report's). The wheelset is held to the track at rail-head
// height by the wheels in contact. Each wheel carries its load share of a stiff
// lateral restraint,
//
//     F_y,i = −(N_i / ΣN)·(k_y·e_i + c_y·ė_i),   e_i = y_tread,i − y_rail,i,
//
// so when one wheel lifts all lateral force passes through the other rail and
// the wheelset pivots about it; with both wheels up there is none. A wheel's
// L/V is then −(k_y·e_i + c_y·ė_i)/ΣN: the wheelset's force over the wheelset's
// load, not its own, so it cannot show one wheel climbing.
//
// Creep and flange. Each wheel carries its own lateral creep force on the tread,
// saturating at μ·N_i (calcLateralCreepForce, slip velocity ẏ_tread,i), and past
// the flangeway clearance a flange contact on its rail's gauge face at the flange
// angle (calcFlangeForces), whose normal force has a vertical part and whose
// friction is limited by μ as well. Tread and flange can be in contact at once.
// The wheel's vertical force is V_i = N_i + F_z,flange,i and its lateral force
// L_i = F_creep,i + F_y,flange,i, each its own.
//
// Energy audit: the system boundary runs between the contacts and the rails.
// The rails move only vertically, so through the contacts they do work at the
// rate Σ V_i·ż_rail,i; the contacts store Σ ½·k·δ_i² (and ½·k·p_i² in a flange)
// and dissipate their Hunt–Crossley parts, the creep power −F_creep,i·ẏ_i ≥ 0 and
// the flange friction's. The restraint is the rails' lateral reaction and is
// booked as an external force: its work on the wheelset, Σ F_y,i·ė_i, is rail input, and it holds no stored
// energy. It cannot be booked as an element: with the shares s_i = N_i/ΣN it is
// not conservative. Σ s_i·½·k_y·e_i² is not a potential of it (the shares change
// with the loads), and when one wheel lands with the other up (s_i: 0 → 1) the
// restraint springs on at full stiffness at whatever offset the airborne
// wheelset drifted to, so that "energy" jumps by ½·k_y·e_i² with no work done
// (measured: −328 kJ of imbalance by 0.8 s on a 50 in cross-level case, where
// the wheelset left both rails and drifted 6.5 in; docs/model.md "Energy audit").
#include "contacts/DynamicsCache.h"
#include "contacts/UnilateralContact.h"
#include "contacts/WheelRailLaws.h"

#include <array>
#include <functional>

namespace rockroll {

/// Rail top heights and their rates under one wheelset at time t (left, right).
struct RailHeights {
    double z[2] = {0, 0};     ///< [m]
    double zDot[2] = {0, 0};  ///< [m/s]
    double speed = 0;         ///< forward speed V [m/s] (the creepages' denominator)
};
using RailInputFunction = std::function<RailHeights(double t)>;

struct WheelRailLaw {
    UnilateralContactLaw vertical;  ///< per wheel (its n lumped wheels together); the flange's normal law too
    double lateralStiffness = 0;    ///< k_y, the restraint [N/m]
    double lateralDamping = 0;      ///< c_y, the restraint [N·s/m]
    WheelRailSettings settings;     ///< which lateral formulation, and creep and flange data
    double wheels = 1;              ///< n real wheels lumped into each side's contact
};

struct WheelRailForces {
    std::array<double, 2> normal{0, 0};   ///< tread normal force N_L, N_R [N]
    std::array<double, 2> vertical{0, 0}; ///< the wheel's vertical force V_i = N_i + flange's [N]
    std::array<double, 2> lateral{0, 0};  ///< the wheel's lateral force L_i on the wheelset, +y [N]
    std::array<double, 2> creep{0, 0};    ///< tread creep part of L_i, +y [N]
    std::array<double, 2> flange{0, 0};   ///< flange normal force N_f,i, ≥ 0 [N]
    std::array<double, 2> lift{0, 0};     ///< tread-to-rail gap, ≥ 0 [m]
    std::array<double, 2> offset{0, 0};   ///< e_i = y_tread,i − y_rail,i [m]
    // Energy audit (W):
    double railInputPower = 0;  ///< work rate of the rails: Σ V_i·ż_rail,i (+ Σ F_y,i·ė_i, restraint)
    double dissipatedPower = 0; ///< Hunt–Crossley parts, creep and flange friction
};

class WheelRailContact : public SimTK::Force::Custom::Implementation {
public:
    /// Side index 0 = left (+y), 1 = right (−y). p_Tread are the tread points
    /// on the wheelset; y_rail the rails' lateral positions.
    WheelRailContact(const SimTK::GeneralForceSubsystem& forces, SimTK::MobilizedBody wheelset,
                     std::array<SimTK::Vec3, 2> p_Tread, std::array<double, 2> yRail, RailInputFunction rails,
                     WheelRailLaw law)
        : forces_(forces), wheelset_(std::move(wheelset)), p_Tread_(p_Tread), yRail_(yRail),
          rails_(std::move(rails)), law_(law) {}

    /// At Dynamics stage and above, the forces calcForce computed for this State.
    WheelRailForces calcForces(const SimTK::State& s) const;
    RailHeights getRailHeights(double t) const { return rails_(t); }

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
    /// Elastic energy: Σ ½·k·δ_i² of the wheels in contact and Σ ½·k·p_i² of the
    /// flanges in contact. The lateral restraint is external (its work is rail
    /// input) and holds none.
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;
    /// The cache lives in the element's own force subsystem, whose Topology-stage
    /// allocations survive a change of Model-stage options (Euler angles instead of
    /// quaternions: RockingModel::makeDefaultState).
    void realizeTopology(SimTK::State& s) const override { cache_.allocate(forces_, s); }

private:
    void evaluate(const SimTK::State& s, WheelRailForces& out) const;

    const SimTK::GeneralForceSubsystem& forces_;
    SimTK::MobilizedBody wheelset_;
    std::array<SimTK::Vec3, 2> p_Tread_;
    std::array<double, 2> yRail_;
    RailInputFunction rails_;
    WheelRailLaw law_;
    DynamicsCache<WheelRailForces> cache_;
};

}  // namespace rockroll
