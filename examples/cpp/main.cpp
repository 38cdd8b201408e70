// Loads a scenario file, runs it for 2 s of simulated time and prints the
// largest car-body roll. Usage: max_roll SCENARIO.toml [MODEL]
#include "scenarios/ScenarioLoader.h"
#include "scenarios/ScenarioRun.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: %s SCENARIO.toml [halfcar|fullcar|eom|reduced]\n", argv[0]);
        return 2;
    }
    try {
        rockroll::Scenario sc = rockroll::loadScenarioFile(argv[1]);
        if (argc == 3) sc.model = argv[2];
        sc.run.duration = 2.0;  // [s] simulated
        const rockroll::ScenarioRun run = rockroll::runScenario(sc);
        std::printf("model %s, %.1f s simulated: max roll %.4f deg\n", sc.model.c_str(), run.result.simTime,
                    run.summary.maxRollDeg);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
