#pragma once
// Progress of the speeds of sweeps (rockroll sweep, validate): a bar redrawn in place
// when stderr is a terminal; otherwise (a log file, a pipe) one line per finished
// speed with its result and an ETA, so logs hold no carriage returns.
#include "scenarios/SpeedSweep.h"

#include <chrono>
#include <cstddef>
#include <string>

namespace rockroll::app {

class SweepProgress {
public:
    /// `label` starts each line ("sweep", "validate sweeps"); `total` speeds in all.
    SweepProgress(std::string label, size_t total);
    /// After each finished speed (runSweeps calls its callback under a lock).
    void operator()(const SweepPoint& p);

    /// "3/10 speeds: 15.00 mph up (continued): severe, max roll 2.31 deg; ETA 12 s".
    static std::string formatLine(size_t done, size_t total, const SweepPoint& p, double etaS);

private:
    std::string label_;
    size_t total_, done_ = 0, failed_ = 0;
    bool terminal_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace rockroll::app
