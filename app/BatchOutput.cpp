#include "app/BatchOutput.h"

#include <cstdio>
#include <fmt/format.h>

namespace rockroll::app {

std::unique_ptr<JournalWriter> openBatchJournal(
    OutputDirectory& dir, const std::string& kind, const nlohmann::ordered_json& identity, std::string& command,
    const std::function<void(const ParsedJournal&, const std::string& fileName)>& collect) {
    const std::filesystem::path file = dir.getPartialPath(kJournalFileName);
    std::vector<nlohmann::ordered_json> points;
    if (dir.isResumed()) {
        const ParsedJournal journal = readJournal(file);
        if (journal.header.at("journal") != kind)
            throw ScenarioError(fmt::format("--resume: {} is the journal of a {}, not of a {}; expected the same "
                                            "command as the interrupted run, or --force to start over",
                                            file.string(), journal.header.at("journal").dump(), kind));
        checkJournalIdentity(journal, identity, file.string());
        collect(journal, file.string());
        if (journal.header.contains("command") && journal.header["command"].is_string())
            command = journal.header["command"].get<std::string>();
        points = journal.points;
        fmt::print(stderr, "{}: resuming from {} finished points in {}{}\n", kind, points.size(), file.string(),
                   journal.droppedTornLine ? " (its cut-off last line dropped: that point runs again)" : "");
    }
    auto writer = std::make_unique<JournalWriter>(file, makeJournalHeader(kind, identity, command), points);
    dir.keepPartial();
    return writer;
}

void commitBatch(OutputDirectory& dir) {
    std::filesystem::remove(dir.getPartialPath(kJournalFileName));
    dir.commit();
}

}  // namespace rockroll::app
