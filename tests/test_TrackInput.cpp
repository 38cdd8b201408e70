#include "mbmodel/TrackInput.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockroll;

namespace {
TrackSpec sine(double A, int rails = 0) {
    TrackSpec t;
    t.amplitude = A;
    t.railLength = 11.8872;
    t.rails = rails;
    return t;
}
}  // namespace

TEST(TrackInput, LevelBeforeStartAndContinuousAtIt) {
    const TrackInput track(sine(0.01905));
    for (double s : {-5.0, -0.1, 0.0}) {
        const RailPoint p = track.calcRails(s);
        EXPECT_EQ(p.z[0], 0.0);
        EXPECT_EQ(p.z[1], 0.0);
    }
    const RailPoint just = track.calcRails(1e-9);
    EXPECT_NEAR(just.z[0], 0.0, 1e-9);
    EXPECT_NEAR(just.z[1], 0.0, 1e-9);
}

TEST(TrackInput, CrossLevelSwingsBetweenMinusAndPlusAWithRailPeriod) {
    const double A = 0.0254, L = 11.8872;
    const TrackInput track(sine(A));
    double lo = 1, hi = -1;
    for (int i = 0; i <= 4000; ++i) {
        const double s = 2 * L * i / 4000.0;
        lo = std::min(lo, track.calcCrossLevel(s));
        hi = std::max(hi, track.calcCrossLevel(s));
        EXPECT_NEAR(track.calcCrossLevel(s + L), track.calcCrossLevel(s), 1e-12);
    }
    EXPECT_NEAR(hi, A, 1e-6);
    EXPECT_NEAR(lo, -A, 1e-6);
}

TEST(TrackInput, SlopeIsTheDerivative) {
    const TrackInput track(sine(0.02));
    for (double s : {0.7, 3.1, 5.5, 9.0}) {
        const double h = 1e-6;
        const RailPoint p = track.calcRails(s);
        for (int i = 0; i < 2; ++i)
            EXPECT_NEAR(p.slope[i], (track.calcRails(s + h).z[i] - track.calcRails(s - h).z[i]) / (2 * h), 1e-6);
    }
}

TEST(TrackInput, EndsLevelAfterNRails) {
    const TrackInput track(sine(0.02, 3));
    const double L = 11.8872;
    EXPECT_NEAR(track.calcRails(3 * L - 1e-9).z[1], 0.0, 1e-8);
    EXPECT_EQ(track.calcRails(3 * L + 0.5).z[1], 0.0);
    EXPECT_NE(track.calcRails(2.5 * L).z[1], 0.0);
}

TEST(TrackInput, MirrorSwapsRails) {
    TrackSpec m = sine(0.02);
    m.mirror = true;
    const TrackInput a(sine(0.02)), b(m);
    for (double s : {1.0, 4.0, 7.0}) EXPECT_DOUBLE_EQ(a.calcCrossLevel(s), -b.calcCrossLevel(s));
}

TEST(TrackInput, MeasuredTableIsInterpolated) {
    TrackSpec t;
    t.measured = {{0, 0, 0}, {10, 0.02, 0.004}, {20, 0, 0}};
    const TrackInput track(t);
    EXPECT_NEAR(track.calcCrossLevel(5), 0.01, 1e-12);
    const RailPoint p = track.calcRails(5);
    EXPECT_NEAR(p.z[1], 0.002 + 0.005, 1e-12);
    EXPECT_NEAR(p.z[0], 0.002 - 0.005, 1e-12);
    EXPECT_NEAR(p.slope[1] - p.slope[0], 0.002, 1e-12);
    EXPECT_EQ(track.calcCrossLevel(25), 0.0);
    t.measured = {{0, 0, 0}, {0, 0.01, 0}};
    EXPECT_THROW(TrackInput{t}, std::invalid_argument);
}
