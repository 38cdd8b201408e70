// libFuzzer harness: a study file and its base scenario (app/Study.h loadStudy), as
// `rockroll study` reads them (FuzzTargets.h readStudy).
#include "bench/fuzz/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)rockroll::fuzz::readStudy(rockroll::fuzz::asText(data, size));
    return 0;
}
