// libFuzzer harness: the report's numbers (scenarios/reference/mit1976.toml; mbmodel/Mit1976.h),
// a data file ROCKROLL_MIT1976 or ROCKROLL_DATA_DIR can point at another copy of.
#include "bench/fuzz/FuzzFiles.h"
#include "mbmodel/DataFiles.h"
#include "mbmodel/Mit1976.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace rockroll;
    const auto path = fuzz::writeFuzzFile("mit1976.toml", fuzz::asText(data, size));
    try {
        const Mit1976 ref(path);
        (void)ref.count("table3");
    } catch (const DataFileError&) {
    }
    return 0;
}
