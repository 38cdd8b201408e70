#include "app/Study.h"
#include "app/BuildInfo.h"
#include "app/CommandResults.h"
#include "app/Journal.h"
#include "scenarios/ScenarioRun.h"
#include "scenarios/SpeedSweep.h"
#include "scenarios/TomlInput.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <toml++/toml.h>

namespace rockroll::app {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

int lineOf(const toml::node& n) { return int(n.source().begin.line); }

/// A value of the study file with its unit split off: "0.25 in" → 0.25, "in".
struct Quantity {
    double number = 0;
    std::string unit;
};
std::optional<Quantity> splitQuantity(std::string_view text) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    double x = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), x);
    if (r.ec != std::errc() || !std::isfinite(x)) return std::nullopt;
    std::string_view unit(r.ptr, size_t(text.data() + text.size() - r.ptr));
    while (!unit.empty() && unit.front() == ' ') unit.remove_prefix(1);
    while (!unit.empty() && unit.back() == ' ') unit.remove_suffix(1);
    if (!unit.empty() && r.ptr == text.data() + text.size()) return std::nullopt;
    if (!unit.empty() && *r.ptr != ' ') return std::nullopt;  // "12mph" or "1e": a word, not a quantity
    return Quantity{x, std::string(unit)};
}

/// A number of the study's unit as the loader reads it: 12 significant digits, so
/// stepped and sampled values are the text a person would write (0.3, not 0.30000000000000004).
double roundForText(double x) { return std::stod(fmt::format("{:.12g}", x)); }
StudyValue makeNumberValue(double x, const std::string& unit) {
    const double v = roundForText(x);
    return StudyValue{unit.empty() ? fmt::format("{}", v) : fmt::format("{} {}", v, unit), Json(v)};
}

/// One element of a [vary] list: a quantity with its unit, a number, a word or a boolean.
StudyValue readElement(const toml::node& n, const std::string& where, std::string& unit, bool& unitSet) {
    auto sameUnit = [&](const std::string& u) {
        if (!unitSet) {
            unit = u;
            unitSet = true;
        } else if (u != unit) {
            throw ScenarioError(fmt::format("{}: value in \"{}\", the others in \"{}\": expected every value of a key "
                                            "in one unit (study.csv has one column per key)",
                                            where, u, unit));
        }
    };
    if (const auto* s = n.as_string()) {
        const std::string text = s->get();
        if (auto q = splitQuantity(text)) {
            sameUnit(q->unit);
            return StudyValue{text, Json(q->number)};
        }
        sameUnit("");
        return StudyValue{text, Json(text)};
    }
    if (const auto* i = n.as_integer()) {
        sameUnit("");
        return StudyValue{fmt::format("{}", i->get()), Json(i->get())};
    }
    if (const auto* f = n.as_floating_point()) {
        sameUnit("");
        return StudyValue{fmt::format("{}", f->get()), Json(f->get())};
    }
    if (const auto* b = n.as_boolean()) {
        sameUnit("");
        return StudyValue{b->get() ? "true" : "false", Json(b->get())};
    }
    throw ScenarioError(fmt::format("{}: expected a value (\"0.25 in\", 4, \"halfcar\", true)", where));
}

/// A range end: "12 mph" or a number; `unit` as the study file wrote it.
Quantity readRangeEnd(const toml::table& t, const char* name, const std::string& where, bool required) {
    const toml::node* n = t.get(name);
    if (!n) {
        if (required)
            throw ScenarioError(fmt::format("{}: the range has no '{}': expected {{ from = \"12 mph\", to = \"18 mph\", "
                                            "step = \"1 mph\" }}",
                                            where, name));
        return Quantity{std::nan(""), ""};
    }
    if (const auto* s = n->as_string())
        if (auto q = splitQuantity(s->get())) return *q;
    if (auto v = n->value<double>()) return Quantity{*v, ""};
    throw ScenarioError(fmt::format("{}: {} = {}: expected a number with its unit, e.g. \"12 mph\"", where, name,
                                    n->is_string() ? "\"" + std::string(*n->value<std::string>()) + "\"" : "a non-number"));
}

VariedKey readVaried(const std::string& file, const std::string& key, const toml::node& n, bool hypercube) {
    VariedKey v;
    v.line = lineOf(n);
    const std::string where = fmt::format("{}:{}: [vary] \"{}\"", file, v.line, key);
    try {
        v.key = resolveScenarioKey(key, OverrideKeys::FullOnly);
    } catch (const ScenarioError& e) {
        throw ScenarioError(fmt::format("{}: {}", where, e.what()));
    }
    bool unitSet = false;
    if (const auto* list = n.as_array()) {
        if (list->empty()) throw ScenarioError(fmt::format("{}: an empty list: expected at least one value", where));
        if (hypercube)
            throw ScenarioError(fmt::format("{}: a list; a Latin hypercube samples ranges: expected {{ from = ..., "
                                            "to = ... }}",
                                            where));
        for (const toml::node& e : *list) v.values.push_back(readElement(e, where, v.unit, unitSet));
    } else if (const auto* range = n.as_table()) {
        for (const auto& [name, value] : *range)
            if (name.str() != "from" && name.str() != "to" && name.str() != "step")
                throw ScenarioError(fmt::format("{}: unknown range key '{}': expected from, to and step", where,
                                                name.str()));
        const Quantity from = readRangeEnd(*range, "from", where, true), to = readRangeEnd(*range, "to", where, true);
        const Quantity step = readRangeEnd(*range, "step", where, !hypercube);
        if (to.unit != from.unit || (!std::isnan(step.number) && step.unit != from.unit))
            throw ScenarioError(fmt::format("{}: from in \"{}\", to in \"{}\", step in \"{}\": expected one unit",
                                            where, from.unit, to.unit, step.unit));
        if (!(to.number >= from.number))
            throw ScenarioError(fmt::format("{}: to {} is below from {}: expected to ≥ from", where, to.number,
                                            from.number));
        v.unit = from.unit;
        v.isRange = true;
        v.from = from.number;
        v.to = to.number;
        if (!hypercube) {
            if (!(step.number > 0))
                throw ScenarioError(fmt::format("{}: step {}: expected a positive step", where, step.number));
            const double count = std::floor((to.number - from.number) / step.number + 1e-9) + 1;
            if (count > kMaxSweepSpeeds)
                throw ScenarioError(fmt::format("{}: {:.0f} values: expected at most {} (a larger step)", where, count,
                                                kMaxSweepSpeeds));
            for (long k = 0; k < long(count); ++k)
                v.values.push_back(makeNumberValue(from.number + double(k) * step.number, v.unit));
        }
    } else {
        throw ScenarioError(fmt::format("{}: expected a list of values ([\"0.125 in\", \"0.25 in\"]) or a range "
                                        "({{ from = \"12 mph\", to = \"18 mph\", step = \"1 mph\" }})",
                                        where));
    }
    v.column = v.unit.empty() ? v.key : fmt::format("{}_{}", v.key, v.unit);
    return v;
}

/// A uniform double in [0, 1) from the top 53 bits of one mt19937_64 draw (fixed and
/// portable, unlike std::uniform_real_distribution).
double drawUniform(std::mt19937_64& g) { return double(g() >> 11) * 0x1.0p-53; }
/// Fisher–Yates with j = draw mod (i + 1): fixed and portable.
std::vector<size_t> drawPermutation(std::mt19937_64& g, size_t n) {
    std::vector<size_t> p(n);
    for (size_t i = 0; i < n; ++i) p[i] = i;
    for (size_t i = n; i > 1; --i) std::swap(p[i - 1], p[size_t(g() % i)]);
    return p;
}

void makePoints(StudyPlan& plan) {
    const size_t keys = plan.varied.size();
    if (plan.combine == "grid") {
        size_t total = 1;
        for (const auto& v : plan.varied) {
            total *= v.values.size();
            if (total > size_t(kMaxSweepSpeeds) * 10)
                throw ScenarioError(fmt::format("{}: the grid has over {} points: expected fewer values", plan.file,
                                                size_t(kMaxSweepSpeeds) * 10));
        }
        // Row-major in the order the keys appear in the study file: the last key varies fastest.
        for (size_t i = 0; i < total; ++i) {
            std::vector<StudyValue> point(keys);
            size_t rest = i;
            for (size_t k = keys; k-- > 0;) {
                point[k] = plan.varied[k].values[rest % plan.varied[k].values.size()];
                rest /= plan.varied[k].values.size();
            }
            plan.points.push_back(std::move(point));
        }
    } else if (plan.combine == "zip") {
        for (const auto& v : plan.varied)
            if (v.values.size() != plan.varied.front().values.size())
                throw ScenarioError(fmt::format("{}:{}: [vary] \"{}\" has {} values, \"{}\" has {}: combine = \"zip\" "
                                                "expects every key to have as many values",
                                                plan.file, v.line, v.key, v.values.size(), plan.varied.front().key,
                                                plan.varied.front().values.size()));
        for (size_t i = 0; i < plan.varied.front().values.size(); ++i) {
            std::vector<StudyValue> point;
            for (const auto& v : plan.varied) point.push_back(v.values[i]);
            plan.points.push_back(std::move(point));
        }
    } else {
        // Latin hypercube: each key's range cut into N equal strata, one sample in each,
        // the strata of each key in a random order. Keys draw in file order.
        std::mt19937_64 g(plan.seed);
        const size_t n = plan.hypercubePoints;
        plan.points.assign(n, std::vector<StudyValue>(keys));
        for (size_t k = 0; k < keys; ++k) {
            VariedKey& v = plan.varied[k];
            const std::vector<size_t> strata = drawPermutation(g, n);
            for (size_t i = 0; i < n; ++i) {
                const double u = (double(strata[i]) + drawUniform(g)) / double(n);
                plan.points[i][k] = makeNumberValue(v.from + u * (v.to - v.from), v.unit);
                v.values.push_back(plan.points[i][k]);
            }
        }
    }
}

}  // namespace

std::string describeStudyPoint(const StudyPlan& plan, size_t i) {
    std::vector<std::string> parts;
    for (size_t k = 0; k < plan.varied.size(); ++k)
        parts.push_back(fmt::format("{} = \"{}\"", plan.varied[k].key, plan.points[i][k].text));
    return fmt::format("{}", fmt::join(parts, ", "));
}

namespace {

Scenario loadPointScenario(const StudyPlan& plan, size_t i) {
    Scenario sc = parseScenario(plan.scenarioText, plan.scenarioPath, getPointOverrides(plan, i));
    sc.sourceSha256 = calcSha256(plan.scenarioText);
    return sc;
}

/// The sweeps of a point of kind "sweep": those `rockroll sweep` would run ([sweep] as its options).
std::vector<SweepSpec> makePointSweeps(const StudyPlan& plan, const Scenario& sc) {
    SweepOptions o;
    o.fromMph = plan.fromMph;
    o.toMph = plan.toMph;
    o.stepMph = plan.stepMph;
    o.direction = plan.direction;
    o.fresh = plan.fresh;
    return makeSweepSpecs({sc}, o);
}

}  // namespace

std::vector<ScenarioOverride> getPointOverrides(const StudyPlan& plan, size_t i) {
    std::vector<ScenarioOverride> o = plan.sets;
    for (size_t k = 0; k < plan.varied.size(); ++k) o.push_back({plan.varied[k].key, plan.points.at(i)[k].text});
    return o;
}

StudyPlan loadStudy(const std::string& path) {
    StudyPlan plan;
    plan.file = path;
    plan.content = readInputFile(path, "study file");  // its size limit and regular-file check
    plan.sha256 = calcSha256(plan.content);
    toml::table root;
    root = parseToml(plan.content, path);
    const std::set<std::string> known = {"description", "scenario", "model", "kind", "combine", "set", "sweep", "vary"};
    for (const auto& [k, n] : root)
        if (!known.count(std::string(k.str())))
            throw ScenarioError(fmt::format("{}:{}: unknown key '{}': expected {}", path, lineOf(n), k.str(),
                                            fmt::join(known, ", ")));
    auto text = [&](const char* key, bool required, const std::string& fallback) -> std::string {
        const toml::node* n = root.get(key);
        if (!n) {
            if (required) throw ScenarioError(fmt::format("{}: missing key '{}'", path, key));
            return fallback;
        }
        if (!n->is_string()) throw ScenarioError(fmt::format("{}:{}: '{}' must be a string", path, lineOf(*n), key));
        return std::string(*n->value<std::string>());
    };
    const std::string scenario = text("scenario", true, "");
    plan.scenarioPath = (fs::path(path).parent_path() / scenario).lexically_normal().string();
    plan.scenarioText =
        readInputFile(plan.scenarioPath, fmt::format("base scenario (key 'scenario' of {})", path).c_str());
    plan.kind = text("kind", false, "run");
    if (plan.kind != "run" && plan.kind != "sweep")
        throw ScenarioError(fmt::format("{}:{}: kind = \"{}\": expected \"run\" or \"sweep\"", path,
                                        lineOf(*root.get("kind")), plan.kind));
    if (const toml::node* m = root.get("model")) {
        if (!m->is_string()) throw ScenarioError(fmt::format("{}:{}: 'model' must be a string", path, lineOf(*m)));
        plan.sets.push_back({"run.model", std::string(*m->value<std::string>())});
    }
    std::vector<int> setLines(plan.sets.size(), root.get("model") ? lineOf(*root.get("model")) : 0);
    if (const toml::node* s = root.get("set")) {
        const toml::table* t = s->as_table();
        if (!t) throw ScenarioError(fmt::format("{}:{}: 'set' must be a table [set]", path, lineOf(*s)));
        for (const auto& [k, n] : *t) {
            const std::string where = fmt::format("{}:{}: [set] \"{}\"", path, lineOf(n), k.str());
            std::string key;
            try {
                key = resolveScenarioKey(std::string(k.str()), OverrideKeys::FullOnly);
            } catch (const ScenarioError& e) {
                throw ScenarioError(fmt::format("{}: {}", where, e.what()));
            }
            std::string unit;
            bool unitSet = false;
            plan.sets.push_back({key, readElement(n, where, unit, unitSet).text});
            setLines.push_back(lineOf(n));
        }
    }
    // [sweep]: the speeds of each point's sweep (kind = "sweep").
    if (const toml::node* s = root.get("sweep")) {
        const toml::table* t = s->as_table();
        if (!t) throw ScenarioError(fmt::format("{}:{}: 'sweep' must be a table [sweep]", path, lineOf(*s)));
        if (plan.kind != "sweep")
            throw ScenarioError(fmt::format("{}:{}: a [sweep] table in a study of kind \"{}\": expected kind = \"sweep\"",
                                            path, lineOf(*s), plan.kind));
        const std::string where = fmt::format("{}:{}: [sweep]", path, lineOf(*s));
        for (const auto& [k, n] : *t)
            if (k.str() != "from" && k.str() != "to" && k.str() != "step" && k.str() != "direction" && k.str() != "fresh")
                throw ScenarioError(fmt::format("{}: unknown key '{}': expected from, to, step, direction, fresh", where,
                                                k.str()));
        auto speed = [&](const char* name) {
            const Quantity q = readRangeEnd(*t, name, where, true);
            const std::string text = fmt::format("{} {}", q.number, q.unit.empty() ? "mph" : q.unit);
            try {
                return units::parseQuantity(text, units::Dimension::Speed) / units::mph;
            } catch (const std::invalid_argument& e) {
                throw ScenarioError(fmt::format("{}: {} = \"{}\": {}", where, name, text, e.what()));
            }
        };
        plan.fromMph = speed("from");
        plan.toMph = speed("to");
        plan.stepMph = speed("step");
        if (const toml::node* d = t->get("direction")) plan.direction = d->value<std::string>().value_or("?");
        if (plan.direction != "up" && plan.direction != "down" && plan.direction != "both")
            throw ScenarioError(fmt::format("{}: direction = \"{}\": expected up, down or both", where, plan.direction));
        if (const toml::node* f = t->get("fresh")) {
            if (!f->is_boolean()) throw ScenarioError(fmt::format("{}: fresh: expected true or false", where));
            plan.fresh = *f->value<bool>();
        }
    } else if (plan.kind == "sweep") {
        throw ScenarioError(fmt::format("{}: kind = \"sweep\" needs a [sweep] table: from, to, step (speeds with "
                                        "units), direction (up, down, both), fresh",
                                        path));
    }
    // combine
    if (const toml::node* c = root.get("combine")) {
        const std::string where = fmt::format("{}:{}: combine", path, lineOf(*c));
        if (const auto* s = c->as_string()) {
            plan.combine = s->get();
            if (plan.combine != "grid" && plan.combine != "zip")
                throw ScenarioError(fmt::format("{} = \"{}\": expected \"grid\", \"zip\" or {{ latin_hypercube = N, "
                                                "seed = S }}",
                                                where, plan.combine));
        } else if (const auto* t = c->as_table()) {
            const toml::node* count = t->get("latin_hypercube");
            const toml::node* seed = t->get("seed");
            const int64_t n = count && count->is_integer() ? count->as_integer()->get() : 0;
            const int64_t s = seed && seed->is_integer() ? seed->as_integer()->get() : -1;
            if (n < 1 || n > 100000 || s < 0 || t->size() != 2)
                throw ScenarioError(fmt::format("{}: expected {{ latin_hypercube = N, seed = S }} with N a whole number "
                                                "in [1, 100000] and S a whole number ≥ 0",
                                                where));
            plan.combine = "latin_hypercube";
            plan.hypercubePoints = size_t(n);
            plan.seed = uint64_t(s);
        } else {
            throw ScenarioError(fmt::format("{}: expected \"grid\", \"zip\" or {{ latin_hypercube = N, seed = S }}",
                                            where));
        }
    }
    // [vary], in the order of the file (toml++ keeps tables sorted by key).
    const toml::node* vary = root.get("vary");
    if (!vary || !vary->as_table() || vary->as_table()->empty())
        throw ScenarioError(fmt::format("{}: missing or empty [vary] table: expected keys mapped to lists or ranges, "
                                        "e.g. \"car.side_bearing_clearance\" = [\"0.125 in\", \"0.25 in\"]",
                                        path));
    std::vector<std::pair<const toml::node*, std::string>> entries;
    for (const auto& [k, n] : *vary->as_table()) entries.emplace_back(&n, std::string(k.str()));
    std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
        const auto& sa = a.first->source().begin;
        const auto& sb = b.first->source().begin;
        return sa.line != sb.line ? sa.line < sb.line : sa.column < sb.column;
    });
    for (const auto& [n, key] : entries) {
        plan.varied.push_back(readVaried(path, key, *n, plan.combine == "latin_hypercube"));
        for (const auto& other : plan.varied)
            if (&other != &plan.varied.back() && other.key == plan.varied.back().key)
                throw ScenarioError(fmt::format("{}:{}: [vary] \"{}\" is varied twice", path, plan.varied.back().line,
                                                other.key));
        for (const auto& s : plan.sets)
            if (s.key == plan.varied.back().key)
                throw ScenarioError(fmt::format("{}:{}: [vary] \"{}\" is also fixed by {}: expected one of them", path,
                                                plan.varied.back().line, s.key,
                                                s.key == "run.model" ? "model" : "[set]"));
        if (plan.kind == "sweep" && plan.varied.back().key == "run.speed")
            throw ScenarioError(fmt::format("{}:{}: [vary] \"run.speed\" in a study of kind \"sweep\": the sweep sets "
                                            "the speed ([sweep] from, to, step)",
                                            path, plan.varied.back().line));
    }
    // Every fixed and varied value through the loader, as a --set: the errors name the study line.
    for (size_t s = 0; s < plan.sets.size(); ++s) {
        try {
            parseScenario(plan.scenarioText, plan.scenarioPath, {plan.sets.begin(), plan.sets.begin() + long(s) + 1});
        } catch (const ScenarioError& e) {
            throw ScenarioError(fmt::format("{}:{}: \"{}\" = \"{}\": {}", path, setLines[s], plan.sets[s].key,
                                            plan.sets[s].value, e.what()));
        }
    }
    for (const VariedKey& v : plan.varied) {
        std::vector<StudyValue> checked = v.values;
        if (v.isRange && plan.combine == "latin_hypercube")
            checked = {makeNumberValue(v.from, v.unit), makeNumberValue(v.to, v.unit)};
        for (const StudyValue& value : checked) {
            std::vector<ScenarioOverride> o = plan.sets;
            o.push_back({v.key, value.text});
            try {
                checkScenario(parseScenario(plan.scenarioText, plan.scenarioPath, o));
            } catch (const ScenarioError& e) {
                throw ScenarioError(fmt::format("{}:{}: [vary] \"{}\" = \"{}\": {}", path, v.line, v.key, value.text,
                                                e.what()));
            }
        }
    }
    makePoints(plan);
    // Every combination, before anything runs (cross-checks between keys).
    std::set<std::string> ignored;
    for (size_t i = 0; i < plan.points.size(); ++i) {
        try {
            const Scenario sc = loadPointScenario(plan, i);
            checkScenario(sc);
            checkSwitchesApply(sc);
            for (const std::string& key : getIgnoredSettings(sc)) ignored.insert(key);
            if (plan.kind == "sweep") checkSweepSpecs(makePointSweeps(plan, sc));
        } catch (const ScenarioError& e) {
            throw ScenarioError(fmt::format("{}: point {} ({}): {}", path, i, describeStudyPoint(plan, i), e.what()));
        }
    }
    plan.ignoredSettings.assign(ignored.begin(), ignored.end());
    return plan;
}

Json makeStudyInfo(const StudyPlan& plan) {
    Json info;
    info["file"] = fs::path(plan.file).filename().string();
    info["sha256"] = plan.sha256;
    info["content"] = plan.content;
    info["scenario_file"] = fs::path(plan.scenarioPath).filename().string();
    info["scenario_sha256"] = calcSha256(plan.scenarioText);
    info["kind"] = plan.kind;
    info["combine"] = plan.combine;
    info["point_count"] = plan.points.size();
    info["ignored_settings"] = plan.ignoredSettings;
    info["rockroll_version"] = kVersion;
    info["git_commit"] = kGitCommit;
    return info;
}

Json makeVariedJson(const StudyPlan& plan) {
    Json varied = Json::array();
    for (const VariedKey& v : plan.varied) {
        Json values = Json::array();
        for (const StudyValue& s : v.values) values.push_back(s.shown);
        varied.push_back({{"key", v.key}, {"column", v.column}, {"unit", v.unit}, {"values", values}});
    }
    return varied;
}

namespace {
/// A run summary as the flat fields of sweep.csv (makeSweepRecords), without the
/// wall time: a study's results are the same on any machine and any shard.
Json makeFlatSummary(Json summary) {
    Json records = makeSweepRecords(Json::array({std::move(summary)}));
    Json r = records.at(0);
    r.erase("wall_time_s");
    return r;
}

/// The sweep-level fields of a study of kind "sweep" (docs/studies.md, "Output").
Json summarizeSweeps(const std::vector<std::vector<SweepPoint>>& sweeps, std::string& status) {
    size_t speeds = 0, failed = 0, severe = 0, criteriaFailed = 0;
    const SweepPoint* maxRoll = nullptr;
    double lift = 0, sideBearing = 0, centerPlate = 0, minRatio = INFINITY, lOverV = NAN, pitch = NAN, yaw = NAN,
           twist = NAN;
    auto keepLarger = [](double& best, double x) {
        if (!std::isnan(x)) best = std::isnan(best) ? x : std::max(best, x);
    };
    status = "ok";
    for (const auto& sweep : sweeps)
        for (const SweepPoint& p : sweep) {
            ++speeds;
            if (p.failed) {
                ++failed;
                continue;
            }
            const RunSummary& s = p.summary;
            if (!maxRoll || s.maxRollDeg > maxRoll->summary.maxRollDeg) maxRoll = &p;
            lift = std::max(lift, s.maxWheelLiftIn);
            sideBearing = std::max(sideBearing, s.maxSideBearingLoadLb);
            centerPlate = std::max(centerPlate, s.maxCenterPlateLoadLb);
            minRatio = std::min(minRatio, s.minWheelLoadRatio);
            keepLarger(lOverV, s.maxLOverV);
            keepLarger(pitch, s.maxPitchDeg);
            keepLarger(yaw, s.maxYawDeg);
            keepLarger(twist, s.maxCarBodyTwistDeg);
            severe += s.regime == "severe" ? 1 : 0;
            criteriaFailed += s.passesCriteria() ? 0 : 1;
            if ((s.regime == "derailed" || s.regime == "overturned") && status == "ok") status = s.regime;
        }
    if (failed) status = "failed";
    auto orNull = [](double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); };
    Json j;
    j["speeds"] = speeds;
    j["failed_speeds"] = failed;
    j["max_roll_deg"] = maxRoll ? Json(maxRoll->summary.maxRollDeg) : Json(nullptr);
    j["max_roll_speed_mph"] = maxRoll ? Json(maxRoll->speedMph) : Json(nullptr);
    j["max_roll_direction"] = maxRoll ? Json(maxRoll->direction) : Json(nullptr);
    j["max_wheel_lift_in"] = maxRoll ? Json(lift) : Json(nullptr);
    j["max_side_bearing_load_lb"] = maxRoll ? Json(sideBearing) : Json(nullptr);
    j["max_center_plate_load_lb"] = maxRoll ? Json(centerPlate) : Json(nullptr);
    j["min_wheel_load_ratio"] = orNull(minRatio);
    j["max_l_over_v"] = orNull(lOverV);
    j["max_pitch_deg"] = orNull(pitch);
    j["max_yaw_deg"] = orNull(yaw);
    j["max_car_body_twist_deg"] = orNull(twist);
    // Each direction's jump by the sweeps' one rule (scenarios/SpeedSweep.h, findSweepJump); null: none.
    double jump[2] = {NAN, NAN};
    for (const auto& sweep : sweeps) {
        if (sweep.empty()) continue;
        const bool up = sweep.front().direction == "up";
        jump[up ? 0 : 1] = findSweepJump(sweep, up ? SweepDirection::Up : SweepDirection::Down).speedMph;
    }
    j["jump_up_mph"] = orNull(jump[0]);
    j["jump_down_mph"] = orNull(jump[1]);
    j["severe_speeds"] = severe;
    j["criteria_failed_speeds"] = criteriaFailed;
    j["criteria_pass"] = failed == 0 && criteriaFailed == 0;
    return j;
}
}  // namespace

Json runStudyPoint(const StudyPlan& plan, size_t i) {
    Json point;
    point["point"] = i;
    Json values = Json::object();
    for (size_t k = 0; k < plan.varied.size(); ++k) values[plan.varied[k].column] = plan.points.at(i)[k].shown;
    point["values"] = values;
    std::string status = "ok", error;
    Json summary = Json::object();
    try {
        const Scenario sc = loadPointScenario(plan, i);
        if (plan.kind == "run") {
            const ScenarioRun run = runScenario(sc);
            summary = makeFlatSummary(makeRunJson(run, sc, ""));
            if (run.result.stop) status = run.result.stop->regime;
        } else {
            const auto sweeps = runSweeps(makePointSweeps(plan, sc), 1);
            summary = summarizeSweeps(sweeps, status);
            if (status == "failed") {
                for (const auto& sweep : sweeps)
                    for (const SweepPoint& p : sweep)
                        if (p.failed && error.empty())
                            error = fmt::format("{} mph {}: {}", p.speedMph, p.direction, p.error);
            }
        }
    } catch (const std::exception& e) {
        status = "failed";
        error = e.what();
        summary = Json::object();
    }
    point["status"] = status;
    if (!error.empty()) point["error"] = error;
    point["summary"] = summary;
    return point;
}

Json makeStudyJson(const Json& info, const Json& varied, size_t shardK, size_t shardN, std::vector<Json> points) {
    std::sort(points.begin(), points.end(),
              [](const Json& a, const Json& b) { return a.at("point").get<size_t>() < b.at("point").get<size_t>(); });
    Json j;
    j["study"] = info;
    j["varied"] = varied;
    j["shard"] = {{"k", shardK}, {"n", shardN}};
    j["points"] = Json(std::move(points));
    return j;
}

Json makeStudyRecords(const Json& study) {
    Json records = Json::array();
    for (const Json& p : study.at("points")) {
        Json r;
        r["point"] = p.at("point");
        for (const Json& v : study.at("varied")) {
            const std::string column = v.at("column").get<std::string>();
            r[column] = p.at("values").at(column);
        }
        r["status"] = p.at("status");
        for (const auto& [key, value] : p.at("summary").items()) r[key] = value;
        records.push_back(std::move(r));
    }
    return records;
}

Json mergeStudies(const std::vector<std::string>& dirs) {
    if (dirs.empty()) throw ScenarioError("merge: expected at least one shard directory");
    std::vector<Json> shards;
    for (const std::string& d : dirs) {
        const fs::path file = fs::path(d) / "study.json";
        std::ifstream in(file);
        if (!in) throw ScenarioError(fmt::format("merge: {}: cannot read; expected a study output directory", file.string()));
        Json j = Json::parse(in, nullptr, false);
        if (j.is_discarded() || !j.is_object() || !j.contains("study") || !j.contains("varied") || !j.contains("shard") ||
            !j.contains("points") || !j["points"].is_array())
            throw ScenarioError(fmt::format("merge: {}: not a rockroll study.json (expected study, varied, shard, "
                                            "points)",
                                            file.string()));
        shards.push_back(std::move(j));
    }
    const Json& first = shards.front();
    std::map<size_t, std::string> shardOf;   // shard k → directory
    std::map<size_t, std::string> pointOf;   // point → directory
    std::vector<Json> points;
    for (size_t s = 0; s < shards.size(); ++s) {
        const Json& j = shards[s];
        if (auto d = describeJsonDifference(first.at("study"), j.at("study")))
            throw ScenarioError(fmt::format("merge: {} and {} are shards of different studies: {}", dirs.front(),
                                            dirs[s], *d));
        if (auto d = describeJsonDifference(first.at("varied"), j.at("varied")))
            throw ScenarioError(fmt::format("merge: {} and {} vary different values: {}", dirs.front(), dirs[s], *d));
        const size_t k = getJsonInteger<size_t>(j.at("shard"), "k"), n = getJsonInteger<size_t>(j.at("shard"), "n");
        if (n != getJsonInteger<size_t>(first.at("shard"), "n"))
            throw ScenarioError(fmt::format("merge: {} is shard {}/{}, {} is shard {}/{}: expected shards of one split",
                                            dirs.front(), first["shard"]["k"].get<size_t>(),
                                            first["shard"]["n"].get<size_t>(), dirs[s], k, n));
        if (auto [it, added] = shardOf.emplace(k, dirs[s]); !added)
            throw ScenarioError(fmt::format("merge: {} and {} are both shard {}/{}", it->second, dirs[s], k, n));
        for (const Json& p : j.at("points")) {
            const size_t i = getJsonInteger<size_t>(p, "point");
            if (auto [it, added] = pointOf.emplace(i, dirs[s]); !added)
                throw ScenarioError(fmt::format("merge: point {} is in both {} and {}", i, it->second, dirs[s]));
            points.push_back(p);
        }
    }
    const size_t count = getJsonInteger<size_t>(first.at("study"), "point_count");
    std::vector<size_t> missing;
    for (size_t i = 0; i < count; ++i)
        if (!pointOf.count(i)) missing.push_back(i);
    if (!missing.empty()) {
        std::vector<size_t> shown(missing.begin(), missing.begin() + long(std::min<size_t>(missing.size(), 20)));
        const size_t n = getJsonInteger<size_t>(first.at("shard"), "n");
        std::vector<size_t> absent;
        for (size_t k = 1; k <= n; ++k)
            if (!shardOf.count(k)) absent.push_back(k);
        throw ScenarioError(fmt::format("merge: {} of the study's {} points missing: {}{}{}", missing.size(), count,
                                        fmt::join(shown, ", "), missing.size() > shown.size() ? ", ..." : "",
                                        absent.empty() ? std::string()
                                                       : fmt::format(" (no directory of shard {} of {})",
                                                                     fmt::join(absent, ", "), n)));
    }
    for (const auto& [i, dir] : pointOf)
        if (i >= count)
            throw ScenarioError(fmt::format("merge: {} holds point {}, beyond the study's {} points", dir, i, count));
    return makeStudyJson(first.at("study"), first.at("varied"), 1, 1, std::move(points));
}

}  // namespace rockroll::app
