// Registry entry of the equation-of-motion half car (bespoke/EomHalfCarModel.h),
// integrated by CVODE BDF (bespoke/EomSimulation.h).
#include "bespoke/EomSimulation.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioLoader.h"
#include "scenarios/ScenarioRun.h"

#include <stdexcept>

namespace rockroll {

namespace {
class EomTimeDomainModel final : public TimeDomainModel {
public:
    explicit EomTimeDomainModel(EomHalfCarModel model) : model_(std::move(model)) {}
    const ChannelLayout& getChannels() const override { return model_.getChannels(); }
    std::vector<double> calcStaticState() const override {
        const EomHalfCarModel::State y = model_.makeStaticState();
        return std::vector<double>(y.data(), y.data() + y.size());
    }
    RunResult simulate(const Scenario& sc, const std::vector<double>& y0) const override {
        const EomRunSettings settings{sc.run.duration, sc.run.outputRate, sc.run.integrator.accuracy,
                                      resolveRunLimits(sc.run.limits, sc.car, sc.wheelRail)};
        if (y0.empty()) return simulateEom(model_, settings);
        if (y0.size() != size_t(EomHalfCarModel::kNumStates))
            throw std::invalid_argument("eom model: initial state has the wrong size");
        return simulateEom(model_, settings, Eigen::Map<const EomHalfCarModel::State>(y0.data()));
    }

    /// [q (9), q̇ (9), w (4)]: the energy audit's integrals are quadratures outside the state.
    std::vector<StateKind> getStateKinds() const override {
        using M = EomHalfCarModel;
        std::vector<StateKind> kinds(M::kNumStates, StateKind::Internal);
        for (int i = 0; i < 2 * M::kNumDofs; ++i) kinds[i] = i < M::kNumDofs ? StateKind::Position : StateKind::Rate;
        return kinds;
    }

private:
    EomHalfCarModel model_;
};
}  // namespace

ModelDescriptor describeEomHalfCarModel() {
    ModelDescriptor d;
    d.name = model_names::kEom;
    d.description = "equation-of-motion half car, the Simbody half car's equations written out (report §4.1)";
    // CVODE BDF at the scenario's accuracy; its own method and step control (bespoke/EomSimulation.h).
    d.settings = getCommonSettings();
    for (const char* key : {"run.output_rate", "integrator.accuracy", "eom.*", "wheel_rail.*", "limits.flange_climb_time"}) d.settings.emplace_back(key);
    const std::vector<std::string> car = getCarSettings(kFullCarOnlyParameters);  // a half car: no pitch, no yaw
    d.settings.insert(d.settings.end(), car.begin(), car.end());
    d.make = [](const Scenario& sc, const TrackMotion& motion) {
        return std::unique_ptr<TimeDomainModel>(std::make_unique<EomTimeDomainModel>(makeScenarioEomModel(sc, motion)));
    };
    return d;
}

}  // namespace rockroll
