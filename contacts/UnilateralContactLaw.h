#pragma once
// Unilateral compliant normal contact law, shared by the center plate rim, side
// bearings, gib stops and wheel–rail contacts of every model (Simbody and the
// hand-written equation-of-motion model). No Simbody dependency.

namespace rockroll {

/// Stiffness and dissipation of a compliant unilateral contact.
struct UnilateralContactLaw {
    double stiffness = 0;    ///< k [N/m]
    double dissipation = 0;  ///< Hunt–Crossley d [s/m]
};

/// Normal force for penetration δ (positive = bodies overlap) and its rate δ̇:
///
///     f = max(0, k·δ·(1 + d·δ̇))   for δ > 0,
///     f = 0                        for δ ≤ 0.
///
/// The damping term is proportional to δ (Hunt–Crossley), so the force is
/// continuous at touch-down; the clamp keeps a separating contact from pulling.
double calcUnilateralNormalForce(double penetration, double penetrationRate,
                                 const UnilateralContactLaw& law);

/// Elastic energy held in the contact (energy audit):
///
///     V = ½·k·δ²   for δ > 0,   V = 0 otherwise,
///
/// so −dV/dδ is the elastic part k·δ of the normal force.
double calcUnilateralContactEnergy(double penetration, const UnilateralContactLaw& law);

/// Power dissipated by the contact (energy audit). The force f does work f·δ̇ on
/// the contact; dV/dt = k·δ·δ̇ of it is stored, the rest is dissipated:
///
///     P = (f − k·δ)·δ̇ = k·d·δ·δ̇²  ≥ 0                  (unclamped)
///     P = −k·δ·δ̇                  ≥ 0                  (clamped, f = 0: then δ̇ < −1/d < 0)
///     P = 0                                             (open, δ ≤ 0)
double calcUnilateralContactDissipation(double penetration, double penetrationRate,
                                        const UnilateralContactLaw& law);

}  // namespace rockroll
