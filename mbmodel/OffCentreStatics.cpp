#include "mbmodel/OffCentreStatics.h"

#include <Eigen/Dense>
#include <cmath>

namespace rockroll {

OffCentreStatics calcOffCentreStatics(const CarParameters& car) {
    const double W = car.getCarBodyWeight(), s = car.truckSpacing, h = car.cgAboveCenterPlate;
    const double kcp = car.contactStiffnessScale * car.centerPlateStiffness;
    const double kwr = car.contactStiffnessScale * car.wheelRailStiffness;
    const double kv = car.springVerticalRate, a = car.centerPlateDiameter / 2;
    const double kTheta = kcp * a * a / 2;
    const double c = 1 / kcp + 1 / (2 * kv) + 1 / (4 * kwr);

    OffCentreStatics r;
    const double dQ = (2 * W * car.cgLongitudinalOffset / s) / (1 + 4 * kTheta * c / (s * s) - 2 * W * h * c / (s * s));
    r.pitch = c * dQ / s;

    const double WB = car.bolsterWeight, Wu = car.wheelsetWeight + car.sideFrameWeight;
    const double hp = car.centerPlateAboveSprings, b = car.springOffset, g = car.gauge;
    const double Hs = car.springTopAboveRail - car.wheelRadius, e = car.cgLateralOffset;
    // x = [φ_c, then per truck φ_b, φ_w, P_L − P_R, N_L − N_R]: the body's balance and each
    // truck's four equations of the header (the body, rigid, rolls as one).
    Eigen::Matrix<double, 9, 9> A = Eigen::Matrix<double, 9, 9>::Zero();
    Eigen::Matrix<double, 9, 1> y = Eigen::Matrix<double, 9, 1>::Zero();
    A(0, 0) = W * h - 2 * kTheta;
    y(0) = W * e;
    std::array<double, 2> Q{};
    for (int t = 0; t < 2; ++t) {
        Q[size_t(t)] = W / 2 + (t == 0 ? dQ : -dQ) / 2;
        const int i = 1 + 4 * t;  // this truck's first unknown and equation
        A(0, i) = kTheta;
        // (P_L − P_R)·b = −k_θ·(φ_c − φ_b) − Q·a·φ_b
        A(i, 0) = kTheta, A(i, i) = -kTheta + Q[size_t(t)] * hp, A(i, i + 2) = b;
        // P_L − P_R = 2k_v·b·(φ_w − φ_b)
        A(i + 1, i) = 2 * kv * b, A(i + 1, i + 1) = -2 * kv * b, A(i + 1, i + 2) = 1;
        // N_L − N_R = −k_wr·g·φ_w
        A(i + 2, i + 1) = kwr * g, A(i + 2, i + 3) = 1;
        // (N_L − N_R)·g/2 = (P_L − P_R)·b/2 − (Q + W_B)/2·H_s·φ_w
        A(i + 3, i + 1) = (Q[size_t(t)] + WB) / 2 * Hs, A(i + 3, i + 2) = -b / 2, A(i + 3, i + 3) = g / 2;
    }
    const Eigen::Matrix<double, 9, 1> x = A.partialPivLu().solve(y);
    for (int t = 0; t < 2; ++t) {
        OffCentreTruckStatics& ts = r.trucks[size_t(t)];
        const int i = 1 + 4 * t;
        ts.centerPlate = Q[size_t(t)];
        ts.carBodyRoll = x(0);
        ts.bolsterRoll = x(i);
        ts.wheelsetRoll = x(i + 1);
        const double base = (Q[size_t(t)] + WB) / 4 + Wu / 2;
        ts.wheel = {base + x(i + 3) / 2, base - x(i + 3) / 2};
        const double seated = Q[size_t(t)] / kcp, tilt = std::abs(x(0) - x(i));
        // A rim point at angle ψ sinks a·(θ·cos ψ + (φ_c − φ_b)·sin ψ) more than the centre: at
        // most a·√(θ² + (φ_c − φ_b)²).
        if (a * std::hypot(r.pitch, tilt) >= seated) r.rimSeated = false;
        if (car.sideBearingOffset * tilt >= car.sideBearingClearance) r.sideBearingsOpen = false;
    }
    return r;
}

}  // namespace rockroll
