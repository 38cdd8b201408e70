#include "mbmodel/LowPassFilter.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockroll;

TEST(LowPassFilter, PassesConstantsAndSlowSignals) {
    const LowPassFilter f(20, 500);
    std::vector<double> c(500, 3.5);
    for (double y : f.apply(c)) EXPECT_NEAR(y, 3.5, 1e-9);
    std::vector<double> slow(1000);
    for (size_t i = 0; i < slow.size(); ++i) slow[i] = std::sin(2 * M_PI * 1.0 * i / 500.0);
    const auto y = f.apply(slow);
    for (size_t i = 100; i < 900; ++i) EXPECT_NEAR(y[i], slow[i], 2e-3);  // zero phase, unit gain
}

TEST(LowPassFilter, AttenuatesAboveCutoff) {
    const LowPassFilter f(20, 500);
    std::vector<double> x(1000);
    for (size_t i = 0; i < x.size(); ++i) x[i] = std::sin(2 * M_PI * 100.0 * i / 500.0);
    const auto y = f.apply(x);
    double peak = 0;
    for (size_t i = 200; i < 800; ++i) peak = std::max(peak, std::abs(y[i]));
    EXPECT_LT(peak, 0.01);  // 4th-order roll-off, two and a third octaves up
}

TEST(LowPassFilter, RejectsCutoffAboveNyquist) { EXPECT_THROW(LowPassFilter(300, 500), std::invalid_argument); }
