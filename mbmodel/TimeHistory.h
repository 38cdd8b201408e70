#pragma once
// A recorded run, shared by every model (Simbody and bespoke). No Simbody dependency.
#include <stdexcept>
#include <string>
#include <vector>

namespace rockroll {

struct TimeHistory {
    std::vector<std::string> names;            ///< "t_s" then the model's channels
    std::vector<std::vector<double>> samples;  ///< one row per output time
    int column(const std::string& name) const {
        for (size_t i = 0; i < names.size(); ++i)
            if (names[i] == name) return int(i);
        throw std::out_of_range("no channel " + name);
    }
};

struct RunResult {
    TimeHistory history;
    long steps = 0;
    long realizations = 0;  ///< right-hand-side evaluations (System realizations) the integrator made
    double simTime = 0;   ///< [s]
    double wallTime = 0;  ///< [s]
    std::vector<double> finalState;  ///< the model's state at the end, flat, to continue from
};

}  // namespace rockroll
