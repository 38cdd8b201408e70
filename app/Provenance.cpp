#include "app/Provenance.h"
#include "mbmodel/DataFiles.h"

#include "app/BuildInfo.h"
#include "scenarios/ScenarioRun.h"

#include <algorithm>

#include <fmt/format.h>

namespace rockroll::app {

namespace {
std::string& commandLine() {
    static std::string line;
    return line;
}
}  // namespace

void setCommandLine(int argc, char** argv) {
    std::string& line = commandLine();
    line.clear();
    for (int i = 0; i < argc; ++i) {
        if (i) line += ' ';  // a char: GCC 12 -O2 -std=c++20 gives a false -Wrestrict for (i ? " " : "") + string
        line += argv[i];
    }
}
const std::string& getCommandLine() { return commandLine(); }

std::string getVersionString() {
    std::string data;
    try {
        data = findDataFile("scenarios/reference/mit1976.toml").parent_path().parent_path().parent_path().string();
    } catch (const std::exception& e) {
        data = std::string("not found: ") + e.what();
    }
    return fmt::format("rockroll {} (commit {})\n{}\ndata files: {}", kVersion, kGitCommit, ROCKROLL_SIMBODY_BUILD, data);
}

nlohmann::ordered_json makeProvenance(const Scenario& sc, const std::string& command) {
    nlohmann::ordered_json p;
    p["rockroll_version"] = kVersion;
    p["git_commit"] = kGitCommit;
    p["simbody"] = ROCKROLL_SIMBODY_BUILD;
    p["command"] = command;
    p["scenario_file"] = sc.source;
    p["scenario_sha256"] = sc.sourceSha256;
    p["model"] = sc.model;
    p["integrator"] = {{"method", sc.run.integrator.method},
                       {"accuracy", sc.run.integrator.accuracy},
                       {"max_step_s", sc.run.integrator.maxStepSize},
                       {"output_rate_hz", getRecordedOutputRate(sc)}};
    p["car_base"] = sc.car.name;
    nlohmann::ordered_json overrides = nlohmann::ordered_json::object();
    for (const auto& [key, text] : sc.carOverrides) overrides[key] = text;
    p["car_overrides"] = overrides;
    // KEY=VALUE overrides applied on top of the scenario file, in order (scenario_toml has their effect).
    nlohmann::ordered_json applied = nlohmann::ordered_json::array();
    for (const auto& [key, text] : sc.overrides) applied.push_back({{"key", key}, {"value", text}});
    p["overrides"] = applied;
    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    for (const CarParameterInfo& info : getCarParameterTable()) {
        const double si = sc.car.*(info.member);
        const std::string unit = info.dimension == units::Dimension::Dimensionless ? "" : info.displayUnit;
        const double shown = unit.empty() ? si : si / units::parseQuantity(fmt::format("1 {}", unit), info.dimension);
        params[info.key] = {{"value", shown}, {"unit", unit}};
    }
    p["car_parameters"] = params;
    p["scenario_toml"] = formatScenarioToml(sc);
    // What the scenario file and --set gave, and which of those the model does not use.
    p["settings_set"] = sc.settingsSet;
    p["ignored_settings"] = getIgnoredSettings(sc);
    return p;
}

Scenario loadScenarioFromSummary(const std::string& path) { return loadScenarioFromSummaryWithOverrides(path, {}); }

Scenario loadScenarioFromSummaryWithOverrides(const std::string& path, const std::vector<ScenarioOverride>& overrides) {
    const std::string text = readInputFile(path, "summary file");
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw ScenarioError(fmt::format("{}: not a JSON summary: {}", path, e.what()));
    }
    const nlohmann::json* prov = j.contains("provenance") ? &j["provenance"] : nullptr;
    if (!prov || !prov->contains("scenario_toml") || !(*prov)["scenario_toml"].is_string())
        throw ScenarioError(fmt::format("{}: key 'provenance.scenario_toml' is missing: expected a summary.json "
                                        "written by `rockroll run` (version 0.9 or later)",
                                        path));
    // A value as the messages show it: a string or a number as written, anything else by its
    // kind (a deeply nested array would otherwise be printed, or recursed into, whole).
    auto show = [](const nlohmann::json& v) {
        return v.is_string() || v.is_number() || v.is_boolean() || v.is_null() ? v.dump(-1, ' ', false,
                                                                                        nlohmann::json::error_handler_t::replace)
                                                                              : std::string("a JSON ") + v.type_name();
    };
    if (j.contains("start") && j["start"] != "rest")
        throw ScenarioError(fmt::format("{}: key 'start' = {}: expected \"rest\"; this point continued a speed sweep "
                                        "from the previous speed's state, so rerun the sweep instead",
                                        path, show(j["start"])));
    auto getText = [&](const char* key, const std::string& fallback) {
        if (!prov->contains(key)) return fallback;
        const nlohmann::json& v = (*prov)[key];
        if (!v.is_string())
            throw ScenarioError(fmt::format("{}: key 'provenance.{}' = {}: expected a string", path, key, show(v)));
        return v.get<std::string>();
    };
    Scenario sc =
        parseScenario((*prov)["scenario_toml"].get<std::string>(), path + " (provenance.scenario_toml)", overrides);
    const auto applied = sc.overrides;  // the new ones, recorded after the summary's own
    sc.sourceSha256 = getText("scenario_sha256", "");
    sc.source = getText("scenario_file", path);
    sc.carOverrides.clear();
    if (prov->contains("car_overrides") && (*prov)["car_overrides"].is_object())
        for (const auto& [key, text] : (*prov)["car_overrides"].items()) {
            if (text.is_structured())
                throw ScenarioError(fmt::format("{}: key 'provenance.car_overrides.{}' = {}: expected the value's text",
                                                path, key, show(text)));
            sc.carOverrides.emplace_back(key, text.is_string() ? text.get<std::string>() : show(text));
        }
    sc.overrides.clear();
    if (prov->contains("overrides") && (*prov)["overrides"].is_array())
        for (const auto& o : (*prov)["overrides"])
            if (o.is_object() && o.contains("key") && o.contains("value") && o["key"].is_string() &&
                o["value"].is_string())
                sc.overrides.emplace_back(o["key"].get<std::string>(), o["value"].get<std::string>());
    sc.overrides.insert(sc.overrides.end(), applied.begin(), applied.end());
    // scenario_toml holds every key; what the user set is settings_set (unknown in a summary
    // written before it was recorded), with the keys of the new overrides.
    std::vector<std::string> keys;
    if (prov->contains("settings_set")) {
        const nlohmann::json& set = (*prov)["settings_set"];
        if (!set.is_array())
            throw ScenarioError(fmt::format("{}: key 'provenance.settings_set' = {}: expected an array of key names",
                                            path, show(set)));
        for (const auto& k : set) {
            if (!k.is_string())
                throw ScenarioError(fmt::format("{}: key 'provenance.settings_set' holds {}: expected key names (strings)",
                                                path, show(k)));
            keys.push_back(k.get<std::string>());
        }
    }
    for (const auto& [key, text] : applied) keys.push_back(key);
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    sc.settingsSet = std::move(keys);
    return sc;
}

}  // namespace rockroll::app
