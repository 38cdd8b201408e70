#include "contacts/SpringGroupLaws.h"

#include <cmath>

namespace rockroll {

double calcVerticalSpringForce(double Z, const VerticalSpringLaw& law) {
    if (Z <= 0) return 0;
    if (Z <= law.travel) return law.rate * Z;
    return law.rate * law.travel + law.bottomingRate * (Z - law.travel);
}

double calcVerticalSpringEnergy(double Z, const VerticalSpringLaw& law) {
    if (Z <= 0) return 0;
    if (Z <= law.travel) return 0.5 * law.rate * Z * Z;
    const double b = Z - law.travel;
    return 0.5 * law.rate * law.travel * law.travel + law.rate * law.travel * b + 0.5 * law.bottomingRate * b * b;
}

double calcVerticalSpringCompression(double P, const VerticalSpringLaw& law) {
    if (P <= 0) return 0;
    const double atBottom = law.rate * law.travel;
    if (P <= atBottom) return P / law.rate;
    return law.travel + (P - atBottom) / law.bottomingRate;
}

double calcLateralSpringForce(double Y, double Ydot, const LateralSpringLaw& law) {
    const double sgn = Y >= 0 ? 1.0 : -1.0;
    const double gib = calcUnilateralNormalForce(std::abs(Y) - law.gibClearance, sgn * Ydot,
                                                 {law.gibRate, law.gibDissipation});
    return law.rate * Y + sgn * gib;
}

double calcLateralSpringEnergy(double Y, const LateralSpringLaw& law) {
    return 0.5 * law.rate * Y * Y + calcUnilateralContactEnergy(std::abs(Y) - law.gibClearance, {law.gibRate, 0});
}

double calcLateralSpringDissipation(double Y, double Ydot, const LateralSpringLaw& law) {
    const double sgn = Y >= 0 ? 1.0 : -1.0;
    return calcUnilateralContactDissipation(std::abs(Y) - law.gibClearance, sgn * Ydot,
                                            {law.gibRate, law.gibDissipation});
}

}  // namespace rockroll
