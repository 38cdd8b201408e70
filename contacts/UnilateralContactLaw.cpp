#include "contacts/UnilateralContactLaw.h"

#include <algorithm>

namespace rockroll {

double calcUnilateralNormalForce(double penetration, double penetrationRate,
                                 const UnilateralContactLaw& law) {
    if (penetration <= 0) return 0;
    const double f = law.stiffness * penetration * (1 + law.dissipation * penetrationRate);
    return std::max(0.0, f);
}

double calcUnilateralContactEnergy(double penetration, const UnilateralContactLaw& law) {
    return penetration > 0 ? 0.5 * law.stiffness * penetration * penetration : 0.0;
}

double calcUnilateralContactDissipation(double penetration, double penetrationRate,
                                        const UnilateralContactLaw& law) {
    if (penetration <= 0) return 0;
    const double f = calcUnilateralNormalForce(penetration, penetrationRate, law);
    return (f - law.stiffness * penetration) * penetrationRate;
}

}  // namespace rockroll
