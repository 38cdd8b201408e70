#pragma once
// Zero-phase low-pass filter for force channels before their maxima are taken
// (docs/model.md §6, "Outputs"): a 2nd-order Butterworth section (bilinear transform with
// pre-warping) run forward then backward, so the result has no phase lag and a
// 4th-order magnitude roll-off with −6 dB at the cut-off.
#include <string>
#include <vector>

namespace rockroll {

class LowPassFilter {
public:
    LowPassFilter(double cutoffHz, double sampleRateHz);
    std::vector<double> apply(const std::vector<double>& x) const;
    std::string getDescription() const;

private:
    std::vector<double> pass(const std::vector<double>& x) const;
    double cutoff_, rate_;
    double b0_, b1_, b2_, a1_, a2_;
};

}  // namespace rockroll
