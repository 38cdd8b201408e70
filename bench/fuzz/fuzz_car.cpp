// libFuzzer harness: a car file (scenarios/cars/*.toml; ScenarioLoader.h parseCarFile).
#include "bench/fuzz/FuzzFiles.h"
#include "scenarios/ScenarioLoader.h"

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace rockroll;
    try {
        parseCarFile(fuzz::asText(data, size), "<fuzz>");
    } catch (const ScenarioError&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
