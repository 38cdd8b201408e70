#include "mbmodel/FullCarModel.h"

#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

namespace rockroll {
// Inside the namespace, so it reaches no other library's code in a unity build.
using namespace SimTK;

FullCarModel::FullCarModel(const CarParameters& car, const TrackInput& track, ModelOptions options)
    : RockingModel(car, track, options) {
    const double m = car.getCarBodyWeight() / units::g;
    if (!options.carBody.torsion) {
        carBody_ = MobilizedBody::Free(matter_.updGround(), Transform(),
                                       Body::Rigid(MassProperties(m, Vec3(0), Inertia(car.rollInertia, car.pitchInertia,
                                                                                      car.yawInertia))),
                                       Transform());
    } else {
        const TwistingCarBody b = calcTwistingCarBody(car);
        const Body::Rigid half(MassProperties(b.halfMass, Vec3(0), Inertia(b.halfRollInertia, b.halfPitchInertia,
                                                                          b.halfYawInertia)));
        carBody_ = MobilizedBody::Free(matter_.updGround(), Transform(), half, Transform());
        // The pin's axis is its frames' z: turned onto the car's x, at the car's CG (x = 0).
        const Rotation zAlongX(SimTK::Pi / 2, SimTK::YAxis);
        const MobilizedBody::Pin rear(carBody_, Transform(zAlongX, Vec3(-b.halfOffset, 0, 0)), half,
                                      Transform(zAlongX, Vec3(b.halfOffset, 0, 0)));
        setTwistingCarBody({{carBody_, b.halfOffset}, {rear, -b.halfOffset}}, rear, car.carBodyTorsionalStiffness,
                           b.damping);
        frontHalfOffset_ = b.halfOffset;
    }

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
        plates.push_back(Vec3(sign * half, 0, -car.cgAboveCenterPlate));  // car frame (addTrucks)
    }
    addTrucks(std::move(trucks), plates);
}

void FullCarModel::setCarBodyHeight(State& s, double z) const {
    carBody_.setQToFitTranslation(s, Vec3(frontHalfOffset_, 0, z));
}

TwistingCarBody calcTwistingCarBody(const CarParameters& car) {
    TwistingCarBody b;
    const double m = car.getCarBodyWeight() / units::g;
    b.halfMass = m / 2;
    b.length = std::sqrt(12 * car.pitchInertia / m);
    b.halfOffset = b.length / 4;
    b.halfRollInertia = car.rollInertia / 2;
    b.halfPitchInertia = car.pitchInertia / 8;
    b.halfYawInertia = (car.yawInertia - m * b.halfOffset * b.halfOffset) / 2;
    const double Ix = b.halfRollInertia, Iy = b.halfPitchInertia, Iz = b.halfYawInertia;
    if (!(Iz > 0 && Ix + Iy >= Iz && Ix + Iz >= Iy && Iy + Iz >= Ix))
        throw std::invalid_argument(fmt::format(
            "car '{}': car_body.torsion splits the car body into two halves of a uniform beam {:.1f} ft long "
            "(its pitch inertia); the yaw inertia {:.4g} lb*in*s^2 leaves the halves no valid inertia (halves' roll, "
            "pitch, yaw {:.4g}, {:.4g}, {:.4g} lb*in*s^2): expected a yaw inertia above 3/4 of the pitch inertia and "
            "within the triangle inequality",
            car.name, b.length / units::foot, car.yawInertia / (units::lbf * units::inch * 1), Ix / (units::lbf * units::inch),
            Iy / (units::lbf * units::inch), Iz / (units::lbf * units::inch)));
    b.relativeRollInertia = b.halfRollInertia / 2;
    b.damping = 2 * car.carBodyTorsionalDampingRatio * std::sqrt(car.carBodyTorsionalStiffness * b.relativeRollInertia);
    return b;
}

}  // namespace rockroll
