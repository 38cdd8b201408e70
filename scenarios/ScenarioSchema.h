#pragma once
// The scenario schema: every key of a scenario file declared once, in the order
// getScenarioKeys lists them. A scalar key's entry says what it is (a quantity with
// a dimension, a plain number, a whole number, a boolean, or one of a list of
// names), its accepted range, its default as a scenario file would spell it, and
// how it reads and writes its Scenario member. The loader's readers, the writer
// (formatScenarioToml), getScenarioKeys, getValueRanges and checkScenario all walk
// this one table (test ScenarioOverrides.SchemaIsWhatTheLoaderReadsAndTheWriterWrites;
// docs/cli.md, "Keys and defaults", test ModelRegistry.TheDocsSayWhichModelUsesWhichKey).
//
// The keys with a structure of their own are listed here by name only (Structured)
// and read by the loader itself: description, car.base, car.file, car.name, the car
// parameters (mbmodel/CarParameters.h, getCarParameterTable: a table of their own),
// track.file, track.taper and track.repeat (with the measured rows).
#include "mbmodel/Units.h"

#include <string>
#include <string_view>
#include <vector>

namespace rockroll {

struct Scenario;

enum class FieldKind {
    Quantity,   ///< "<number> <unit>" of `dimension`; a plain number when dimensionless
    Integer,    ///< a TOML integer
    Flag,       ///< a TOML boolean
    Choice,     ///< one of getChoices()
    Structured  ///< read and written by the loader itself (see above)
};

struct ScenarioField {
    const char* key = "";            ///< dotted: "run.speed"
    FieldKind kind = FieldKind::Structured;
    units::Dimension dimension = units::Dimension::Dimensionless;
    const char* unit = "";           ///< the unit messages print values and limits in
    double low = 0, high = 0;        ///< accepted range [SI] (Quantity, Integer)
    bool lowOpen = false, highOpen = false;
    /// The default, as a scenario file writes it ("16.5 mph", "false", "cpodes"); what a
    /// scenario that leaves the key out gets (docs/cli.md, "Keys and defaults").
    const char* defaultText = "";
    /// 0 stands for "derived from the car" (the default): never range-checked or written.
    bool zeroIsDerived = false;
    double (*getNumber)(const Scenario&) = nullptr;  ///< Quantity, Integer [SI]
    void (*setNumber)(Scenario&, double) = nullptr;
    bool (*getFlag)(const Scenario&) = nullptr;
    void (*setFlag)(Scenario&, bool) = nullptr;
    std::string (*getText)(const Scenario&) = nullptr;  ///< Choice
    void (*setText)(Scenario&, const std::string&) = nullptr;
    std::vector<std::string> (*getChoices)() = nullptr;
    /// How the writer spells the value when not in its SI unit ("6 deg"); null: SI.
    std::string (*formatValue)(const Scenario&) = nullptr;

    /// "run" of "run.speed": the TOML table the key lives in ("" for a top-level key).
    std::string getTable() const;
    /// "speed" of "run.speed".
    std::string getName() const;
};

/// The new name of a key that was renamed ("attribution.truck_gravity" →
/// "attribution.unsprung_gravity": it acts on the wheelsets and side frames only); nullptr
/// for any other key. A renamed key is refused with its new name.
const char* findRenamedKey(std::string_view oldKey);

/// Every key but the car parameters, in schema order.
const std::vector<ScenarioField>& getScenarioSchema();
/// The field of `key`; nullptr when it is not a key of the schema.
const ScenarioField* findScenarioField(std::string_view key);

}  // namespace rockroll
