// libFuzzer harness: a `--set KEY=VALUE` override (parseScenarioOverride) applied to the
// default scenario, bare keys allowed; one override per input line.
#include "bench/fuzz/FuzzFiles.h"
#include "scenarios/DefaultScenario.h"
#include "scenarios/ScenarioLoader.h"

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace rockroll;
    std::string_view text = fuzz::asText(data, size);
    try {
        std::vector<ScenarioOverride> overrides;
        while (!text.empty()) {
            const auto nl = text.find('\n');
            overrides.push_back(parseScenarioOverride(text.substr(0, nl)));
            text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
        }
        const Scenario sc = parseScenario(kDefaultScenarioToml, "<default>", overrides, OverrideKeys::AllowBare);
        checkScenario(sc);
    } catch (const ScenarioError&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
