#include "mbmodel/HalfCarModel.h"

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

HalfCarModel::HalfCarModel(const CarParameters& car, const TrackInput& track, ModelOptions options)
    : RockingModel(car, track, options) {
    const double m = car.getCarBodyWeight() / 2 / units::g;
    const double I = car.rollInertia / 2;
    carBody_ = makeCrossSectionBody(matter_.updGround(), 0, Body::Rigid(MassProperties(m, Vec3(0), Inertia(I))));

    TruckSpec truck;
    truck.label = "F";
    truck.carBodyLoad = car.getCarBodyWeight() / 2;
    truck.wheelsets.push_back({0.0, 2, makeRailInput({0.0, -car.wheelbase})});
    addTrucks({truck}, {Vec3(0, 0, -car.cgAboveCenterPlate)});
}

void HalfCarModel::setCarBodyPose(State& s, const std::vector<double>& plateZ) const {
    carBody_.setOneQ(s, 2, plateZ[0] + car_.cgAboveCenterPlate);
}

}  // namespace rockroll
