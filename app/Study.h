#pragma once
// Parameter studies (rockroll study, rockroll merge; docs/studies.md): a
// study file names a base scenario, a model, a kind (run or sweep) and a [vary] table
// of scenario keys to values; its points are numbered deterministically from 0 and
// may be split into shards (point i in shard K of N when i mod N = K − 1) that merge
// back into exactly the unsharded study.csv and study.json.
#include "app/Commands.h"
#include "scenarios/ScenarioLoader.h"

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rockroll::app {

/// One value of a varied key: the text given to the scenario loader (as --set gives
/// it: "0.25 in", "halfcar", "4") and the value study.csv shows (the number in the
/// study's unit, or the text).
struct StudyValue {
    std::string text;
    nlohmann::ordered_json shown;
};

struct VariedKey {
    std::string key;     ///< full scenario key ("car.side_bearing_clearance")
    std::string unit;    ///< the unit word the study file used ("in"); empty: unitless
    std::string column;  ///< "<key>_<unit>", or "<key>" when unitless
    int line = 0;        ///< in the study file
    std::vector<StudyValue> values;  ///< as listed or stepped (grid, zip)
    bool isRange = false;            ///< given as { from, to[, step] }
    double from = 0, to = 0;         ///< a range's ends, in `unit` (Latin hypercube)
};

struct StudyPlan {
    std::string file;               ///< the study file's path as given
    std::string content, sha256;    ///< its bytes and their SHA-256
    std::string scenarioPath;       ///< the base scenario, resolved against the study file's folder
    std::string scenarioText;       ///< its bytes
    std::string kind = "run";       ///< run | sweep
    std::vector<ScenarioOverride> sets;  ///< [set]: fixed overrides of every point (model as run.model)
    double fromMph = 0, toMph = 0, stepMph = 0;  ///< [sweep]
    std::string direction = "both";
    bool fresh = false;
    std::vector<VariedKey> varied;
    std::string combine = "grid";   ///< grid | zip | latin_hypercube
    size_t hypercubePoints = 0;
    uint64_t seed = 0;
    /// points[i][k]: the value of varied[k] at point i.
    std::vector<std::vector<StudyValue>> points;
    /// The keys set (base scenario, [set], [vary]) that the model of some point does not use
    /// (getIgnoredSettings), sorted; study.json's `study.ignored_settings`.
    std::vector<std::string> ignoredSettings;
};

/// Reads and checks a study file: every key, value and combination goes through the
/// scenario loader as a --set would. ScenarioError naming the study file, the line,
/// the key, the value and what is accepted (bad input, exit 2).
StudyPlan loadStudy(const std::string& path);

/// "car.side_bearing_clearance = \"0.25 in\", run.speed = \"14 mph\"": point i's values.
std::string describeStudyPoint(const StudyPlan& plan, size_t i);

/// The overrides of point i: [set], then each varied key's value.
std::vector<ScenarioOverride> getPointOverrides(const StudyPlan& plan, size_t i);

/// study.json's "study": the file's name, content, SHA-256, base scenario and its
/// SHA-256, kind, combine, point count and rockroll's version and commit.
nlohmann::ordered_json makeStudyInfo(const StudyPlan& plan);
/// study.json's "varied": [{key, column, unit, values}].
nlohmann::ordered_json makeVariedJson(const StudyPlan& plan);

/// Runs point i (a run, or the sweep of [sweep]): {"point", "values", "status",
/// "summary"} ("error" too when it failed). Never throws for the point's own failure:
/// that is status "failed" with the error.
nlohmann::ordered_json runStudyPoint(const StudyPlan& plan, size_t i);

/// study.json: info, varied, shard and the points (sorted by index).
nlohmann::ordered_json makeStudyJson(const nlohmann::ordered_json& info, const nlohmann::ordered_json& varied,
                                     size_t shardK, size_t shardN, std::vector<nlohmann::ordered_json> points);
/// study.csv's records: point, one column per varied key, status, the summary fields.
nlohmann::ordered_json makeStudyRecords(const nlohmann::ordered_json& study);

/// The shard directories' study.json files merged into the unsharded study.json
/// (shard 1 of 1). ScenarioError (exit 2) for shards of different studies, of
/// different shard counts, twice the same shard, a point in two shards, or points
/// missing (each named).
nlohmann::ordered_json mergeStudies(const std::vector<std::string>& dirs);

}  // namespace rockroll::app
