#pragma once
// rockroll orbits: periodic orbits of a time-domain model by shooting, continued in
// speed, with their Floquet multipliers (scenarios/PeriodicOrbit.h,
// scenarios/OrbitContinuation.h; docs/orbits.md).
#include "app/Commands.h"

#include <optional>
#include <string>

namespace rockroll::app {

struct OrbitsOptions : CommonOptions {
    std::string scenario;
    std::optional<std::string> model;
    std::optional<double> amplitudeIn;
    double fromMph = 16, toMph = 10, stepMph = 0.25;
    double startDurationS = 30;  ///< the run from rest at --from-mph whose end the first shooting starts from [s]
    /// When set, the start is a speed sweep from this speed to --from-mph in --step-mph steps
    /// (startDurationS at each speed, the state carried over), not a run from rest: the way
    /// onto an upper branch that a run from rest does not reach [mph].
    std::optional<double> startSweepFromMph;
    double startRampS = 1.0;     ///< the start sweep's speed ramp between speeds; 0: a step [s]
    double accuracy = 1e-7;      ///< integrator accuracy of the map
    int refinements = 2;         ///< step halvings at a failure before the branch ends
    int newtonSteps = 20;        ///< Newton steps per shooting (on P, then on P∘P)
    int settlePeriods = 0;
    bool iterate = false;        ///< find each orbit by iterating the map (attracting orbits only), not Newton       ///< periods the map runs from the start before the first shooting
    double fdStepScale = 1;      ///< scales the monodromy's finite-difference steps (the tolerance is unchanged)
    int jobs = 0;                ///< threads for the monodromy's columns (0: one per core)
    bool json = false;
};

/// Exit 0 with the branch (stopped at a fold, a branch end or --to-mph); 2 bad input
/// (a track that does not repeat, a model whose state cannot be shot, options); 3
/// when shooting does not converge at --from-mph or the start run fails.
int orbitsCommand(const OrbitsOptions& options);

}  // namespace rockroll::app
