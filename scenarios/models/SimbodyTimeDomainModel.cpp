#include "scenarios/models/SimbodyTimeDomainModel.h"

#include "mbmodel/FullCarModel.h"
#include "mbmodel/HalfCarModel.h"
#include "mbmodel/Simulation.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioLoader.h"

namespace rockroll {

std::vector<double> SimbodyTimeDomainModel::calcStaticState() const {
    const SimTK::State s = model_->makeStaticState();
    return std::vector<double>(&s.getY()[0], &s.getY()[0] + s.getNY());
}

RunResult SimbodyTimeDomainModel::simulate(const Scenario& sc, const std::vector<double>& y0) const {
    RunSettings settings = sc.run;
    settings.limits = resolveRunLimits(sc.run.limits, sc.car, sc.wheelRail);
    return rockroll::simulate(*model_, settings, y0);
}

std::vector<StateKind> SimbodyTimeDomainModel::getStateKinds() const {
    const SimTK::State s = model_->makeStaticState(false);
    const int nq = s.getNQ(), nu = s.getNU();
    std::vector<StateKind> kinds(s.getNY(), StateKind::Internal);
    for (int i = 0; i < nq + nu; ++i) kinds[i] = i < nq ? StateKind::Position : StateKind::Rate;
    for (int i : model_->getEnergyAuditYIndices()) kinds[i] = StateKind::Accumulating;
    return kinds;
}

ModelOptions makeModelOptions(const Scenario& sc, const TrackMotion& motion) {
    return ModelOptions{sc.speed, sc.entry, motion, sc.attribution, sc.wheelRail, sc.carBody};
}

namespace {
template <class Car>
ModelDescriptor describeSimbodyCar(std::string name, std::string description) {
    ModelDescriptor d;
    d.name = std::move(name);
    d.description = std::move(description);
    d.settings = getCommonSettings();
    for (const char* key : {"run.output_rate", "integrator.*", "attribution.*", "wheel_rail.*", "limits.flange_climb_time"}) d.settings.emplace_back(key);
    // The half car's truck is two-dimensional: no pitch, no yaw (mbmodel/Truck.cpp).
    const std::vector<std::string> car = getCarSettings(
        std::is_same_v<Car, FullCarModel> ? std::vector<std::string_view>{} : kFullCarOnlyParameters);
    d.settings.insert(d.settings.end(), car.begin(), car.end());
    d.makeMultibody = [](const CarParameters& car, const TrackInput& track, const ModelOptions& options) {
        return std::unique_ptr<RockingModel>(std::make_unique<Car>(car, track, options));
    };
    d.make = [](const Scenario& sc, const TrackMotion& motion) {
        return std::unique_ptr<TimeDomainModel>(std::make_unique<SimbodyTimeDomainModel>(
            std::make_unique<Car>(sc.car, TrackInput(sc.track), makeModelOptions(sc, motion))));
    };
    return d;
}
}  // namespace

ModelDescriptor describeHalfCarModel() {
    return describeSimbodyCar<HalfCarModel>(
        model_names::kHalfCar, "Simbody half car: car body, bolster, equivalent wheelset (report §2.2)");
}

ModelDescriptor describeFullCarModel() {
    ModelDescriptor d = describeSimbodyCar<FullCarModel>(
        model_names::kFullCar, "Simbody full car: car body, two trucks, four wheelsets, with pitch and yaw");
    d.settings.emplace_back("track.entry");  // where the trailing truck meets the track (FullCarModel.cpp)
    d.settings.emplace_back("car_body.*");   // its car body's torsion (FullCarModel.cpp)
    return d;
}

}  // namespace rockroll
