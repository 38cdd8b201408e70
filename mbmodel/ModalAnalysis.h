#pragma once
// Natural frequencies and damping of a Simbody rocking model linearized about
// static equilibrium with every contact closed (rim and wheel contacts act as
// the linear springs and dampers of their closed state; the side bearings keep
// their clearance) and the friction wedges and center-plate yaw friction
// removed (a Coulomb element has no linearization; a sticking bristle would
// lock the suspension).
//
// Linearization: ẋ = A x in mobility coordinates, x = [δ (displacement along
// the mobilities), u], A = [0 I; ∂u̇/∂δ ∂u̇/∂u] by central differences (the
// displacement δ_i moves q by N(q)·e_i·h). Each complex pair λ = −ζω ± iω√(1−ζ²)
// is a mode: f = |λ|/2π, ζ = −Re λ/|λ|. A mode is named by the body and motion
// holding the largest share of its kinetic energy, ½·x̄ᵀM x with M the
// mobility mass matrix; car-body modes that mix sway and roll are the lower and
// upper sway–roll modes, in order of frequency.
#include "mbmodel/RockingModel.h"

#include <string>
#include <vector>

namespace rockroll {

struct Mode {
    std::string name;        ///< e.g. "car body heave", "car body lower sway-roll", "wheelset sway (2)"
    std::string body;        ///< the body kind holding most energy: "car body", "bolster", "wheelset"
    std::string motion;      ///< heave | sway | roll | pitch | yaw | longitudinal | sway-roll | twist
    double frequencyHz = 0;
    double dampingRatio = 0;
    double energyShare = 0;  ///< of the dominant body and motion
};

/// Modes sorted by frequency. The model should be built with the friction
/// parameters set to zero (see makeModalCar).
std::vector<Mode> calcModes(const RockingModel& model);

/// The car with its Coulomb elements removed, for calcModes.
CarParameters makeModalCar(CarParameters car);

/// The report's Table 1 uncoupled estimates from a car's parameters:
/// heave √(4K/M)/2π, sway √(4K_h/M)/2π, roll √(K_v l²/(I + M h²))/2π, with
/// M, I of the car body (and bolsters), the bolster, or the wheelset.
struct UncoupledEstimate {
    std::string body, motion;
    double frequencyHz = 0;
    double reportHz = 0;  ///< the value printed in the report's Table 1 (0 where it gives none)
};
std::vector<UncoupledEstimate> calcTable1Estimates(const CarParameters& car);

}  // namespace rockroll
