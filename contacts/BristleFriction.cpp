#include "contacts/BristleFriction.h"

#include <algorithm>
#include <cmath>

namespace rockroll {

namespace {
double smoothstep(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3 - 2 * x);
}
}  // namespace

BristleFrictionState calcBristleFriction(double w, double v, const BristleFrictionLaw& law) {
    BristleFrictionState out;
    if (law.limit <= 0) {
        // No normal load: the bristle relaxes and carries nothing.
        out.deflectionRate = -w / law.relaxationTime;
        out.slipping = true;
        return out;
    }
    const double wMax = law.limit / law.stiffness;
    const double ratio = std::abs(w) / wMax;
    // Slip blends in near the limit deflection, and only while the surfaces move
    // further in the loading direction; both blends are smooth (C¹) so the
    // implicit integrator does not see a jump when the velocity reverses.
    const double loading = smoothstep(v * (w >= 0 ? 1 : -1) / law.reversalVelocity);
    const double alpha = loading * (ratio >= 1 ? 1.0 : smoothstep((ratio - law.presliding) / (1 - law.presliding)));
    double wDot = v * (1 - alpha);
    if (ratio > 1) wDot -= (w - std::copysign(wMax, w)) / law.relaxationTime;
    const double f = std::clamp(law.stiffness * w + law.damping * wDot, -law.limit, law.limit);
    out.force = -f;
    out.deflectionRate = wDot;
    out.slipping = alpha > 0.5;
    return out;
}

double calcBristleEnergy(double w, const BristleFrictionLaw& law) { return 0.5 * law.stiffness * w * w; }

double calcBristleDissipation(double w, double v, const BristleFrictionLaw& law) {
    const BristleFrictionState s = calcBristleFriction(w, v, law);
    return -s.force * v - law.stiffness * w * s.deflectionRate;
}

}  // namespace rockroll
