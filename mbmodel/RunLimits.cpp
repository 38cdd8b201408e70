#include "mbmodel/RunLimits.h"

#include "contacts/SpringGroupLaws.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <fmt/format.h>
#include <limits>

namespace rockroll {

double calcStaticRolloverAngle(const CarParameters& car) {
    // Spring groups carry half of one truck's car-body share plus half its bolster.
    const double springLoad = (car.getCarBodyWeight() / 2 + car.bolsterWeight) / 2;
    const double compression =
        calcVerticalSpringCompression(springLoad, {car.springVerticalRate, car.springTravel, car.bottomingRate});
    const double cgHeight =
        car.springTopAboveRail - compression + car.centerPlateAboveSprings + car.cgAboveCenterPlate;
    return std::atan2(car.gauge / 2, cgHeight);
}

RunLimits resolveRunLimits(RunLimits l, const CarParameters& car, const WheelRailSettings& wheelRail) {
    l.flangeHeight = wheelRail.flangeHeight;
    l.flangeClearance = wheelRail.flangewayClearance;
    l.nadalLimit = wheelRail.lateral == LateralWheelRail::CreepAndFlange
                       ? calcNadalLimit(wheelRail.flangeAngle, wheelRail.friction)
                       : 0.0;
    if (l.wheelsOffTime == 0) l.wheelsOffTime = 2 * std::sqrt(2 * l.flangeHeight / units::g);
    if (l.rolloverAngle == 0) l.rolloverAngle = calcStaticRolloverAngle(car);
    if (l.energyRunawayFloor == 0) l.energyRunawayFloor = car.getCarBodyWeight() * units::inch;
    return l;
}

double estimateHistoryBytes(double duration, double outputRate, size_t channels) {
    // A std::vector<double> row: its 24-byte header in the history plus its heap block
    // (values and ~16 bytes of allocator overhead).
    const double rows = std::floor(duration * outputRate) + 1;
    return rows * (double(channels + 1) * sizeof(double) + 24 + 16);
}

double getMemoryLimitBytes() {
    constexpr double kMiB = 1024.0 * 1024.0;
    const char* text = std::getenv("ROCKROLL_MAX_MEMORY_MB");
    if (!text || !*text) return 2048 * kMiB;
    char* end = nullptr;
    const double mb = std::strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(mb) || !(mb > 0))
        throw std::invalid_argument(fmt::format("environment variable ROCKROLL_MAX_MEMORY_MB = \"{}\": expected a "
                                                "positive number of MiB (default 2048)", text));
    return mb * kMiB;
}

RunGuard::RunGuard(const ChannelLayout& layout, const RunLimits& limits)
    : layout_(layout), limits_(limits), start_(std::chrono::steady_clock::now()),
      airborneSince_(layout.wheelsets.size(), std::numeric_limits<double>::quiet_NaN()),
      climbingSince_(layout.wheelsets.size(), {std::numeric_limits<double>::quiet_NaN(),
                                               std::numeric_limits<double>::quiet_NaN()}) {}

void RunGuard::checkWallTime(double simTime) const {
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (wall > limits_.maxWallTime)
        throw NumericalFailure(fmt::format("wall-time limit of {:g} s passed at t = {:.6f} s simulated (raise it with "
                                           "--max-wall-s or [limits] max_wall_time)",
                                           limits_.maxWallTime, simTime),
                               simTime);
}

bool RunGuard::check(std::span<const double> row, RunResult& result) {
    const double t = row[0];
    auto ch = [&row](int c) { return row[size_t(c) + 1]; };
    for (size_t i = 1; i < row.size(); ++i)
        if (!std::isfinite(row[i]))
            throw NumericalFailure(fmt::format("runaway: channel {} is {} at t = {:.6f} s", layout_.names[i - 1],
                                               row[i], t),
                                   t);
    checkWallTime(t);
    if (!limits_.enabled) return false;
    auto stop = [&](const char* regime, std::string reason) {
        result.stop = RunStop{regime, std::move(reason), t};
        return true;
    };

    const double roll = std::abs(ch(layout_.roll)) * units::degree;
    if (limits_.rolloverAngle > 0 && roll > limits_.rolloverAngle)
        return stop("overturned", fmt::format("car-body roll {:.2f} deg passed the rollover angle limit {:.2f} deg ([limits] rollover_angle; by default the static rollover angle of the car)",
                                              roll / units::degree, limits_.rolloverAngle / units::degree));

    for (size_t w = 0; w < layout_.wheelsets.size(); ++w) {
        const ChannelLayout::Wheelset& ws = layout_.wheelsets[w];
        const double lift[2] = {ch(ws.liftLeft) * units::inch, ch(ws.liftRight) * units::inch};
        if (ws.lateral >= 0) {
            // Left wheel (+y) climbs its rail when the wheelset moves +y past flange
            // contact with that wheel lifted above its flange; the right one mirrored.
            const double lateral = ch(ws.lateral) * units::inch;
            // Both wheels above their flanges and the wheelset past flange contact
            // either way: no flange can hold it, it lands beside a rail.
            if (lift[0] > limits_.flangeHeight && lift[1] > limits_.flangeHeight &&
                std::abs(lateral) > limits_.flangeClearance)
                return stop("derailed", fmt::format("both wheels of wheelset {} lifted above the flange height ({:.2f} and "
                                                    "{:.2f} in) while it moved {:.2f} in laterally (flange contact at "
                                                    "{:.3f} in)",
                                                    w + 1, lift[0] / units::inch, lift[1] / units::inch,
                                                    std::abs(lateral) / units::inch,
                                                    limits_.flangeClearance / units::inch));
            for (int side : {0, 1}) {
                const double towardRail = side == 0 ? lateral : -lateral;
                if (lift[side] > limits_.flangeHeight && towardRail > limits_.flangeClearance)
                    return stop("derailed",
                                fmt::format("{} lifted {:.2f} in (flange height {:.2f} in) while its wheelset moved "
                                            "{:.2f} in toward that rail (flange contact at {:.3f} in)",
                                            layout_.names[size_t(side == 0 ? ws.liftLeft : ws.liftRight)],
                                            lift[side] / units::inch, limits_.flangeHeight / units::inch,
                                            towardRail / units::inch, limits_.flangeClearance / units::inch));
            }
        }
        // Flange climb: a wheel in flange contact whose own L/V, the rail's lateral force
        // on it away from that rail over its vertical force, stays above Nadal's limit.
        for (int side : {0, 1}) {
            if (limits_.nadalLimit <= 0 || ws.flange[side] < 0 || ws.lOverV[side] < 0) continue;
            const double towardOwnRail = side == 0 ? -ch(ws.lOverV[side]) : ch(ws.lOverV[side]);
            double& since = climbingSince_[w][size_t(side)];
            if (ch(ws.flange[side]) > 0 && towardOwnRail > limits_.nadalLimit) {
                if (std::isnan(since)) since = t;
                if (t - since > limits_.flangeClimbTime)
                    return stop("derailed",
                                fmt::format("flange climb: {} in flange contact with its L/V above Nadal's limit "
                                            "{:.3f} for {:.3f} s (limit {:.3f} s; now {:.3f})",
                                            layout_.names[size_t(ws.flange[side])], limits_.nadalLimit, t - since,
                                            limits_.flangeClimbTime, towardOwnRail));
            } else {
                since = std::numeric_limits<double>::quiet_NaN();
            }
        }
        if (lift[0] > 0 && lift[1] > 0) {
            if (std::isnan(airborneSince_[w])) airborneSince_[w] = t;
            if (t - airborneSince_[w] > limits_.wheelsOffTime)
                return stop("derailed", fmt::format("both wheels of wheelset {} ({}, {}) off their rails for {:.3f} s "
                                                    "(limit {:.3f} s)",
                                                    w + 1, layout_.names[size_t(ws.liftLeft)],
                                                    layout_.names[size_t(ws.liftRight)], t - airborneSince_[w],
                                                    limits_.wheelsOffTime));
        } else {
            airborneSince_[w] = std::numeric_limits<double>::quiet_NaN();
        }
    }

    if (limits_.energyRunawayFloor > 0 && layout_.energyStored >= 0 && layout_.energyInput >= 0 &&
        layout_.energyDissipated >= 0) {
        const double E = ch(layout_.energyStored), W = ch(layout_.energyInput), D = ch(layout_.energyDissipated);
        if (first_) energy0_ = E;
        const double excess = (E - energy0_) - (W - D);
        const double scale = std::max({std::abs(W), D, limits_.energyRunawayFloor});
        if (excess > limits_.energyRunawayFraction * scale)
            throw NumericalFailure(
                fmt::format("runaway: stored energy grew {:.4g} J more than the rails' work less dissipation "
                            "(work {:.4g} J, dissipated {:.4g} J, limit {:g} x {:.4g} J) at t = {:.6f} s",
                            excess, W, D, limits_.energyRunawayFraction, scale, t),
                t);
    }
    first_ = false;
    return false;
}

}  // namespace rockroll
