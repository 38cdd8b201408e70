#include "bespoke/TruckEquilibrium.h"

#include "contacts/SpringGroupLaws.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rockroll {

namespace {
constexpr double kSide[2] = {+1.0, -1.0};
enum Unknown { ZB, TB, ZW, TW, FCL, FCR, FSL, FSR, WL, WR, PHIL, PHIR, YB, FH, PHIH, N };
using Row = Eigen::Matrix<double, 1, N>;

/// A quantity linear in the unknowns: row·x + c.
struct Linear {
    Row row = Row::Zero();
    double c = 0;
    double evaluate(const Eigen::Matrix<double, N, 1>& x) const { return row.dot(x) + c; }
};

bool closesRim(CarBodySupport s, int side) {
    using S = CarBodySupport;
    switch (s) {
    case S::TwoPointCenterPlate: return true;
    case S::CornerLeft: case S::SideBearingAndCornerLeft: return side == 0;
    case S::CornerRight: case S::SideBearingAndCornerRight: return side == 1;
    default: return false;
    }
}

bool closesSideBearing(CarBodySupport s, int side) {
    using S = CarBodySupport;
    if (s == S::SideBearingAndCornerLeft || s == S::SideBearingLeft) return side == 0;
    if (s == S::SideBearingAndCornerRight || s == S::SideBearingRight) return side == 1;
    return false;
}

bool liftsWheel(WheelContact w, int side) {
    return (w == WheelContact::LiftLeft && side == 0) || (w == WheelContact::LiftRight && side == 1);
}

struct Kinematics {
    std::array<Linear, 2> rimGap, padGap, compression, treadLift;
    Linear lateral;  ///< Y = y_b − y_seat = y_b + θ_w·h_st
};

Kinematics makeKinematics(const TruckGeometry& g, const TruckInputs& in) {
    Kinematics k;
    const double seatHeight = g.springTopAboveRail - g.wheelRadius;
    for (int i : {0, 1}) {
        const double s = kSide[i];
        // Bolster rim: z_b + h_cp + θ_b·s·a_c; gap = car body rim − bolster rim.
        k.rimGap[i].row[ZB] = -1;
        k.rimGap[i].row[TB] = -s * g.a_c;
        k.rimGap[i].c = in.rimZ[i] - g.cpAboveSprings;
        // Side bearing top: z_b + h_sb + θ_b·s·a_s; gap = pad + clearance − top.
        k.padGap[i].row[ZB] = -1;
        k.padGap[i].row[TB] = -s * g.a_s;
        k.padGap[i].c = in.padZ[i] + g.clearance - g.sbAboveSprings;
        // Compression Z = seat − bolster end = (z_w + h_seat + θ_w·s·l_s) − (z_b + θ_b·s·l_s).
        k.compression[i].row[ZW] = 1;
        k.compression[i].row[TW] = s * g.l_s;
        k.compression[i].row[ZB] = -1;
        k.compression[i].row[TB] = -s * g.l_s;
        k.compression[i].c = seatHeight;
        // Tread above rail: z_w − R + θ_w·s·g/2 − rail.
        k.treadLift[i].row[ZW] = 1;
        k.treadLift[i].row[TW] = s * g.halfGauge;
        k.treadLift[i].c = -g.wheelRadius - in.railZ[i];
    }
    k.lateral.row[YB] = 1;
    k.lateral.row[TW] = g.springTopAboveRail;
    return k;
}

/// Spring force of the assumed segment, linear in the unknowns.
Linear makeSpringForce(const TruckGeometry& g, const Linear& Z, SpringSegment seg) {
    Linear P;
    if (seg == SpringSegment::Linear) {
        P.row = g.Kv * Z.row;
        P.c = g.Kv * Z.c;
    } else if (seg == SpringSegment::Bottomed) {
        P.row = g.Kb * Z.row;
        P.c = g.Kb * Z.c + (g.Kv - g.Kb) * g.travel;
    }
    return P;
}
}  // namespace

std::string TruckMode::describe() const {
    static const char* support[] = {"center plate two-point", "corner L", "corner R", "side bearing L + corner L",
                                    "side bearing R + corner R", "side bearing L", "side bearing R", "no contact"};
    static const char* wheels[] = {"both wheels", "left wheel lifted", "right wheel lifted"};
    static const char* wedge[] = {"stick", "slip up", "slip down"};
    static const char* spring[] = {"free", "linear", "bottomed"};
    static const char* gibs[] = {"gibs open", "gib +", "gib −"};
    return fmt::format("{}, {}, wedges {}/{}, springs {}/{}, lateral wedges {}, {}", support[int(this->support)],
                       wheels[int(this->wheels)], wedge[int(this->wedge[0])], wedge[int(this->wedge[1])],
                       spring[int(this->spring[0])], spring[int(this->spring[1])], wedge[int(lateralWedge)],
                       gibs[int(gib)]);
}

std::vector<TruckMode> enumerateTruckModes() {
    std::vector<TruckMode> modes;
    for (int s = 0; s < 8; ++s)
        for (int w = 0; w < 3; ++w)
            for (int sp = 0; sp < 9; ++sp)
                for (int f = 0; f < 9; ++f) {
                    TruckMode m;
                    m.support = CarBodySupport(s);
                    m.wheels = WheelContact(w);
                    m.spring = {SpringSegment((sp / 3 + 1) % 3), SpringSegment((sp % 3 + 1) % 3)};  // linear first
                    m.wedge = {WedgeState(f / 3), WedgeState(f % 3)};
                    for (int lat = 0; lat < 9; ++lat) {
                        m.lateralWedge = WedgeState(lat / 3);
                        m.gib = GibContact(lat % 3);
                        modes.push_back(m);
                    }
                }
    return modes;
}

TruckGeometry::TruckGeometry(const CarParameters& car)
    : a_c(car.centerPlateDiameter / 2), a_s(car.sideBearingOffset), l_s(car.springOffset), halfGauge(car.gauge / 2),
      cpAboveSprings(car.centerPlateAboveSprings), sbAboveSprings(car.sideBearingAboveSprings),
      springTopAboveRail(car.springTopAboveRail), wheelRadius(car.wheelRadius), clearance(car.sideBearingClearance),
      Kv(car.springVerticalRate), travel(car.springTravel), Kb(car.bottomingRate), Fv(car.verticalFriction),
      kBristle(car.verticalFriction / car.frictionBristleDeflection), Kh(car.springLateralRate),
      gibClearance(car.gibClearance), Kgib(car.gibRate), Fh(car.lateralFriction),
      kBristleLateral(car.lateralFriction / car.frictionBristleDeflection),
      kPin(car.contactStiffnessScale * car.centerPinStiffness) {}

TruckSolution solveTruckMode(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode) {
    const Kinematics k = makeKinematics(g, in);
    std::array<Linear, 2> P, load;  // spring force; spring + friction on the bolster
    for (int i : {0, 1}) {
        P[i] = makeSpringForce(g, k.compression[i], mode.spring[i]);
        load[i] = P[i];
        load[i].row[i == 0 ? PHIL : PHIR] += 1;
    }
    Eigen::Matrix<double, N, N> A = Eigen::Matrix<double, N, N>::Zero();
    Eigen::Matrix<double, N, 1> b = Eigen::Matrix<double, N, 1>::Zero();
    auto set = [&](int eq, const Linear& lhs, double rhs) {
        A.row(eq) = lhs.row;
        b[eq] = rhs - lhs.c;
    };
    auto unknown = [](int u) {
        Linear l;
        l.row[u] = 1;
        return l;
    };
    Linear e;
    // Bolster and wheelset balances.
    e = Linear{};
    e.row[FCL] = e.row[FCR] = e.row[FSL] = e.row[FSR] = -1;
    e.row += load[0].row + load[1].row;
    e.c = load[0].c + load[1].c - g.bolsterWeight;
    set(0, e, 0);
    e = Linear{};
    e.row[FCL] = -g.a_c, e.row[FCR] = g.a_c, e.row[FSL] = -g.a_s, e.row[FSR] = g.a_s;
    e.row += g.l_s * (load[0].row - load[1].row);
    e.row[FH] += g.cpAboveSprings;
    e.c = g.l_s * (load[0].c - load[1].c);
    set(1, e, 0);
    e = Linear{};
    e.row[WL] = e.row[WR] = 1;
    e.row -= load[0].row + load[1].row;
    e.c = -(load[0].c + load[1].c) - g.wheelsetWeight;
    set(2, e, 0);
    e = Linear{};
    e.row[WL] = g.halfGauge, e.row[WR] = -g.halfGauge;
    e.row -= g.l_s * (load[0].row - load[1].row);
    e.row[FH] += g.springTopAboveRail;
    e.c = -g.l_s * (load[0].c - load[1].c);
    set(3, e, 0);
    // Center pin: F_h + k_pin (y_plate − y_b + θ_b h_cp) = 0.
    e = Linear{};
    e.row[FH] = 1, e.row[YB] = -g.kPin, e.row[TB] = g.kPin * g.cpAboveSprings;
    set(12, e, -g.kPin * in.plateY);
    // Bolster lateral balance: −F_h − 2 f₂(Y) − Φ_H = 0.
    const double gibSign = mode.gib == GibContact::Positive ? 1 : (mode.gib == GibContact::Negative ? -1 : 0);
    const double kLat = 2 * (g.Kh + (gibSign != 0 ? g.Kgib : 0));
    e = Linear{};
    e.row[FH] = -1, e.row[PHIH] = -1;
    e.row -= kLat * k.lateral.row;
    e.c = -kLat * k.lateral.c + 2 * g.Kgib * gibSign * g.gibClearance;
    set(13, e, 0);
    // Lateral wedges.
    switch (mode.lateralWedge) {
    case WedgeState::Stick: {
        Linear stick = unknown(PHIH);
        stick.row -= 2 * g.kBristleLateral * k.lateral.row;
        stick.c = -2 * g.kBristleLateral * k.lateral.c;
        set(14, stick, -2 * g.kBristleLateral * in.lateralAnchor);
        break;
    }
    case WedgeState::SlipUp: set(14, unknown(PHIH), 2 * g.Fh); break;
    case WedgeState::SlipDown: set(14, unknown(PHIH), -2 * g.Fh); break;
    }
    // Contacts, wheels, wedges.
    for (int i : {0, 1}) {
        if (closesRim(mode.support, i)) set(4 + i, k.rimGap[i], 0);
        else set(4 + i, unknown(FCL + i), 0);
        if (closesSideBearing(mode.support, i)) set(6 + i, k.padGap[i], 0);
        else set(6 + i, unknown(FSL + i), 0);
        if (liftsWheel(mode.wheels, i)) set(8 + i, unknown(WL + i), 0);
        else set(8 + i, k.treadLift[i], 0);
        switch (mode.wedge[i]) {
        case WedgeState::Stick: {  // Φ − k_b·Z = −k_b·Z_a
            Linear stick = unknown(PHIL + i);
            stick.row -= g.kBristle * k.compression[i].row;
            stick.c = -g.kBristle * k.compression[i].c;
            set(10 + i, stick, -g.kBristle * in.wedgeAnchor[i]);
            break;
        }
        case WedgeState::SlipUp: set(10 + i, unknown(PHIL + i), -g.Fv); break;
        case WedgeState::SlipDown: set(10 + i, unknown(PHIL + i), g.Fv); break;
        }
    }

    TruckSolution sol;
    sol.mode = mode;
    // Equilibrate: unknowns in mm, mrad and 10 kN, then every row to unit max,
    // so the rank test compares like with like (spring rows carry 1e7 N/m).
    Eigen::Matrix<double, N, 1> colScale;
    colScale << 1e-3, 1e-3, 1e-3, 1e-3, 1e4, 1e4, 1e4, 1e4, 1e4, 1e4, 1e4, 1e4, 1e-3, 1e4, 1e4;
    Eigen::Matrix<double, N, N> As = A * colScale.asDiagonal();
    Eigen::Matrix<double, N, 1> bs = b;
    for (int r = 0; r < N; ++r) {
        const double m = As.row(r).cwiseAbs().maxCoeff();
        if (m > 0) As.row(r) /= m, bs[r] /= m;
    }
    const Eigen::FullPivLU<Eigen::Matrix<double, N, N>> lu(As);
    if (!lu.isInvertible()) {
        sol.violation = 1e300;
        return sol;
    }
    const Eigen::Matrix<double, N, 1> x = colScale.asDiagonal() * lu.solve(bs);
    sol.zBolster = x[ZB], sol.rollBolster = x[TB], sol.zWheelset = x[ZW], sol.rollWheelset = x[TW];
    sol.yBolster = x[YB], sol.pinForce = x[FH], sol.lateralFriction = x[PHIH];
    sol.lateral = k.lateral.evaluate(x);
    double worst = 0;  // forces in units of 10 kN, lengths in units of 0.1 mm
    auto needAtLeast = [&worst](double value, double minimum, double unit) {
        worst = std::max(worst, (minimum - value) / unit);
    };
    for (int i : {0, 1}) {
        sol.rim[i] = x[FCL + i], sol.sideBearing[i] = x[FSL + i], sol.wheel[i] = x[WL + i];
        sol.friction[i] = x[PHIL + i];
        sol.compression[i] = k.compression[i].evaluate(x);
        sol.spring[i] = P[i].evaluate(x);
        sol.wheelLift[i] = std::max(0.0, k.treadLift[i].evaluate(x));
        needAtLeast(sol.rim[i], 0, 1e4);
        needAtLeast(sol.sideBearing[i], 0, 1e4);
        needAtLeast(sol.wheel[i], 0, 1e4);
        needAtLeast(k.rimGap[i].evaluate(x), 0, 1e-4);
        needAtLeast(k.padGap[i].evaluate(x), 0, 1e-4);
        needAtLeast(k.treadLift[i].evaluate(x), 0, 1e-4);
        const double Z = sol.compression[i];
        switch (mode.spring[i]) {
        case SpringSegment::Free: needAtLeast(0, Z, 1e-4); break;
        case SpringSegment::Linear: needAtLeast(Z, 0, 1e-4), needAtLeast(g.travel, Z, 1e-4); break;
        case SpringSegment::Bottomed: needAtLeast(Z, g.travel, 1e-4); break;
        }
        const double dZ = Z - in.compressionOld[i];
        sol.wedgeAnchor[i] = mode.wedge[i] == WedgeState::Stick ? in.wedgeAnchor[i] : Z - sol.friction[i] / g.kBristle;
        switch (mode.wedge[i]) {
        case WedgeState::Stick: needAtLeast(g.Fv, std::abs(sol.friction[i]), 1e4); break;
        case WedgeState::SlipUp: needAtLeast(0, dZ, 1e-4); break;    // Z falling
        case WedgeState::SlipDown: needAtLeast(dZ, 0, 1e-4); break;  // Z rising
        }
    }
    const double Y = sol.lateral, dY = Y - in.lateralOld;
    switch (mode.gib) {
    case GibContact::Open: needAtLeast(Y, -g.gibClearance, 1e-4), needAtLeast(g.gibClearance, Y, 1e-4); break;
    case GibContact::Positive: needAtLeast(Y, g.gibClearance, 1e-4); break;
    case GibContact::Negative: needAtLeast(-g.gibClearance, Y, 1e-4); break;
    }
    switch (mode.lateralWedge) {
    case WedgeState::Stick: needAtLeast(2 * g.Fh, std::abs(sol.lateralFriction), 1e4); break;
    case WedgeState::SlipUp: needAtLeast(dY, 0, 1e-4); break;
    case WedgeState::SlipDown: needAtLeast(0, dY, 1e-4); break;
    }
    sol.lateralAnchor = mode.lateralWedge == WedgeState::Stick
                            ? in.lateralAnchor
                            : Y - sol.lateralFriction / (2 * g.kBristleLateral);
    sol.violation = worst;
    sol.consistent = worst <= 1e-9;
    return sol;
}

std::vector<TruckMode> findNeighbourModes(const TruckMode& m) {
    std::vector<TruckMode> out;
    auto push = [&](auto setter, int count) {
        for (int v = 0; v < count; ++v) {
            TruckMode c = m;
            setter(c, v);
            if (!(c == m)) out.push_back(c);
        }
    };
    push([](TruckMode& c, int v) { c.support = CarBodySupport(v); }, 8);
    push([](TruckMode& c, int v) { c.wheels = WheelContact(v); }, 3);
    push([](TruckMode& c, int v) { c.wedge[0] = WedgeState(v); }, 3);
    push([](TruckMode& c, int v) { c.wedge[1] = WedgeState(v); }, 3);
    push([](TruckMode& c, int v) { c.spring[0] = SpringSegment(v); }, 3);
    push([](TruckMode& c, int v) { c.spring[1] = SpringSegment(v); }, 3);
    push([](TruckMode& c, int v) { c.lateralWedge = WedgeState(v); }, 3);
    push([](TruckMode& c, int v) { c.gib = GibContact(v); }, 3);
    return out;
}

TruckSolution findTruckEquilibrium(const TruckGeometry& g, const TruckInputs& in, const TruckMode& previous) {
    // 1. The previous mode; 2. every mode that differs from it in one choice,
    // then in two (contacts often open and close together); 3. every mode.
    // First consistent wins; else the smallest violation.
    TruckSolution best = solveTruckMode(g, in, previous);
    if (best.consistent) return best;
    const std::vector<TruckMode> first = findNeighbourModes(previous);
    for (const TruckMode& m : first) {
        TruckSolution s = solveTruckMode(g, in, m);
        if (s.consistent) return s;
        if (s.violation < best.violation) best = s;
    }
    for (const TruckMode& n : first)
        for (const TruckMode& m : findNeighbourModes(n)) {
            if (m == previous) continue;
            TruckSolution s = solveTruckMode(g, in, m);
            if (s.consistent) return s;
            if (s.violation < best.violation) best = s;
        }
    static const std::vector<TruckMode> modes = enumerateTruckModes();
    for (const TruckMode& m : modes) {
        TruckSolution s = solveTruckMode(g, in, m);
        if (s.consistent) return s;
        if (s.violation < best.violation) best = s;
    }
    return best;
}

}  // namespace rockroll
