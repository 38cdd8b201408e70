// libFuzzer harness: scenario text parsed from memory (parseScenario), then written back
// (formatScenarioToml) and parsed again: what the loader accepts must round-trip.
#include "bench/fuzz/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)rockroll::fuzz::readScenarioText(rockroll::fuzz::asText(data, size));
    return 0;
}
