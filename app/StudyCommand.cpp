// rockroll study and rockroll merge (app/Study.h): the output directory, the journal
// (app/BatchOutput.h, the same as sweeps'), the points on --jobs threads, progress lines.
#include "app/BatchOutput.h"
#include "app/Commands.h"
#include "app/Provenance.h"
#include "app/Study.h"
#include "mbmodel/Parallel.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>
#include <mutex>

namespace rockroll::app {

using Json = nlohmann::ordered_json;

namespace {

/// "K/N" with 1 ≤ K ≤ N ≤ 100000.
std::pair<size_t, size_t> parseShard(const std::string& text) {
    const auto slash = text.find('/');
    size_t k = 0, n = 0;
    auto number = [](std::string_view s, size_t& out) {
        const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
        return r.ec == std::errc() && r.ptr == s.data() + s.size() && !s.empty();
    };
    if (slash == std::string::npos || !number(std::string_view(text).substr(0, slash), k) ||
        !number(std::string_view(text).substr(slash + 1), n) || k < 1 || n < 1 || k > n || n > 100000)
        throw ScenarioError(fmt::format("--shard \"{}\": expected K/N, whole numbers with 1 ≤ K ≤ N ≤ 100000 (shard K "
                                        "of N runs the points i with i mod N = K − 1)",
                                        text));
    return {k, n};
}

void writeStudy(OutputDirectory& dir, const Json& study) {
    dir.write("study.csv", [&](std::ostream& out) { writeRecordsCsv(out, makeStudyRecords(study)); });
    dir.writeJson("study.json", study);
}

}  // namespace

int studyCommand(const StudyOptions& o) {
    const auto [k, n] = parseShard(o.shard);
    if (o.outDir.empty()) throw ScenarioError("study: expected --out DIR");
    const StudyPlan plan = loadStudy(o.study);
    if (!plan.ignoredSettings.empty())
        fmt::print(stderr, "study: the model does not use {} (set in {} or its base scenario): ignored\n",
                   fmt::join(plan.ignoredSettings, ", "), o.study);
    std::vector<size_t> mine;
    for (size_t i = 0; i < plan.points.size(); ++i)
        if (i % n == k - 1) mine.push_back(i);
    OutputDirectory dir(o.outDir, o.force, JournaledOutput{o.resume});
    const Json info = makeStudyInfo(plan), varied = makeVariedJson(plan);
    const Json identity = {{"study", info}, {"shard", {{"k", k}, {"n", n}}}};
    std::map<size_t, Json> points;
    std::string command = getCommandLine();
    auto journal = openBatchJournal(dir, "study", identity, command, [&](const ParsedJournal& j, const std::string& file) {
        for (size_t m = 0; m < j.points.size(); ++m) {
            const Json& p = j.points[m];
            const bool readable = p.contains("point") && p["point"].is_number_unsigned() && p.contains("values") &&
                                  p.contains("status") && p["status"].is_string() && p.contains("summary") &&
                                  p["summary"].is_object();
            const size_t i = readable ? p["point"].get<size_t>() : 0;
            if (!readable || i >= plan.points.size() || i % n != k - 1 || points.count(i))
                throw ScenarioError(fmt::format("{}:{}: not a new point of shard {}/{} of this study; expected "
                                                "{{\"point\", \"values\", \"status\", \"summary\"}}",
                                                file, m + 2, k, n));
            points[i] = p;
        }
    });
    std::vector<size_t> todo;
    for (size_t i : mine)
        if (!points.count(i)) todo.push_back(i);
    std::vector<Json> results(todo.size());
    std::mutex lock;
    size_t finished = 0;
    const auto start = std::chrono::steady_clock::now();
    const int jobs = resolveJobCount(o.jobs);
    parallelFor(todo.size(), jobs, [&](size_t t) {
        results[t] = runStudyPoint(plan, todo[t]);
        std::lock_guard guard(lock);
        journal->append(results[t]);
        ++finished;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const Json& r = results[t];
        const std::string result =
            r.at("status") == "failed" ? "FAILED: " + r.value("error", std::string()).substr(0, r.value("error", std::string()).find('\n'))
            : r.at("summary").contains("max_roll_deg") && r.at("summary").at("max_roll_deg").is_number()
                ? fmt::format("{}, max roll {:.2f} deg", r.at("status").get<std::string>(),
                              r.at("summary").at("max_roll_deg").get<double>())
                : r.at("status").get<std::string>();
        fmt::print(stderr, "study: {}/{} points: point {} ({}): {}; ETA {:.0f} s\n", finished, todo.size(), todo[t],
                   describeStudyPoint(plan, todo[t]), result,
                   elapsed / double(finished) * double(todo.size() - finished));
    });
    for (size_t t = 0; t < todo.size(); ++t) points[todo[t]] = std::move(results[t]);
    std::vector<Json> all;
    size_t failed = 0;
    for (auto& [i, p] : points) {
        if (p.at("status") == "failed") {
            ++failed;
            fmt::print(stderr, "study: point {} ({}) FAILED: {}\n", i, describeStudyPoint(plan, i),
                       p.value("error", std::string()));
        }
        all.push_back(std::move(p));
    }
    const Json study = makeStudyJson(info, varied, k, n, std::move(all));
    writeStudy(dir, study);
    journal.reset();
    commitBatch(dir);
    fmt::print("study {}: {} of its {} points{} ({} failed); wrote {} and {}\n", o.study, mine.size(),
               plan.points.size(), n > 1 ? fmt::format(" in shard {}/{}", k, n) : "", failed,
               dir.getFinalPath("study.csv").string(), dir.getFinalPath("study.json").string());
    return failed ? kExitFailedPoints : kExitOk;
}

int mergeCommand(const MergeOptions& o) {
    if (o.outDir.empty()) throw ScenarioError("merge: expected --out DIR");
    const Json study = mergeStudies(o.dirs);
    OutputDirectory dir(o.outDir, o.force);
    writeStudy(dir, study);
    dir.commit();
    size_t failed = 0;
    for (const Json& p : study.at("points")) failed += p.at("status") == "failed" ? 1 : 0;
    fmt::print("merged {} shard directories: {} points ({} failed); wrote {} and {}\n", o.dirs.size(),
               study.at("points").size(), failed, dir.getFinalPath("study.csv").string(),
               dir.getFinalPath("study.json").string());
    return failed ? kExitFailedPoints : kExitOk;
}

}  // namespace rockroll::app
