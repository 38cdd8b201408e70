#pragma once
// What each libFuzzer harness (bench/fuzz/fuzz_<reader>.cpp) does with one input, shared
// with the regression test of the inputs the fuzzer found (app/test/test_FuzzRegressions.cpp,
// tests/data/fuzz/fuzz_<reader>/). Each returns the error message of a refused input ("" when
// accepted); a bad input may only be refused with the error type the command line maps
// to exit 2 (ScenarioError, std::invalid_argument, DataFileError). Any other exception, a
// crash or a sanitizer report is a finding.
#include "app/Journal.h"
#include "app/Provenance.h"
#include "app/Study.h"
#include "bench/fuzz/FuzzFiles.h"
#include "mbmodel/DataFiles.h"
#include "mbmodel/Mit1976.h"
#include "mbmodel/TrackInput.h"
#include "scenarios/DefaultScenario.h"
#include "scenarios/ScenarioLoader.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rockroll::fuzz {

/// Runs `read`; the message of a bad-input error, or "".
template <class Read>
std::string getInputError(Read&& read) {
    try {
        read();
    } catch (const ScenarioError& e) {
        return e.what();
    } catch (const std::invalid_argument& e) {
        return e.what();
    } catch (const DataFileError& e) {
        return e.what();
    }
    return "";
}

/// A scenario file, then the files it may name: the input's part after a line "#@track.csv"
/// is the file track.csv, after "#@car.toml" the file car.toml, both beside the scenario.
inline std::string readScenarioFile(std::string_view input) {
    const auto [scenario, files] = splitAtMarker(input, "#@track.csv");
    const auto [track, car] = splitAtMarker(files, "#@car.toml");
    writeFuzzFile("track.csv", track);
    writeFuzzFile("car.toml", car);
    const std::string path = writeFuzzFile("scenario.toml", scenario).string();
    return getInputError([&] {
        const Scenario sc = loadScenarioFile(path);
        checkScenario(sc);
        formatScenarioToml(sc);
    });
}

/// Scenario text from memory; what is accepted must be accepted again once written back.
inline std::string readScenarioText(std::string_view input) {
    Scenario sc;
    const std::string error = getInputError([&] { sc = parseScenario(input, "<fuzz>"); });
    if (error.empty()) parseScenario(formatScenarioToml(sc), "<fuzz, formatted>");  // throws: a finding
    return error;
}

/// `--set KEY=VALUE` overrides, one per line, on the default scenario (bare keys allowed).
inline std::string readOverrides(std::string_view input) {
    return getInputError([&] {
        std::vector<ScenarioOverride> overrides;
        while (!input.empty()) {
            const auto nl = input.find('\n');
            overrides.push_back(parseScenarioOverride(input.substr(0, nl)));
            input = nl == std::string_view::npos ? std::string_view() : input.substr(nl + 1);
        }
        checkScenario(parseScenario(kDefaultScenarioToml, "<default>", overrides, OverrideKeys::AllowBare));
    });
}

/// A measured track's CSV; the rows accepted must give finite rails along the whole track.
inline std::string readTrackTable(std::string_view input) {
    TrackSpec spec;
    const std::string error = getInputError([&] { spec.measured = readTrackCsv(input, "<fuzz>", spec.taper); });
    if (!error.empty()) return error;
    const TrackInput track(spec);  // accepted rows are a valid track: a throw here is a finding
    const double end = spec.measured.back().distance + 2 * spec.taper;
    for (int i = 0; i <= 64; ++i) {
        const RailPoint p = track.calcRails(end * i / 64);
        if (!std::isfinite(p.z[0]) || !std::isfinite(p.z[1])) std::abort();
    }
    return "";
}

/// A car file (scenarios/cars/*.toml).
inline std::string readCar(std::string_view input) {
    return getInputError([&] { parseCarFile(input, "<fuzz>"); });
}

/// The summary.json `rockroll run --from-summary` reads.
inline std::string readSummary(std::string_view input) {
    const std::string path = writeFuzzFile("summary.json", input).string();
    return getInputError([&] { checkScenario(app::loadScenarioFromSummary(path)); });
}

/// The report's numbers (scenarios/reference/mit1976.toml; ROCKROLL_MIT1976 names another copy).
inline std::string readMit1976(std::string_view input) {
    const auto path = writeFuzzFile("mit1976.toml", input);
    return getInputError([&] { (void)Mit1976(path).count("table3"); });
}

/// A sweep journal (DIR.partial/journal.jsonl), read as `rockroll sweep --resume` reads it:
/// parsed, then each point line read as a sweep point. A point line that cannot be read
/// (a missing or mistyped key, a bad hex float, an integer out of range) is refused naming
/// its line, as collectSweepPoints refuses it.
inline std::string readJournal(std::string_view input) {
    return getInputError([&] {
        const app::ParsedJournal journal = app::parseJournal(input, "<fuzz>");
        for (size_t n = 0; n < journal.points.size(); ++n) {
            try {
                (void)app::sweepPointFromJournal(journal.points[n]);
            } catch (const nlohmann::json::exception& e) {
                throw ScenarioError("<fuzz>:" + std::to_string(n + 2) + ": not a point of this sweep: " + e.what());
            } catch (const std::invalid_argument& e) {
                throw ScenarioError("<fuzz>:" + std::to_string(n + 2) + ": not a point of this sweep: " + e.what());
            }
        }
    });
}

/// A study file (docs/studies.md), read as `rockroll study` reads it: the input's part after a
/// line "#@scenario.toml" is its base scenario, the file scenario.toml beside it (`scenario =
/// "scenario.toml"` names it). Every point of an accepted plan must give a scenario that loads.
inline std::string readStudy(std::string_view input) {
    const auto [study, scenario] = splitAtMarker(input, "#@scenario.toml");
    writeFuzzFile("scenario.toml", scenario);
    const std::string path = writeFuzzFile("study.toml", study).string();
    return getInputError([&] {
        const app::StudyPlan plan = app::loadStudy(path);
        for (size_t i = 0; i < plan.points.size() && i < 16; ++i) (void)app::getPointOverrides(plan, i);
    });
}

}  // namespace rockroll::fuzz
