#pragma once
// Half-car model (report §2.2, Fig. 2): the planar section through the leading
// truck. Bodies, each with lateral, vertical and roll motion:
//   car body  — half the car body mass and half its roll inertia,
//   bolster,
//   equivalent wheelset — both wheelsets and side frames of the truck, whose
//   rail input is the mean over the two axles (report eqs 6–7).
#include "mbmodel/RockingModel.h"

namespace rockroll {

class HalfCarModel : public RockingModel {
public:
    HalfCarModel(const CarParameters& car, const TrackInput& track, ModelOptions options);

protected:
    void setCarBodyPose(SimTK::State& s, const std::vector<double>& plateZ) const override;
};

}  // namespace rockroll
