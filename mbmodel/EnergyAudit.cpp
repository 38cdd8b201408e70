#include "mbmodel/EnergyAudit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rockroll {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// History columns are "t_s" followed by the layout's channels.
struct Columns {
    int stored = -1, input = -1, dissipated = -1;
    bool valid(const TimeHistory& h) const {
        const int n = int(h.names.size());
        return stored > 0 && input > 0 && dissipated > 0 && stored < n && input < n && dissipated < n &&
               !h.samples.empty();
    }
};

Columns findColumns(const ChannelLayout& layout) {
    if (layout.energyStored < 0 || layout.energyInput < 0 || layout.energyDissipated < 0) return {};
    return {layout.energyStored + 1, layout.energyInput + 1, layout.energyDissipated + 1};
}

double relativeError(std::span<const double> first, std::span<const double> row, const Columns& c) {
    const double W = row[c.input], D = row[c.dissipated], dE = row[c.stored] - first[c.stored];
    const double scale = std::max(std::abs(W), D);
    if (!(scale > 0)) return kNaN;
    return std::abs(W - dE - D) / scale;
}
}  // namespace

double calcEnergyBalanceError(const TimeHistory& h, const ChannelLayout& layout) {
    const Columns c = findColumns(layout);
    if (!c.valid(h)) return kNaN;
    return relativeError(h.samples.front(), h.samples.back(), c);
}

double calcWorstEnergyBalanceError(const TimeHistory& h, const ChannelLayout& layout, double tFrom) {
    const Columns c = findColumns(layout);
    if (!c.valid(h)) return kNaN;
    double worst = kNaN;
    for (const auto& row : h.samples) {
        if (row[0] < tFrom) continue;
        const double e = relativeError(h.samples.front(), row, c);
        if (std::isnan(e)) continue;
        worst = std::isnan(worst) ? e : std::max(worst, e);
    }
    return worst;
}

}  // namespace rockroll
