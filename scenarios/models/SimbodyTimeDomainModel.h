#pragma once
// A Simbody RockingModel (half or full car) seen through TimeDomainModel: the
// multibody driver of mbmodel/Simulation.h runs it.
#include "mbmodel/RockingModel.h"
#include "scenarios/TimeDomainModel.h"

#include <memory>

namespace rockroll {

class SimbodyTimeDomainModel final : public TimeDomainModel {
public:
    explicit SimbodyTimeDomainModel(std::unique_ptr<RockingModel> model) : model_(std::move(model)) {}
    const ChannelLayout& getChannels() const override { return model_->getChannels(); }
    std::vector<double> calcStaticState() const override;
    RunResult simulate(const Scenario& sc, const std::vector<double>& y0) const override;
    /// Simbody's Y = [q, u, z]: z holds the friction bristles and the energy audit's two integrals.
    std::vector<StateKind> getStateKinds() const override;
    const RockingModel& getRockingModel() const { return *model_; }

private:
    std::unique_ptr<RockingModel> model_;
};

/// The ModelOptions of a scenario's run along `motion`.
ModelOptions makeModelOptions(const Scenario& sc, const TrackMotion& motion);

}  // namespace rockroll
