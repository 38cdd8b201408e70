#pragma once
// Side bearing: a unilateral contact between the car body's bearing pad and the
// bolster's side bearing, closed only once the clearance is taken up:
//
//     δ = z_bolster − z_pad − c_sb,   F = f_unilateral(δ, δ̇)   (UnilateralContact.h)
#include "contacts/UnilateralContact.h"

namespace rockroll {

class SideBearing : public SimTK::Force::Custom::Implementation {
public:
    /// `pair.upper` is the car body pad, `pair.lower` the bolster bearing top,
    /// `pair.clearance` the vertical clearance c_sb.
    SideBearing(VerticalPointPair pair, UnilateralContactLaw law) : pair_(std::move(pair)), law_(law) {}

    double calcForce(const SimTK::State& s) const {
        return calcUnilateralNormalForce(pair_.calcPenetration(s), pair_.calcPenetrationRate(s), law_);
    }
    double calcGap(const SimTK::State& s) const { return -pair_.calcPenetration(s); }

    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
        pair_.applyNormalForce(s, calcForce(s), bodyForces);
    }
    SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
        return calcUnilateralContactEnergy(pair_.calcPenetration(s), law_);
    }
    /// Hunt–Crossley dissipation (energy audit); state realized to Velocity.
    double calcDissipatedPower(const SimTK::State& s) const {
        return calcUnilateralContactDissipation(pair_.calcPenetration(s), pair_.calcPenetrationRate(s), law_);
    }

private:
    VerticalPointPair pair_;
    UnilateralContactLaw law_;
};

}  // namespace rockroll
