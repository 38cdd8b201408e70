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
