#include "scenarios/ModelRegistry.h"

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
    return {"description",  "car.*",         "track.amplitude", "track.rail_length", "track.rails",
            "track.mirror", "track.file",    "track.taper",     "track.repeat",      "track.measured",
            "run.speed",    "run.duration",  "run.model",       "run.filter_cutoff", "limits.*",
            "criteria.*"};
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
