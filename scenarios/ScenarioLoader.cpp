#include "scenarios/ScenarioLoader.h"

#include "scenarios/ModelRegistry.h"

#include "scenarios/BuiltinCars.h"
#include "scenarios/DefaultScenario.h"

#include <fmt/format.h>
#include <cmath>
#include <filesystem>
#include <fmt/ranges.h>
#include <fstream>
#include <set>
#include <sstream>
#include <openssl/evp.h>
#include <toml++/toml.h>

namespace rockroll {

namespace {

/// Reads typed values out of one TOML table, remembering which keys were used.
class TableReader {
public:
    TableReader(const toml::table* table, std::string source, std::string prefix)
        : table_(table), source_(std::move(source)), prefix_(std::move(prefix)) {}

    bool has(const std::string& key) const { return table_ && table_->contains(key); }

    [[noreturn]] void fail(const std::string& key, const std::string& value, const std::string& expected) const {
        throw ScenarioError(fmt::format("{}: key '{}{}' = {}: expected {}", source_, prefix_, key, value, expected));
    }

    double getQuantity(const std::string& key, units::Dimension dim) {
        const toml::node* n = require(key);
        if (dim == units::Dimension::Dimensionless) {
            if (auto v = n->value<double>()) return *v;
            fail(key, describe(*n), "a plain number");
        }
        const auto text = n->value<std::string>();
        if (!text)
            fail(key, describe(*n), fmt::format("a string \"<number> <unit>\" with a {} unit ({})",
                                                units::getDimensionName(dim), units::getAcceptedUnits(dim)));
        try {
            return units::parseQuantity(*text, dim);
        } catch (const std::invalid_argument& e) {
            fail(key, describe(*n), fmt::format("a {} ({})", units::getDimensionName(dim), e.what()));
        }
    }
    double getQuantity(const std::string& key, units::Dimension dim, double fallback) {
        return has(key) ? getQuantity(key, dim) : fallback;
    }
    std::string getString(const std::string& key, const std::set<std::string>& allowed) {
        const toml::node* n = require(key);
        const auto v = n->value<std::string>();
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        if (!v || !allowed.count(*v)) fail(key, describe(*n), "one of: " + list);
        return *v;
    }
    std::string getString(const std::string& key, const std::set<std::string>& allowed, std::string fallback) {
        return has(key) ? getString(key, allowed) : fallback;
    }
    std::string getText(const std::string& key, std::string fallback) {
        if (!has(key)) return fallback;
        const toml::node* n = require(key);
        if (auto v = n->value<std::string>()) return *v;
        fail(key, describe(*n), "a string");
    }
    bool getBool(const std::string& key, bool fallback) {
        if (!has(key)) return fallback;
        const toml::node* n = require(key);
        if (auto v = n->value<bool>()) return *v;
        fail(key, describe(*n), "true or false");
    }
    long getInt(const std::string& key, long fallback, long minimum) {
        if (!has(key)) return fallback;
        const toml::node* n = require(key);
        const auto v = n->value<int64_t>();
        if (!v || !n->is_integer() || *v < minimum) fail(key, describe(*n), fmt::format("an integer ≥ {}", minimum));
        return long(*v);
    }
    /// Every key present in the table that nobody read is an error.
    void rejectUnknown(const std::set<std::string>& alsoAllowed = {}) const {
        if (!table_) return;
        for (const auto& [k, v] : *table_) {
            const std::string key(k.str());
            if (!used_.count(key) && !alsoAllowed.count(key))
                fail(key, describe(v), "no such key here (misspelt or not supported)");
        }
    }
    static std::string describe(const toml::node& n) {
        std::ostringstream os;
        n.visit([&os](const auto& v) { os << v; });
        return os.str();
    }
    const toml::node* require(const std::string& key) {
        used_.insert(key);
        const toml::node* n = table_ ? table_->get(key) : nullptr;
        if (!n) fail(key, "(missing)", "this key to be present");
        return n;
    }

private:
    const toml::table* table_;
    std::string source_, prefix_;
    std::set<std::string> used_;
};

const toml::table* getTable(const toml::table& root, const std::string& name, const std::string& source,
                            bool required) {
    const toml::node* n = root.get(name);
    if (!n) {
        if (required) throw ScenarioError(fmt::format("{}: table [{}] is missing", source, name));
        return nullptr;
    }
    if (!n->is_table()) throw ScenarioError(fmt::format("{}: key '{}' must be a table [{}]", source, name, name));
    return n->as_table();
}

/// A car parameter's value must be finite, and positive unless zero means something.
void checkCarValue(const TableReader& reader, const std::string& key, const CarParameterInfo& info, double value,
                   const toml::node& given) {
    if (!std::isfinite(value) || value < 0 || (value == 0 && !info.mayBeZero))
        reader.fail(key, TableReader::describe(given), info.mayBeZero ? "a finite value ≥ 0" : "a finite positive value");
}

toml::table parseToml(std::string_view text, const std::string& source) {
    try {
        return toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        throw ScenarioError(fmt::format("{}:{}:{}: TOML syntax error: {}", source, e.source().begin.line,
                                        e.source().begin.column, e.description()));
    }
}

std::string readFile(const std::string& path, const char* what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ScenarioError(fmt::format("{}: cannot open {}", path, what));
    std::stringstream buf;
    buf << in.rdbuf();
    return buf.str();
}

/// A car file: name, description, and [parameters] with every parameter of the
/// table as { value = "<number> <unit>", source = "<where it comes from>" }.
CarParameters readCarFile(const toml::table& root, const std::string& src) {
    TableReader top(&root, src, "");
    CarParameters car;
    car.name = top.getText("name", "");
    if (car.name.empty()) top.fail("name", "(missing)", "the car's name, a non-empty string");
    top.getText("description", "");
    const toml::table* params = getTable(root, "parameters", src, true);
    TableReader reader(params, src, "parameters.");
    for (const CarParameterInfo& info : getCarParameterTable()) {
        const toml::node* n = reader.require(info.key);
        const toml::table* entry = n->as_table();
        if (!entry) reader.fail(info.key, TableReader::describe(*n), "a table { value = ..., source = \"...\" }");
        TableReader item(entry, src, fmt::format("parameters.{}.", info.key));
        const double value = item.getQuantity("value", info.dimension);
        checkCarValue(item, "value", info, value, *entry->get("value"));
        if (item.getText("source", "").empty())
            item.fail("source", "(missing)", "where the value comes from (report table, brief, assumed), a string");
        item.rejectUnknown();
        car.*(info.member) = value;
    }
    reader.rejectUnknown();
    top.rejectUnknown({"parameters"});
    return car;
}

void readCar(const toml::table& root, const std::string& src, Scenario& sc) {
    TableReader car(getTable(root, "car", src, true), src, "car.");
    const bool inline_ = !car.has("base") && !car.has("file");
    if (car.has("base") && car.has("file"))
        car.fail("file", TableReader::describe(*root.get("car")->as_table()->get("file")),
                 "either 'base' (a built-in car) or 'file' (a car file), not both");
    if (car.has("base")) {
        const auto names = getCarNames();
        sc.car = makeCarParameters(car.getString("base", {names.begin(), names.end()}));
    } else if (car.has("file")) {
        // Relative to the scenario file's folder.
        const std::filesystem::path given = car.getText("file", "");
        const std::filesystem::path path = given.is_absolute() ? given : std::filesystem::path(src).parent_path() / given;
        try {
            sc.car = loadCarFile(path.string());
        } catch (const ScenarioError& e) {
            throw ScenarioError(fmt::format("{}: key 'car.file' = \"{}\": {}", src, given.string(), e.what()));
        }
    } else {
        // A complete car inline (as formatScenarioToml writes it): its name and every parameter.
        sc.car = CarParameters{};
        if (!car.has("name"))
            car.fail("base", "(missing)", "'base' (a built-in car), 'file' (a car file) or a complete car with 'name'");
    }
    if (car.has("name")) {  // names the car (with base or file: a variant of it)
        sc.car.name = car.getText("name", "");
        if (sc.car.name.empty()) car.fail("name", "\"\"", "a non-empty string");
    }
    for (const auto& [k, v] : *root.get("car")->as_table()) {
        const CarParameterInfo* info = findCarParameter(k.str());
        if (!info) continue;  // base/file/name were read above; rejectUnknown reports the rest
        const double value = car.getQuantity(info->key, info->dimension);
        checkCarValue(car, info->key, *info, value, v);
        sc.car.*(info->member) = value;
        const auto text = v.value<std::string>();
        sc.carOverrides.emplace_back(info->key, text ? *text : TableReader::describe(v));
    }
    if (inline_)
        for (const CarParameterInfo& info : getCarParameterTable())
            if (!car.has(info.key)) car.require(info.key);  // names the first missing parameter
    car.rejectUnknown();
}

void readTrack(const toml::table& root, const std::string& src, Scenario& sc) {
    using units::Dimension;
    const toml::table* t = getTable(root, "track", src, true);
    TableReader track(t, src, "track.");
    sc.track.amplitude = track.getQuantity("amplitude", Dimension::Length);
    if (sc.track.amplitude < 0) track.fail("amplitude", fmt::format("{}", sc.track.amplitude), "a length ≥ 0");
    sc.track.railLength = track.getQuantity("rail_length", Dimension::Length);
    if (!(sc.track.railLength > 0)) track.fail("rail_length", "≤ 0", "a positive length");
    sc.track.rails = int(track.getInt("rails", 0, 0));
    sc.track.mirror = track.getBool("mirror", false);
    sc.entry = track.getString("entry", {"lead", "synchronized"}, "lead") == "lead" ? TrackEntry::Lead
                                                                                  : TrackEntry::Synchronized;
    if (track.has("measured")) {
        const toml::node* m = track.require("measured");
        const toml::array* arr = m->as_array();
        if (!arr || !arr->is_array_of_tables())
            track.fail("measured", TableReader::describe(*m), "an array of tables [[track.measured]]");
        for (size_t i = 0; i < arr->size(); ++i) {
            TableReader row(arr->get(i)->as_table(), src, fmt::format("track.measured[{}].", i));
            MeasuredTrackSample sample;
            sample.distance = row.getQuantity("distance", Dimension::Length);
            sample.crossLevel = row.getQuantity("cross_level", Dimension::Length);
            sample.profile = row.getQuantity("profile", Dimension::Length, 0.0);
            row.rejectUnknown();
            if (!sc.track.measured.empty() && !(sample.distance > sc.track.measured.back().distance))
                row.fail("distance", TableReader::describe(*arr->get(i)), "distances that increase strictly");
            sc.track.measured.push_back(sample);
        }
    }
    track.rejectUnknown();
}

void readRun(const toml::table& root, const std::string& src, Scenario& sc) {
    using units::Dimension;
    TableReader run(getTable(root, "run", src, true), src, "run.");
    sc.speed = run.getQuantity("speed", Dimension::Speed);
    if (!(sc.speed > 0)) run.fail("speed", "≤ 0", "a positive speed");
    sc.run.duration = run.getQuantity("duration", Dimension::Time);
    if (!(sc.run.duration > 0)) run.fail("duration", "≤ 0", "a positive time");
    const std::vector<std::string> models = ModelRegistry::get().getNames();
    sc.model = run.getString("model", std::set<std::string>(models.begin(), models.end()));
    sc.run.outputRate = run.getQuantity("output_rate", Dimension::Frequency, 500.0);
    sc.filterCutoffHz = run.getQuantity("filter_cutoff", Dimension::Frequency, 20.0);
    if (!(sc.filterCutoffHz < sc.run.outputRate / 2))
        run.fail("filter_cutoff", fmt::format("{} Hz", sc.filterCutoffHz), "a cut-off below half the output rate");
    run.rejectUnknown();

    TableReader integ(getTable(root, "integrator", src, true), src, "integrator.");
    const auto methods = getIntegratorNames();
    sc.run.integrator.method = integ.getString("method", {methods.begin(), methods.end()});
    sc.run.integrator.accuracy = integ.getQuantity("accuracy", Dimension::Dimensionless);
    if (!(sc.run.integrator.accuracy > 0 && sc.run.integrator.accuracy < 1))
        integ.fail("accuracy", fmt::format("{}", sc.run.integrator.accuracy), "a number in (0, 1)");
    sc.run.integrator.maxStepSize = integ.getQuantity("max_step", Dimension::Time, 0.0);
    integ.rejectUnknown();
}

void readEom(const toml::table& root, const std::string& src, Scenario& sc) {
    TableReader eom(getTable(root, "eom", src, false), src, "eom.");
    EomSimplifications& e = sc.eom;
    e.linearSprings = eom.getBool("linear_springs", false);
    e.lockBolsterLateral = eom.getBool("lock_bolster_lateral", false);
    e.elasticContacts = eom.getBool("elastic_contacts", false);
    e.equalLateralShares = eom.getBool("equal_lateral_shares", false);
    e.smallAngles = eom.getBool("small_angles", false);
    eom.rejectUnknown();
}

/// [limits]: the run monitor's physical limits (mbmodel/RunLimits.h) and the
/// severe-regime duration. Every key is optional and range-checked.
void readLimits(const toml::table& root, const std::string& src, Scenario& sc) {
    using units::Dimension;
    TableReader lim(getTable(root, "limits", src, false), src, "limits.");
    RunLimits& l = sc.run.limits;
    auto ranged = [&](const char* key, Dimension dim, double fallback, double lo, double hi, bool loOpen,
                      const std::string& expected) {
        if (!lim.has(key)) return fallback;
        const double v = lim.getQuantity(key, dim);
        if (!std::isfinite(v) || v > hi || v < lo || (loOpen && v == lo))
            lim.fail(key, TableReader::describe(*lim.require(key)), expected);
        return v;
    };
    l.enabled = lim.getBool("enabled", l.enabled);
    l.flangeHeight = ranged("flange_height", Dimension::Length, l.flangeHeight, 0, 3 * units::inch, true,
                            "a length in (0, 3 in]");
    l.flangeClearance = ranged("flange_clearance", Dimension::Length, l.flangeClearance, 0, 3 * units::inch, false,
                               "a length in [0, 3 in]");
    l.wheelsOffTime = ranged("wheels_off_time", Dimension::Time, l.wheelsOffTime, 0, 10, true,
                             "a time in (0, 10 s] (omit it for the flanges' free-flight time)");
    l.rolloverAngle = ranged("rollover_angle", Dimension::Angle, l.rolloverAngle, 0, 90 * units::degree, true,
                             "an angle in (0, 90 deg] (omit it for the static rollover angle of the car)");
    l.energyRunawayFraction = ranged("energy_runaway_fraction", Dimension::Dimensionless, l.energyRunawayFraction,
                                     0, 100, true, "a number in (0, 100]");
    l.maxWallTime = ranged("max_wall_time", Dimension::Time, l.maxWallTime, 0, 7 * 86400, true,
                           "a time in (0 s, 7 days]");
    sc.severeSeparationTime = ranged("severe_separation", Dimension::Time, sc.severeSeparationTime, 0, 1, false,
                                     "a time in [0, 1 s]");
    lim.rejectUnknown();
}

/// A TOML boolean only (toml++ would read 0 or 1 as a bool).
bool getStrictBool(TableReader& table, const std::string& key, bool fallback) {
    if (table.has(key) && !table.require(key)->is_boolean())
        table.fail(key, TableReader::describe(*table.require(key)), "true or false");
    return table.getBool(key, fallback);
}

void readReduced(const toml::table& root, const std::string& src, Scenario& sc) {
    TableReader reduced(getTable(root, "reduced", src, false), src, "reduced.");
    sc.reduced.truckWeight = getStrictBool(reduced, "truck_weight", false);
    reduced.rejectUnknown();
}

void readAttribution(const toml::table& root, const std::string& src, Scenario& sc) {
    TableReader attribution(getTable(root, "attribution", src, false), src, "attribution.");
    sc.attribution.truckGravity = getStrictBool(attribution, "truck_gravity", true);
    if (attribution.has("truck_mass_scale")) {
        const double f = attribution.getQuantity("truck_mass_scale", units::Dimension::Dimensionless);
        if (!(f >= 0.001 && f <= 1))
            attribution.fail("truck_mass_scale", fmt::format("{}", f), "a plain number in [0.001, 1]");
        sc.attribution.truckMassScale = f;
    }
    attribution.rejectUnknown();
}

/// [criteria]: limits of the summary's freight criteria (mbmodel/RunSummary.h,
/// CriteriaLimits); every key optional, each a positive finite limit.
void readCriteria(const toml::table& root, const std::string& src, Scenario& sc) {
    using units::Dimension;
    TableReader table(getTable(root, "criteria", src, false), src, "criteria.");
    CriteriaLimits& c = sc.criteria;
    auto ranged = [&](const char* key, Dimension dim, double fallback, double hi, const std::string& expected) {
        if (!table.has(key)) return fallback;
        const double v = table.getQuantity(key, dim);
        if (!std::isfinite(v) || v <= 0 || v > hi) table.fail(key, TableReader::describe(*table.require(key)), expected);
        return v;
    };
    // Echoed in degrees without the conversion's round-off.
    c.rollPeakToPeakDeg = std::round(ranged("roll_peak_to_peak", Dimension::Angle, c.rollPeakToPeakDeg * units::degree,
                                            90 * units::degree, "an angle in (0, 90 deg]") /
                                     units::degree * 1e9) / 1e9;
    c.wheelUnloading = ranged("wheel_unloading", Dimension::Dimensionless, c.wheelUnloading, 1,
                              "a plain number in (0, 1]: (static - load) / static");
    c.lOverV = ranged("l_over_v", Dimension::Dimensionless, c.lOverV, 10, "a plain number in (0, 10]");
    c.carBodyVerticalAccelG = ranged("car_body_vertical_accel_g", Dimension::Dimensionless, c.carBodyVerticalAccelG,
                                     10, "a plain number of g in (0, 10]");
    c.carBodyLateralAccelG = ranged("car_body_lateral_accel_g", Dimension::Dimensionless, c.carBodyLateralAccelG, 10,
                                    "a plain number of g in (0, 10]");
    table.rejectUnknown();
}

}  // namespace

const std::vector<std::string>& getScenarioKeys() {
    static const std::vector<std::string> keys = [] {
        // Every key the read* functions above accept, table by table. The test
        // ScenarioOverrides.SchemaIsWhatTheLoaderReadsAndTheWriterWrites keeps this list,
        // the readers and formatScenarioToml in step.
        std::vector<std::string> k{"description", "car.base", "car.file", "car.name"};
        for (const CarParameterInfo& info : getCarParameterTable()) k.push_back(std::string("car.") + info.key);
        for (const char* key :
             {"track.amplitude", "track.rail_length", "track.rails", "track.mirror", "track.entry", "run.speed",
              "run.duration", "run.model", "run.output_rate", "run.filter_cutoff", "integrator.method",
              "integrator.accuracy", "integrator.max_step", "eom.linear_springs", "eom.lock_bolster_lateral",
              "eom.elastic_contacts", "eom.equal_lateral_shares", "eom.small_angles", "limits.enabled",
              "limits.flange_height", "limits.flange_clearance", "limits.wheels_off_time", "limits.rollover_angle",
              "limits.energy_runaway_fraction", "limits.max_wall_time", "limits.severe_separation",
              "reduced.truck_weight", "attribution.truck_gravity", "attribution.truck_mass_scale",
              "criteria.roll_peak_to_peak", "criteria.wheel_unloading", "criteria.l_over_v",
              "criteria.car_body_vertical_accel_g", "criteria.car_body_lateral_accel_g"})
            k.push_back(key);
        return k;
    }();
    return keys;
}

namespace {
std::string_view trim(std::string_view s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string_view::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::string joinKeys(const std::vector<std::string>& keys, const char* separator) {
    std::string out;
    for (const auto& k : keys) out += (out.empty() ? "" : separator) + k;
    return out;
}
}  // namespace

ScenarioOverride parseScenarioOverride(std::string_view text) {
    const auto eq = text.find('=');
    if (eq == std::string_view::npos || trim(text.substr(0, eq)).empty())
        throw ScenarioError(fmt::format("override '{}': expected KEY=VALUE, e.g. car.side_bearing_clearance=0.25 in",
                                        text));
    return {std::string(trim(text.substr(0, eq))), std::string(trim(text.substr(eq + 1)))};
}

std::string resolveScenarioKey(const std::string& key, OverrideKeys mode, const std::vector<std::string>& keys) {
    for (const auto& k : keys)
        if (k == key) return k;
    std::vector<std::string> named;
    if (mode == OverrideKeys::AllowBare && key.find('.') == std::string::npos)
        for (const auto& k : keys) {
            const auto dot = k.rfind('.');
            if ((dot == std::string::npos ? k : k.substr(dot + 1)) == key) named.push_back(k);
        }
    if (named.size() == 1) return named.front();
    if (named.size() > 1)
        throw ScenarioError(fmt::format("override key '{}' is ambiguous: it names {}; give the full key", key,
                                        joinKeys(named, " and ")));
    throw ScenarioError(fmt::format("override key '{}': no such scenario key; accepted keys: {}{}", key,
                                    joinKeys(keys, ", "),
                                    mode == OverrideKeys::AllowBare
                                        ? " (or the last part of one of them alone, when it names only that key)"
                                        : ""));
}

namespace {
/// `root` with `overrides` applied: each value text becomes the TOML value it spells, or a string.
void applyOverrides(toml::table& root, const std::vector<ScenarioOverride>& overrides, OverrideKeys mode,
                    const std::string& source, Scenario& sc) {
    for (const ScenarioOverride& o : overrides) {
        const std::string key = resolveScenarioKey(o.key, mode);
        const auto dot = key.find('.');
        toml::table* table = &root;
        if (dot != std::string::npos) {
            const std::string name = key.substr(0, dot);
            if (!root.contains(name)) root.insert(name, toml::table{});
            table = root.get(name)->as_table();
            if (!table) throw ScenarioError(fmt::format("{}: key '{}' must be a table [{}]", source, name, name));
        }
        const std::string leaf = dot == std::string::npos ? key : key.substr(dot + 1);
        bool placed = false;
        try {
            const toml::table parsed = toml::parse("v = " + o.value);
            const toml::node* v = parsed.get("v");
            if (parsed.size() == 1 && v) {
                v->visit([&](const auto& node) { table->insert_or_assign(leaf, node); });
                placed = true;
            }
        } catch (const toml::parse_error&) {
        }
        if (!placed) table->insert_or_assign(leaf, o.value);
        sc.overrides.emplace_back(key, o.value);
    }
}
}  // namespace

Scenario parseScenario(std::string_view text, const std::string& source) { return parseScenario(text, source, {}); }

Scenario parseScenario(std::string_view text, const std::string& source, const std::vector<ScenarioOverride>& overrides,
                       OverrideKeys mode) {
    toml::table root = parseToml(text, source);
    Scenario sc;
    sc.source = source;
    applyOverrides(root, overrides, mode, source, sc);
    TableReader top(&root, source, "");
    sc.description = top.getText("description", "");
    readCar(root, source, sc);
    readTrack(root, source, sc);
    readRun(root, source, sc);
    readEom(root, source, sc);
    readLimits(root, source, sc);
    readReduced(root, source, sc);
    readAttribution(root, source, sc);
    readCriteria(root, source, sc);
    for (const char* t : {"car", "track", "run", "integrator"}) top.require(t);
    top.rejectUnknown({"eom", "limits", "reduced", "attribution", "criteria"});
    return sc;
}

Scenario loadScenarioFile(const std::string& path) { return loadScenarioFile(path, {}); }

Scenario loadScenarioFile(const std::string& path, const std::vector<ScenarioOverride>& overrides, OverrideKeys mode) {
    const std::string text = readFile(path, "scenario file");
    Scenario sc = parseScenario(text, path, overrides, mode);
    sc.sourceSha256 = calcSha256(text);
    return sc;
}

CarParameters parseCarFile(std::string_view text, const std::string& source) {
    return readCarFile(parseToml(text, source), source);
}

CarParameters loadCarFile(const std::string& path) { return parseCarFile(readFile(path, "car file"), path); }

std::vector<std::string> getCarNames() {
    std::vector<std::string> names;
    for (const auto& c : kBuiltinCars) names.emplace_back(c.name);
    return names;
}

CarParameters makeCarParameters(std::string_view carName) {
    for (const auto& c : kBuiltinCars)
        if (carName == c.name) {
            CarParameters car = parseCarFile(c.toml, fmt::format("<built-in car: scenarios/cars/{}.toml>", c.name));
            if (car.name != c.name)
                throw ScenarioError(fmt::format("scenarios/cars/{}.toml: key 'name' = \"{}\": expected \"{}\" (the file's name)",
                                                c.name, car.name, c.name));
            return car;
        }
    throw ScenarioError(fmt::format("unknown car \"{}\"; expected one of: {}", carName, fmt::join(getCarNames(), ", ")));
}

Scenario getDefaultScenario() {
    Scenario sc = parseScenario(kDefaultScenarioToml, "<embedded default: 70ton-loaded.toml>");
    sc.sourceSha256 = calcSha256(kDefaultScenarioToml);
    return sc;
}

std::string calcSha256(std::string_view bytes) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int n = 0;
    if (!EVP_Digest(bytes.data(), bytes.size(), digest, &n, EVP_sha256(), nullptr))
        throw std::runtime_error("SHA-256 failed (OpenSSL EVP_Digest)");
    std::string hex;
    for (unsigned int i = 0; i < n; ++i) hex += fmt::format("{:02x}", digest[i]);
    return hex;
}

namespace {
/// SI value with the SI unit whose factor is exactly 1, shortest round-trip digits.
std::string formatSi(double value, units::Dimension dim) {
    using units::Dimension;
    const char* unit = "";
    switch (dim) {
        case Dimension::Length: unit = "m"; break;
        case Dimension::Speed: unit = "m/s"; break;
        case Dimension::Force: unit = "N"; break;
        case Dimension::Stiffness: unit = "N/m"; break;
        case Dimension::Time: unit = "s"; break;
        case Dimension::Frequency: unit = "Hz"; break;
        case Dimension::MomentOfInertia: unit = "kg*m^2"; break;
        case Dimension::Angle: unit = "rad"; break;
        case Dimension::AngularStiffness: unit = "N*m/rad"; break;
        case Dimension::Dimensionless: break;
    }
    return fmt::format("{} {}", value, unit);
}
}  // namespace

std::string formatScenarioToml(const Scenario& sc) {
    using units::Dimension;
    toml::table root;
    if (!sc.description.empty()) root.insert("description", sc.description);
    toml::table car;  // the complete car inline, so the document does not depend on a car file
    car.insert("name", sc.car.name);
    for (const CarParameterInfo& info : getCarParameterTable()) {
        const double v = sc.car.*(info.member);
        if (info.dimension == Dimension::Dimensionless) car.insert(info.key, v);
        else car.insert(info.key, formatSi(v, info.dimension));
    }
    root.insert("car", std::move(car));

    toml::table track;
    track.insert("amplitude", formatSi(sc.track.amplitude, Dimension::Length));
    track.insert("rail_length", formatSi(sc.track.railLength, Dimension::Length));
    track.insert("rails", int64_t(sc.track.rails));
    track.insert("mirror", sc.track.mirror);
    track.insert("entry", sc.entry == TrackEntry::Lead ? "lead" : "synchronized");
    if (!sc.track.measured.empty()) {
        toml::array rows;
        for (const MeasuredTrackSample& m : sc.track.measured)
            rows.push_back(toml::table{{"distance", formatSi(m.distance, Dimension::Length)},
                                       {"cross_level", formatSi(m.crossLevel, Dimension::Length)},
                                       {"profile", formatSi(m.profile, Dimension::Length)}});
        track.insert("measured", std::move(rows));
    }
    root.insert("track", std::move(track));

    toml::table run;
    run.insert("speed", formatSi(sc.speed, Dimension::Speed));
    run.insert("duration", formatSi(sc.run.duration, Dimension::Time));
    run.insert("model", sc.model);
    run.insert("output_rate", formatSi(sc.run.outputRate, Dimension::Frequency));
    run.insert("filter_cutoff", formatSi(sc.filterCutoffHz, Dimension::Frequency));
    root.insert("run", std::move(run));

    toml::table integ;
    integ.insert("method", sc.run.integrator.method);
    integ.insert("accuracy", sc.run.integrator.accuracy);
    integ.insert("max_step", formatSi(sc.run.integrator.maxStepSize, Dimension::Time));
    root.insert("integrator", std::move(integ));

    root.insert("eom", toml::table{{"linear_springs", sc.eom.linearSprings},
                                   {"lock_bolster_lateral", sc.eom.lockBolsterLateral},
                                   {"elastic_contacts", sc.eom.elasticContacts},
                                   {"equal_lateral_shares", sc.eom.equalLateralShares},
                                   {"small_angles", sc.eom.smallAngles}});

    root.insert("reduced", toml::table{{"truck_weight", sc.reduced.truckWeight}});
    root.insert("attribution", toml::table{{"truck_gravity", sc.attribution.truckGravity},
                                           {"truck_mass_scale", sc.attribution.truckMassScale}});

    const RunLimits& l = sc.run.limits;
    toml::table limits{{"enabled", l.enabled},
                       {"flange_height", formatSi(l.flangeHeight, Dimension::Length)},
                       {"flange_clearance", formatSi(l.flangeClearance, Dimension::Length)},
                       {"energy_runaway_fraction", l.energyRunawayFraction},
                       {"max_wall_time", formatSi(l.maxWallTime, Dimension::Time)},
                       {"severe_separation", formatSi(sc.severeSeparationTime, Dimension::Time)}};
    // Zero means "from the car": leave it out so the default is derived again.
    if (l.wheelsOffTime > 0) limits.insert("wheels_off_time", formatSi(l.wheelsOffTime, Dimension::Time));
    if (l.rolloverAngle > 0) limits.insert("rollover_angle", formatSi(l.rolloverAngle, Dimension::Angle));
    root.insert("limits", std::move(limits));
    root.insert("criteria", toml::table{{"roll_peak_to_peak", fmt::format("{} deg", sc.criteria.rollPeakToPeakDeg)},
                                        {"wheel_unloading", sc.criteria.wheelUnloading},
                                        {"l_over_v", sc.criteria.lOverV},
                                        {"car_body_vertical_accel_g", sc.criteria.carBodyVerticalAccelG},
                                        {"car_body_lateral_accel_g", sc.criteria.carBodyLateralAccelG}});

    std::ostringstream os;
    os << toml::toml_formatter(root, toml::format_flags::none);
    return os.str() + "\n";
}

}  // namespace rockroll
