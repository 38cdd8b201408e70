#pragma once
// A three-piece truck as a subsystem template: it owns the topology (bolster,
// wheelsets with their side-frame shares, and every force element between them
// and the car body). Concrete cars supply data only (CarParameters, TruckSpec).
// Left and right elements are built from one definition mirrored by side sign.
#include "contacts/CenterPlateContact.h"
#include "contacts/FrictionWedge.h"
#include "contacts/LateralSpringGroup.h"
#include "contacts/SideBearing.h"
#include "contacts/VerticalSpringGroup.h"
#include "contacts/WheelRailContact.h"
#include "mbmodel/CarParameters.h"
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/TruckStatics.h"

#include <Simbody.h>
#include <array>
#include <string>
#include <vector>

namespace rockroll {

struct WheelsetSpec {
    double x = 0;              ///< axle position on the car, forward of car center [m]
    int lumpedWheelsets = 1;   ///< 2 = the half car's equivalent wheelset
    RailInputFunction rails;   ///< rail heights under this wheelset
};

struct TruckSpec {
    std::string label;                  ///< "F" (leading) or "R"
    double x = 0;                       ///< truck center on the car [m]
    std::vector<WheelsetSpec> wheelsets;
    double carBodyLoad = 0;             ///< static load on its center plate [N]
    bool threeDimensional = false;      ///< rim ring, yaw friction, longitudinal pin
    // Attribution switches (RockingModel.h, AttributionSwitches), wheelset bodies only.
    bool unsprungGravity = true;        ///< false: the model excludes the wheelsets from gravity
    double unsprungMassScale = 1;       ///< mass and inertia factor; the lost weight as a constant force
    WheelRailSettings wheelRail;        ///< the wheel–rail contacts' lateral formulation and data
};

/// One truck's element forces and kinematics at one output time (Truck::calcSample), SI.
struct TruckSample {
    double crossLevel = 0;                         ///< mean over its wheelsets, right − left [m]
    double centerPlate = 0;                        ///< vertical [N]
    std::array<double, 2> sideBearing{0, 0}, spring{0, 0}, lateralSpring{0, 0};  ///< left, right [N]
    std::array<BristleFrictionState, 2> wedgeVertical{}, wedgeLateral{};
    double bolsterRoll = 0, bolsterLateral = 0;    ///< [rad], [m]
    std::vector<WheelRailForces> wheels;           ///< one per wheelset body
    SimTK::Vec3 carBodyAcceleration{0};            ///< car-body point over the truck at CG height, ground axes [m/s²]
};

/// Everything a Simbody rocking model records at one output time (its channels'
/// evaluators read only this; RockingModel::calcSample fills it once per sample).
struct CarSample {
    SimTK::Vec3 angles{0};          ///< body-fixed XYZ roll, pitch, yaw [rad] (roll: the halves' mean)
    SimTK::Vec3 position{0};        ///< car-body CG [m] (a twisting body's: the halves' mean)
    double verticalFromStatic = 0;  ///< CG height above its static height [m]
    SimTK::Vec3 cgAcceleration{0};  ///< car-body CG, ground axes [m/s²]
    double twist = 0;               ///< rear half against front half about x (a twisting car body) [rad]
    double torque = 0;              ///< torsional moment carried by the car body [N·m]
    std::vector<TruckSample> trucks;
    double energyStored = 0, energyInput = 0, energyDissipated = 0;  ///< [J]
};

/// Energy-audit powers of one truck's elements [W] (state realized to Velocity).
struct TruckPowers {
    double railInput = 0;        ///< work rate of the rails on the wheels
    double dissipated = 0;       ///< contact damping, pin and lateral damping, friction
};

class Truck {
public:
    /// p_CarBodyPlate: the car body's center-plate point in the car body frame.
    Truck(SimTK::SimbodyMatterSubsystem& matter, SimTK::GeneralForceSubsystem& forces,
          const SimTK::MobilizedBody& carBody, const SimTK::Vec3& p_CarBodyPlate,
          const CarParameters& car, TruckSpec spec);

    /// Places bolster and wheelsets in static equilibrium on level rails at
    /// height 0 under the truck's static load; returns the ground height the
    /// car body's plate must have.
    double setStaticState(SimTK::State& s) const;

    TruckPowers calcPowers(const SimTK::State& s) const;

    /// Declares this truck's channels; `index` is the truck's place in CarSample::trucks.
    void declareChannels(ChannelTable<CarSample>& table, int index) const;
    /// Declares its freight channels: each wheel's unloading ratio and L/V. The unloading is
    /// measured from `staticLoads` [wheelset][side] when given (an off-centre car body's
    /// solved static state), else from calcStaticWheelLoad.
    void declareFreightChannels(ChannelTable<CarSample>& table, int index,
                                const std::vector<std::array<double, 2>>& staticLoads = {}) const;
    /// This truck's forces (state realized to Velocity); carBodyAcceleration is left 0.
    TruckSample calcSample(const SimTK::State& s) const;
    const std::string& getLabel() const { return spec_.label; }
    double getX() const { return spec_.x; }
    /// Static load of each wheel of wheelset body i [N] (both wheels of a lumped body).
    double calcStaticWheelLoad(int wheelset) const;
    /// This truck's static equilibrium (the one definition, TruckStatics.h).
    TruckStatics calcStatics() const;

    const SimTK::MobilizedBody& getBolster() const { return bolster_; }
    const SimTK::MobilizedBody& getWheelset(int i) const { return wheelsets_[i]; }
    int getNumWheelsets() const { return int(wheelsets_.size()); }
    const WheelRailContact& getWheelRail(int i) const { return *wheelRail_[i]; }
    const CenterPlateContact& getCenterPlate() const { return *centerPlate_; }
    const SideBearing& getSideBearing(int side) const { return *sideBearing_[side]; }
    const VerticalSpringGroup& getVerticalSpring(int side) const { return *verticalSpring_[side]; }
    const FrictionWedge& getFrictionWedge(int side) const { return *wedge_[side]; }

private:
    void addBodies(SimTK::SimbodyMatterSubsystem& matter);
    void addElements(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& carBody,
                     const SimTK::Vec3& p_CarBodyPlate);
    SuspensionLink makeSuspensionLink(double sideSign) const;

    const CarParameters car_;
    const TruckSpec spec_;
    SimTK::MobilizedBody bolster_;
    std::vector<SimTK::MobilizedBody> wheelsets_;
    // Owned by the force subsystem; kept for output.
    const CenterPlateContact* centerPlate_ = nullptr;
    const SideBearing* sideBearing_[2] = {nullptr, nullptr};
    const VerticalSpringGroup* verticalSpring_[2] = {nullptr, nullptr};
    const LateralSpringGroup* lateralSpring_[2] = {nullptr, nullptr};
    const FrictionWedge* wedge_[2] = {nullptr, nullptr};
    std::vector<const WheelRailContact*> wheelRail_;
};

/// A body moving in the track's cross-section plane at longitudinal position x:
/// lateral y, vertical z and roll about x (SimTK Planar mobilizer, q = [roll, y, z]).
SimTK::MobilizedBody::Planar makeCrossSectionBody(SimTK::MobilizedBody& ground, double x,
                                                  const SimTK::Body::Rigid& body);

}  // namespace rockroll
