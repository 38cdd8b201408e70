#pragma once
// A recorded run, shared by every model (Simbody and bespoke). No Simbody dependency.
#include "mbmodel/SampleTable.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockroll {

struct TimeHistory {
    std::vector<std::string> names;            ///< "t_s" then the model's channels
    SampleTable samples;                       ///< one row per output time
    /// Room for `count` samples of names.size() values (none when count ≤ 0): a simulator
    /// reserves its whole run before recording.
    void reserveSamples(long count) { samples.reserve(size_t(count > 0 ? count : 0), names.size()); }
    int column(const std::string& name) const {
        for (size_t i = 0; i < names.size(); ++i)
            if (names[i] == name) return int(i);
        throw std::out_of_range("no channel " + name);
    }
};

/// Why a run stopped before its end time (derailment, overturning).
struct RunStop {
    std::string regime;  ///< "derailed" | "overturned"
    std::string reason;  ///< what was detected, with the values and the limit
    double time = 0;     ///< [s]
};

/// Thrown when a run fails numerically (integrator failure, step limit,
/// non-finite or runaway state, wall-time limit); what() names the time and the state.
class NumericalFailure : public std::runtime_error {
public:
    NumericalFailure(const std::string& what, double time) : std::runtime_error(what), time_(time) {}
    double getTime() const { return time_; }

private:
    double time_;
};

struct RunResult {
    TimeHistory history;
    long steps = 0;
    long realizations = 0;  ///< right-hand-side evaluations (System realizations) the integrator made
    double simTime = 0;   ///< [s]
    double wallTime = 0;  ///< [s]
    std::vector<double> finalState;  ///< the model's state at the end, flat, to continue from
    std::optional<RunStop> stop;     ///< set when a run limit stopped the run early
};

}  // namespace rockroll
