#pragma once
// Full-car 3-D model: the car body with vertical, lateral, roll, pitch and yaw
// motion (and a longitudinal coordinate held by the center pins); two trucks,
// each with a bolster and two wheelsets moving laterally, vertically and in
// roll; side frames lumped into the wheelsets they rest on.
#include "mbmodel/RockingModel.h"

namespace rockroll {

class FullCarModel : public RockingModel {
public:
    FullCarModel(const CarParameters& car, const TrackInput& track, ModelOptions options);

protected:
    void setCarBodyHeight(SimTK::State& s, double z) const override;
};

}  // namespace rockroll
