#pragma once
// Unilateral compliant normal contact: the law shared by the center plate rim,
// side bearings and wheel–rail contacts, and a helper that measures the
// approach of two body points along ground z.
#include <Simbody.h>

namespace rockroll {

/// Stiffness and dissipation of a compliant unilateral contact.
struct UnilateralContactLaw {
    double stiffness = 0;    ///< k [N/m]
    double dissipation = 0;  ///< Hunt–Crossley d [s/m]
};

/// Normal force for penetration δ (positive = bodies overlap) and its rate δ̇:
///
///     f = max(0, k·δ·(1 + d·δ̇))   for δ > 0,
///     f = 0                        for δ ≤ 0.
///
/// The damping term is proportional to δ (Hunt–Crossley), so the force is
/// continuous at touch-down; the clamp keeps a separating contact from pulling.
double calcUnilateralNormalForce(double penetration, double penetrationRate,
                                 const UnilateralContactLaw& law);

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
