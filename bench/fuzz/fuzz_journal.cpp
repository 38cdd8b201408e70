// libFuzzer harness: a sweep journal (app/Journal.h parseJournal), each point line also
// read as a sweep point, as --resume does (FuzzTargets.h readJournal).
#include "bench/fuzz/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)rockroll::fuzz::readJournal(rockroll::fuzz::asText(data, size));
    return 0;
}
