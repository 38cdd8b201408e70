#pragma once
// Output helpers shared by the sub-commands: run summaries as JSON (toJson, in
// app/SummaryJson.h, library rr_report), time histories and tables of records as CSV,
// files written through a temporary name, and output directories that appear
// complete or not at all.
#include "app/SummaryJson.h"
#include "mbmodel/RunSummary.h"
#include "mbmodel/TimeHistory.h"

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockroll::app {

/// An output that cannot be written (a path under a file, no permission, a full disk):
/// exit 2 at the command line (docs/cli.md, "Exit codes"), its message naming the path.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Writes through a temporary name and renames when complete, so a reader never
/// sees a half-written file. The temporary is removed on SIGINT/SIGTERM. OutputError
/// when the file cannot be written.
void writeAtomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

/// The history as CSV (mbmodel/CsvWriter): every channel, or only `columns` in
/// that order (each must exist), with `digits` significant digits.
void writeHistoryCsv(std::ostream& out, const TimeHistory& h, const std::vector<std::string>& columns = {},
                     int digits = 7);

/// A JSON array of flat objects as a CSV table (mbmodel/CsvWriter), one row per object.
/// Columns: every key in the order first met; a key an object lacks (or null) is an
/// empty cell. Numbers are written as the shortest text that reads back to the JSON's
/// double, so the CSV and the JSON carry the same values; booleans as true/false;
/// nested objects and arrays are refused (std::logic_error).
void writeRecordsCsv(std::ostream& out, const nlohmann::ordered_json& records);

/// Blocks SIGINT and SIGTERM in the calling thread (and in every thread it starts
/// later) and waits for them in a thread of its own, which removes every temporary
/// (DIR.partial directories and files' .tmp names) and exits with 130. Call it first
/// in main, before any other thread exists.
void installInterruptHandler();

/// An output directory that appears complete or not at all. The constructor checks
/// `dir` (an existing non-empty directory needs `force`; otherwise ScenarioError, naming
/// `flag` and the directory: bad input, exit 2) and creates `dir`.partial (OutputError naming
/// `flag` and the path when it cannot), where every
/// file goes; commit() renames it to `dir` (replacing the old directory with `force`).
/// Until then an exception (destructor) or SIGINT/SIGTERM (installInterruptHandler)
/// removes `dir`.partial, and `dir` is left as it was.
///
/// A journaled directory (sweeps and studies, app/Journal.h) keeps `dir`.partial and its
/// journal once keepPartial() is called: from then on neither an exception nor SIGINT or
/// SIGTERM removes it, so `--resume` can continue. Its constructor finds an existing
/// `dir`.partial with a journal and, with `resume`, keeps it (isResumed()); with `force`
/// starts over; with neither refuses (ScenarioError: the journal would be lost).
struct JournaledOutput {
    bool resume = false;
};
class OutputDirectory {
public:
    OutputDirectory(std::filesystem::path dir, bool force, const std::string& flag = "--out");
    OutputDirectory(std::filesystem::path dir, bool force, JournaledOutput journaled, const std::string& flag = "--out");
    ~OutputDirectory();
    OutputDirectory(const OutputDirectory&) = delete;
    OutputDirectory& operator=(const OutputDirectory&) = delete;

    /// The final path of the file `name` (where it will be after commit()).
    std::filesystem::path getFinalPath(const std::string& name) const { return dir_ / name; }
    /// Where the files go until commit() (`dir`.partial), for a writer of its own (rockroll plot).
    const std::filesystem::path& getPartialPath() const { return partial_; }
    void write(const std::string& name, const std::function<void(std::ostream&)>& writer);
    void writeJson(const std::string& name, const nlohmann::ordered_json& document);  ///< app/JsonWriter.h
    void commit();

    /// Where `name` is while the directory is being written (`dir`.partial/name).
    std::filesystem::path getPartialPath(const std::string& name) const { return partial_ / name; }
    bool isResumed() const { return resumed_; }
    void keepPartial();

private:
    std::filesystem::path dir_, partial_;
    bool force_ = false, committed_ = false, kept_ = false, resumed_ = false;
    OutputDirectory(std::filesystem::path dir, bool force, std::optional<JournaledOutput> journaled,
                    const std::string& flag);
};

}  // namespace rockroll::app
