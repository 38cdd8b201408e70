#include "app/Output.h"
#include "app/JsonWriter.h"
#include "app/Journal.h"
#include "mbmodel/CsvWriter.h"
#include "scenarios/ScenarioLoader.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fmt/format.h>
#include <fstream>
#include <mutex>
#include <optional>
#include <pthread.h>
#include <set>
#include <thread>
#include <unistd.h>

namespace rockroll::app {

namespace fs = std::filesystem;

namespace {
/// Temporaries that SIGINT/SIGTERM remove. Writers hold the lock while they create or
/// rename a temporary, so the interrupt thread sees each one either whole or gone.
std::recursive_mutex& getTemporariesMutex() {
    static std::recursive_mutex m;
    return m;
}
std::set<fs::path>& getTemporaries() {
    static std::set<fs::path> t;
    return t;
}
void addTemporary(const fs::path& p) {
    std::lock_guard lock(getTemporariesMutex());
    getTemporaries().insert(p);
}
void dropTemporary(const fs::path& p) {
    std::lock_guard lock(getTemporariesMutex());
    getTemporaries().erase(p);
}
/// DIR.partial directories kept for --resume (OutputDirectory::keepPartial), named on SIGINT/SIGTERM.
std::set<fs::path>& getKeptPartials() {
    static std::set<fs::path> k;
    return k;
}
}  // namespace

void installInterruptHandler() {
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    std::thread([signals] {
        int sig = 0;
        if (sigwait(&signals, &sig) != 0) return;
        std::lock_guard lock(getTemporariesMutex());  // held until exit: no writer continues
        for (const fs::path& p : getTemporaries()) {
            std::error_code ec;
            fs::remove_all(p, ec);
        }
        fmt::print(stderr, "\nrockroll: interrupted by {}; temporaries removed, nothing half-written (exit 130)\n",
                   sig == SIGINT ? "SIGINT" : "SIGTERM");
        for (const fs::path& p : getKeptPartials())
            fmt::print(stderr, "rockroll: the finished points are kept in {}: the same command with --resume "
                               "continues, --force starts over\n",
                       (p / kJournalFileName).string());
        std::fflush(stderr);
        _exit(130);
    }).detach();
}

void writeAtomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
    const fs::path tmp = path.string() + ".tmp";
    std::lock_guard lock(getTemporariesMutex());
    addTemporary(tmp);
    {
        std::ofstream out(tmp);
        if (!out) throw OutputError(fmt::format("cannot write {}", tmp.string()));
        write(out);
        out.flush();
        if (!out) throw OutputError(fmt::format("error while writing {}", tmp.string()));
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw OutputError(fmt::format("cannot rename {} to {}: {}", tmp.string(), path.string(), ec.message()));
    dropTemporary(tmp);
}

void writeHistoryCsv(std::ostream& out, const TimeHistory& h, const std::vector<std::string>& columns, int digits) {
    const std::vector<std::string>& names = columns.empty() ? h.names : columns;
    std::vector<int> index;
    for (const auto& c : names) index.push_back(h.column(c));
    if (!h.samples.empty() && h.samples.getWidth() != h.names.size())
        throw std::logic_error(fmt::format("writeHistoryCsv: rows of {} values under {} names", h.samples.getWidth(),
                                           h.names.size()));
    CsvWriter csv(out, names);
    std::vector<CsvCell> cells;
    for (const auto& row : h.samples) {
        cells.clear();
        for (int k : index) cells.push_back(CsvCell::significant(row[size_t(k)], digits));
        csv.writeRow(cells);
    }
}

void writeRecordsCsv(std::ostream& out, const nlohmann::ordered_json& records) {
    if (!records.is_array()) throw std::logic_error("writeRecordsCsv: expected a JSON array of objects");
    std::vector<std::string> columns;
    for (const auto& r : records)
        for (const auto& [key, value] : r.items())
            if (std::find(columns.begin(), columns.end(), key) == columns.end()) columns.push_back(key);
    CsvWriter csv(out, columns);
    std::vector<CsvCell> cells;
    for (const auto& r : records) {
        cells.clear();
        for (const std::string& c : columns) {
            if (!r.contains(c) || r[c].is_null()) cells.push_back(CsvCell::empty());
            else if (r[c].is_boolean()) cells.push_back(CsvCell(r[c].get<bool>() ? "true" : "false"));
            else if (r[c].is_number_integer()) cells.push_back(CsvCell(r[c].get<long long>()));
            else if (r[c].is_number()) cells.push_back(CsvCell(r[c].get<double>()));
            else if (r[c].is_string()) cells.push_back(CsvCell(r[c].get<std::string>()));
            else throw std::logic_error(fmt::format("writeRecordsCsv: column '{}' holds a nested value", c));
        }
        csv.writeRow(cells);
    }
}

OutputDirectory::OutputDirectory(fs::path dir, bool force, const std::string& flag)
    : OutputDirectory(std::move(dir), force, std::optional<JournaledOutput>{}, flag) {}

OutputDirectory::OutputDirectory(fs::path dir, bool force, JournaledOutput journaled, const std::string& flag)
    : OutputDirectory(std::move(dir), force, std::optional<JournaledOutput>{journaled}, flag) {}

OutputDirectory::OutputDirectory(fs::path dir, bool force, std::optional<JournaledOutput> journaled,
                                 const std::string& flag)
    : dir_(std::move(dir)), force_(force) {
    if (dir_.empty()) throw ScenarioError(fmt::format("{} \"\": expected a directory path", flag));
    while (!dir_.has_filename() && dir_.has_parent_path() && dir_ != dir_.parent_path()) dir_ = dir_.parent_path();
    partial_ = dir_.string() + ".partial";
    std::error_code ec;
    if (fs::exists(dir_, ec)) {
        if (!fs::is_directory(dir_, ec))
            throw ScenarioError(fmt::format("{} {}: exists and is not a directory; expected a directory path", flag,
                                            dir_.string()));
        if (!fs::is_empty(dir_, ec) && !force_)
            throw ScenarioError(fmt::format("{} {}: the directory exists and is not empty; expected a new or empty "
                                            "directory, or --force to replace it",
                                            flag, dir_.string()));
    }
    if (journaled && fs::exists(partial_ / kJournalFileName, ec)) {
        if (journaled->resume) {
            resumed_ = kept_ = true;  // the journal is the user's: never removed from here on
            return;
        }
        if (!force_)
            throw ScenarioError(fmt::format("{} {}: {} holds the journal of an unfinished run; expected --resume to "
                                            "continue it, or --force to start over",
                                            flag, dir_.string(), (partial_ / kJournalFileName).string()));
    }
    std::lock_guard lock(getTemporariesMutex());
    addTemporary(partial_);
    try {
        fs::remove_all(partial_);  // left by a run that was killed (SIGKILL) before it could clean up
        fs::create_directories(partial_);
    } catch (const fs::filesystem_error& e) {
        throw OutputError(fmt::format("{} {}: cannot create the directory {}: {}; expected a path in a writable "
                                      "directory",
                                      flag, dir_.string(), partial_.string(), e.code().message()));
    }
}

void OutputDirectory::keepPartial() {
    std::lock_guard lock(getTemporariesMutex());
    dropTemporary(partial_);
    getKeptPartials().insert(partial_);
    kept_ = true;
}

OutputDirectory::~OutputDirectory() {
    if (committed_ || kept_) return;
    std::lock_guard lock(getTemporariesMutex());
    std::error_code ec;
    fs::remove_all(partial_, ec);
    dropTemporary(partial_);
}

void OutputDirectory::write(const std::string& name, const std::function<void(std::ostream&)>& writer) {
    writeAtomically(partial_ / name, writer);
}

void OutputDirectory::writeJson(const std::string& name, const nlohmann::ordered_json& document) {
    writeJsonFile(partial_ / name, document);
}

void OutputDirectory::commit() {
    std::lock_guard lock(getTemporariesMutex());
    if (fs::exists(dir_)) {
        // With --force (or an empty directory): the old one goes aside, the new one takes its name.
        const fs::path old = dir_.string() + ".replaced";
        addTemporary(old);
        fs::remove_all(old);
        fs::rename(dir_, old);
        fs::rename(partial_, dir_);
        fs::remove_all(old);
        dropTemporary(old);
    } else {
        if (dir_.has_parent_path()) fs::create_directories(dir_.parent_path());
        fs::rename(partial_, dir_);
    }
    dropTemporary(partial_);
    getKeptPartials().erase(partial_);
    committed_ = true;
}

}  // namespace rockroll::app
