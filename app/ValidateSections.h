#pragma once
// The validate sections that live outside app/Validate.cpp: attribution of the
// half car – reduced model difference (issue 9, item 6) and convergence in
// contact stiffness and integrator accuracy (item 7). Each returns its markdown
// section and fills its key of the validation.json meta object.
#include "app/Output.h"
#include "scenarios/ScenarioRun.h"

#include <atomic>
#include <cmath>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace rockroll::app {

struct SectionSettings {
    bool quick = false;
    int jobs = 2;  ///< threads (validate --jobs)
};

std::string makeAttributionSection(const SectionSettings& s, nlohmann::ordered_json& meta);
std::string makeConvergenceSection(const SectionSettings& s, nlohmann::ordered_json& meta);

namespace validate_detail {

/// Runs independent jobs on `threads` threads, in order of submission; rethrows the first error.
inline void runJobs(std::vector<std::function<void()>> jobs, int threads) {
    std::atomic<size_t> next{0};
    std::mutex errorMutex;
    std::string firstError;
    auto worker = [&] {
        for (size_t i = next++; i < jobs.size(); i = next++) {
            try {
                jobs[i]();
            } catch (const std::exception& e) {
                std::lock_guard<std::mutex> lock(errorMutex);
                if (firstError.empty()) firstError = e.what();
            }
        }
    };
    std::vector<std::thread> pool;
    for (int k = 0; k < std::max(1, threads); ++k) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    if (!firstError.empty()) throw std::runtime_error(firstError);
}

/// The 70-ton loaded car (the embedded default scenario) at amplitude and speed,
/// from rest, recorded at 100 Hz as in section 1.
inline Scenario makeLoaded70(const std::string& model, double amplitudeIn, double speedMph, double durationS) {
    Scenario sc = getDefaultScenario();
    sc.model = model;
    sc.track.amplitude = amplitudeIn * units::inch;
    sc.speed = speedMph * units::mph;
    sc.run.duration = durationS;
    sc.run.outputRate = 100;
    return sc;
}

/// Relative change from a to b, |b − a| / max(|a|, |b|); 0 when both are below `floor`.
inline double relativeChange(double a, double b, double floor) {
    const double d = std::max(std::abs(a), std::abs(b));
    return d < floor ? 0.0 : std::abs(b - a) / d;
}

}  // namespace validate_detail
}  // namespace rockroll::app
