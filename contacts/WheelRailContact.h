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
// Energy audit: the rails move only vertically, so they do work at the rate
// Σ N_i·ż_rail,i. The contacts store Σ ½·k·δ_i² and dissipate their
// Hunt–Crossley part; the lateral restraint stores Σ s_i·½·k_y·e_i² (s_i = N_i/ΣN)
// and dissipates Σ s_i·c_y·ė_i². Because the shares s_i change with the loads the
// restraint is not exactly conservative: it also does the work −Σ ṡ_i·½·k_y·e_i²,
// which is second order (e_L − e_R = gauge·(cos θ − 1)) and shows in the balance.
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
    double railInputPower = 0;  ///< work rate of the rails on the wheels, Σ N_i·ż_rail,i
    double dissipatedPower = 0; ///< Hunt–Crossley + Σ (N_i/ΣN)·c_y·ė_i²
};

class WheelRailContact : public SimTK::Force::Custom::Implementation {
public:
    /// Side index 0 = left (+y), 1 = right (−y). p_Tread are the tread points
    /// on the wheelset; y_rail the rails' lateral positions.
    WheelRailContact(SimTK::MobilizedBody wheelset, std::array<SimTK::Vec3, 2> p_Tread,
                     std::array<double, 2> yRail, RailInputFunction rails, WheelRailLaw law)
        : wheelset_(std::move(wheelset)), p_Tread_(p_Tread), yRail_(yRail),
          rails_(std::move(rails)), law_(law) {}

    WheelRailForces calcForces(const SimTK::State& s) const;
    RailHeights getRailHeights(double t) const { return rails_(t); }

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override;
    /// Elastic energy: Σ ½·k·δ_i² of the wheels in contact, plus the lateral
    /// restraint's Σ (N_i/ΣN)·½·k_y·e_i².
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override;

private:
    SimTK::MobilizedBody wheelset_;
    std::array<SimTK::Vec3, 2> p_Tread_;
    std::array<double, 2> yRail_;
    RailInputFunction rails_;
    WheelRailLaw law_;
};

}  // namespace rockroll
