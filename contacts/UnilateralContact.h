#pragma once
// Unilateral compliant normal contact: the law shared by the center plate rim,
// side bearings and wheel–rail contacts, and a helper that measures the
// approach of two body points along ground z.
#include "contacts/BodyKinematics.h"
#include "contacts/UnilateralContactLaw.h"

#include <Simbody.h>

namespace rockroll {

/// Two points, one on each body, whose approach along ground z is measured.
/// `upper` sits above `lower`; penetration δ = z_lower − z_upper − clearance.
struct VerticalPointPair {
    SimTK::MobilizedBody upper;
    SimTK::Vec3 p_UpperPoint;  ///< station on the upper body [m]
    SimTK::MobilizedBody lower;
    SimTK::Vec3 p_LowerPoint;  ///< station on the lower body [m]
    double clearance = 0;      ///< gap when both points are at the same height [m]

    double calcPenetration(const SimTK::State& s) const;
    double calcPenetrationRate(const SimTK::State& s) const;
    /// The same, from the two bodies' kinematics already read (BodyKinematics.h).
    double calcPenetration(const BodyPose& upperBody, const BodyPose& lowerBody) const {
        return lowerBody.findStationLocationInGround(p_LowerPoint)[2] -
               upperBody.findStationLocationInGround(p_UpperPoint)[2] - clearance;
    }
    double calcPenetrationRate(const BodyKinematics& upperBody, const BodyKinematics& lowerBody) const {
        return lowerBody.findStationVelocityInGround(p_LowerPoint)[2] -
               upperBody.findStationVelocityInGround(p_UpperPoint)[2];
    }
    void applyNormalForce(const BodyPose& upperBody, const BodyPose& lowerBody, double f,
                          SimTK::Vector_<SimTK::SpatialVec>& bodyForces) const {
        if (f == 0) return;
        upperBody.applyForceToBodyPoint(p_UpperPoint, SimTK::Vec3(0, 0, f), bodyForces);
        lowerBody.applyForceToBodyPoint(p_LowerPoint, SimTK::Vec3(0, 0, -f), bodyForces);
    }
    /// Pushes the bodies apart with force f ≥ 0 along ground z.
    void applyNormalForce(const SimTK::State& s, double f,
                          SimTK::Vector_<SimTK::SpatialVec>& bodyForces) const;
};

}  // namespace rockroll
