#include "mbmodel/Simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <memory>

using SimTK::State; using SimTK::Vec3; using SimTK::Vector; using SimTK::MobilizedBody; using SimTK::Transform;
using SimTK::Rotation; using SimTK::Mat33; using SimTK::Body; using SimTK::MassProperties; using SimTK::Inertia;
using SimTK::Stage; using SimTK::Force; using SimTK::SimbodyMatterSubsystem; using SimTK::GeneralForceSubsystem;
using SimTK::System; using SimTK::Integrator; using SimTK::CPodesIntegrator; using SimTK::CPodes;
using SimTK::RungeKuttaMersonIntegrator; using SimTK::RungeKutta3Integrator; using SimTK::RungeKuttaFeldbergIntegrator;
using SimTK::VerletIntegrator; using SimTK::MobilizedBodyIndex;

namespace rockroll {


std::vector<std::string> getIntegratorNames() { return {"cpodes", "rkmerson", "rk3", "rkf", "verlet"}; }

namespace {
std::unique_ptr<Integrator> makeIntegrator(const System& sys, const IntegratorSettings& s) {
    std::unique_ptr<Integrator> integ;
    if (s.method == "cpodes") integ = std::make_unique<CPodesIntegrator>(sys, CPodes::BDF, CPodes::Newton);
    else if (s.method == "rkmerson") integ = std::make_unique<RungeKuttaMersonIntegrator>(sys);
    else if (s.method == "rk3") integ = std::make_unique<RungeKutta3Integrator>(sys);
    else if (s.method == "rkf") integ = std::make_unique<RungeKuttaFeldbergIntegrator>(sys);
    else if (s.method == "verlet") integ = std::make_unique<VerletIntegrator>(sys);
    else
        throw std::invalid_argument(fmt::format("unknown integrator \"{}\"; expected one of: cpodes, rkmerson, "
                                                "rk3, rkf, verlet", s.method));
    if (!(s.accuracy > 0 && s.accuracy < 1))
        throw std::invalid_argument(fmt::format("integrator accuracy {} must be in (0, 1)", s.accuracy));
    integ->setAccuracy(s.accuracy);
    if (s.maxStepSize > 0) integ->setMaximumStepSize(s.maxStepSize);
    integ->setReturnEveryInternalStep(false);
    return integ;
}

std::string describeState(const RockingModel& model, const State& s) {
    std::string out = fmt::format("t = {:.6f} s\n", s.getTime());
    for (int b = 1; b < model.getMatter().getNumBodies(); ++b) {
        const MobilizedBody& mb = model.getMatter().getMobilizedBody(MobilizedBodyIndex(b));
        out += fmt::format("  body {}: q = [", b);
        for (int i = 0; i < mb.getNumQ(s); ++i) out += fmt::format("{}{:.6g}", i ? ", " : "", mb.getOneQ(s, i));
        out += "], u = [";
        for (int i = 0; i < mb.getNumU(s); ++i) out += fmt::format("{}{:.6g}", i ? ", " : "", mb.getOneU(s, i));
        out += "]\n";
    }
    out += "  z (friction bristles) = [";
    for (int i = 0; i < s.getNZ(); ++i) out += fmt::format("{}{:.6g}", i ? ", " : "", s.getZ()[i]);
    return out + "]";
}
}  // namespace

RunResult simulate(const RockingModel& model, const RunSettings& settings, const std::vector<double>& initialY) {
    if (!(settings.duration > 0)) throw std::invalid_argument("run duration must be positive");
    if (!(settings.outputRate > 0)) throw std::invalid_argument("output rate must be positive");
    const auto wall0 = std::chrono::steady_clock::now();
    RunResult result;
    result.history.names.push_back("t_s");
    for (const auto& n : model.getChannels().names) result.history.names.push_back(n);

    auto integ = makeIntegrator(model.getSystem(), settings.integrator);
    State s0 = model.makeDefaultState();
    if (initialY.empty()) {
        s0 = model.makeStaticState();
    } else {
        if (int(initialY.size()) != s0.getNY())
            throw std::invalid_argument(fmt::format("initial state has {} entries; the model has {}", initialY.size(),
                                                    s0.getNY()));
        for (int i = 0; i < s0.getNY(); ++i) s0.updY()[i] = initialY[i];
        model.resetEnergyAccounts(s0);  // the energy audit counts from this run's start
        s0.setTime(0);
    }
    integ->initialize(s0);
    // Bounded internal steps per stepTo call, so the wall-time guard is checked
    // even when the integrator crawls.
    integ->setInternalStepLimit(2000);
    RunGuard guard(model.getChannels(), settings.limits);

    std::vector<double> channels;
    auto record = [&](const State& s) {
        model.getSystem().realize(s, Stage::Velocity);  // every channel is a function of q, u, z, t
        model.calcChannels(s, channels);
        return result.history.samples.append(s.getTime(), channels);
    };
    auto fail = [&](const std::string& why) {
        return NumericalFailure(fmt::format("integration failed ({}, accuracy {:g}) near t = {:.6f} s: {}\n"
                                            "last good state:\n{}",
                                            settings.integrator.method, settings.integrator.accuracy,
                                            integ->getTime(), why, describeState(model, integ->getState())),
                                integ->getTime());
    };
    const long nOut = std::lround(settings.duration * settings.outputRate);
    result.history.reserveSamples(nOut + 1);
    guard.check(record(integ->getState()), result);

    for (long k = 1; k <= nOut && !result.stop; ++k) {
        const double tOut = std::min(settings.duration, double(k) / settings.outputRate);
        try {
            // stepTo returns early at the internal step limit or at the start of
            // the interval; repeat until tOut.
            while (integ->getTime() < tOut && !integ->isSimulationOver()) {
                const Integrator::SuccessfulStepStatus status = integ->stepTo(tOut);
                if (status == Integrator::EndOfSimulation) break;
                guard.checkWallTime(integ->getTime());
            }
        } catch (const NumericalFailure&) {
            throw;
        } catch (const std::exception& e) {
            throw fail(e.what());
        }
        if (integ->isSimulationOver() && integ->getTime() < tOut - 1e-12)
            throw fail(Integrator::getTerminationReasonString(integ->getTerminationReason()));
        const State& s = integ->getState();
        for (int i = 0; i < s.getNY(); ++i)
            if (!std::isfinite(s.getY()[i])) throw fail("the state became non-finite");
        if (std::abs(s.getTime() - tOut) > 1e-9 * std::max(1.0, tOut))
            throw fail(fmt::format("the integrator returned at t = {:.9f} s instead of the output time {:.9f} s",
                                   s.getTime(), tOut));
        guard.check(record(s), result);
    }
    result.steps = integ->getNumStepsTaken();
    const State& sEnd = integ->getState();
    result.finalState.assign(&sEnd.getY()[0], &sEnd.getY()[0] + sEnd.getNY());
    result.realizations = integ->getNumRealizations();
    result.simTime = integ->getTime();
    result.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return result;
}

}  // namespace rockroll
