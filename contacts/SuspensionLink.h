#pragma once
// Kinematics shared by the suspension elements: a point on the bolster end and
// the side-frame seat below it. With side frames lumped into the wheelsets the
// seat is the mean of the journal points of the wheelsets the side frame rests
// on (one equivalent wheelset in the half car, two in the full car); a force on
// the seat is split equally between them, as a massless rigid side frame pinned
// at its journals would split it.
#include <Simbody.h>

#include <vector>

namespace rockroll {

struct SideFrameSeat {
    std::vector<SimTK::MobilizedBody> bodies;
    std::vector<SimTK::Vec3> stations;  ///< one per body, in that body's frame [m]

    SimTK::Vec3 findLocationInGround(const SimTK::State& s) const;
    SimTK::Vec3 findVelocityInGround(const SimTK::State& s) const;
    void applyForce(const SimTK::State& s, const SimTK::Vec3& f_G,
                    SimTK::Vector_<SimTK::SpatialVec>& bodyForces) const;
};

/// Bolster end point above a side-frame seat. Deflections are measured in
/// ground axes (rolls stay below ~10°; documented in docs/model.md).
struct SuspensionLink {
    SimTK::MobilizedBody bolster;
    SimTK::Vec3 p_BolsterPoint;
    SideFrameSeat seat;

    /// p_bolster − p_seat in ground [m]
    SimTK::Vec3 calcRelativeLocation(const SimTK::State& s) const {
        return bolster.findStationLocationInGround(s, p_BolsterPoint) - seat.findLocationInGround(s);
    }
    SimTK::Vec3 calcRelativeVelocity(const SimTK::State& s) const {
        return bolster.findStationVelocityInGround(s, p_BolsterPoint) - seat.findVelocityInGround(s);
    }
    /// Applies f_G to the bolster and −f_G to the seat.
    void applyForceOnBolster(const SimTK::State& s, const SimTK::Vec3& f_G,
                             SimTK::Vector_<SimTK::SpatialVec>& bodyForces) const {
        bolster.applyForceToBodyPoint(s, p_BolsterPoint, f_G, bodyForces);
        seat.applyForce(s, -f_G, bodyForces);
    }
};

}  // namespace rockroll
