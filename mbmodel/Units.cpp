#include "mbmodel/Units.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fmt/format.h>

namespace rockroll::units {

namespace {
struct UnitDef {
    std::string_view name;
    Dimension dim;
    double toSI;
};
constexpr std::array kUnits{
    UnitDef{"m", Dimension::Length, 1.0},        UnitDef{"mm", Dimension::Length, 1e-3},
    UnitDef{"in", Dimension::Length, inch},      UnitDef{"ft", Dimension::Length, foot},
    UnitDef{"m/s", Dimension::Speed, 1.0},       UnitDef{"km/h", Dimension::Speed, 1 / 3.6},
    UnitDef{"mph", Dimension::Speed, mph},       UnitDef{"N", Dimension::Force, 1.0},
    UnitDef{"kN", Dimension::Force, 1e3},        UnitDef{"lbf", Dimension::Force, lbf},
    UnitDef{"lb", Dimension::Force, lbf},
    // A mass where a weight is expected: its weight under standard gravity (Units.h).
    UnitDef{"kg", Dimension::Force, g},          UnitDef{"t", Dimension::Force, tonne * g},
    UnitDef{"N/m", Dimension::Stiffness, 1.0},   UnitDef{"N/mm", Dimension::Stiffness, 1e3},
    UnitDef{"kN/m", Dimension::Stiffness, 1e3},  UnitDef{"kN/mm", Dimension::Stiffness, 1e6},
    UnitDef{"lb/in", Dimension::Stiffness, lbfPerInch},
    UnitDef{"lbf/in", Dimension::Stiffness, lbfPerInch},
    UnitDef{"s", Dimension::Time, 1.0},          UnitDef{"ms", Dimension::Time, 1e-3},
    UnitDef{"Hz", Dimension::Frequency, 1.0},    UnitDef{"kg*m^2", Dimension::MomentOfInertia, 1.0},
    UnitDef{"kg·m²", Dimension::MomentOfInertia, 1.0},
    UnitDef{"lb*in*s^2", Dimension::MomentOfInertia, lbInS2},
    UnitDef{"lbf*in*s^2", Dimension::MomentOfInertia, lbInS2},
    UnitDef{"rad", Dimension::Angle, 1.0},       UnitDef{"deg", Dimension::Angle, degree},
    UnitDef{"N*m/rad", Dimension::AngularStiffness, 1.0},
    UnitDef{"lb*in/rad", Dimension::AngularStiffness, lbf * inch},
    UnitDef{"N*s/m", Dimension::Damping, 1.0},   UnitDef{"N·s/m", Dimension::Damping, 1.0},
    UnitDef{"lb*s/in", Dimension::Damping, lbfPerInch},
    UnitDef{"lbf*s/in", Dimension::Damping, lbfPerInch},
    // Per unit of speed: the Hunt–Crossley contact dissipation d (F = k·δ^n·(1 + d·δ̇)).
    UnitDef{"s/m", Dimension::InverseSpeed, 1.0},    UnitDef{"s/in", Dimension::InverseSpeed, 1 / inch},
    UnitDef{"s/ft", Dimension::InverseSpeed, 1 / foot},
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}
}  // namespace

std::string_view getDimensionName(Dimension d) {
    switch (d) {
        case Dimension::Length: return "length";
        case Dimension::Speed: return "speed";
        case Dimension::Force: return "force";
        case Dimension::Stiffness: return "stiffness";
        case Dimension::Time: return "time";
        case Dimension::Frequency: return "frequency";
        case Dimension::MomentOfInertia: return "moment of inertia";
        case Dimension::Angle: return "angle";
        case Dimension::AngularStiffness: return "angular stiffness";
        case Dimension::Damping: return "viscous damping";
        case Dimension::InverseSpeed: return "dissipation per speed";
        case Dimension::Dimensionless: return "plain number";
    }
    return "?";
}

std::string getAcceptedUnits(Dimension d) {
    std::string out;
    for (const auto& u : kUnits)
        if (u.dim == d) out += (out.empty() ? "" : ", ") + std::string(u.name);
    return out.empty() ? "no unit" : out;
}

double parseQuantity(std::string_view text, Dimension expected) {
    const std::string_view t = trim(text);
    double value = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || !std::isfinite(value))
        throw std::invalid_argument(fmt::format("\"{}\" does not start with a number; expected a {} "
                                                "written as \"<number> <unit>\" with unit one of: {}",
                                                text, getDimensionName(expected), getAcceptedUnits(expected)));
    const std::string_view unit = trim(std::string_view(end, t.data() + t.size() - end));
    if (expected == Dimension::Dimensionless) {
        if (!unit.empty())
            throw std::invalid_argument(fmt::format("\"{}\" has a unit; expected a plain number", text));
        return value;
    }
    for (const auto& u : kUnits)
        if (u.name == unit) {
            if (u.dim != expected)
                throw std::invalid_argument(fmt::format("\"{}\" is a {}, expected a {} ({})", text,
                                                        getDimensionName(u.dim), getDimensionName(expected),
                                                        getAcceptedUnits(expected)));
            return value * u.toSI;
        }
    throw std::invalid_argument(fmt::format("\"{}\": unknown or missing unit \"{}\"; expected a {} in one of: {}",
                                            text, unit, getDimensionName(expected),
                                            getAcceptedUnits(expected)));
}

}  // namespace rockroll::units
