#pragma once
// The journal of a resumable batch (rockroll sweep and rockroll study --out DIR):
// DIR.partial/journal.jsonl, one JSON object a line. Line 1 is the header: what the
// batch is ("kind"), its identity (everything its results depend on: scenario,
// model, speeds, overrides, build) and the command that started it. Every further
// line is one finished point, appended, flushed and fsync'd as it finishes, in the
// order points finish. `--resume` reads it back (parseJournal), refuses a journal of
// another batch (checkJournalIdentity) and runs only the points it lacks.
//
// Doubles that must come back bit for bit (the state a sweep continues from) are
// stored as C99 hex-float strings ("0x1.91eb851eb851fp+1"; formatHexDouble).
#include "mbmodel/RunSummary.h"
#include "scenarios/SpeedSweep.h"
#include "scenarios/TimeDomainModel.h"

#include <cstdint>
#include <filesystem>
#include <limits>
#include <mutex>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <vector>

namespace rockroll::app {

inline constexpr const char* kJournalFileName = "journal.jsonl";

/// A double as an exact hex-float string, and back. parseHexDouble throws
/// std::invalid_argument for anything that is not a whole hex float (or inf/nan).
std::string formatHexDouble(double x);
double parseHexDouble(std::string_view text);
nlohmann::ordered_json toHexJson(const std::vector<double>& v);
std::vector<double> fromHexJson(const nlohmann::ordered_json& a);

/// The integer `j[key]` as T. std::invalid_argument naming the key unless the value is a
/// JSON integer within T's range: a journal or shard is a file a person may edit, and
/// nlohmann's get<T>() of a number such as 1e300 converts it with undefined behaviour.
template <class T>
T getJsonInteger(const nlohmann::ordered_json& j, const char* key) {
    const nlohmann::ordered_json& v = j.at(key);
    if (v.is_number_unsigned()) {
        const auto u = v.get<std::uint64_t>();
        if (u <= static_cast<std::uint64_t>(std::numeric_limits<T>::max())) return static_cast<T>(u);
    } else if (v.is_number_integer()) {  // negative
        const auto i = v.get<std::int64_t>();
        if (std::is_signed_v<T> && i >= static_cast<std::int64_t>(std::numeric_limits<T>::min()))
            return static_cast<T>(i);
    }
    throw std::invalid_argument("\"" + std::string(key) + "\" is " + v.dump() + "; expected an integer from " +
                                std::to_string(std::numeric_limits<T>::min()) + " to " +
                                std::to_string(std::numeric_limits<T>::max()));
}

/// A continuation state (scenarios/TimeDomainModel.h) as JSON with hex doubles, and back.
nlohmann::ordered_json toJson(const RestartState& s);
RestartState restartStateFromJson(const nlohmann::ordered_json& j);

/// The inverse of toJson(RunSummary) (app/SummaryJson.h): toJson(summaryFromJson(toJson(s)))
/// is toJson(s) byte for byte (JSON numbers are written shortest-round-trip).
RunSummary summaryFromJson(const nlohmann::ordered_json& j);

/// A journal read back: the header and the point lines, in file order.
struct ParsedJournal {
    nlohmann::ordered_json header;
    std::vector<nlohmann::ordered_json> points;
    bool droppedTornLine = false;  ///< the last line was cut off (killed mid-write) and is dropped
};

/// Parses a journal's text. A last line that is not a complete JSON object (a write
/// the kill cut short) is dropped; any other bad line, or a missing or wrong header,
/// is a ScenarioError naming `fileName` and the line (bad input, exit 2).
ParsedJournal parseJournal(std::string_view text, const std::string& fileName);
/// The file read and parsed (ScenarioError when it cannot be read).
ParsedJournal readJournal(const std::filesystem::path& file);

/// The first place where `a` ("there": a journal's, another shard's) and `b` ("here")
/// differ, e.g. "sweeps[0].model is \"reduced\" there, \"eom\" here"; nullopt when equal.
std::optional<std::string> describeJsonDifference(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b,
                                                  const std::string& path = "");

/// ScenarioError when the journal's header identity differs from `expected`: names the
/// file, the first differing item (e.g. "sweeps[0].model") and both values.
void checkJournalIdentity(const ParsedJournal& journal, const nlohmann::ordered_json& expected,
                          const std::string& fileName);

/// A header line: {"journal": kind, "version": 1, "identity": ..., "command": ...}.
nlohmann::ordered_json makeJournalHeader(const std::string& kind, const nlohmann::ordered_json& identity,
                                         const std::string& command);

/// Appends lines to a journal file: each line written whole with one write(2), then
/// fsync'd, under a lock (points finish on several threads).
class JournalWriter {
public:
    /// Writes `header` followed by `points` into a new `file` (through a temporary name,
    /// so a resumed journal never keeps a torn line), then opens it for appending.
    JournalWriter(const std::filesystem::path& file, const nlohmann::ordered_json& header,
                  const std::vector<nlohmann::ordered_json>& points = {});
    ~JournalWriter();
    JournalWriter(const JournalWriter&) = delete;
    JournalWriter& operator=(const JournalWriter&) = delete;
    void append(const nlohmann::ordered_json& point);

private:
    std::filesystem::path file_;
    int fd_ = -1;
    std::mutex mutex_;
};

// ---- speed sweeps ------------------------------------------------------------------

/// The identity of `rockroll sweep`'s batch: for each sweep its provenance (scenario
/// file and SHA-256, resolved scenario TOML with every --set, model, integrator, build)
/// and its speeds, direction and start options.
nlohmann::ordered_json makeSweepIdentity(const std::vector<SweepSpec>& specs);

/// One finished speed as a journal line: its identity ("sweep": index in the batch,
/// "direction", "index" in its sweep, "speed_mph" as given and as a hex float), the
/// point (start, failure, summary) and `next`, the exact state the next speed starts from.
nlohmann::ordered_json toJournalJson(const SweepPoint& p, size_t sweep, size_t index);
SweepPoint sweepPointFromJournal(const nlohmann::ordered_json& j);

/// The journal's points as each sweep's first points, in order (runSweepsFrom's `done`).
/// ScenarioError naming the file and line of a point that is not the next point of its
/// sweep (index, direction or speed differ) or cannot be read.
std::vector<std::vector<SweepPoint>> collectSweepPoints(const ParsedJournal& journal,
                                                        const std::vector<SweepSpec>& specs,
                                                        const std::string& fileName);

}  // namespace rockroll::app
