#include "mbmodel/Units.h"

#include <gtest/gtest.h>

using namespace rockroll::units;

TEST(Units, ParsesUsCustomary) {
    EXPECT_NEAR(parseQuantity("16.5 mph", Dimension::Speed), 16.5 * 0.44704, 1e-12);
    EXPECT_NEAR(parseQuantity("0.75 in", Dimension::Length), 0.01905, 1e-12);
    EXPECT_NEAR(parseQuantity("4000 lbf", Dimension::Force), 4000 * 4.4482216152605, 1e-9);
    EXPECT_NEAR(parseQuantity("39 ft", Dimension::Length), 11.8872, 1e-12);
    EXPECT_NEAR(parseQuantity("20840 lb/in", Dimension::Stiffness), 20840 * 4.4482216152605 / 0.0254, 1e-6);
    EXPECT_NEAR(parseQuantity(" 20 s ", Dimension::Time), 20, 0);
}

TEST(Units, RejectsWrongDimensionMissingAndUnknownUnits) {
    EXPECT_THROW(parseQuantity("16.5 in", Dimension::Speed), std::invalid_argument);
    EXPECT_THROW(parseQuantity("16.5", Dimension::Speed), std::invalid_argument);
    EXPECT_THROW(parseQuantity("16.5 furlongs", Dimension::Length), std::invalid_argument);
    EXPECT_THROW(parseQuantity("fast", Dimension::Speed), std::invalid_argument);
    try {
        parseQuantity("16.5 in", Dimension::Speed);
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("mph"), std::string::npos) << e.what();
    }
}

// The SI and metric forms engineers type (docs/cli.md, "Units"), each against its conversion factor
// (written out here, independently of the table in mbmodel/Units.cpp).
TEST(Units, ParsesMetricFormsByTheirFactors) {
    struct Case {
        const char* text;
        Dimension dim;
        double si;
    };
    const Case cases[] = {
        {"3 N/mm", Dimension::Stiffness, 3 * 1000.0},
        {"3 kN/m", Dimension::Stiffness, 3 * 1000.0},
        {"3 kN/mm", Dimension::Stiffness, 3 * 1e6},
        {"3 kN", Dimension::Force, 3 * 1000.0},
        {"3 t", Dimension::Force, 3 * 1000 * 9.80665},   // tonne, as its weight under standard gravity
        {"3 kg", Dimension::Force, 3 * 9.80665},
        {"3 mm", Dimension::Length, 3 * 0.001},
        {"3 m", Dimension::Length, 3.0},
        {"3 km/h", Dimension::Speed, 3 * 1000.0 / 3600.0},
        {"3 kg·m²", Dimension::MomentOfInertia, 3.0},
        {"3 kg*m^2", Dimension::MomentOfInertia, 3.0},
        {"3 N·s/m", Dimension::Damping, 3.0},
        {"3 N*s/m", Dimension::Damping, 3.0},
        {"3 lb*s/in", Dimension::Damping, 3 * 4.4482216152605 / 0.0254},
        {"5 s/m", Dimension::InverseSpeed, 5.0},
        {"0.127 s/in", Dimension::InverseSpeed, 0.127 / 0.0254},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.text);
        EXPECT_NEAR(parseQuantity(c.text, c.dim), c.si, 1e-12 * c.si);
    }
    // 100 km/h is 62.137 mph.
    EXPECT_NEAR(parseQuantity("100 km/h", Dimension::Speed) / 0.44704, 62.1371, 1e-4);
}

TEST(Units, MetricFormsKeepTheirDimension) {
    EXPECT_THROW(parseQuantity("3 N/mm", Dimension::Force), std::invalid_argument);
    EXPECT_THROW(parseQuantity("3 t", Dimension::Length), std::invalid_argument);
    EXPECT_THROW(parseQuantity("3 kg", Dimension::MomentOfInertia), std::invalid_argument);
    EXPECT_THROW(parseQuantity("3 N·s/m", Dimension::Stiffness), std::invalid_argument);
    EXPECT_THROW(parseQuantity("3 km/h", Dimension::Length), std::invalid_argument);
}
