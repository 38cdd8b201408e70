// libFuzzer harness: a `--set KEY=VALUE` override (parseScenarioOverride) applied to the
// default scenario, bare keys allowed; one override per input line.
#include "bench/fuzz/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)rockroll::fuzz::readOverrides(rockroll::fuzz::asText(data, size));
    return 0;
}
