#pragma once
// The full car's static state with an off-centre car body, in closed form (linear, small
// angles): the independent check of the full car's solved static state
// (RockingModel::solveStaticEquilibrium; test mbmodel/test/test_OffCentreStatics.cpp) and
// the formula of docs/model.md, "Off-centre lading". No Simbody dependency.
//
// The car body (weight W, CG e_x ahead of mid-way between the truck centres, e_y to the
// left, h above the plates) sits on two trucks s apart. Every spring and contact is linear
// in its static range, gravity has no horizontal part, so every horizontal force is zero at
// rest and the vertical problem splits into pitch and one roll chain per truck.
//
// Pitch. The bolsters do not pitch, so each plate's rim (N ≥ 4 points, k_cp/N each, radius
// a) resists the body's pitch θ with k_θ = k_cp·a²/2. A truck's plate sinks c·Q under its
// load Q, c = 1/k_cp + 1/(2k_v) + 1/(4k_wr). With θ = c·ΔQ/s and the CG moved h·θ over the
// plates, the moment balance about mid-way between the plates gives
//
//     ΔQ = Q_F − Q_R = (2W·e_x/s) / (1 + 4k_θ·c/s² − 2W·h·c/s²),   Q_F,R = W/2 ± ΔQ/2,
//
// the lever rule W·(½ ± e_x/s) when k_θ·c and h·c vanish (a pivot plate on stiff trucks).
//
// Roll (the rigid body's roll φ_c; each truck's bolster φ_b and wheelsets φ_w, left side up
// positive; each plate's rim moment M = −k_θ·(φ_c − φ_b); the plate a above the bolster's
// spring plane, the spring seats H_s above the axles, springs b and rails g/2 from the centre
// line). The body, then each truck:
//
//     M_F + M_R               = W·(e_y − h·φ_c)                 the body about its plates
//     (P_L − P_R)·b           = M − Q·a·φ_b                      bolster
//     P_L − P_R               = 2k_v·b·(φ_w − φ_b)               spring groups
//     N_L − N_R               = −k_wr·g·φ_w                      each wheelset's two wheels
//     (N_L − N_R)·g/2         = (P_L − P_R)·b/2 − (Q + W_B)/2·H_s·φ_w   each wheelset
//
// and each wheel carries (Q + W_B)/4 + W_u/2 ± (N_L − N_R)/2, W_u a wheelset with its
// side-frame share. Valid while every rim point stays seated (a·√(θ² + (φ_c − φ_b)²) below
// Q/k_cp) and the side bearings stay open (getIsValid). The twisting car body
// (car_body.torsion) rolls in two halves: this closed form is its stiff limit.
#include "mbmodel/CarParameters.h"

#include <array>

namespace rockroll {

struct OffCentreTruckStatics {
    double centerPlate = 0;               ///< Q [N]
    std::array<double, 2> wheel{0, 0};    ///< each wheel, left and right [N]
    double carBodyRoll = 0, bolsterRoll = 0, wheelsetRoll = 0;  ///< [rad]
};

struct OffCentreStatics {
    std::array<OffCentreTruckStatics, 2> trucks;  ///< front (x = +s/2), rear
    double pitch = 0;                             ///< θ, nose down positive [rad]
    bool rimSeated = true;                        ///< every rim point in contact
    bool sideBearingsOpen = true;                 ///< no side bearing touching
    bool getIsValid() const { return rimSeated && sideBearingsOpen; }
};

/// The closed form above for `car` (its cg_longitudinal_offset and cg_lateral_offset; the
/// contact stiffness scale applied).
OffCentreStatics calcOffCentreStatics(const CarParameters& car);

}  // namespace rockroll
