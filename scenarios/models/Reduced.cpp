// Registry entry of the report's reduced model: massless truck, fixed-step RK4
// (bespoke/ReducedHalfCarModel.h).
#include "bespoke/ReducedHalfCarModel.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioLoader.h"

#include <cmath>

namespace rockroll {

namespace {
class ReducedTimeDomainModel final : public TimeDomainModel {
public:
    explicit ReducedTimeDomainModel(ReducedHalfCarModel model) : model_(std::move(model)) {}
    const ChannelLayout& getChannels() const override { return model_.getChannels(); }
    std::vector<double> calcStaticState() const override { return model_.calcStaticState(); }
    RunResult simulate(const Scenario& sc, const std::vector<double>& y0) const override {
        return simulateReduced(model_, sc.run.duration, nullptr, y0, resolveRunLimits(sc.run.limits, sc.car, sc.wheelRail));
    }

    /// The flat layout of ReducedHalfCarModel::calcStaticState: [θ, y, z], their rates,
    /// the truck mode (8 enumerations), then the truck's memory: spring compressions
    /// and the lateral deflection at the last step (they pick a slip direction), the
    /// wedge anchors (bristle-like: the stuck force is k_b·(Z − Z_a)) and the truck's
    /// two roll angles.
    std::vector<StateKind> getStateKinds() const override {
        std::vector<StateKind> kinds(6, StateKind::Position);
        for (int i = 3; i < 6; ++i) kinds[size_t(i)] = StateKind::Rate;
        kinds.insert(kinds.end(), 8, StateKind::Discrete);
        kinds.insert(kinds.end(), 8, StateKind::Internal);
        return kinds;
    }

private:
    ReducedHalfCarModel model_;
};
}  // namespace

ModelDescriptor describeReducedModel() {
    ModelDescriptor d;
    d.name = model_names::kReduced;
    d.description = "the report's reduced half car: massless truck, fixed-step RK4 at 0.005 s (report §2.2)";
    d.masslessTruck = true;
    d.settings = getCommonSettings();
    for (const char* key : {"run.output_rate", "reduced.*", "wheel_rail.flange_height"}) d.settings.emplace_back(key);
    // A half car with a massless truck and rigid contacts (report §2.2, bespoke/TruckEquilibrium.h):
    // no truck inertias, contact stiffnesses or contact damping.
    std::vector<std::string_view> unused(kFullCarOnlyParameters);
    for (std::string_view key :
         {"bolster_roll_inertia", "wheelset_roll_inertia", "wheel_rail_stiffness", "center_plate_stiffness",
          "side_bearing_stiffness", "contact_dissipation", "wheel_rail_lateral_stiffness",
          "lateral_contact_damping_ratio", "friction_bristle_damping_ratio"})
        unused.push_back(key);
    const std::vector<std::string> car = getCarSettings(unused);
    d.settings.insert(d.settings.end(), car.begin(), car.end());
    d.fixedOutputRateHz = std::round(1 / ReducedHalfCarModel::kStep);  // it records every step
    d.make = [](const Scenario& sc, const TrackMotion& motion) {
        return std::unique_ptr<TimeDomainModel>(std::make_unique<ReducedTimeDomainModel>(ReducedHalfCarModel(
            sc.car, makeEquivalentWheelsetInput(TrackInput(sc.track), motion, sc.car.wheelbase), sc.reduced)));
    };
    return d;
}

}  // namespace rockroll
