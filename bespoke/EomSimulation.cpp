#include "bespoke/EomSimulation.h"

#include "bespoke/StiffIntegrator.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rockroll {

std::vector<double> getEomAbsoluteTolerances(double accuracy) {
    using M = EomHalfCarModel;
    std::vector<double> tol(M::kNumStates);
    // Lengths are compared with contact deflections of ~1e-4 m, rates with
    // ~1e-2 m/s, bristle deflections with their ~2.5e-4 m limit.
    for (int i = 0; i < M::kNumDofs; ++i) tol[i] = accuracy * 1e-4;
    for (int i = M::kNumDofs; i < 2 * M::kNumDofs; ++i) tol[i] = accuracy * 1e-2;
    for (int i = 2 * M::kNumDofs; i < M::kNumStates; ++i) tol[i] = accuracy * 1e-4;
    return tol;
}

RunResult simulateEom(const EomHalfCarModel& model, const EomRunSettings& settings) {
    return simulateEom(model, settings, model.makeStaticState());
}

RunResult simulateEom(const EomHalfCarModel& model, const EomRunSettings& settings, const EomHalfCarModel::State& y0) {
    using State = EomHalfCarModel::State;
    const auto wall0 = std::chrono::steady_clock::now();
    StiffIntegrator integ(
        EomHalfCarModel::kNumStates,
        [&model](double t, const double* y, double* yDot) {
            State s = Eigen::Map<const State>(y), d;
            model.calcStateDerivative(t, s, d);
            Eigen::Map<State> out(yDot);
            out = d;
        },
        settings.accuracy, getEomAbsoluteTolerances(settings.accuracy));
    integ.setStateNames(model.getStateNames());
    integ.setQuadrature(EomHalfCarModel::kNumEnergyIntegrals, [&model](double t, const double* y, double* rates) {
        model.calcEnergyRates(t, Eigen::Map<const State>(y), rates);  // energy audit: rail work, dissipation
    });
    integ.initialize(0, y0.data());

    RunResult result;
    result.history.names = {"t_s"};
    for (const auto& n : model.getChannels().names) result.history.names.push_back(n);
    std::vector<double> row;
    RunGuard guard(model.getChannels(), settings.limits);
    auto record = [&](double t, const State& y) {
        model.calcChannels(t, y, row, integ.getQuadrature().data());
        return result.history.samples.append(t, row);
    };
    const long nOut = std::lround(settings.duration * settings.outputRate);
    result.history.reserveSamples(nOut + 1);
    guard.check(record(0, y0), result);
    for (long k = 1; k <= nOut && !result.stop; ++k) {
        const double tOut = std::min(settings.duration, double(k) / settings.outputRate);
        integ.advanceTo(tOut);
        guard.check(record(tOut, Eigen::Map<const State>(integ.getState().data())), result);
    }
    result.steps = integ.getNumSteps();
    result.finalState = integ.getState();
    result.realizations = integ.getNumRhsEvaluations();
    result.simTime = integ.getTime();
    result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return result;
}

}  // namespace rockroll
