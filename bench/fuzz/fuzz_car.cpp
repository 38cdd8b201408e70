// libFuzzer harness: a car file (scenarios/cars/*.toml; ScenarioLoader.h parseCarFile).
#include "bench/fuzz/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)rockroll::fuzz::readCar(rockroll::fuzz::asText(data, size));
    return 0;
}
