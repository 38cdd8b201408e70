#pragma once
// Which time-domain models exist, by name. The only place a model's name is
// bound to its implementation: the scenario loader, the command line, sweeps,
// validate, bench and Python look models up here. Adding a model is one file in
// scenarios/models/ plus one line in ModelRegistry.cpp.
#include "scenarios/TimeDomainModel.h"

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rockroll {

struct CarParameters;
struct ModelOptions;
struct TrackMotion;
class RockingModel;
class TrackInput;

/// The registered names, for code that studies a particular formulation (validate's
/// comparisons, bench cases). Everything else enumerates the registry.
namespace model_names {
inline constexpr const char* kHalfCar = "halfcar";
inline constexpr const char* kFullCar = "fullcar";
inline constexpr const char* kEom = "eom";
inline constexpr const char* kReduced = "reduced";
}  // namespace model_names

struct ModelDescriptor {
    std::string name;         ///< as scenarios and --model spell it
    std::string description;  ///< one line for --help and reports
    /// Builds the model of a scenario for one run; `motion` is the track's s(t),
    /// continuing an earlier run's distance and speed when a sweep carries state.
    std::function<std::unique_ptr<TimeDomainModel>(const Scenario&, const TrackMotion&)> make;
    /// Simbody multibody models only (null otherwise): the RockingModel itself,
    /// for modal analysis and model-level tests. Also what makes the [attribution]
    /// switches (truck gravity, truck mass scale) apply.
    std::function<std::unique_ptr<RockingModel>(const CarParameters&, const TrackInput&, const ModelOptions&)>
        makeMultibody;
    /// The model has a massless truck (report §2.2), so [reduced] truck_weight applies.
    bool masslessTruck = false;
    /// The scenario keys the model uses: full dotted keys ("integrator.accuracy") or a
    /// whole table ("car.*"); getCommonSettings() plus the model's own. A key a scenario
    /// sets (Scenario::settingsSet) outside this list is reported as ignored
    /// (getIgnoredSettings; docs/cli.md, "Which model uses which key").
    std::vector<std::string> settings;
    /// The rate the model records at whatever run.output_rate says [Hz] (the reduced model:
    /// every RK4 step, 200 Hz); 0: it follows run.output_rate. A scenario that sets another
    /// run.output_rate for it is refused (checkSwitchesApply).
    double fixedOutputRateHz = 0;

    bool isMultibody() const { return bool(makeMultibody); }
    /// Whether `key` (a full dotted key) is one of `settings`.
    bool usesSetting(std::string_view key) const;
};

/// The keys every model uses: the description, how the car is named (car.base, car.file,
/// car.name), the track but its entry, the run but its output rate, the run limits and the
/// criteria. The car's parameters are each model's own (getCarSettings).
std::vector<std::string> getCommonSettings();
/// "car.<key>" of every car parameter but `unused` (keys of getCarParameterTable();
/// std::logic_error for a key that is none).
std::vector<std::string> getCarSettings(const std::vector<std::string_view>& unused);
/// The car parameters of the full car's three-dimensional truck and body alone: pitch and
/// yaw, the truck spacing, the center plate's yaw friction and rim (mbmodel/Truck.cpp), the
/// twisting body's stiffness and damping, and the off-centre CG (mbmodel/FullCarModel.h).
inline const std::vector<std::string_view> kFullCarOnlyParameters{
    "pitch_inertia", "yaw_inertia", "truck_spacing", "center_plate_friction", "center_plate_yaw_bristle_angle",
    "center_plate_rim_points", "car_body_torsional_stiffness", "car_body_torsional_damping_ratio",
    "cg_longitudinal_offset", "cg_lateral_offset"};

class ModelRegistry {
public:
    /// Every model, in a fixed order (the order --help lists them).
    static const ModelRegistry& get();

    const std::vector<ModelDescriptor>& getModels() const { return models_; }
    std::vector<std::string> getNames() const;
    /// The names of the multibody (Simbody) models.
    std::vector<std::string> getMultibodyNames() const;
    /// nullptr when no model has that name.
    const ModelDescriptor* find(std::string_view name) const;
    /// The model of that name; std::invalid_argument naming the name and listing
    /// the models when there is none.
    const ModelDescriptor& getModel(std::string_view name) const;

private:
    ModelRegistry();
    std::vector<ModelDescriptor> models_;
};

// One function per file in scenarios/models/.
ModelDescriptor describeFullCarModel();
ModelDescriptor describeHalfCarModel();
ModelDescriptor describeEomHalfCarModel();
ModelDescriptor describeReducedModel();

}  // namespace rockroll
