#pragma once
// The report's reduced-complexity simulation (§2.2): the half car body with
// vertical, lateral and roll motion on a massless truck in equilibrium at every
// instant (TruckEquilibrium.h), integrated by fixed-step RK4 at Δt = 0.005 s.
//
// Car body (mass M = half the car body, roll inertia I about its CG, small angles):
//
//     M z̈ = F_cL + F_cR + F_sL + F_sR − M g
//     M ÿ = F_h
//     I θ̈ = Σ_k F_k·(p_y,k − θ·p_z,k) + h·F_h        (report eq. 5)
//
// where F_k are the rim and side-bearing forces at the car-body points p_k and
// h the CG height above the center plate. The lateral center-pin force F_h
// (pin stiffness k_pin, assumed: docs/model.md) comes out of the same truck
// equilibrium as the vertical forces.
#include "bespoke/EomHalfCarModel.h"
#include "bespoke/TruckEquilibrium.h"
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/RunLimits.h"
#include "mbmodel/TimeHistory.h"

#include <Eigen/Dense>
#include <memory>

namespace rockroll {

/// Scenario table [reduced].
struct ReducedOptions {
    /// false (the report's §2.2): the truck is massless and weightless, so a wheel
    /// carries only the car body's share (42 583 lb, 70-ton loaded). true: the
    /// truck's equilibrium also carries the bolster's and the equivalent
    /// wheelset's weights (2 wheelsets, 2 side frames), still without inertia, so
    /// the static wheel load equals the Simbody half car's (docs/bespoke.md).
    bool truckWeight = false;
};

class ReducedHalfCarModel {
public:
    using State = Eigen::Matrix<double, 6, 1>;  ///< [θ, y, z, θ̇, ẏ, ż] of the car body
    static constexpr double kStep = 0.005;      ///< the report's Δt [s]

    /// What the truck remembers between steps (the kinematic rule's "old" values).
    struct TruckMemory {
        TruckMode mode;
        std::array<double, 2> compression{0, 0};
        std::array<double, 2> wedgeAnchor{0, 0};
        double lateralDeflection = 0;  ///< Y = y_bolster − y_seat
        double lateralAnchor = 0;      ///< Y_a of the lateral wedges
        double rollBolster = 0, rollWheelset = 0;
    };

    struct Evaluation {
        State derivative;
        TruckSolution truck;
        double railInputPower = 0;  ///< energy audit: Σ W_i·ż_rail,i [W]
        RailState rail;             ///< the rails at the evaluation's time
    };

    ReducedHalfCarModel(const CarParameters& car, RailStateFunction rails, ReducedOptions options = {});

    State makeStaticState() const;
    TruckMemory makeStaticMemory() const;
    /// The static state and truck memory as one flat vector, the layout of
    /// RunResult::finalState and of simulateReduced's `initial`.
    std::vector<double> calcStaticState() const;
    /// counts: the truck-mode search's counts are added there (nullptr: not counted).
    Evaluation evaluate(double t, const State& y, const TruckMemory& memory, TruckSearchCounts* counts = nullptr) const;
    /// The same with the rails at the evaluation's time already computed (calcRails(t)).
    Evaluation evaluate(const RailState& rail, const State& y, const TruckMemory& memory,
                        TruckSearchCounts* counts = nullptr) const;
    RailState calcRails(double t) const { return rails_(t); }

    /// What one output time records: the half car's common values and this model's truck.
    struct Sample : HalfCarSample {
        TruckSolution truck;
    };
    const ChannelLayout& getChannels() const { return channels_.getLayout(); }
    Sample calcSample(double t, const State& y, const Evaluation& e, const double* energyIntegrals = nullptr) const;
    /// Static load of each wheel of the equivalent wheelset [N]: the truck's
    /// equilibrium at the static state on level rails.
    double calcStaticWheelLoad() const;
    /// The truck's static loads and spring compression (the one definition,
    /// mbmodel/TruckStatics.h; massless unless `[reduced] truck_weight`).
    TruckStatics calcTruckStatics() const;
    /// energyIntegrals: {rail work, dissipated energy} since t = 0 [J]; NaN when null.
    void calcChannels(double t, const State& y, const Evaluation& e, std::vector<double>& out,
                      const double* energyIntegrals = nullptr) const;
    /// Energy audit: car body kinetic + gravity energy plus the truck's elastic
    /// energy (springs, gibs, wedge bristles, center pin; the rigid contacts store none) [J].
    double calcStoredEnergy(const State& y, const TruckSolution& truck) const;
    /// Energy dissipated by the wedges' sliders when the truck memory moves from
    /// `before` to the solution `after`: Σ |Φ_i|·|ΔZ_a,i| + |Φ_H|·|ΔY_a| [J].
    static double calcSliderDissipation(const TruckMemory& before, const TruckSolution& after);
    /// What the truck remembers after accepting `accepted`: its mode, compressions,
    /// anchors, lateral deflection and rolls.
    static TruckMemory makeMemoryAfter(const TruckSolution& accepted);
    const TruckGeometry& getTruckGeometry() const { return truck_; }
    double getMass() const { return mass_; }
    double getInertia() const { return inertia_; }
    TruckInputs makeTruckInputs(double t, const State& y, const TruckMemory& memory) const;

private:
    TruckInputs makeTruckInputs(const RailState& rail, const State& y, const TruckMemory& memory) const;
    void declareChannels();
    CarParameters car_;
    RailStateFunction rails_;
    TruckGeometry truck_;
    TruckWeight truckWeight_ = TruckWeight::Massless;
    std::shared_ptr<const TruckModeCache> modeCache_;  // per-mode factorizations (TruckModeCache::getShared)
    double mass_ = 0, inertia_ = 0, staticZ_ = 0;
    ChannelTable<Sample> channels_;
};

struct ReducedRunStatistics {
    long steps = 0, inconsistentSteps = 0;
    TruckSearchCounts modes;  ///< every truck-mode search of the run
};

/// Fixed-step RK4 at Δt = 0.005 s; records every step (200 Hz). A duration that is
/// not a whole number of steps ends with one shorter step. From static
/// equilibrium, or from `initial` (a previous RunResult::finalState: the car
/// body state followed by the truck's memory).
/// `limits` (resolved) stop the run on derailment or overturning and fail it on
/// runaway or the wall-time limit (RunGuard).
RunResult simulateReduced(const ReducedHalfCarModel& model, double duration, ReducedRunStatistics* stats = nullptr,
                          const std::vector<double>& initial = {}, const RunLimits& limits = {});

}  // namespace rockroll
