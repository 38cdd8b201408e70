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

    // Off-centre lading (docs/model.md, "Off-centre lading"): the car body's CG sits at
    // (e_x, e_y) from the point mid-way between the truck centres on the centre line, so
    // the lever rule shares its weight W between the trucks as W·(½ ± e_x/s).
    const double half = car.truckSpacing / 2, B = car.wheelbase;
    const double ex = car.cgLongitudinalOffset, ey = car.cgLateralOffset;
    cgOffset_ = Vec3(ex, ey, 0);
    if (ex != 0 || ey != 0) setStaticStateNeedsSolving();
    const double leadAxle = half + B / 2;
    std::vector<TruckSpec> trucks;
    std::vector<Vec3> plates;
    for (double sign : {+1.0, -1.0}) {
        TruckSpec t;
        // One char, not a const char* assignment: GCC 12 at -O2 in C++20 reports a false
        // -Wrestrict for std::string = (cond ? "F" : "R") (a known GCC 12 false positive).
        t.label.assign(1, sign > 0 ? 'F' : 'R');
        t.x = sign * half;
        t.carBodyLoad = car.getCarBodyWeight() * (0.5 + sign * ex / car.truckSpacing);
        t.threeDimensional = true;
        const double entryAxle = options.entry == TrackEntry::Lead ? leadAxle : t.x + B / 2;
        for (double ax : {t.x + B / 2, t.x - B / 2})
            t.wheelsets.push_back({ax, 1, makeRailInput({ax - entryAxle})});
        trucks.push_back(std::move(t));
        plates.push_back(Vec3(sign * half - ex, -ey, -car.cgAboveCenterPlate));  // car frame (addTrucks)
    }
    addTrucks(std::move(trucks), plates);
}

void FullCarModel::setCarBodyPose(State& s, const std::vector<double>& plateZ) const {
    const double h = car_.cgAboveCenterPlate;
    if (plateZ[0] == plateZ[1]) {
        carBody_.setQToFitTranslation(s, cgOffset_ + Vec3(frontHalfOffset_, 0, plateZ[0] + h));
        return;
    }
    // Pitched through both plate points: a car-frame point (x, 0, −h) rotated by θ about y
    // is at height z_CG − x·sin θ − h·cos θ, and the plates are the truck spacing s apart.
    const double sinTheta = (plateZ[1] - plateZ[0]) / car_.truckSpacing;
    const double theta = std::asin(sinTheta);
    const double zCG = plateZ[0] + (car_.truckSpacing / 2 - cgOffset_[0]) * sinTheta + h * std::cos(theta);
    const Rotation R_GB(theta, SimTK::YAxis);
    carBody_.setQToFitTransform(s, Transform(R_GB, Vec3(cgOffset_[0], cgOffset_[1], zCG) +
                                                      R_GB * Vec3(frontHalfOffset_, 0, 0)));
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
