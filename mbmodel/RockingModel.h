#pragma once
// Common base of the Simbody rocking models: the multibody system, the car body,
// its trucks, static equilibrium and the recorded channels.
#include "mbmodel/CarParameters.h"
#include "mbmodel/ModelOptions.h"
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/TrackInput.h"
#include "mbmodel/Truck.h"

#include <Simbody.h>
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace rockroll {

class RockingModel {
public:
    virtual ~RockingModel() = default;
    RockingModel(const RockingModel&) = delete;
    RockingModel& operator=(const RockingModel&) = delete;

    const SimTK::MultibodySystem& getSystem() const { return system_; }
    const SimTK::SimbodyMatterSubsystem& getMatter() const { return matter_; }
    const SimTK::GeneralForceSubsystem& getForces() const { return forces_; }
    const CarParameters& getCar() const { return car_; }
    const Truck& getTruck(int i) const { return *trucks_[i]; }
    int getNumTrucks() const { return int(trucks_.size()); }
    const SimTK::MobilizedBody& getCarBody() const { return carBody_; }
    /// The car body twists (two halves): its twist, rear half relative to front about the
    /// car's x axis [rad], and the torsional moment the body carries, K·θ + C·θ̇ [N·m].
    bool isCarBodyTwisting() const { return !twist_.isEmptyHandle(); }
    /// The rear half's pin on the front half (a twisting car body only).
    const SimTK::MobilizedBody& getCarBodyTwistPin() const { return twist_; }
    double getCarBodyTwist(const SimTK::State& s) const;
    double calcCarBodyTorque(const SimTK::State& s) const;

    /// State at t = 0 with every body in static equilibrium on level rails and
    /// every friction wedge unloaded. The trucks' statics place it (TruckStatics.h); an
    /// off-centre car body is then brought to equilibrium by Newton's method
    /// (solveStaticEquilibrium).
    /// requireLevelRails: refuse (throw) unless the rails are level at t = 0, as
    /// a run from rest needs; a run continuing a sweep only uses the geometry.
    SimTK::State makeStaticState(bool requireLevelRails = true) const;
    /// Simbody's default state with every unrestricted orientation (the full car's Free car
    /// body) as body-fixed x-y-z angles instead of a quaternion, realized to Model stage. Its
    /// q̇ = N(q)·u has no normalization constraint, so CPodes projects nothing after a step
    /// (bench/README.md, "Euler angles for the full car's body"); the angles are singular only
    /// at ±90° of pitch.
    SimTK::State makeDefaultState() const;

    const ChannelLayout& getChannels() const { return channels_.getLayout(); }
    /// Every recorded value at `s` (realizes it to Acceleration: the car-body accelerations).
    CarSample calcSample(const SimTK::State& s) const;
    /// One sample of every channel (no time column).
    void calcChannels(const SimTK::State& s, std::vector<double>& out) const;

    /// Total mechanical energy of the bodies and conservative elements [J]:
    /// kinetic + gravity + elastic energy of every element (contacts, springs,
    /// center pin, wheel–rail lateral restraint, friction bristles).
    double calcMechanicalEnergy(const SimTK::State& s) const;

    /// Energy audit: cumulative work of the rails on the wheels and energy
    /// dissipated since the start of the run [J], integrated as z states of the
    /// force subsystem alongside the dynamics (state realized to Velocity).
    struct EnergyAccounts {
        double input = 0, dissipated = 0;
    };
    EnergyAccounts getEnergyAccounts(const SimTK::State& s) const;
    /// Zeroes the accumulated energies: a run continued from another run's final
    /// state counts its energies from its own start.
    void resetEnergyAccounts(SimTK::State& s) const;
    /// Where the energy audit's integrals sit in the flat state Y = [q, u, z].
    std::vector<int> getEnergyAuditYIndices() const;
    /// Vertical load of one wheel in the static state (makeStaticState) [N]: wheelset body
    /// `wheelset` of truck `truck`, side kLeft or kRight (CarSide.h).
    double getStaticWheelLoad(int truck, int wheelset, int side) const {
        return staticWheelLoads_[size_t(truck)][size_t(wheelset)][size_t(side)];
    }
    /// Sum of every truck's element powers [W].
    TruckPowers calcPowers(const SimTK::State& s) const;

protected:
    RockingModel(const CarParameters& car, const TrackInput& track, ModelOptions options);
    /// Called by derived constructors once the car body exists. p_CarBodyPlates: each
    /// truck's center-plate point in the car frame (origin at the car body's CG); each
    /// truck hangs from the car-body part over it (carBodyParts_).
    void addTrucks(std::vector<TruckSpec> specs, const std::vector<SimTK::Vec3>& p_CarBodyPlates);
    /// A rigid piece of the car body: the whole body, or one half of a twisting body.
    struct CarBodyPart {
        SimTK::MobilizedBody body;
        double x = 0;  ///< its CG (body origin) on the car, forward of the car's CG [m]
    };
    /// Declares the car body as two halves, the rear joined to the front by `twist`, a pin
    /// about the car's longitudinal axis with torsional stiffness and damping [N·m/rad,
    /// N·m·s/rad] (FullCarModel). Left alone: the car body is carBody_ alone, at x = 0.
    void setTwistingCarBody(std::vector<CarBodyPart> parts, const SimTK::MobilizedBody& twist, double stiffness,
                            double damping);
    /// Places the car body on its trucks: each truck's center-plate point (p_CarBodyPlates
    /// of addTrucks) at the ground height plateZ[truck] [m].
    virtual void setCarBodyPose(SimTK::State& s, const std::vector<double>& plateZ) const = 0;
    /// The placed static state needs solving (an off-centre car body, FullCarModel): set
    /// before addTrucks.
    void setStaticStateNeedsSolving() { staticSolve_ = true; }
    /// Moves the positions of `s` (velocities zero, z states kept) until every generalized
    /// acceleration vanishes: Newton's method with a central-difference Jacobian in the
    /// generalized speeds' directions (q += N·δu), solved in the least-squares sense so a
    /// direction without static stiffness takes no step. std::runtime_error when it does
    /// not converge.
    void solveStaticEquilibrium(SimTK::State& s) const;
    /// Rail input at a wheelset, averaging over the listed axle offsets.
    RailInputFunction makeRailInput(std::vector<double> trackOffsets) const;
    void declareChannels();

    const CarParameters car_;
    const TrackInput track_;
    const ModelOptions options_;
    SimTK::MultibodySystem system_;
    SimTK::SimbodyMatterSubsystem matter_;
    SimTK::GeneralForceSubsystem forces_;
    SimTK::MobilizedBody carBody_;  ///< the car body, or its front half when it twists
    std::vector<CarBodyPart> carBodyParts_;
    std::vector<int> truckPart_;    ///< each truck's part of carBodyParts_
    SimTK::MobilizedBody twist_;    ///< the halves' pin when the car body twists
    double torsionalStiffness_ = 0, torsionalDamping_ = 0;
    std::vector<std::unique_ptr<Truck>> trucks_;
    ChannelTable<CarSample> channels_;
    double staticCarBodyHeight_ = 0;  // z of the CG at rest [m]
    using StaticWheelLoads = std::vector<std::array<double, 2>>;  // [wheelset][side] [N]
    std::vector<StaticWheelLoads> staticWheelLoads_;  // each truck's, in the static state
    bool staticSolve_ = false;
    class EnergyMeter;
    const EnergyMeter* energyMeter_ = nullptr;  // owned by the force subsystem
};


}  // namespace rockroll
