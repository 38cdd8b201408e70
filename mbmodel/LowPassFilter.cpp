#include "mbmodel/LowPassFilter.h"

#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

namespace rockroll {

LowPassFilter::LowPassFilter(double cutoffHz, double sampleRateHz) : cutoff_(cutoffHz), rate_(sampleRateHz) {
    if (!(cutoffHz > 0) || !(cutoffHz < sampleRateHz / 2))
        throw std::invalid_argument(fmt::format("filter cut-off {} Hz must lie in (0, {} Hz)", cutoffHz,
                                                sampleRateHz / 2));
    // H(s) = 1/(s² + √2 s + 1) at s → (1/K)(1 − z⁻¹)/(1 + z⁻¹), K = tan(π f_c / f_s).
    const double K = std::tan(M_PI * cutoffHz / sampleRateHz);
    const double norm = 1 / (1 + std::sqrt(2.0) * K + K * K);
    b0_ = K * K * norm;
    b1_ = 2 * b0_;
    b2_ = b0_;
    a1_ = 2 * (K * K - 1) * norm;
    a2_ = (1 - std::sqrt(2.0) * K + K * K) * norm;
}

std::vector<double> LowPassFilter::pass(const std::vector<double>& x) const {
    std::vector<double> y(x.size());
    if (x.empty()) return y;
    // Start in steady state at the first sample so a constant signal passes unchanged.
    double x1 = x[0], x2 = x[0], y1 = x[0], y2 = x[0];
    for (size_t n = 0; n < x.size(); ++n) {
        y[n] = b0_ * x[n] + b1_ * x1 + b2_ * x2 - a1_ * y1 - a2_ * y2;
        x2 = x1; x1 = x[n];
        y2 = y1; y1 = y[n];
    }
    return y;
}

std::vector<double> LowPassFilter::apply(const std::vector<double>& x) const {
    std::vector<double> y = pass(x);
    std::vector<double> r(y.rbegin(), y.rend());
    r = pass(r);
    return {r.rbegin(), r.rend()};
}

std::string LowPassFilter::getDescription() const {
    return fmt::format("Butterworth 2nd order, {:g} Hz, zero-phase (forward-backward), {:g} Hz sampling",
                       cutoff_, rate_);
}

}  // namespace rockroll
