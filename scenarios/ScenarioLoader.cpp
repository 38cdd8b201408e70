#include "scenarios/ScenarioLoader.h"
#include "scenarios/ScenarioSchema.h"
#include "scenarios/TomlInput.h"

#include "scenarios/ModelRegistry.h"

#include "scenarios/BuiltinCars.h"
#include "scenarios/DefaultScenario.h"

#include <fmt/format.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fmt/ranges.h>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <openssl/evp.h>

namespace rockroll {

namespace {
/// The unit's factor to SI ("mph" → 0.44704); 1 for a plain number.
double getUnitFactor(units::Dimension dim, std::string_view unit) {
    return dim == units::Dimension::Dimensionless ? 1.0 : units::parseQuantity(fmt::format("1 {}", unit), dim);
}

/// The accepted ranges [SI]: the schema's numbers (scenarios/ScenarioSchema.h), then the
/// car parameters: finite, and positive unless zero means something (no clearance, no damping)
/// or the parameter is a signed offset.
std::vector<ValueRange> makeValueRanges() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::vector<ValueRange> r;
    for (const ScenarioField& f : getScenarioSchema())
        if (f.kind == FieldKind::Quantity || f.kind == FieldKind::Integer)
            r.push_back({f.key, f.dimension, f.low, f.high, f.lowOpen, f.highOpen, f.unit, f.kind == FieldKind::Integer});
    for (const CarParameterInfo& info : getCarParameterTable())
        r.push_back({std::string("car.") + info.key, info.dimension, info.isSigned ? -inf : 0, inf,
                     !info.mayBeZero || info.isSigned, true, info.displayUnit, info.integer});
    return r;
}

std::string formatNumber(double v) { return fmt::format("{:.6g}", v); }
}  // namespace

toml::table parseToml(std::string_view text, const std::string& source) {
    try {
        return toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        throw ScenarioError(fmt::format("{}:{}:{}: TOML syntax error: {}", source, e.source().begin.line,
                                        e.source().begin.column, e.description()));
    }
}

bool ValueRange::contains(double si) const {
    if (!std::isfinite(si)) return false;
    if (integer && si != std::floor(si)) return false;
    return (lowOpen ? si > low : si >= low) && (highOpen ? si < high : si <= high);
}

std::string ValueRange::format(double si) const {
    const double f = getUnitFactor(dimension, unit);
    return unit.empty() ? formatNumber(si / f) : fmt::format("{} {}", formatNumber(si / f), unit);
}

std::string ValueRange::describe() const {
    const std::string_view name = units::getDimensionName(dimension);
    const std::string what = integer ? "an integer"
                             : dimension == units::Dimension::Dimensionless
                                 ? "a number"
                                 : fmt::format("{} {}", std::string_view("aeiou").find(name[0]) == std::string_view::npos ? "a" : "an", name);
    if (std::isinf(low) && std::isinf(high)) return fmt::format("{} (finite)", what);
    if (std::isinf(high)) return fmt::format("{} {} {} (finite)", what, lowOpen ? ">" : "≥", format(low));
    return fmt::format("{} in {}{}, {}{}", what, lowOpen ? "(" : "[", format(low), format(high), highOpen ? ")" : "]");
}

const std::vector<ValueRange>& getValueRanges() {
    static const std::vector<ValueRange> ranges = makeValueRanges();
    return ranges;
}

const ValueRange& getValueRange(std::string_view key) {
    for (const ValueRange& r : getValueRanges())
        if (r.key == key) return r;
    throw std::out_of_range(fmt::format("no declared range for scenario key '{}'", key));
}

namespace {
/// A run's summary needs a few recorded samples (mbmodel/RunSummary.cpp).
void checkSampleCount(const std::string& source, double duration, double outputRate) {
    constexpr double kMinIntervals = 4;
    if (!(duration * outputRate >= kMinIntervals))
        throw ScenarioError(fmt::format("{}: key 'run.duration' = {} s at run.output_rate = {} Hz: expected at least {} "
                                        "output intervals, a duration ≥ {} s",
                                        source, duration, outputRate, kMinIntervals, kMinIntervals / outputRate));
}
}  // namespace

CriteriaLimits resolveCriteriaLimits(const Scenario& sc) {
    CriteriaLimits l = sc.criteria;
    if (l.lOverV == 0) l.lOverV = calcNadalLimit(sc.wheelRail.flangeAngle, sc.wheelRail.friction);
    return l;
}

namespace {
/// The car's cross-checks, for a model with two trucks (one that uses the truck spacing): its
/// trucks within its length, its CG between the truck centres and inside the rails
/// (docs/model.md, "Off-centre lading").
void checkCarGeometry(const Scenario& sc) {
    const ModelDescriptor* model = ModelRegistry::get().find(sc.model);
    if (model && !model->usesSetting("car.truck_spacing")) return;
    const CarParameters& c = sc.car;
    const double in = units::inch, ft = units::foot;
    const double m = c.getCarBodyWeight() / units::g;
    if (!(m > 0))
        throw ScenarioError(fmt::format("{}: key 'car.body_and_bolsters_weight' = {:.6g} lb: expected more than the two "
                                        "bolsters' weight, 2 x car.bolster_weight = {:.6g} lb",
                                        sc.source, c.bodyAndBolstersWeight / units::lbf, 2 * c.bolsterWeight / units::lbf));
    // The car's length: the uniform beam of the body's pitch inertia (docs/model.md, "Car-body torsion").
    const double length = std::sqrt(12 * c.pitchInertia / m);
    if (c.truckSpacing + c.wheelbase > length)
        throw ScenarioError(fmt::format(
            "{}: key 'car.truck_spacing' = {:.6g} ft: expected the outer wheelsets within the car body's length, "
            "truck_spacing + wheelbase ({:.6g} in) <= {:.4g} ft (the uniform beam of its pitch inertia, "
            "sqrt(12 x pitch_inertia / mass))",
            sc.source, c.truckSpacing / ft, c.wheelbase / in, length / ft));
    if (!(std::abs(c.cgLongitudinalOffset) < c.truckSpacing / 2))
        throw ScenarioError(fmt::format("{}: key 'car.cg_longitudinal_offset' = {:.6g} in: expected the car body's CG "
                                        "between the truck centres, |offset| < truck_spacing / 2 = {:.6g} in",
                                        sc.source, c.cgLongitudinalOffset / in, c.truckSpacing / 2 / in));
    if (!(std::abs(c.cgLateralOffset) < c.gauge / 2))
        throw ScenarioError(fmt::format("{}: key 'car.cg_lateral_offset' = {:.6g} in: expected the car body's CG inside "
                                        "the rails, |offset| < gauge / 2 = {:.6g} in",
                                        sc.source, c.cgLateralOffset / in, c.gauge / 2 / in));
}
}  // namespace

void checkScenario(const Scenario& sc) {
    auto check = [&sc](const std::string& key, double value) {
        const ValueRange& range = getValueRange(key);
        if (!range.contains(value))
            throw ScenarioError(fmt::format("{}: key '{}' = {}: expected {}", sc.source, key, range.format(value),
                                            range.describe()));
    };
    for (const CarParameterInfo& info : getCarParameterTable())
        check(std::string("car.") + info.key, sc.car.*(info.member));
    for (const ScenarioField& f : getScenarioSchema()) {
        if (f.kind != FieldKind::Quantity && f.kind != FieldKind::Integer) continue;
        const double v = f.getNumber(sc);
        if (f.zeroIsDerived && v == 0) continue;
        check(f.key, v);
    }
    checkCarGeometry(sc);
    if (!(sc.filterCutoffHz < sc.run.outputRate / 2))
        throw ScenarioError(fmt::format("{}: key 'run.filter_cutoff' = {} Hz: expected a cut-off below the Nyquist "
                                        "frequency, half the output rate ({} Hz)",
                                        sc.source, sc.filterCutoffHz, sc.run.outputRate / 2));
    checkSampleCount(sc.source, sc.run.duration, sc.run.outputRate);
}

void checkMemoryEstimate(const Scenario& sc, size_t channels) {
    const double bytes = estimateHistoryBytes(sc.run.duration, sc.run.outputRate, channels);
    const double limit = getMemoryLimitBytes();
    if (bytes > limit)
        throw ScenarioError(fmt::format(
            "{}: run.duration = {} s at run.output_rate = {} Hz records {:.0f} samples x {} channels, about {:.0f} MiB "
            "of history: expected at most {:.0f} MiB (ROCKROLL_MAX_MEMORY_MB); shorten the run or lower the output rate",
            sc.source, sc.run.duration, sc.run.outputRate, std::floor(sc.run.duration * sc.run.outputRate) + 1,
            channels + 1, bytes / (1024.0 * 1024.0), limit / (1024.0 * 1024.0)));
}

namespace {

/// Reads typed values out of one TOML table, remembering which keys were used.
class TableReader {
public:
    TableReader(const toml::table* table, std::string source, std::string prefix)
        : table_(table), source_(std::move(source)), prefix_(std::move(prefix)) {}

    bool has(const std::string& key) const { return table_ && table_->contains(key); }

    [[noreturn]] void fail(const std::string& key, const std::string& value, const std::string& expected) const {
        throw ScenarioError(fmt::format("{}: key '{}{}' = {}: expected {}", locate(key), prefix_, key, value, expected));
    }
    /// "file:line" of the key (or of its table when it is missing); the file alone for a
    /// value an override put there (it has no line).
    std::string locate(const std::string& key) const {
        const toml::node* n = table_ ? table_->get(key) : nullptr;
        const toml::source_region& at = n ? n->source() : table_ ? table_->source() : toml::source_region{};
        return at.begin.line > 0 ? fmt::format("{}:{}", source_, at.begin.line) : source_;
    }
    /// A value of `key` (prefix + key is a key of getValueRanges) within its declared range.
    double getRanged(const std::string& key) {
        const ValueRange& range = getValueRange(prefix_ + key);
        if (range.integer && !require(key)->is_integer()) fail(key, describe(*require(key)), range.describe());
        const double v = range.integer ? double(*require(key)->value<int64_t>()) : getQuantity(key, range.dimension);
        if (!range.contains(v)) fail(key, describe(*require(key)), range.describe());
        return v;
    }
    double getRanged(const std::string& key, double fallback) { return has(key) ? getRanged(key) : fallback; }

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
    /// A TOML boolean only (toml++'s value<bool>() would also take 0 or 1).
    bool getBool(const std::string& key, bool fallback) {
        if (!has(key)) return fallback;
        const toml::node* n = require(key);
        if (n->is_boolean()) return *n->value<bool>();
        fail(key, describe(*n), "true or false");
    }
    /// Every key present in the table that nobody read is an error.
    void rejectUnknown(const std::set<std::string>& alsoAllowed = {}) const {
        if (!table_) return;
        for (const auto& [k, v] : *table_) {
            const std::string key(k.str());
            if (used_.count(key) || alsoAllowed.count(key)) continue;
            if (const char* renamed = findRenamedKey(prefix_ + key))
                fail(key, describe(v), fmt::format("its new name, '{}'", renamed));
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

/// A car parameter's value must be within its declared range: finite, and positive unless zero means something.
void checkCarValue(const TableReader& reader, const std::string& key, const CarParameterInfo& info, double value,
                   const toml::node& given) {
    const ValueRange& range = getValueRange(std::string("car.") + info.key);
    if (!range.contains(value)) reader.fail(key, TableReader::describe(given), range.describe());
}


/// A scalar field's default (ScenarioField::defaultText) into sc.
void applyDefault(const ScenarioField& f, Scenario& sc) {
    switch (f.kind) {
        case FieldKind::Quantity:
            f.setNumber(sc, f.dimension == units::Dimension::Dimensionless ? std::stod(f.defaultText)
                                                                          : units::parseQuantity(f.defaultText, f.dimension));
            break;
        case FieldKind::Integer: f.setNumber(sc, std::stod(f.defaultText)); break;
        case FieldKind::Flag: f.setFlag(sc, std::string_view(f.defaultText) == "true"); break;
        case FieldKind::Choice: f.setText(sc, f.defaultText); break;
        case FieldKind::Structured: break;
    }
}

/// Every scalar field of the schema in TOML table `table`, read from `reader` (range,
/// type and choices checked) or, when left out, its default.
void readFields(TableReader& reader, const std::string& table, Scenario& sc) {
    for (const ScenarioField& f : getScenarioSchema()) {
        if (f.kind == FieldKind::Structured || f.getTable() != table) continue;
        const std::string name = f.getName();
        if (!reader.has(name)) {
            applyDefault(f, sc);
            continue;
        }
        switch (f.kind) {
            case FieldKind::Quantity:
            case FieldKind::Integer: f.setNumber(sc, reader.getRanged(name)); break;
            case FieldKind::Flag: f.setFlag(sc, reader.getBool(name, false)); break;
            case FieldKind::Choice: {
                const std::vector<std::string> choices = f.getChoices();
                f.setText(sc, reader.getString(name, {choices.begin(), choices.end()}));
                break;
            }
            case FieldKind::Structured: break;
        }
    }
}

/// A table whose every key is a scalar field of the schema.
void readFieldTable(const toml::table& root, const std::string& table, const std::string& src, Scenario& sc) {
    TableReader reader(getTable(root, table, src, false), src, table + ".");
    readFields(reader, table, sc);
    reader.rejectUnknown();
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
            item.fail("source", "(missing)", "where the value comes from (report table, derived, assumed), a string");
        item.rejectUnknown();
        car.*(info.member) = value;
    }
    reader.rejectUnknown();
    top.rejectUnknown({"parameters"});
    return car;
}

void readCar(const toml::table& root, const std::string& src, Scenario& sc) {
    const toml::table* table = getTable(root, "car", src, false);
    TableReader car(table, src, "car.");
    const bool inline_ = !car.has("base") && !car.has("file") && car.has("name");
    if (car.has("base") && car.has("file"))
        car.fail("file", TableReader::describe(*table->get("file")),
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
    } else if (inline_) {
        // A complete car inline (as formatScenarioToml writes it): its name and every parameter.
        sc.car = CarParameters{};
    } else {
        sc.car = makeCarParameters(findScenarioField("car.base")->defaultText);
    }
    if (car.has("name")) {  // names the car (with base or file: a variant of it)
        sc.car.name = car.getText("name", "");
        if (sc.car.name.empty()) car.fail("name", "\"\"", "a non-empty string");
    }
    for (const auto& [k, v] : table ? *table : toml::table{}) {
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
    const toml::table* t = getTable(root, "track", src, false);
    TableReader track(t, src, "track.");
    const bool measured = track.has("file") || track.has("measured");
    const std::string file = track.getText("file", "");  // its type first
    if (track.has("file") && file.empty()) track.fail("file", "\"\"", "a track CSV path, relative to the scenario");
    if (track.has("file") && track.has("measured"))
        track.fail("file", TableReader::describe(*t->get("file")),
                   "either 'file' (a track CSV) or [[track.measured]] rows, not both");
    if (track.has("file"))
        for (const char* sine : {"amplitude", "rails"})
            if (track.has(sine))
                track.fail(sine, TableReader::describe(*t->get(sine)),
                           "no rectified-sine key with 'file' (the measured track replaces the sine)");
    readFields(track, "track", sc);
    if (measured && !track.has("amplitude")) sc.track.amplitude = 0;  // a measured track replaces the sine
    // A measured table's run-in/run-out when not level at its ends, and whether it repeats (mbmodel/TrackInput.h).
    sc.track.taper = track.getQuantity("taper", Dimension::Length,
                                       units::parseQuantity(kDefaultTaperText, Dimension::Length));
    if (!(sc.track.taper > 0) || !std::isfinite(sc.track.taper))
        track.fail("taper", TableReader::describe(*t->get("taper")), "a finite positive length");
    if (track.has("repeat") && !t->get("repeat")->is_boolean())
        track.fail("repeat", TableReader::describe(*t->get("repeat")), "true or false");
    sc.track.repeat = track.getBool("repeat", false);
    if (track.has("file")) {
        // Relative to the scenario file's folder.
        const std::filesystem::path given = file;
        const std::filesystem::path path = given.is_absolute() ? given : std::filesystem::path(src).parent_path() / given;
        std::string text;
        try {
            text = readInputFile(path.string(), "track file", kMaxTrackFileBytes);
            sc.track.measured = readTrackCsv(text, path.string(), sc.track.taper);
        } catch (const std::exception& e) {
            throw ScenarioError(fmt::format("{}: key 'track.file' = \"{}\": {}", src, given.string(), e.what()));
        }
    }
    if (track.has("measured")) {
        const toml::node* m = track.require("measured");
        const toml::array* arr = m->as_array();
        if (!arr || !arr->is_array_of_tables())
            track.fail("measured", TableReader::describe(*m), "an array of tables [[track.measured]]");
        if (arr->size() > kMaxTrackRows)
            track.fail("measured", fmt::format("{} rows", arr->size()),
                       fmt::format("at most {} rows [[track.measured]] (docs/cli.md, \"Input size limits\")",
                                   kMaxTrackRows));
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
        if (sc.track.measured.size() < 2)
            track.fail("measured", TableReader::describe(*m), "at least two rows [[track.measured]]");
    }
    if (sc.track.repeat) {
        const auto& rows = sc.track.measured;
        if (rows.empty())
            track.fail("repeat", "true", "a measured track to repeat ('file' or [[track.measured]]), or false");
        if (rows.front().crossLevel != rows.back().crossLevel || rows.front().profile != rows.back().profile)
            track.fail("repeat", "true", "a measured table whose last row equals its first (otherwise the rails "
                                         "would step where it starts again), or false");
    }
    track.rejectUnknown();
}

void readRun(const toml::table& root, const std::string& src, Scenario& sc) {
    TableReader run(getTable(root, "run", src, false), src, "run.");
    readFields(run, "run", sc);
    if (!(sc.filterCutoffHz < sc.run.outputRate / 2))
        run.fail("filter_cutoff", fmt::format("{} Hz", sc.filterCutoffHz),
                 fmt::format("a cut-off below the Nyquist frequency, half the output rate ({} Hz)", sc.run.outputRate / 2));
    checkSampleCount(run.locate("duration"), sc.run.duration, sc.run.outputRate);
    run.rejectUnknown();
}

}  // namespace

const std::vector<std::string>& getScenarioKeys() {
    static const std::vector<std::string> keys = [] {
        // The schema in order, the car parameters after car.name.
        std::vector<std::string> k;
        for (const ScenarioField& f : getScenarioSchema()) {
            k.push_back(f.key);
            if (std::string_view(f.key) == "car.name")
                for (const CarParameterInfo& info : getCarParameterTable()) k.push_back(std::string("car.") + info.key);
        }
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
    if (const char* renamed = findRenamedKey(key))
        throw ScenarioError(fmt::format("override key '{}': renamed; expected its new name, '{}'", key, renamed));
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
/// The dotted keys of a scenario document ("description", "run.speed", "track.measured"), sorted.
std::vector<std::string> listKeys(const toml::table& root) {
    std::vector<std::string> keys;
    for (const auto& [name, node] : root) {
        if (const toml::table* table = node.as_table())
            for (const auto& [key, value] : *table) keys.push_back(fmt::format("{}.{}", name.str(), key.str()));
        else
            keys.emplace_back(name.str());
    }
    std::sort(keys.begin(), keys.end());
    return keys;
}

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
    for (const char* table : {"integrator", "eom", "limits", "reduced", "attribution", "wheel_rail", "car_body", "criteria"})
        readFieldTable(root, table, source, sc);
    top.rejectUnknown({"car", "track", "run", "integrator", "eom", "limits", "reduced", "attribution", "wheel_rail", "car_body",
                       "criteria"});
    sc.settingsSet = listKeys(root);
    checkCarGeometry(sc);
    return sc;
}

Scenario loadScenarioFile(const std::string& path) { return loadScenarioFile(path, {}); }

Scenario loadScenarioFile(const std::string& path, const std::vector<ScenarioOverride>& overrides, OverrideKeys mode) {
    const std::string text = readInputFile(path, "scenario file");
    Scenario sc = parseScenario(text, path, overrides, mode);
    sc.sourceSha256 = calcSha256(text);
    return sc;
}

CarParameters parseCarFile(std::string_view text, const std::string& source) {
    return readCarFile(parseToml(text, source), source);
}

CarParameters loadCarFile(const std::string& path) { return parseCarFile(readInputFile(path, "car file"), path); }

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

std::string readInputFile(const std::string& path, const char* what, std::uintmax_t maxBytes) {
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) throw ScenarioError(fmt::format("{}: cannot open {}", path, what));
    // A folder, FIFO or device (/dev/zero) would fail late, hang or never end.
    if (!std::filesystem::is_regular_file(status))
        throw ScenarioError(fmt::format("{}: cannot open {}: not a regular file", path, what));
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > maxBytes)
        throw ScenarioError(fmt::format("{}: the {} is {} bytes; expected at most {} bytes ({} MiB, docs/cli.md, "
                                        "\"Input size limits\")",
                                        path, what, size, maxBytes, maxBytes >> 20));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ScenarioError(fmt::format("{}: cannot open {}", path, what));
    // Read to the end, not to the size stat gave: a file that grew, or one of /proc (size 0).
    std::string text;
    std::array<char, 1 << 16> chunk;
    while (in.read(chunk.data(), chunk.size()) || in.gcount() > 0) {
        text.append(chunk.data(), static_cast<size_t>(in.gcount()));
        if (text.size() > maxBytes)
            throw ScenarioError(fmt::format("{}: the {} is larger than {} bytes ({} MiB, docs/cli.md, \"Input size "
                                            "limits\")",
                                            path, what, maxBytes, maxBytes >> 20));
    }
    return text;
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
        case Dimension::Damping: unit = "N*s/m"; break;
        case Dimension::InverseSpeed: unit = "s/m"; break;
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

    // Every scalar field of the schema, in its table.
    auto tableOf = [&root](const std::string& name) -> toml::table& {
        if (!root.contains(name)) root.insert(name, toml::table{});
        return *root.get_as<toml::table>(name);
    };
    for (const ScenarioField& f : getScenarioSchema()) {
        toml::table* t = f.kind == FieldKind::Structured ? nullptr : &tableOf(f.getTable());
        const std::string name = f.getName();
        switch (f.kind) {
            case FieldKind::Quantity: {
                const double v = f.getNumber(sc);
                if (f.zeroIsDerived && v == 0) break;  // left out, so the default is derived again
                if (f.formatValue) t->insert(name, f.formatValue(sc));
                else if (f.dimension == Dimension::Dimensionless) t->insert(name, v);
                else t->insert(name, formatSi(v, f.dimension));
                break;
            }
            case FieldKind::Integer: t->insert(name, int64_t(f.getNumber(sc))); break;
            case FieldKind::Flag: t->insert(name, f.getFlag(sc)); break;
            case FieldKind::Choice: t->insert(name, f.getText(sc)); break;
            case FieldKind::Structured: break;
        }
    }
    if (!sc.track.measured.empty()) {
        toml::table& track = tableOf("track");
        toml::array rows;
        for (const MeasuredTrackSample& m : sc.track.measured)
            rows.push_back(toml::table{{"distance", formatSi(m.distance, Dimension::Length)},
                                       {"cross_level", formatSi(m.crossLevel, Dimension::Length)},
                                       {"profile", formatSi(m.profile, Dimension::Length)}});
        track.insert("measured", std::move(rows));
        track.insert("taper", formatSi(sc.track.taper, Dimension::Length));
        track.insert("repeat", sc.track.repeat);
    }

    std::ostringstream os;
    os << toml::toml_formatter(root, toml::format_flags::none);
    return os.str() + "\n";
}

}  // namespace rockroll
