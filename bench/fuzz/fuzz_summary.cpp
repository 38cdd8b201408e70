// libFuzzer harness: the summary.json `rockroll run --from-summary` reads
// (app/Provenance.h loadScenarioFromSummary).
#include "app/Provenance.h"
#include "bench/fuzz/FuzzFiles.h"

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace rockroll;
    const std::string path = fuzz::writeFuzzFile("summary.json", fuzz::asText(data, size)).string();
    try {
        const Scenario sc = app::loadScenarioFromSummary(path);
        checkScenario(sc);
    } catch (const ScenarioError&) {
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
