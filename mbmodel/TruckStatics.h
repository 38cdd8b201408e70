#pragma once
// One truck's static equilibrium on level rails: the single definition every
// formulation places its static state from (the Simbody half and full car through
// Truck, the equations-of-motion half car, the describing function through it, and
// the reduced model's massless truck). No Simbody dependency.
//
// A truck carries the car-body load Q on its center plate. With bolster weight W_B
// and, per wheelset, the unsprung weight W_u = wheelset + two side-frame halves:
//
//     center plate           F_c = Q
//     spring group, per side P   = (Q + W_B) / 2
//     its compression        Z   = P⁻¹(P)    (calcVerticalSpringCompression; K_v⁻¹·P when linear)
//     wheels, per truck side W   = P + W_u   (both wheelsets of the side)
//
// A wheelset body that lumps n of the truck's wheelsets among `bodies` bodies carries
// P/bodies + n·W_u/2 on each wheel. Compliant contacts deflect by their load over
// their stiffness (the contact stiffness scale included): each rail contact by
// W/(2·k_wr) per real wheel, the center plate by Q/k_cp. The reduced model's
// contacts are rigid (deflections 0), and the report's massless truck sets
// W_B = W_u = 0 (TruckWeight::Massless).
#include "mbmodel/CarParameters.h"

namespace rockroll {

enum class TruckWeight {
    Carried,   ///< bolster and unsprung weight load the springs and the rails
    Massless,  ///< the 1976 reduced model's truck: neither
};

struct TruckStaticLoad {
    double carBody = 0;            ///< Q, on the center plate [N]
    TruckWeight weight = TruckWeight::Carried;
    bool unsprungWeight = true;    ///< false: the wheelsets left out of gravity (attribution switch)
    bool linearSprings = false;    ///< EOM simplification: no bottoming in the static solve
};

class TruckStatics {
public:
    TruckStatics(const CarParameters& car, const TruckStaticLoad& load);

    double getCenterPlateLoad() const { return centerPlate_; }       ///< F_c [N]
    double getSpringLoad() const { return spring_; }                 ///< P per side [N]
    double getSpringCompression() const { return compression_; }     ///< Z [m]
    /// Load on each wheel of a wheelset body lumping `lumped` of the truck's two
    /// wheelsets, the truck having `bodies` wheelset bodies [N].
    double calcWheelLoad(int lumped, int bodies) const;
    /// All wheels on one rail of the truck, W = P + W_u [N].
    double getTruckSideWheelLoad() const { return calcWheelLoad(2, 1); }
    /// Rail contact deflection of that body's wheel (compliant contacts) [m].
    double calcWheelDeflection(int lumped, int bodies) const;
    /// Center-plate contact deflection (compliant contacts) [m].
    double getCenterPlateDeflection() const;

private:
    double centerPlate_ = 0, spring_ = 0, compression_ = 0, unsprungPerWheelset_ = 0;
    // Contact stiffnesses with the car's contact stiffness scale applied [N/m].
    double wheelRailStiffness_ = 0, centerPlateStiffness_ = 0;
};

}  // namespace rockroll
