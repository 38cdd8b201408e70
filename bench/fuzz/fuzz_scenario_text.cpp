// libFuzzer harness: scenario text parsed from memory (parseScenario), then written back
// (formatScenarioToml) and parsed again: what the loader accepts must round-trip.
#include "bench/fuzz/FuzzFiles.h"
#include "scenarios/ScenarioLoader.h"

#include <cstdlib>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace rockroll;
    Scenario sc;
    try {
        sc = parseScenario(fuzz::asText(data, size), "<fuzz>");
    } catch (const ScenarioError&) {
        return 0;
    } catch (const std::invalid_argument&) {
        return 0;
    }
    // Accepted: its resolved form must be accepted again.
    const std::string again = formatScenarioToml(sc);
    parseScenario(again, "<fuzz, formatted>");
    return 0;
}
