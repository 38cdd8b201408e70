#pragma once
// The one interface every time-domain formulation implements: the Simbody half
// and full car, the equation-of-motion half car and the report's reduced
// massless-truck model. run, sweep, validate, bench and the Python module reach a
// model only through this interface and the ModelRegistry.
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/TimeHistory.h"

#include <string>
#include <vector>

namespace rockroll {

struct Scenario;

/// The end of a run, kept to continue from: whose state it is, the state, and
/// where on the track the car was and how fast it went. A state continues only
/// in the model that produced it (runScenario refuses anything else).
struct RestartState {
    std::string model;      ///< ModelDescriptor::name of the model that produced `y`
    std::vector<double> y;  ///< that model's flat state (its own layout)
    double distance = 0;    ///< track distance s reached [m]
    double speed = 0;       ///< speed at the end [m/s]
};

/// What an entry of a model's flat state y is, for shooting a periodic orbit
/// (scenarios/PeriodicOrbit.h perturbs each entry by its kind's step and leaves the
/// accumulating ones out of the orbit).
enum class StateKind {
    Position,     ///< a generalized coordinate [m, rad] (quaternion entries included)
    Rate,         ///< a generalized speed [m/s, rad/s]
    Internal,     ///< an element's internal state: a friction bristle's deflection [m, rad]
    Accumulating, ///< grows without bound over a run (the energy audit's integrals)
    Discrete      ///< an enumerated mode stored as a whole number (the reduced model's truck mode)
};

class TimeDomainModel {
public:
    virtual ~TimeDomainModel() = default;

    /// The recorded channels (names with units, roles of the summary).
    virtual const ChannelLayout& getChannels() const = 0;

    /// The flat state at static equilibrium on level rails: what a run from rest
    /// starts from, in the layout RestartState::y uses.
    virtual std::vector<double> calcStaticState() const = 0;

    /// Runs sc.run (duration, output rate, integrator, limits resolved against the
    /// car) from static equilibrium (y0 empty) or from y0. Throws NumericalFailure.
    virtual RunResult simulate(const Scenario& sc, const std::vector<double>& y0) const = 0;

    /// The kind of every entry of the flat state, in its order; empty when the
    /// state cannot be shot for a periodic orbit (the default).
    virtual std::vector<StateKind> getStateKinds() const { return {}; }
};

}  // namespace rockroll
