#pragma once
// Scenario helpers shared by the model tests.
#include "scenarios/ScenarioRun.h"

#include <string>
#include <vector>

namespace rockroll::test_cases {

/// The default scenario (70-ton loaded) with model, amplitude, speed and duration set.
inline Scenario makeCase(const std::string& model, double amplitudeIn, double speedMph, double duration) {
    Scenario sc = getDefaultScenario();
    sc.model = model;
    sc.track.amplitude = amplitudeIn * units::inch;
    sc.speed = speedMph * units::mph;
    sc.run.duration = duration;
    return sc;
}

/// One recorded channel of a run.
inline std::vector<double> getColumn(const RunResult& r, const std::string& name) {
    const int c = r.history.column(name);
    std::vector<double> out;
    for (const auto& row : r.history.samples) out.push_back(row[c]);
    return out;
}

}  // namespace rockroll::test_cases
