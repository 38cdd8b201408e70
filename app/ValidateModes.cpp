// validate, section 6: the car-body modes of the linearized Simbody models against
// the report's Table 1 (its values: scenarios/reference/mit1976.toml, via calcTable1Estimates).
#include "app/ValidateSections.h"
#include "scenarios/ModelRegistry.h"
#include "mbmodel/ModalAnalysis.h"

#include <fmt/format.h>

namespace rockroll::app {

using namespace validate_detail;

std::string makeModesSection() {
    std::string md = "## 6. Modes against the report's Table 1\n\nMade by `rockroll modes scenarios/<car>.toml --model halfcar` "
                     "(and `--model fullcar` for pitch and yaw); why coupled and uncoupled values differ: docs/model.md, "
                     "section Modes.\n\n| car | mode | coupled, Hz | Table 1 (report), Hz |\n|---|---|---|---|\n";
    for (const char* carName : {"70ton-loaded", "70ton-empty", "100ton-loaded"}) {
        const Scenario sc = loadCarScenario(carName);
        TrackSpec level = sc.track;
        level.amplitude = 0;
        for (const char* model : {model_names::kHalfCar, model_names::kFullCar}) {
            if (std::string(model) == model_names::kFullCar && std::string(carName) != "70ton-loaded") continue;
            const auto m = ModelRegistry::get().getModel(model).makeMultibody(
                makeModalCar(sc.car), TrackInput(level), ModelOptions{sc.speed, sc.entry, TrackMotion{}, AttributionSwitches{}, WheelRailSettings{}, CarBodySettings{}});
            const auto table1 = calcTable1Estimates(sc.car);
            for (const Mode& mode : calcModes(*m)) {
                if (mode.body != "car body") continue;
                std::string motion = mode.motion == "sway-roll" ? (mode.name.find("lower") != std::string::npos ? "roll" : "sway") : mode.motion;
                double rep = 0;
                for (const auto& e : table1)
                    if (e.body == "car body" && e.motion == motion) rep = e.reportHz;
                md += fmt::format("| {} ({}) | {} | {:.3f} | {} |\n", carName, model, mode.name, mode.frequencyHz,
                                  rep > 0 ? fmt::format("{:.2f} ({})", rep, motion) : "—");
            }
        }
    }
    return md + "\n";
}

}  // namespace rockroll::app
