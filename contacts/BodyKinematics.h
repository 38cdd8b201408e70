#pragma once
// One body's pose (and, once realized to Velocity, its spatial velocity) read
// from the State once per evaluation. An element with many points on the same
// two bodies (the center plate's rim, a side frame's journals) then pays one
// State lookup per body instead of one per point.
//
// The formulas are Simbody's own (MobilizedBody::findStationLocationInGround,
// findStationVelocityInGround, applyForceToBodyPoint), operation for operation,
// so results are bitwise the same as calling those per point:
//
//     p_GS = X_GB · p_BS
//     v_GS = v_GB + ω_GB × (R_GB · p_BS)
//     F_B += [ (R_GB · p_BS) × f_G ,  f_G ]
#include <Simbody.h>

namespace rockroll {

struct BodyPose {
    SimTK::MobilizedBodyIndex index;
    SimTK::Transform X_GB;

    static BodyPose calc(const SimTK::MobilizedBody& b, const SimTK::State& s) {
        return {b.getMobilizedBodyIndex(), b.getBodyTransform(s)};
    }
    SimTK::Vec3 findStationLocationInGround(const SimTK::Vec3& p_BS) const { return X_GB * p_BS; }
    void applyForceToBodyPoint(const SimTK::Vec3& p_BS, const SimTK::Vec3& f_G,
                               SimTK::Vector_<SimTK::SpatialVec>& bodyForces) const {
        bodyForces[index] += SimTK::SpatialVec((X_GB.R() * p_BS) % f_G, f_G);
    }
};

struct BodyKinematics : BodyPose {
    SimTK::SpatialVec V_GB;  ///< [ω_GB, v_GB] in ground

    static BodyKinematics calc(const SimTK::MobilizedBody& b, const SimTK::State& s) {
        return {BodyPose::calc(b, s), b.getBodyVelocity(s)};
    }
    SimTK::Vec3 findStationVelocityInGround(const SimTK::Vec3& p_BS) const {
        const SimTK::Vec3 r = X_GB.R() * p_BS;
        return V_GB[1] + V_GB[0] % r;
    }
};

}  // namespace rockroll
