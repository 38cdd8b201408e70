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

// ---- measured track: tapers, repeat, and the CSV reader (docs/cli.md, "Measured track") ----

namespace {
/// What readTrackCsv throws for `csv`, or "".
std::string csvError(const std::string& csv) {
    try {
        readTrackCsv(csv, "t.csv", 20 * 0.3048);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}
}  // namespace

// A table not level at its ends rises from level before its first row and returns to
// level after its last, each over the taper: the rails never step (a table not ending
// at zero used to drop to level right after its last row).
TEST(TrackInput, MeasuredTableEndsAreTaperedNotStepped) {
    TrackSpec t;
    t.taper = 4;
    t.measured = {{10, 0.02, 0.004}, {20, -0.01, 0.002}};
    const TrackInput track(t);
    const double h = 1e-9;
    for (double edge : {10.0, 20.0, 6.0, 24.0}) {
        const RailPoint a = track.calcRails(edge - h), b = track.calcRails(edge + h);
        for (int i = 0; i < 2; ++i) EXPECT_NEAR(a.z[i], b.z[i], 1e-9) << "step at s = " << edge;
    }
    // Halfway down the end taper: half the last row's heights, slope -last/taper.
    const RailPoint mid = track.calcRails(22);
    EXPECT_NEAR(mid.z[1], 0.5 * (0.002 + (-0.01) / 2), 1e-15);
    EXPECT_NEAR(mid.slope[1], -(0.002 + (-0.01) / 2) / 4, 1e-15);
    EXPECT_NEAR(track.calcRails(8).z[0], 0.5 * (0.004 - 0.02 / 2), 1e-15);
    EXPECT_EQ(track.calcRails(24.5).z[0], 0.0);
    EXPECT_EQ(track.calcRails(5.5).z[1], 0.0);
}

TEST(TrackInput, MeasuredTableRepeatsWithItsLength) {
    TrackSpec t;
    t.repeat = true;
    t.measured = {{0, 0, 0}, {3, 0.01, 0}, {10, 0, 0}};
    const TrackInput track(t);
    for (double s : {1.0, 4.5, 9.0})
        for (int k : {1, 2, 7}) EXPECT_NEAR(track.calcCrossLevel(s + 10 * k), track.calcCrossLevel(s), 1e-12);
    t.measured.back().crossLevel = 0.001;  // the seam would step
    EXPECT_THROW(TrackInput{t}, std::invalid_argument);
}

TEST(TrackInput, ReadsCsvWithUnitsCommentsAndAnyColumnOrder) {
    const std::string csv = "# a comment\n\nright [mm], distance [ft], left [in]\n# another\n0, 0, 0\n"
                            "10, 10, 0.5\n\n20,20,-1\n";
    const auto rows = readTrackCsv(csv, "t.csv", 1.0);
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_NEAR(rows[1].distance, 10 * 0.3048, 1e-15);
    EXPECT_NEAR(rows[1].crossLevel, 0.010 - 0.5 * 0.0254, 1e-15);         // right − left
    EXPECT_NEAR(rows[1].profile, (0.010 + 0.5 * 0.0254) / 2, 1e-15);      // mean
    EXPECT_NEAR(rows[2].distance, 20 * 0.3048, 1e-15);
    // Placement: a level first row is at s = 0; otherwise the taper comes first.
    const auto shifted = readTrackCsv("distance [m], left [m], right [m]\n5, 0.01, 0\n6, 0, 0\n", "t.csv", 2.0);
    EXPECT_DOUBLE_EQ(shifted.front().distance, 2.0);
    EXPECT_DOUBLE_EQ(shifted.back().distance, 3.0);
    const auto level = readTrackCsv("distance [m], left [m], right [m], alignment [mm]\n5, 0, 0, 0\n6, 0.01, 0, 0\n",
                                    "t.csv", 2.0);
    EXPECT_DOUBLE_EQ(level.front().distance, 0.0);
}

TEST(TrackInput, CsvErrorsNameLineAndColumn) {
    const std::string head = "distance [ft], left [in], right [in]\n";
    struct Case {
        std::string csv, expect;
    };
    const Case cases[] = {
        {head + "0, 0, 0\n1, 0, 0\n1, 0.1, 0\n", "t.csv:4: column 1 (distance [ft]) = \"1\": distances must increase"},
        {head + "0, 0, 0\n1, nan, 0\n", "t.csv:3: column 2 (left [in]) = \"nan\": expected a finite number"},
        {head + "0, 0, 0\n1, 0.1, inf\n", "t.csv:3: column 3 (right [in]) = \"inf\": expected a finite number"},
        {head + "0, 0, 0\n1, abc, 0\n", "t.csv:3: column 2 (left [in]) = \"abc\": expected a finite number"},
        {head + "0, 0\n", "t.csv:2: 2 cells; expected 3"},
        {"distance [ft], left [in]\n0, 0\n1, 0\n", "t.csv:1: the column 'right' is missing"},
        {"distance [ft], left, right [in]\n", "t.csv:1: column 2 \"left\": the unit is missing"},
        {"distance [ft], left [furlong], right [in]\n", "t.csv:1: column 2 \"left [furlong]\": unit \"furlong\""},
        {"distance [ft], left [lbf], right [in]\n", "expected one of: in, ft, mm, m"},
        {"distance [ft], height [in], right [in]\n", "t.csv:1: column 2 \"height [in]\": expected one of distance"},
        {head + "0, 0, 0\n", "1 data row(s); expected at least two"},
        {"# only a comment\n", "no header"},
        {"distance [ft], left [in], right [in], alignment [in]\n0, 0, 0, 0\n1, 0, 0, 0.2\n",
         "t.csv:3: column 4 (alignment [in]) = \"0.2\": the models take vertical rail input only"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.csv);
        const std::string e = csvError(c.csv);
        EXPECT_NE(e.find(c.expect), std::string::npos) << e;
    }
}

// Input size limits (docs/cli.md, "Input size limits"): a table of kMaxTrackRows rows reads,
// one more row is refused naming its line; text over kMaxTrackFileBytes is refused unread.
TEST(TrackInput, TablesOverTheSizeLimitsAreRefused) {
    std::string csv = "distance [m], left [m], right [m]\n";
    csv.reserve(kMaxTrackRows * 16);
    for (size_t i = 0; i < kMaxTrackRows; ++i) csv += std::to_string(i) + ",0,0\n";
    EXPECT_EQ(readTrackCsv(csv, "t.csv", 1.0).size(), kMaxTrackRows);
    csv += std::to_string(kMaxTrackRows) + ",0,0\n";
    const std::string rowError = csvError(csv);
    EXPECT_NE(rowError.find("t.csv:" + std::to_string(kMaxTrackRows + 2) + ": more than 100000 data rows"),
              std::string::npos)
        << rowError;
    const std::string big(kMaxTrackFileBytes + 1, '#');
    const std::string sizeError = csvError(big);
    EXPECT_NE(sizeError.find("t.csv: 16777217 bytes; expected at most 16777216 bytes (16 MiB)"), std::string::npos)
        << sizeError;
}
