#pragma once
// Force laws of the suspension spring groups (report Fig. 4), shared by every
// model. No Simbody dependency.
#include "contacts/UnilateralContactLaw.h"

namespace rockroll {

struct VerticalSpringLaw {
    double rate = 0;            ///< K_v [N/m]
    double travel = 0;          ///< free height to bottomed [m]
    double bottomingRate = 0;   ///< K_bottom [N/m]
};

/// Spring force for compression Z (positive = shorter than free height):
///
///     P = 0                                  Z < 0   (bolster off its springs)
///     P = K_v·Z                              0 ≤ Z ≤ travel
///     P = K_v·travel + K_bottom·(Z − travel) Z > travel (coils solid)
double calcVerticalSpringForce(double compression, const VerticalSpringLaw& law);

/// Elastic energy of the vertical spring group (energy audit), V with P = dV/dZ:
///
///     V = 0                                                  Z < 0
///     V = ½·K_v·Z²                                           0 ≤ Z ≤ travel
///     V = ½·K_v·travel² + K_v·travel·b + ½·K_bottom·b²        b = Z − travel > 0
///
/// The group is elastic: it dissipates nothing.
double calcVerticalSpringEnergy(double compression, const VerticalSpringLaw& law);

/// Inverse of calcVerticalSpringForce for P ≥ 0 (used to place the static state).
double calcVerticalSpringCompression(double force, const VerticalSpringLaw& law);

struct LateralSpringLaw {
    double rate = 0;           ///< K_h [N/m]
    double gibClearance = 0;   ///< c_gib, half the total gib clearance [m]
    double gibRate = 0;        ///< K_gib [N/m]
    double gibDissipation = 0; ///< Hunt–Crossley d of the gib contact [s/m]
};

/// Lateral force resisting relative displacement Y (bolster relative to side frame):
///
///     P = K_h·Y + sign(Y)·f_gib(|Y| − c_gib, d|Y|/dt)
///
/// where f_gib is the unilateral contact law (zero inside the clearance).
double calcLateralSpringForce(double Y, double Ydot, const LateralSpringLaw& law);

/// Elastic energy of the lateral group and gib (energy audit):
///
///     V = ½·K_h·Y² + V_gib(|Y| − c_gib)     (V_gib: calcUnilateralContactEnergy)
double calcLateralSpringEnergy(double Y, const LateralSpringLaw& law);

/// Power dissipated by the gib contact (the spring itself is elastic):
///
///     P = P_gib(|Y| − c_gib, d|Y|/dt) ≥ 0    (calcUnilateralContactDissipation)
double calcLateralSpringDissipation(double Y, double Ydot, const LateralSpringLaw& law);

/// A linear spring and viscous damper F = −(k·x + c·ẋ) (center pin, wheel–rail
/// lateral restraint, locked bolster link): stored V = ½·k·x², dissipated P = c·ẋ² ≥ 0.
inline double calcLinearSpringEnergy(double stiffness, double x) { return 0.5 * stiffness * x * x; }
inline double calcViscousDissipation(double damping, double velocity) { return damping * velocity * velocity; }

}  // namespace rockroll
