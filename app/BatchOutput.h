#pragma once
// The output directory of a resumable batch (rockroll sweep, rockroll study): an
// OutputDirectory (app/Output.h) whose DIR.partial holds the batch's journal
// (app/Journal.h) while it runs. One implementation for sweeps and studies.
#include "app/Journal.h"
#include "app/Output.h"

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace rockroll::app {

/// Starts the journal of `dir` and keeps DIR.partial from now on (an interrupt leaves it
/// for --resume). A resumed directory's journal is read first: refused (ScenarioError)
/// when its identity differs from `identity`; otherwise `collect(journal, fileName)`
/// takes its points, `command` becomes the command that started the batch (the results
/// carry it, so a resumed batch writes what an uninterrupted one would), and the
/// journal is rewritten without a torn last line. Prints to stderr how many points it
/// resumes from.
std::unique_ptr<JournalWriter> openBatchJournal(
    OutputDirectory& dir, const std::string& kind, const nlohmann::ordered_json& identity, std::string& command,
    const std::function<void(const ParsedJournal&, const std::string& fileName)>& collect);

/// Removes the journal (the results now hold everything) and commits `dir`.
void commitBatch(OutputDirectory& dir);

}  // namespace rockroll::app
