// libFuzzer harness: the journal parser of resumable sweeps and studies (app/Journal.h)
// on arbitrary bytes. A bad journal must be refused with a ScenarioError (bad input,
// exit 2); any other exception, a crash or a hang is a finding. Each parsed point line
// is also read as a sweep point, as --resume does.
#include "app/Journal.h"
#include "scenarios/ScenarioLoader.h"

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const rockroll::app::ParsedJournal journal = rockroll::app::parseJournal(text, "fuzz.jsonl");
        for (const auto& line : journal.points) {
            try {
                (void)rockroll::app::sweepPointFromJournal(line);
            } catch (const nlohmann::json::exception&) {  // a missing or mistyped key: refused by collectSweepPoints
            } catch (const std::invalid_argument&) {      // a bad hex float: refused likewise
            }
        }
    } catch (const rockroll::ScenarioError&) {
    }
    return 0;
}
