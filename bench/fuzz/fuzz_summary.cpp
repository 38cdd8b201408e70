// libFuzzer harness: the summary.json `rockroll run --from-summary` reads
// (app/Provenance.h loadScenarioFromSummary).
#include "bench/fuzz/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)rockroll::fuzz::readSummary(rockroll::fuzz::asText(data, size));
    return 0;
}
