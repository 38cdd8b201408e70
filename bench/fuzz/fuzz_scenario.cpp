// libFuzzer harness: a scenario file's text (scenarios/ScenarioLoader.h parseScenario), with
// `[track] file` and `[car] file` read from the files that follow the scenario in the input
// (after a line "#@track.csv" and a line "#@car.toml"), so the measured-track and car
// readers run behind the loader too (FuzzTargets.h readScenarioFile).
#include "bench/fuzz/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)rockroll::fuzz::readScenarioFile(rockroll::fuzz::asText(data, size));
    return 0;
}
