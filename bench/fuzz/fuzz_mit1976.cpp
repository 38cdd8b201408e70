// libFuzzer harness: the report's numbers (scenarios/reference/mit1976.toml; mbmodel/Mit1976.h),
// a data file ROCKROLL_MIT1976 or ROCKROLL_DATA_DIR can point at another copy of.
#include "bench/fuzz/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)rockroll::fuzz::readMit1976(rockroll::fuzz::asText(data, size));
    return 0;
}
