#pragma once
// Scenario helpers shared by the model tests.
#include "scenarios/ScenarioRun.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rockroll::test_cases {

/// The smallest complete scenario file: 70-ton loaded car, 0.75 in, 16.5 mph, 20 s, full car.
inline const std::string kMinimalScenarioToml = R"(
[car]
base = "70ton-loaded"
[track]
amplitude = "0.75 in"
rail_length = "39 ft"
[run]
speed = "16.5 mph"
duration = "20 s"
model = "fullcar"
[integrator]
method = "cpodes"
accuracy = 1e-4
)";

/// The default scenario (70-ton loaded) with model, amplitude, speed and duration set.
inline Scenario makeCase(const std::string& model, double amplitudeIn, double speedMph, double duration) {
    Scenario sc = getDefaultScenario();
    sc.model = model;
    sc.track.amplitude = amplitudeIn * units::inch;
    sc.speed = speedMph * units::mph;
    sc.run.duration = duration;
    return sc;
}

/// `s` with its first `from` replaced by `to`; a test failure when `from` is not in it.
inline std::string replaceOnce(std::string s, const std::string& from, const std::string& to) {
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
    return s;
}

/// One recorded channel of a run.
inline std::vector<double> getColumn(const RunResult& r, const std::string& name) {
    const int c = r.history.column(name);
    std::vector<double> out;
    for (const auto& row : r.history.samples) out.push_back(row[c]);
    return out;
}

}  // namespace rockroll::test_cases
