#pragma once
// Wheel–rail contact of one wheelset (two wheels).
//
// Vertical, per wheel i: a unilateral compliant contact between the wheel's
// tread point and its rail top, δ_i = z_rail,i(t) − z_tread,i,
// N_i = f_unilateral(δ_i, δ̇_i): the wheel may lift off.
// Lateral: the wheelset is held to the track at rail-head height by the wheels
// in contact. Each wheel carries its load share of a stiff lateral restraint,
//
//     F_y,i = −(N_i / ΣN)·(k_y·e_i + c_y·ė_i),   e_i = y_tread,i − y_rail,i,
//
// so when one wheel lifts all lateral force passes through the other rail and
// the wheelset pivots about it; with both wheels up there is none.
//
// Energy audit: the system boundary runs between the vertical contacts and the
// rails, and around the lateral restraint. The rails move only vertically, so
// through the vertical contacts they do work at the rate Σ N_i·ż_rail,i; the
// contacts store Σ ½·k·δ_i² and dissipate their Hunt–Crossley part. The lateral
// restraint is the rails' lateral reaction and is booked as an external force:
// its work on the wheelset, Σ F_y,i·ė_i, is rail input, and it holds no stored
// energy. It cannot be booked as an element: with the shares s_i = N_i/ΣN it is
// not conservative. Σ s_i·½·k_y·e_i² is not a potential of it (the shares change
// with the loads), and when one wheel lands with the other up (s_i: 0 → 1) the
// restraint springs on at full stiffness at whatever offset the airborne
// wheelset drifted to, so that "energy" jumps by ½·k_y·e_i² with no work done
// (measured: −328 kJ of imbalance by 0.8 s on a 50 in cross-level case, where
// the wheelset left both rails and drifted 6.5 in; docs/model.md "Energy audit").
#include "contacts/DynamicsCache.h"
#include "contacts/UnilateralContact.h"

#include <array>
#include <functional>

namespace rockroll {

/// Rail top heights and their rates under one wheelset at time t (left, right).
struct RailHeights {
    double z[2] = {0, 0};     ///< [m]
    double zDot[2] = {0, 0};  ///< [m/s]
};
using RailInputFunction = std::function<RailHeights(double t)>;

struct WheelRailLaw {
    UnilateralContactLaw vertical;  ///< per wheel
    double lateralStiffness = 0;    ///< k_y [N/m]
    double lateralDamping = 0;      ///< c_y [N·s/m]
};

struct WheelRailForces {
    std::array<double, 2> normal{0, 0};   ///< N_L, N_R [N]
    std::array<double, 2> lateral{0, 0};  ///< on the wheelset [N]
    std::array<double, 2> lift{0, 0};     ///< tread-to-rail gap, ≥ 0 [m]
    std::array<double, 2> offset{0, 0};   ///< e_i = y_tread,i − y_rail,i [m]
    // Energy audit (W):
    double railInputPower = 0;  ///< work rate of the rails: Σ N_i·ż_rail,i + Σ F_y,i·ė_i (restraint)
    double dissipatedPower = 0; ///< the vertical contacts' Hunt–Crossley part
};

class WheelRailContact : public SimTK::Force::Custom::Implementation {
public:
    /// Side index 0 = left (+y), 1 = right (−y). p_Tread are the tread points
    /// on the wheelset; y_rail the rails' lateral positions.
    WheelRailContact(SimTK::MobilizedBody wheelset, std::array<SimTK::Vec3, 2> p_Tread,
                     std::array<double, 2> yRail, RailInputFunction rails, WheelRailLaw law)
        : wheelset_(std::move(wheelset)), p_Tread_(p_Tread), yRail_(yRail),
          rails_(std::move(rails)), law_(law) {}

    /// At Dynamics stage and above, the forces calcForce computed for this State.
    WheelRailForces calcForces(const SimTK::State& s) const;
    RailHeights getRailHeights(double t) const { return rails_(t); }

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
    /// Elastic energy: Σ ½·k·δ_i² of the wheels in contact. The lateral
    /// restraint is external (its work is rail input) and holds none.
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;
    /// The cache lives in the matter subsystem (this element has no handle on its
    /// force subsystem); q, u, z and time changes invalidate Dynamics system-wide.
    void realizeTopology(SimTK::State& s) const override { cache_.allocate(wheelset_.getMatterSubsystem(), s); }

private:
    void evaluate(const SimTK::State& s, WheelRailForces& out) const;

    SimTK::MobilizedBody wheelset_;
    std::array<SimTK::Vec3, 2> p_Tread_;
    std::array<double, 2> yRail_;
    RailInputFunction rails_;
    WheelRailLaw law_;
    DynamicsCache<WheelRailForces> cache_;
};

}  // namespace rockroll
