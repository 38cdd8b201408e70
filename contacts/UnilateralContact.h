#pragma once
// Unilateral compliant normal contact: the law shared by the center plate rim,
// side bearings and wheel–rail contacts, and a helper that measures the
// approach of two body points along ground z.
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
    /// Pushes the bodies apart with force f ≥ 0 along ground z.
    void applyNormalForce(const SimTK::State& s, double f,
                          SimTK::Vector_<SimTK::SpatialVec>& bodyForces) const;
};

}  // namespace rockroll
