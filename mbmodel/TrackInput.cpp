#include "mbmodel/TrackInput.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rockroll {

TrackInput::TrackInput(TrackSpec spec) : spec_(std::move(spec)) {
    if (!(spec_.railLength > 0)) throw std::invalid_argument("track rail length must be positive");
    if (spec_.rails < 0) throw std::invalid_argument("track rails must be 0 (unlimited) or positive");
    for (size_t i = 1; i < spec_.measured.size(); ++i)
        if (!(spec_.measured[i].distance > spec_.measured[i - 1].distance))
            throw std::invalid_argument("measured track distances must increase strictly");
}

RailPoint TrackInput::calcRails(double s) const {
    RailPoint p = spec_.measured.empty() ? calcRectifiedSine(s) : calcMeasured(s);
    if (spec_.mirror) {
        std::swap(p.z[0], p.z[1]);
        std::swap(p.slope[0], p.slope[1]);
    }
    return p;
}

RailPoint TrackInput::calcRectifiedSine(double s) const {
    RailPoint p;
    const double L = spec_.railLength, A = spec_.amplitude;
    // The level lead-in includes s = 0 itself, so the car stands in static
    // equilibrium at t = 0 and the rails start to move just after.
    if (s <= 0 || (spec_.rails > 0 && s > spec_.rails * L) || A == 0) return p;
    const double k = M_PI / L;
    const double u = k * (s + L / 4);
    const double base = A / std::sqrt(2.0);
    const double phase[2] = {u + M_PI / 2, u};  // left, right
    for (int i = 0; i < 2; ++i) {
        const double sn = std::sin(phase[i]);
        p.z[i] = A * std::abs(sn) - base;
        p.slope[i] = A * k * std::cos(phase[i]) * (sn >= 0 ? 1 : -1);
    }
    return p;
}

RailPoint TrackInput::calcMeasured(double s) const {
    RailPoint p;
    const auto& m = spec_.measured;
    if (m.size() < 2 || s < m.front().distance || s > m.back().distance) return p;
    const auto hi = std::upper_bound(m.begin(), m.end(), s,
                                     [](double x, const MeasuredTrackSample& a) { return x < a.distance; });
    const auto& b = hi == m.end() ? m.back() : *hi;
    const auto& a = hi == m.end() ? *(hi - 2) : *(hi - 1);
    const double f = (s - a.distance) / (b.distance - a.distance);
    const double c = a.crossLevel + f * (b.crossLevel - a.crossLevel);
    const double pr = a.profile + f * (b.profile - a.profile);
    const double dc = (b.crossLevel - a.crossLevel) / (b.distance - a.distance);
    const double dp = (b.profile - a.profile) / (b.distance - a.distance);
    p.z = {pr - c / 2, pr + c / 2};
    p.slope = {dp - dc / 2, dp + dc / 2};
    return p;
}

}  // namespace rockroll
