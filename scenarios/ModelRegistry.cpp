#include "scenarios/ModelRegistry.h"

#include "mbmodel/CarParameters.h"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <stdexcept>

namespace rockroll {

ModelRegistry::ModelRegistry() {
    models_.push_back(describeHalfCarModel());
    models_.push_back(describeFullCarModel());
    models_.push_back(describeEomHalfCarModel());
    models_.push_back(describeReducedModel());
}

bool ModelDescriptor::usesSetting(std::string_view key) const {
    for (const std::string& s : settings) {
        if (s == key) return true;
        if (s.size() > 2 && s.ends_with(".*") && key.starts_with(std::string_view(s).substr(0, s.size() - 1)))
            return true;
    }
    return false;
}

std::vector<std::string> getCommonSettings() {
    return {"description",  "car.base",      "car.file",        "car.name",          "track.amplitude",
            "track.rail_length", "track.rails", "track.mirror", "track.file",        "track.taper",
            "track.repeat", "track.measured", "run.speed",      "run.duration",      "run.model",
            "run.filter_cutoff", "limits.enabled", "limits.wheels_off_time", "limits.rollover_angle",
            "limits.energy_runaway_fraction", "limits.max_wall_time", "limits.severe_separation", "criteria.*"};
}

std::vector<std::string> getCarSettings(const std::vector<std::string_view>& unused) {
    for (std::string_view key : unused)
        if (!findCarParameter(key)) throw std::logic_error(fmt::format("getCarSettings: no car parameter '{}'", key));
    std::vector<std::string> keys;
    for (const CarParameterInfo& info : getCarParameterTable())
        if (std::find(unused.begin(), unused.end(), std::string_view(info.key)) == unused.end())
            keys.push_back(std::string("car.") + info.key);
    return keys;
}

const ModelRegistry& ModelRegistry::get() {
    static const ModelRegistry registry;
    return registry;
}

std::vector<std::string> ModelRegistry::getNames() const {
    std::vector<std::string> names;
    for (const auto& m : models_) names.push_back(m.name);
    return names;
}

std::vector<std::string> ModelRegistry::getMultibodyNames() const {
    std::vector<std::string> names;
    for (const auto& m : models_)
        if (m.isMultibody()) names.push_back(m.name);
    return names;
}

const ModelDescriptor* ModelRegistry::find(std::string_view name) const {
    for (const auto& m : models_)
        if (m.name == name) return &m;
    return nullptr;
}

const ModelDescriptor& ModelRegistry::getModel(std::string_view name) const {
    if (const ModelDescriptor* m = find(name)) return *m;
    throw std::invalid_argument(
        fmt::format("unknown model \"{}\"; expected one of {}", name, fmt::join(getNames(), ", ")));
}

}  // namespace rockroll
