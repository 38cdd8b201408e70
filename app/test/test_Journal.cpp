// The journal of resumable sweeps and studies (app/Journal.h): hex doubles and states
// that come back bit for bit, summaries that come back byte for byte, torn last lines
// dropped, bad lines and journals of another batch refused with the file, line and
// what differs.
#include "app/Journal.h"
#include "app/SummaryJson.h"
#include "scenarios/ScenarioLoader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace rockroll;
using namespace rockroll::app;
using Json = nlohmann::ordered_json;

namespace {
uint64_t bitsOf(double x) {
    uint64_t b = 0;
    std::memcpy(&b, &x, sizeof b);
    return b;
}
double fromBits(uint64_t b) {
    double x = 0;
    std::memcpy(&x, &b, sizeof x);
    return x;
}

RunSummary makeSummary() {
    RunSummary s;
    s.model = "reduced";
    s.car = "70-ton loaded";
    s.speedMph = 16.5;
    s.amplitudeIn = 0.75;
    s.durationS = 20;
    s.maxRollDeg = 1.0 / 3.0;
    s.steadyRollAmplitudeDeg = std::nextafter(0.1, 1.0);
    s.peakToPeakRollDeg = 1e-300;
    s.maxWheelLiftIn = 5e-324;  // the smallest subnormal
    s.maxWheelLoadLb = 41234.56789012345;
    s.minWheelLoadRatio = -0.0;
    s.regime = "severe";
    s.stoppedAtS = 12.25;
    s.stopReason = "roll 30 deg > limit \"25 deg\"";
    s.energyBalanceError = std::numeric_limits<double>::quiet_NaN();
    s.maxLOverV = std::numeric_limits<double>::quiet_NaN();
    s.rawMaxLOverV = std::numeric_limits<double>::quiet_NaN();
    s.maxCarBodyVerticalAccelG = 0.123456789012345678;
    s.trucks = {{"F", 1.5, -2.5, {3.25, 4.125}}, {"R", 5, 6, {7, 8}}};
    s.criteria = {{"roll_peak_to_peak", "deg", 7.1, 6}, {"l_over_v", "ratio", std::numeric_limits<double>::quiet_NaN(), 1}};
    s.filter = "20 Hz low-pass";
    s.simTimeS = 20;
    s.wallTimeS = 1.2345;
    s.steps = 123456789;
    return s;
}
}  // namespace

TEST(Journal, HexDoublesRoundTripBitForBit) {
    std::vector<double> values = {0.0, -0.0, 1.0, -1.0, 0.1, 1.0 / 3.0, 5e-324, -5e-324, 2.2250738585072014e-308,
                                  std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    std::mt19937_64 bits(12);
    for (int i = 0; i < 10000; ++i) {
        const double x = fromBits(bits());
        if (!std::isnan(x)) values.push_back(x);
    }
    for (double x : values) {
        const std::string text = formatHexDouble(x);
        EXPECT_EQ(bitsOf(parseHexDouble(text)), bitsOf(x)) << text;
    }
    EXPECT_EQ(formatHexDouble(1.5), "0x1.8p+0");
    EXPECT_EQ(formatHexDouble(-0.0), "-0x0p+0");
    EXPECT_TRUE(std::isnan(parseHexDouble(formatHexDouble(std::nan("")))));
    for (const char* bad : {"", "1.5", "0x", "0x1.8p", "0x1.8p+0 ", "0x-1", "--0x1p+0", "0x1g", "nan(1)"})
        EXPECT_THROW(parseHexDouble(bad), std::invalid_argument) << bad;
}

TEST(Journal, RestartStateRoundTripsBitForBit) {
    RestartState s{"halfcar", {0.1, -0.0, 5e-324, 1.0 / 7.0, -123456.789}, 4321.000000000001, 7.37};
    const Json j = Json::parse(toJson(s).dump());  // through its text, as the journal stores it
    const RestartState back = restartStateFromJson(j);
    EXPECT_EQ(back.model, s.model);
    ASSERT_EQ(back.y.size(), s.y.size());
    for (size_t i = 0; i < s.y.size(); ++i) EXPECT_EQ(bitsOf(back.y[i]), bitsOf(s.y[i])) << i;
    EXPECT_EQ(bitsOf(back.distance), bitsOf(s.distance));
    EXPECT_EQ(bitsOf(back.speed), bitsOf(s.speed));
}

TEST(Journal, SummaryRoundTripsByteForByte) {
    const RunSummary s = makeSummary();
    const std::string text = toJson(s).dump(2);
    const RunSummary back = summaryFromJson(Json::parse(text));
    EXPECT_EQ(toJson(back).dump(2), text);
    EXPECT_EQ(bitsOf(back.maxRollDeg), bitsOf(s.maxRollDeg));
    EXPECT_EQ(bitsOf(back.maxWheelLiftIn), bitsOf(s.maxWheelLiftIn));
    EXPECT_EQ(back.describeCriteria(), s.describeCriteria());
}

TEST(Journal, SweepPointRoundTripsWithItsContinuation) {
    SweepPoint p;
    p.speedMph = 14.000000000000002;
    p.direction = "down";
    p.start = "continued";
    p.summary = makeSummary();
    p.next.from = RestartState{"reduced", {1.0 / 3.0, -2e-310}, 123.4, 6.25};
    p.next.rampTime = 1.0;
    p.next.staticReference = {0.0, 1.0 / 9.0};
    const Json line = Json::parse(toJournalJson(p, 3, 7).dump());
    EXPECT_EQ(line.at("sweep"), 3);
    EXPECT_EQ(line.at("index"), 7);
    const SweepPoint back = sweepPointFromJournal(line);
    EXPECT_EQ(bitsOf(back.speedMph), bitsOf(p.speedMph));
    EXPECT_EQ(back.start, p.start);
    EXPECT_EQ(toJson(back.summary).dump(), toJson(p.summary).dump());
    ASSERT_TRUE(back.next.from.has_value());
    EXPECT_EQ(bitsOf(back.next.from->y[1]), bitsOf(p.next.from->y[1]));
    EXPECT_EQ(bitsOf(back.next.staticReference[1]), bitsOf(p.next.staticReference[1]));

    SweepPoint failed;
    failed.speedMph = 15;
    failed.direction = "up";
    failed.start = "rest";
    failed.failed = true;
    failed.error = "integrator failed at t = 1.5 s";
    const SweepPoint f = sweepPointFromJournal(Json::parse(toJournalJson(failed, 0, 0).dump()));
    EXPECT_TRUE(f.failed);
    EXPECT_EQ(f.error, failed.error);
    EXPECT_FALSE(f.next.from.has_value());
}

TEST(Journal, TornLastLineIsDroppedOtherBadLinesAreRefused) {
    const std::string header = makeJournalHeader("sweep", Json{{"a", 1}}, "rockroll sweep x").dump() + "\n";
    const std::string point = Json{{"sweep", 0}, {"index", 0}}.dump() + "\n";
    const ParsedJournal whole = parseJournal(header + point + point, "j.jsonl");
    EXPECT_EQ(whole.points.size(), 2u);
    EXPECT_FALSE(whole.droppedTornLine);

    for (size_t cut = 1; cut < point.size(); ++cut) {  // killed at every byte of the last line's write
        const ParsedJournal torn = parseJournal(header + point + point.substr(0, cut), "j.jsonl");
        EXPECT_EQ(torn.points.size(), 1u) << cut;
        EXPECT_TRUE(torn.droppedTornLine) << cut;
    }
    try {
        parseJournal(header + "{\"sweep\": 0, \n" + point, "j.jsonl");
        FAIL() << "a bad line in the middle was accepted";
    } catch (const ScenarioError& e) {
        EXPECT_NE(std::string(e.what()).find("j.jsonl:2"), std::string::npos) << e.what();
    }
    EXPECT_THROW(parseJournal("", "j.jsonl"), ScenarioError);
    EXPECT_THROW(parseJournal("{\"not\": \"a header\"}\n", "j.jsonl"), ScenarioError);
    EXPECT_THROW(parseJournal(header.substr(0, 10), "j.jsonl"), ScenarioError);  // a cut header: nothing to resume
    EXPECT_THROW(parseJournal("[1, 2]\n", "j.jsonl"), ScenarioError);
}

TEST(Journal, AnotherBatchIsRefusedNamingWhatDiffers) {
    const Json identity = {{"sweeps", Json::array({{{"model", "reduced"},
                                                     {"scenario_toml", "[run]\nspeed = \"16 mph\"\nduration = \"4 s\"\n"},
                                                     {"sweep", {{"from_mph", 14}, {"to_mph", 16}}}}})}};
    const ParsedJournal journal =
        parseJournal(makeJournalHeader("sweep", identity, "rockroll sweep").dump() + "\n", "DIR.partial/journal.jsonl");
    EXPECT_NO_THROW(checkJournalIdentity(journal, identity, "DIR.partial/journal.jsonl"));
    auto refusal = [&](const Json& other) {
        try {
            checkJournalIdentity(journal, other, "DIR.partial/journal.jsonl");
        } catch (const ScenarioError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    Json model = identity;
    model["sweeps"][0]["model"] = "eom";
    EXPECT_NE(refusal(model).find("sweeps[0].model is \"reduced\" there, \"eom\" here"), std::string::npos)
        << refusal(model);
    Json speeds = identity;
    speeds["sweeps"][0]["sweep"]["to_mph"] = 17;
    EXPECT_NE(refusal(speeds).find("sweeps[0].sweep.to_mph is 16 there, 17 here"), std::string::npos) << refusal(speeds);
    Json set = identity;
    set["sweeps"][0]["scenario_toml"] = "[run]\nspeed = \"16 mph\"\nduration = \"5 s\"\n";
    EXPECT_NE(refusal(set).find("line 3 is \"duration = \"4 s\"\" there, \"duration = \"5 s\"\" here"),
              std::string::npos)
        << refusal(set);
    EXPECT_NE(refusal(set).find("DIR.partial/journal.jsonl"), std::string::npos);
}

// A journal's or shard's integers (a point's step count, sweep and index, a study shard's
// k and n) are refused unless they are JSON integers in range; a float such as 1e300 was
// converted with undefined behaviour (UBSan, fuzz_journal) and 12.5 read as 12.
TEST(Journal, IntegersMustBeIntegersInRange) {
    const Json j = Json::parse(R"({"n": 7, "neg": -3, "big": 1e300, "half": 12.5, "huge": 18446744073709551615,
                                   "text": "7", "none": null})");
    EXPECT_EQ(getJsonInteger<long>(j, "n"), 7);
    EXPECT_EQ(getJsonInteger<size_t>(j, "n"), 7u);
    EXPECT_EQ(getJsonInteger<long>(j, "neg"), -3);
    EXPECT_EQ(getJsonInteger<size_t>(j, "huge"), std::numeric_limits<size_t>::max());
    for (const char* key : {"big", "half", "text", "none"}) {
        EXPECT_THROW(getJsonInteger<long>(j, key), std::invalid_argument) << key;
        EXPECT_THROW(getJsonInteger<size_t>(j, key), std::invalid_argument) << key;
    }
    EXPECT_THROW(getJsonInteger<size_t>(j, "neg"), std::invalid_argument);
    EXPECT_THROW(getJsonInteger<long>(j, "huge"), std::invalid_argument);
    try {
        getJsonInteger<long>(j, "big");
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("\"big\" is 1e+300; expected an integer"), std::string::npos) << e.what();
    }

    Json summary = toJson(makeSummary());
    summary["steps"] = 1e300;
    EXPECT_THROW(summaryFromJson(summary), std::invalid_argument);
    summary["steps"] = 12.5;
    EXPECT_THROW(summaryFromJson(summary), std::invalid_argument);
}
