#include "mbmodel/TruckStatics.h"

#include "contacts/SpringGroupLaws.h"

namespace rockroll {

TruckStatics::TruckStatics(const CarParameters& car, const TruckStaticLoad& load)
    : wheelRailStiffness_(car.contactStiffnessScale * car.wheelRailStiffness),
      centerPlateStiffness_(car.contactStiffnessScale * car.centerPlateStiffness) {
    const bool carried = load.weight == TruckWeight::Carried;
    centerPlate_ = load.carBody;
    spring_ = (load.carBody + (carried ? car.bolsterWeight : 0.0)) / 2;
    compression_ = load.linearSprings
                       ? spring_ / car.springVerticalRate
                       : calcVerticalSpringCompression(spring_, {car.springVerticalRate, car.springTravel,
                                                                 car.bottomingRate});
    unsprungPerWheelset_ = carried && load.unsprungWeight ? car.wheelsetWeight + car.sideFrameWeight : 0.0;
}

double TruckStatics::calcWheelLoad(int lumped, int bodies) const {
    return spring_ / double(bodies) + lumped * unsprungPerWheelset_ / 2;
}

double TruckStatics::calcWheelDeflection(int lumped, int bodies) const {
    return calcWheelLoad(lumped, bodies) / (lumped * wheelRailStiffness_);
}

double TruckStatics::getCenterPlateDeflection() const {
    return centerPlate_ / centerPlateStiffness_;
}

}  // namespace rockroll
