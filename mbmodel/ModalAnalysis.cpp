#include "mbmodel/ModalAnalysis.h"
#include "mbmodel/Mit1976.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <fmt/format.h>
#include <map>

using SimTK::State; using SimTK::Vector; using SimTK::Matrix; using SimTK::Stage; using SimTK::MobilizedBody;

namespace rockroll {

namespace {
struct Coordinate {
    std::string body, motion;
};

/// Body and motion of every mobility, in u order.
std::vector<Coordinate> describeMobilities(const RockingModel& model, const State& s) {
    std::vector<Coordinate> c(s.getNU());
    auto label = [&](const MobilizedBody& mb, const std::string& body) {
        const int first = int(mb.getFirstUIndex(s)), n = mb.getNumU(s);
        // Planar cross-section bodies: [roll, lateral, vertical]; the Free car
        // body: [ω_x, ω_y, ω_z, v_x, v_y, v_z] in ground axes.
        static const char* planar[] = {"roll", "sway", "heave"};
        static const char* free6[] = {"roll", "pitch", "yaw", "longitudinal", "sway", "heave"};
        for (int k = 0; k < n; ++k) c[first + k] = {body, n == 6 ? free6[k] : planar[k]};
    };
    label(model.getCarBody(), "car body");
    // A twisting car body: its rear half's one mobility, the twist against the front half.
    if (model.isCarBodyTwisting()) c[size_t(model.getCarBodyTwistPin().getFirstUIndex(s))] = {"car body", "twist"};
    for (int t = 0; t < model.getNumTrucks(); ++t) {
        const Truck& truck = model.getTruck(t);
        const std::string T = model.getNumTrucks() > 1 ? (t == 0 ? " F" : " R") : "";
        label(truck.getBolster(), "bolster" + T);
        for (int w = 0; w < truck.getNumWheelsets(); ++w)
            label(truck.getWheelset(w),
                  "wheelset" + T + (truck.getNumWheelsets() > 1 ? fmt::format("{}", w + 1) : std::string()));
    }
    return c;
}

Eigen::VectorXd getUDot(const RockingModel& model, const State& s) {
    model.getSystem().realize(s, Stage::Acceleration);
    const Vector& ud = s.getUDot();
    Eigen::VectorXd out(ud.size());
    for (int i = 0; i < ud.size(); ++i) out[i] = ud[i];
    return out;
}
}  // namespace

CarParameters makeModalCar(CarParameters car) {
    car.verticalFriction = 0;
    car.lateralFriction = 0;
    car.centerPlateFriction = 0;
    return car;
}

std::vector<Mode> calcModes(const RockingModel& model) {
    const State s0 = model.makeStaticState(false);
    const int nu = s0.getNU();
    const auto& matter = model.getMatter();

    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * nu, 2 * nu);
    A.topRightCorner(nu, nu).setIdentity();
    for (int i = 0; i < nu; ++i) {
        const double h = 1e-7;
        Eigen::VectorXd plus, minus;
        for (double sign : {1.0, -1.0}) {
            State s = s0;
            Vector du(nu, 0.0), dq;
            du[i] = sign * h;
            matter.multiplyByN(s0, false, du, dq);
            s.updQ() += dq;
            (sign > 0 ? plus : minus) = getUDot(model, s);
        }
        A.block(nu, i, nu, 1) = (plus - minus) / (2 * h);
        for (double sign : {1.0, -1.0}) {
            State s = s0;
            s.updU()[i] += sign * h;
            (sign > 0 ? plus : minus) = getUDot(model, s);
        }
        A.block(nu, nu + i, nu, 1) = (plus - minus) / (2 * h);
    }

    Matrix Msim;
    matter.calcM(s0, Msim);
    Eigen::MatrixXd M(nu, nu);
    for (int r = 0; r < nu; ++r)
        for (int c = 0; c < nu; ++c) M(r, c) = Msim(r, c);

    const std::vector<Coordinate> coords = describeMobilities(model, s0);
    const Eigen::EigenSolver<Eigen::MatrixXd> es(A);
    std::vector<Mode> modes;
    for (int k = 0; k < 2 * nu; ++k) {
        const std::complex<double> lambda = es.eigenvalues()[k];
        if (lambda.imag() <= 1e-9) continue;  // one of each conjugate pair; overdamped modes skipped
        const Eigen::VectorXcd x = es.eigenvectors().col(k).head(nu);
        // Kinetic-energy share of each mobility: Re(x̄_i (M x)_i) / Re(x̄ᵀ M x).
        const Eigen::VectorXcd Mx = M.cast<std::complex<double>>() * x;
        // Shares by body kind (car body, bolster, wheelset) and motion: symmetric
        // trucks and wheelsets share their modes, so no single body dominates them.
        std::map<std::pair<std::string, std::string>, double> share, byBody;
        double total = 0;
        for (int i = 0; i < nu; ++i) {
            const double e = std::max(0.0, (std::conj(x[i]) * Mx[i]).real());
            const std::string& b = coords[i].body;
            const std::string kind = b.rfind("car body", 0) == 0 ? "car body" : b.substr(0, b.find(' '));
            share[{kind, coords[i].motion}] += e;
            byBody[{b, coords[i].motion}] += e;
            total += e;
        }
        auto larger = [](const auto& a, const auto& b) { return a.second < b.second; };
        const auto best = std::max_element(share.begin(), share.end(), larger);
        Mode m;
        m.body = best->first.first;
        m.motion = best->first.second;
        m.energyShare = best->second / total;
        m.frequencyHz = std::abs(lambda) / (2 * M_PI);
        m.dampingRatio = -lambda.real() / std::abs(lambda);
        if (m.body == "car body" && (m.motion == "sway" || m.motion == "roll")) {
            const double sway = share[{"car body", "sway"}] / total, roll = share[{"car body", "roll"}] / total;
            if (std::min(sway, roll) > 0.1) m.motion = "sway-roll";
        }
        modes.push_back(m);
    }
    std::sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) { return a.frequencyHz < b.frequencyHz; });
    int swayRoll = 0;
    std::map<std::string, int> seen;
    for (Mode& m : modes) {
        if (m.motion == "sway-roll") m.name = m.body + (swayRoll++ == 0 ? " lower " : " upper ") + m.motion;
        else m.name = m.body + " " + m.motion;
        const int n = ++seen[m.name];
        if (n > 1) m.name += fmt::format(" ({})", n);  // the other trucks' and wheelsets' copies
    }
    return modes;
}

std::vector<UncoupledEstimate> calcTable1Estimates(const CarParameters& car) {
    const double g = units::g, Kv = car.springVerticalRate, Kh = car.springLateralRate;
    const double l = 2 * car.springOffset;
    const double M = car.bodyAndBolstersWeight / g;
    const double h = car.cgAboveCenterPlate + car.centerPlateAboveSprings;
    const double Mb = car.bolsterWeight / g, Mw = car.wheelsetWeight / g;
    auto hz = [](double w2) { return std::sqrt(w2) / (2 * M_PI); };
    // The report's printed values (its Table 1; scenarios/reference/mit1976.toml), 0 where it gives none.
    const Mit1976& ref = Mit1976::get();
    auto printed = [&](const char* body, const char* motion) {
        const std::string key = fmt::format("table1.{}.{}_{}", car.name, body, motion);
        return ref.has(key) ? ref(key, "Hz") : 0.0;
    };
    return {
        {"car body", "heave", hz(4 * Kv / M), printed("car_body", "heave")},
        {"car body", "sway", hz(4 * Kh / M), printed("car_body", "sway")},
        {"car body", "roll", hz(Kv * l * l / (car.rollInertia + M * h * h)), printed("car_body", "roll")},
        {"bolster", "heave", hz(4 * Kv / Mb), printed("bolster", "heave")},
        {"bolster", "sway", hz(4 * Kh / Mb), printed("bolster", "sway")},
        {"bolster", "roll", hz(Kv * l * l / car.bolsterRollInertia), printed("bolster", "roll")},
        {"wheelset", "heave", hz(4 * Kv / Mw), printed("wheelset", "heave")},
        {"wheelset", "sway", hz(4 * Kh / Mw), printed("wheelset", "sway")},
        {"wheelset", "roll", hz(Kv * l * l / car.wheelsetRollInertia), printed("wheelset", "roll")},
    };
}

}  // namespace rockroll
