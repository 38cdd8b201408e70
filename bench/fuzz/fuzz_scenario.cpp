// libFuzzer harness: a scenario file's text (scenarios/ScenarioLoader.h parseScenario), with
// `[track] file` and `[car] file` read from the files that follow the scenario in the input
// (after a line "#@track.csv" and a line "#@car.toml"), so the measured-track and car
// readers run behind the loader too. Every bad input must be a ScenarioError or
// std::invalid_argument (exit 2 at the command line); anything else aborts the fuzzer.
#include "bench/fuzz/FuzzFiles.h"
#include "scenarios/ScenarioLoader.h"

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace rockroll;
    const auto [scenario, files] = fuzz::splitAtMarker(fuzz::asText(data, size), "#@track.csv");
    const auto [track, car] = fuzz::splitAtMarker(files, "#@car.toml");
    fuzz::writeFuzzFile("track.csv", track);
    fuzz::writeFuzzFile("car.toml", car);
    const std::string path = fuzz::writeFuzzFile("scenario.toml", scenario).string();
    try {
        const Scenario sc = loadScenarioFile(path);
        checkScenario(sc);
        formatScenarioToml(sc);
    } catch (const ScenarioError&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
