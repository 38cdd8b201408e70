#pragma once
// Wheel–rail laws of one wheel (or of one truck side's n equal wheels), shared by the
// Simbody wheel–rail contact (contacts/WheelRailContact.h) and the hand-written
// equation-of-motion half car (bespoke/EomHalfCarModel.h). No Simbody dependency.
//
// The models' wheelsets have lateral, vertical and roll freedom but no yaw and no spin,
// so only lateral creep exists: longitudinal and spin creep are left out, and so is the
// profile's gravitational stiffness (the tread is flat: a lateral position is held by
// creep and, past the flangeway clearance, by the flange alone). docs/model.md, "Wheel–rail
// contact", gives the defaults and their sources.
#include "contacts/UnilateralContactLaw.h"

#include <string_view>

namespace rockroll {

/// How the lateral wheel–rail force is made.
enum class LateralWheelRail {
    /// The 1976 report's formulation: a stiff two-way lateral spring at rail-head height,
    /// shared between the wheels by load (contacts/WheelRailContact.h).
    Restraint,
    /// Lateral creep on the tread, saturating at μ·N, and a flange contact past the
    /// flangeway clearance (this header).
    CreepAndFlange,
};

/// The wheel–rail settings of a run (scenario [wheel_rail]), SI.
struct WheelRailSettings {
    LateralWheelRail lateral = LateralWheelRail::Restraint;
    double friction = 0.5;                 ///< μ, tread and flange
    double creepCoefficient = 1.0e7;       ///< Kalker's lateral f₂₂, one wheel [N]
    double flangeAngle = 75 * (3.14159265358979323846 / 180);  ///< γ, from the horizontal [rad] (75°)
    double flangewayClearance = 0.375 * 0.0254;  ///< lateral free play of one wheel to flange contact [m]
    double flangeHeight = 1 * 0.0254;            ///< flange tip below the tread [m]
    double flangeStiffnessScale = 1;             ///< the flange's stiffness over the tread's (convergence studies)
};

/// "restraint", "creep_and_flange": the scenario's names of the formulations.
const char* getLateralWheelRailName(LateralWheelRail l);
/// The formulation of that name, or nullptr.
const LateralWheelRail* findLateralWheelRail(std::string_view name);

/// Below this forward speed the creepage is taken at it [m/s]: creepage is slip over
/// the rolling speed, which vanishes at standstill.
constexpr double kMinCreepSpeed = 0.1;

/// Shen–Hedrick–Elkins saturation (Shen, Hedrick and Elkins 1983, "A comparison of
/// alternative creep force models for rail vehicle dynamic analysis"): the linear
/// force's size β = |F_lin|/(μN) maps to
///
///     g(β) = β − β²/3 + β³/27   for β < 3,     g(β) = 1   for β ≥ 3,
///
/// and the force is F = F_lin·g(β)/β: slope 1 at β = 0, μN reached with zero slope at β = 3.
double calcSaturatedCreepFraction(double beta);

/// Lateral creep force on one truck side's `wheels` equal wheels sharing the normal
/// force N (each N/n), from their common lateral slip velocity v (wheel against rail)
/// and the forward speed V:
///
///     ξ = v / max(V, kMinCreepSpeed),   F_lin = −n·f₂₂·ξ,   F = F_lin·g(β)/β,   β = |F_lin|/(μ·N)
///
/// It opposes the slip, so its power F·v ≤ 0 is dissipated. N ≤ 0: no force.
double calcLateralCreepForce(double slipVelocity, double forwardSpeed, double normalForce, double wheels,
                             const WheelRailSettings& w);

/// The flange of one wheel against its rail's gauge face, a plane at the flange angle γ.
/// With e the wheel's lateral displacement toward its own rail from the centred position,
/// c the flangeway clearance and h = z_wheel − z_rail its lift,
///
///     p = (e − c)·sin γ − h·cos γ   for h < flange height,   p = 0 otherwise,
///
/// the penetration normal to the face (lifting the wheel moves the rail's gauge corner
/// toward the flange tip, away from the face). The normal force N_f = f_unilateral(p, ṗ)
/// (UnilateralContactLaw: the tread's, its stiffness times flangeStiffnessScale), and the friction along
/// the face is the creep law with the sliding velocity along it,
///
///     s = ė·cos γ + ḣ·sin γ       (t: up the face, toward the rail),
///     F_t = creep(s, V, N_f),
///
/// so on the wheel, lateral toward its rail and vertical up,
///
///     F_e = −N_f·sin γ + F_t·cos γ,   F_z = N_f·cos γ + F_t·sin γ.
struct FlangeForces {
    double penetration = 0;  ///< p [m]
    double normal = 0;       ///< N_f [N]
    double friction = 0;     ///< F_t along t [N]
    double towardRail = 0;   ///< F_e [N]
    double vertical = 0;     ///< F_z [N]
    double dissipatedPower = 0;  ///< normal (Hunt–Crossley) and friction, ≥ 0 [W]
    double energy = 0;           ///< ½·k_f·p², as calcFlangeEnergy [J]
};
FlangeForces calcFlangeForces(double towardRail, double towardRailRate, double lift, double liftRate,
                              double forwardSpeed, double wheels, const UnilateralContactLaw& normal,
                              const WheelRailSettings& w);

/// Elastic energy of the flange contact: ½·k_f·p² (calcUnilateralContactEnergy), k_f the
/// tread's stiffness times flangeStiffnessScale.
double calcFlangeEnergy(double towardRail, double lift, const UnilateralContactLaw& normal,
                        const WheelRailSettings& w);

/// Nadal's single-wheel limit: the L/V at which a wheel in flange contact on a face at γ
/// with friction μ starts to climb,
///
///     (L/V)_Nadal = (tan γ − μ) / (1 + μ·tan γ).
double calcNadalLimit(double flangeAngle, double friction);

}  // namespace rockroll
