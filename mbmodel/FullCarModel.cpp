#include "mbmodel/FullCarModel.h"

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

FullCarModel::FullCarModel(const CarParameters& car, const TrackInput& track, ModelOptions options)
    : RockingModel(car, track, options) {
    const double m = car.getCarBodyWeight() / units::g;
    carBody_ = MobilizedBody::Free(matter_.updGround(), Transform(),
                                   Body::Rigid(MassProperties(m, Vec3(0), Inertia(car.rollInertia, car.pitchInertia,
                                                                                  car.yawInertia))),
                                   Transform());

    const double half = car.truckSpacing / 2, B = car.wheelbase;
    const double leadAxle = half + B / 2;
    std::vector<TruckSpec> trucks;
    std::vector<Vec3> plates;
    for (double sign : {+1.0, -1.0}) {
        TruckSpec t;
        // One char, not a const char* assignment: GCC 12 at -O2 in C++20 reports a false
        // -Wrestrict for std::string = (cond ? "F" : "R") (a known GCC 12 false positive).
        t.label.assign(1, sign > 0 ? 'F' : 'R');
        t.x = sign * half;
        t.carBodyLoad = car.getCarBodyWeight() / 2;
        t.threeDimensional = true;
        const double entryAxle = options.entry == TrackEntry::Lead ? leadAxle : t.x + B / 2;
        for (double ax : {t.x + B / 2, t.x - B / 2})
            t.wheelsets.push_back({ax, 1, makeRailInput({ax - entryAxle})});
        trucks.push_back(std::move(t));
        plates.push_back(Vec3(sign * half, 0, -car.cgAboveCenterPlate));
    }
    addTrucks(std::move(trucks), plates);
}

void FullCarModel::setCarBodyHeight(State& s, double z) const {
    carBody_.setQToFitTranslation(s, Vec3(0, 0, z));
}

}  // namespace rockroll
