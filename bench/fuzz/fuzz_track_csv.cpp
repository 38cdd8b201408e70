// libFuzzer harness: a measured track's CSV (mbmodel/TrackInput.h readTrackCsv), and the
// track built from the rows it accepts, sampled along its length.
#include "bench/fuzz/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)rockroll::fuzz::readTrackTable(rockroll::fuzz::asText(data, size));
    return 0;
}
