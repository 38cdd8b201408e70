#pragma once
#include <cmath>

// Elasto-plastic ("bristle") Coulomb friction law: a stiff spring in series with
// a slider whose anchor is state. Used by the friction wedges and the center
// plate's yaw friction. It sticks for real: under a steady force below the limit
// the bristle deflection w stops changing, so nothing creeps.

namespace rockroll {

struct BristleFrictionLaw {
    double limit = 0;      ///< Coulomb force (or torque) F_c ≥ 0
    double stiffness = 0;  ///< bristle stiffness k_b > 0
    double damping = 0;    ///< bristle damping c_b ≥ 0
    /// Fraction of the limit deflection where slip starts to blend in (β).
    double presliding = 0.95;
    /// Sliding speed over which slip blends in after a reversal [m/s or rad/s].
    double reversalVelocity = 1e-3;
    /// Time constant that pulls an overstretched bristle (limit dropped) back [s].
    double relaxationTime = 0.002;
};

struct BristleFrictionState {
    double force = 0;          ///< friction force F acting on the sliding body, opposing v
    double deflectionRate = 0; ///< ẇ
    bool slipping = false;
};

/// Bristle deflection w (state) and relative sliding velocity v:
///
///     w_max = F_c / k_b
///     α(w,v) = S(v·sign(w)/v_r) · S((|w|/w_max − β)/(1 − β))   (S: C¹ smoothstep
///              clamped to [0, 1]; S(·) = 1 for |w| ≥ w_max), so α = 0 while
///              unloading (v·w ≤ 0: sticks) and inside β·w_max
///     ẇ = v·(1 − α) − (w − sign(w)·w_max)/τ · [|w| > w_max]
///     F = −clamp(k_b·w + c_b·ẇ, −F_c, F_c)
///
/// In stick (α = 0) ẇ = v, the bristle is a spring; at the limit (α = 1) ẇ = 0
/// and the force is ±F_c while the surfaces slide.
BristleFrictionState calcBristleFriction(double deflection, double slidingVelocity,
                                         const BristleFrictionLaw& law);

/// Elastic energy of the bristle (energy audit): V = ½·k_b·w².
double calcBristleEnergy(double deflection, const BristleFrictionLaw& law);

/// Power dissipated by the element (energy audit). The friction force F acts on
/// the body sliding at v (and −F on the other), so the element absorbs −F·v;
/// dV/dt = k_b·w·ẇ of it is stored in the bristle and the rest is dissipated:
///
///     P = −F·v − k_b·w·ẇ = f·v − k_b·w·ẇ,   f = clamp(k_b·w + c_b·ẇ, −F_c, F_c)
///
/// Stick (ẇ = v, unclamped): P = c_b·v². Slip (α = 1, ẇ = 0): P = F_c·|v|.
/// Clamped while sticking: P = (f − k_b·w)·v ≥ 0 since |k_b·w| ≤ F_c. The
/// relaxation of an overstretched bristle adds k_b·w·(w ∓ w_max)/τ ≥ 0. With
/// no normal load (F_c = 0) the bristle relaxes: P = k_b·w²/τ.
double calcBristleDissipation(double deflection, double slidingVelocity, const BristleFrictionLaw& law);

/// Bristle damping that gives a bristle of stiffness k_b, carrying mass m, the
/// damping ratio ζ: c_b = 2·ζ·√(k_b·m). Every formulation damps its wedge and
/// center-plate yaw bristles this way (docs/model.md, assumed values).
inline double calcBristleDamping(double stiffness, double mass, double dampingRatio) {
    return 2 * dampingRatio * std::sqrt(stiffness * mass);
}

}  // namespace rockroll
