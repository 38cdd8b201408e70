#pragma once
// Unit conversion: SI inside, US customary (and SI) accepted on input.
#include <stdexcept>
#include <string>
#include <string_view>

namespace rockroll::units {

constexpr double lbf = 4.4482216152605;      ///< N
constexpr double inch = 0.0254;              ///< m
constexpr double foot = 0.3048;              ///< m
constexpr double mph = 0.44704;              ///< m/s
constexpr double g = 9.80665;                ///< m/s² (386.088 in/s²)
constexpr double lbfPerInch = lbf / inch;    ///< N/m
constexpr double lbInS2 = lbf * inch;        ///< lb·in·s² → kg·m²
constexpr double degree = 3.14159265358979323846 / 180;

constexpr double tonne = 1000;              ///< kg
/// Force units include the mass units kg and t: a mass given where a weight (force) is
/// expected is its weight under standard gravity g (1 kg → 9.80665 N, 1 t → 9806.65 N).
enum class Dimension { Length, Speed, Force, Stiffness, Time, Frequency, MomentOfInertia,
                       Angle, AngularStiffness, Damping, InverseSpeed, Dimensionless };

std::string_view getDimensionName(Dimension d);
/// Units accepted for a dimension, for error messages ("in, ft, m, mm").
std::string getAcceptedUnits(Dimension d);

/// Parses "<number> <unit>" (e.g. "16.5 mph", "0.75 in", "4000 lbf") into SI.
/// Throws std::invalid_argument naming what was expected.
double parseQuantity(std::string_view text, Dimension expected);

}  // namespace rockroll::units
