#include "bespoke/TruckEquilibrium.h"

#include "bespoke/FullPivotLu.h"
#include "bespoke/TruckModeFactor.h"

#include "contacts/SpringGroupLaws.h"
#include "mbmodel/CarSide.h"
#include "mbmodel/HugePageMemory.h"

#include <algorithm>
#include <atomic>
#include <bitset>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <deque>
#include <mutex>
#include <cstdint>
#include <memory>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <fmt/format.h>

namespace rockroll {

namespace {
enum Unknown { ZB, TB, ZW, TW, FCL, FCR, FSL, FSR, WL, WR, PHIL, PHIR, YB, FH, PHIH, N };
/// The quantities the consistency checks read (left, right where paired): each a row
/// of the unknowns plus a constant (Kinematics).
enum CheckedQuantity {
    kRimForce = 0, kSideBearingForce = 2, kWheelForce = 4, kWedgeFriction = 6, kLateralFriction = 8,
    kRimGap = 9, kPadGap = 11, kTreadLift = 13, kCompression = 15, kLateral = 17, kCheckedCount = 18
};
/// The units of a violation: forces in 10 kN, lengths in 0.1 mm.
constexpr double kForceUnit = 1e4, kLengthUnit = 1e-4;
/// The unit of a violation of a check on quantity q (checkInequalities).
constexpr double getUnit(int q) { return q < kRimGap ? kForceUnit : kLengthUnit; }
/// Whether every mode checks q ≥ 0, as it is (the contact and wheel forces, the gaps, the lifts).
constexpr bool isCheckedAtLeastZero(int q) {
    return (q >= kRimForce && q < kWedgeFriction) || (q >= kRimGap && q < kCompression);
}
using Row = Eigen::Matrix<double, 1, N>;

/// A quantity linear in the unknowns: row·x + c.
struct Linear {
    Row row = Row::Zero();
    double c = 0;
    double evaluate(const Eigen::Matrix<double, N, 1>& x) const { return row.dot(x) + c; }
};

/// The contacts each support closes and the wheels each wheel contact lifts, [choice][side]
/// (CarBodySupport: two-point, corner L, R, side bearing and corner L, R, side bearing L, R,
/// none; WheelContact: both, lift L, R).
constexpr bool kClosesRim[8][2] = {{true, true},  {true, false}, {false, true}, {true, false},
                                   {false, true}, {false, false}, {false, false}, {false, false}};
constexpr bool kClosesSideBearing[8][2] = {{false, false}, {false, false}, {false, false}, {true, false},
                                           {false, true},  {true, false},  {false, true},  {false, false}};
constexpr bool kLiftsWheel[3][2] = {{false, false}, {true, false}, {false, true}};

bool closesRim(CarBodySupport s, int side) { return kClosesRim[int(s)][side]; }
bool closesSideBearing(CarBodySupport s, int side) { return kClosesSideBearing[int(s)][side]; }
bool liftsWheel(WheelContact w, int side) { return kLiftsWheel[int(w)][side]; }

struct Kinematics {
    std::array<Linear, 2> rimGap, padGap, compression, treadLift;
    Linear lateral;  ///< Y = y_b − y_seat = y_b + θ_w·h_st
};

Kinematics makeKinematics(const TruckGeometry& g, const TruckInputs& in) {
    Kinematics k;
    const double seatHeight = g.springTopAboveRail - g.wheelRadius;
    for (int i : {0, 1}) {
        const double s = kSideSign[i];
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

/// The constant of the spring force of the assumed segment (Z's constant c).
double calcSpringConstant(const TruckGeometry& g, double c, SpringSegment seg) {
    if (seg == SpringSegment::Linear) return g.Kv * c;
    if (seg == SpringSegment::Bottomed) return g.Kb * c + (g.Kv - g.Kb) * g.travel;
    return 0;
}

/// Spring force of the assumed segment, linear in the unknowns.
Linear makeSpringForce(const TruckGeometry& g, const Linear& Z, SpringSegment seg) {
    Linear P;
    if (seg == SpringSegment::Linear) P.row = g.Kv * Z.row;
    else if (seg == SpringSegment::Bottomed) P.row = g.Kb * Z.row;
    P.c = calcSpringConstant(g, Z.c, seg);
    return P;
}
/// A mode's two spring forces P_i = row_i·x + c_i (makeSpringForce's rows and constants).
struct SpringForces {
    std::array<const Row*, 2> row{};
    std::array<double, 2> c{};
    double evaluate(int i, const Eigen::Matrix<double, N, 1>& x) const { return row[size_t(i)]->dot(x) + c[size_t(i)]; }
};

/// The mode's 15 equations A·x = b (x unscaled: m, rad, N).
void assembleSystem(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode, const Kinematics& k,
                    const std::array<Linear, 2>& P, Eigen::Matrix<double, N, N>& A, Eigen::Matrix<double, N, 1>& b) {
    std::array<Linear, 2> load;  // spring + friction on the bolster
    for (int i : {0, 1}) {
        load[i] = P[i];
        load[i].row[i == 0 ? PHIL : PHIR] += 1;
    }
    A.setZero();
    b.setZero();
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
}

/// The entries of assembleSystem's b for every choice, each by the same expression, so that a
/// search's many right-hand sides are look-ups (bit-identical: test
/// ReducedModel.CachedModeSolveIsBitIdenticalToTheDirectSolve); A is cached per mode.
struct RhsTable {
    double plate = 0;                                        ///< b[12]
    std::array<double, 3> gib{}, lateralWedge{};              ///< b[13] by GibContact, b[14] by WedgeState
    std::array<std::array<double, 2>, 2> rim{}, pad{}, tread{};  ///< b[4 + i], b[6 + i] [side][closed], b[8 + i] [side][lifted]
    std::array<std::array<double, 3>, 2> wedge{};             ///< b[10 + i] [side][WedgeState]
    double bolsterWeight = 0, wheelsetWeight = 0, l_s = 0;

    RhsTable(const TruckGeometry& g, const TruckInputs& in, const Kinematics& k)
        : bolsterWeight(g.bolsterWeight), wheelsetWeight(g.wheelsetWeight), l_s(g.l_s) {
        plate = -g.kPin * in.plateY - 0.0;
        for (int c = 0; c < 3; ++c) {
            const double gibSign = c == int(GibContact::Positive) ? 1 : (c == int(GibContact::Negative) ? -1 : 0);
            const double kLat = 2 * (g.Kh + (gibSign != 0 ? g.Kgib : 0));
            gib[size_t(c)] = 0 - (-kLat * k.lateral.c + 2 * g.Kgib * gibSign * g.gibClearance);
        }
        lateralWedge = {-2 * g.kBristleLateral * in.lateralAnchor - -2 * g.kBristleLateral * k.lateral.c,
                        2 * g.Fh - 0.0, -2 * g.Fh - 0.0};
        for (int i : {0, 1}) {
            rim[size_t(i)] = {0 - 0.0, 0 - k.rimGap[i].c};
            pad[size_t(i)] = {0 - 0.0, 0 - k.padGap[i].c};
            tread[size_t(i)] = {0 - k.treadLift[i].c, 0 - 0.0};
            wedge[size_t(i)] = {-g.kBristle * in.wedgeAnchor[i] - -g.kBristle * k.compression[i].c, -g.Fv - 0.0,
                                g.Fv - 0.0};
        }
    }
    /// b of the mode, with its two springs' constants.
    void fill(const TruckMode& mode, const std::array<double, 2>& springConstant, Eigen::Matrix<double, N, 1>& b) const {
        const double load0 = springConstant[0], load1 = springConstant[1];  // the friction unknowns add no constant
        b[0] = 0 - (load0 + load1 - bolsterWeight);
        b[1] = 0 - l_s * (load0 - load1);
        b[2] = 0 - (-(load0 + load1) - wheelsetWeight);
        b[3] = 0 - -l_s * (load0 - load1);
        b[12] = plate;
        b[13] = gib[size_t(mode.gib)];
        b[14] = lateralWedge[size_t(mode.lateralWedge)];
        for (int i : {0, 1}) {
            b[4 + i] = rim[size_t(i)][closesRim(mode.support, i)];
            b[6 + i] = pad[size_t(i)][closesSideBearing(mode.support, i)];
            b[8 + i] = tread[size_t(i)][liftsWheel(mode.wheels, i)];
            b[10 + i] = wedge[size_t(i)][size_t(mode.wedge[i])];
        }
    }
};

}  // namespace

static_assert(N == truck_equilibrium_detail::kUnknownCount &&
              kCheckedCount == truck_equilibrium_detail::kCheckedQuantityCount);
using truck_equilibrium_detail::ModeFactor;

namespace {

const Eigen::Matrix<double, N, 1>& getColumnScale() {
    // Unknowns in mm, mrad and 10 kN.
    static const Eigen::Matrix<double, N, 1> colScale = [] {
        Eigen::Matrix<double, N, 1> c;
        c << 1e-3, 1e-3, 1e-3, 1e-3, 1e4, 1e4, 1e4, 1e4, 1e4, 1e4, 1e4, 1e4, 1e-3, 1e4, 1e4;
        return c;
    }();
    return colScale;
}

/// Equilibrates A: unknowns in mm, mrad and 10 kN, then every row to unit max, so the
/// rank test compares like with like (spring rows carry 1e7 N/m). rowScale: each
/// row's largest |coefficient| before its division (0: the row is left as it is).
Eigen::Matrix<double, N, N> scaleSystem(const Eigen::Matrix<double, N, N>& A, Eigen::Matrix<double, N, 1>& rowScale) {
    Eigen::Matrix<double, N, N> As = A * getColumnScale().asDiagonal();
    for (int r = 0; r < N; ++r) {
        const double m = As.row(r).cwiseAbs().maxCoeff();
        rowScale[r] = m;
        if (m > 0) As.row(r) /= m;
    }
    return As;
}

/// The scaled system's factorization (Eigen's FullPivLU, bit for bit), before a
/// ModeFactor keeps it (keepFactor) in the room it needs (ModeFactor::getBytes(lu.getMatrixLU())).
struct ScaledLu {
    Eigen::Matrix<double, N, 1> rowScale;
    FullPivotLu<N> lu;
    explicit ScaledLu(const Eigen::Matrix<double, N, N>& A) : lu(scaleSystem(A, rowScale)) {}
};

void keepFactor(const ScaledLu& s, ModeFactor& f) {
    f.rowScale = s.rowScale;
    f.invertible = s.lu.isInvertible();
    for (int i = 0; i < N; ++i)
        f.p[i] = std::uint8_t(s.lu.getRowPermutation()[i]), f.q[i] = std::uint8_t(s.lu.getColumnPermutation()[i]);
    f.compress(s.lu.getMatrixLU());
}

/// x from the factorization: b row-scaled, solved, unknowns unscaled.
Eigen::Matrix<double, N, 1> solveScaled(const ModeFactor& f, const Eigen::Matrix<double, N, 1>& b,
                                        TruckSubstitution substitution = TruckSubstitution::Sparse) {
    const Eigen::Matrix<double, N, 1>& colScale = getColumnScale();
    return substitution == TruckSubstitution::Sparse ? f.solve(b, colScale) : f.solveDense(b, colScale);
}

/// A quantity a check reads, and a bound on its absolute error: 0 from a solve (the
/// value the checks decide on), the screen's bound from its sums (ScreenValues). The
/// bound is named, not computed: the screened quantity errorOf's bound (none when −1)
/// plus errorAdded. A screen computes it only for a check the value alone fails
/// (ScreenValues::getError), since a bound ≥ 0 can only turn a failed check into an
/// undecided one.
struct Checked {
    double value = 0;
    int errorOf = -1;
    double errorAdded = 0;
};

/// Every inequality of a mode, as need(value, minimum, unit) for "value ≥ minimum",
/// whose violation is (minimum − value)/unit (forces in units of 10 kN, lengths in
/// units of 0.1 mm), on the quantities v(f) gives (SolvedValues: from the mode's
/// solution x). need returns false to stop early. The one definition of the checks:
/// solveFactored takes the largest violation (the mode is consistent when it is at most
/// kConsistentViolation), the screen stops at the first one certainly above it. The forces
/// come first: they are unknowns themselves, and most modes that fail fail on one.
template <class Values, class Need>
void checkInequalities(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode, Values&& v, Need&& need) {
    const Checked zero{};
    auto exact = [](double value) { return Checked{value}; };
    for (int i : {0, 1})
        if (!need(v(kRimForce + i), zero, kForceUnit) || !need(v(kSideBearingForce + i), zero, kForceUnit) ||
            !need(v(kWheelForce + i), zero, kForceUnit))
            return;
    for (int i : {0, 1}) {
        if (!need(v(kRimGap + i), zero, kLengthUnit) || !need(v(kPadGap + i), zero, kLengthUnit) ||
            !need(v(kTreadLift + i), zero, kLengthUnit))
            return;
        const Checked Z = v(kCompression + i);
        switch (mode.spring[i]) {
        case SpringSegment::Free:
            if (!need(zero, Z, kLengthUnit)) return;
            break;
        case SpringSegment::Linear:
            if (!need(Z, zero, kLengthUnit) || !need(exact(g.travel), Z, kLengthUnit)) return;
            break;
        case SpringSegment::Bottomed:
            if (!need(Z, exact(g.travel), kLengthUnit)) return;
            break;
        }
        const Checked dZ{Z.value - in.compressionOld[i], Z.errorOf,
                         Z.errorAdded + 1e-15 * std::abs(in.compressionOld[i])};
        switch (mode.wedge[i]) {
        case WedgeState::Stick: {
            const Checked phi = v(kWedgeFriction + i);
            if (!need(exact(g.Fv), Checked{std::abs(phi.value), phi.errorOf, phi.errorAdded}, kForceUnit)) return;
            break;
        }
        case WedgeState::SlipUp:  // Z falling
            if (!need(zero, dZ, kLengthUnit)) return;
            break;
        case WedgeState::SlipDown:  // Z rising
            if (!need(dZ, zero, kLengthUnit)) return;
            break;
        }
    }
    const Checked Y = v(kLateral);
    const Checked dY{Y.value - in.lateralOld, Y.errorOf, Y.errorAdded + 1e-15 * std::abs(in.lateralOld)};
    switch (mode.gib) {
    case GibContact::Open:
        if (!need(Y, exact(-g.gibClearance), kLengthUnit) || !need(exact(g.gibClearance), Y, kLengthUnit)) return;
        break;
    case GibContact::Positive:
        if (!need(Y, exact(g.gibClearance), kLengthUnit)) return;
        break;
    case GibContact::Negative:
        if (!need(exact(-g.gibClearance), Y, kLengthUnit)) return;
        break;
    }
    switch (mode.lateralWedge) {
    case WedgeState::Stick: {
        const Checked phi = v(kLateralFriction);
        need(exact(2 * g.Fh), Checked{std::abs(phi.value), phi.errorOf, phi.errorAdded}, kForceUnit);
        break;
    }
    case WedgeState::SlipUp: need(dY, zero, kLengthUnit); break;
    case WedgeState::SlipDown: need(zero, dY, kLengthUnit); break;
    }
}

/// The unknown a checked force is (q < kRimGap).
int getCheckedUnknown(int q) {
    static constexpr int unknown[kRimGap] = {FCL, FCR, FSL, FSR, WL, WR, PHIL, PHIR, PHIH};
    return unknown[q];
}

/// The kinematic quantity a checked length is (q ≥ kRimGap): its row and constant.
const Linear& getCheckedKinematics(const Kinematics& k, int q) {
    const int i = (q - kRimGap) % 2;
    return q < kPadGap ? k.rimGap[i]
           : q < kTreadLift ? k.padGap[i]
           : q < kCompression ? k.treadLift[i]
           : q < kLateral ? k.compression[i]
                          : k.lateral;
}

/// The checked quantities from a mode's solution x.
struct SolvedValues {
    const Kinematics& k;
    const Eigen::Matrix<double, N, 1>& x;
    Checked operator()(int q) const {
        return {q < kRimGap ? x[getCheckedUnknown(q)] : getCheckedKinematics(k, q).evaluate(x)};
    }
};

/// Solves with the factorization and checks every inequality of the mode.
TruckSolution solveFactored(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode, const Kinematics& k,
                            const SpringForces& P, const ModeFactor& f, const Eigen::Matrix<double, N, 1>& b,
                            TruckSubstitution substitution = TruckSubstitution::Sparse) {
    TruckSolution sol;
    sol.mode = mode;
    if (!f.invertible) {
        sol.violation = 1e300;
        return sol;
    }
    const Eigen::Matrix<double, N, 1> x = solveScaled(f, b, substitution);
    // Every checked quantity once: the solution's fields and the checks read the same values.
    std::array<double, kCheckedCount> quantity;
    const SolvedValues solved{k, x};
    // Unrolled, so that each quantity's row is chosen at compile time (bench/README.md, "The
    // search's bookkeeping").
#pragma GCC unroll 18
    for (int q = 0; q < kCheckedCount; ++q) quantity[size_t(q)] = solved(q).value;
    sol.zBolster = x[ZB], sol.rollBolster = x[TB], sol.zWheelset = x[ZW], sol.rollWheelset = x[TW];
    sol.yBolster = x[YB], sol.pinForce = x[FH], sol.lateralFriction = x[PHIH];
    sol.lateral = quantity[kLateral];
    for (int i : {0, 1}) {
        sol.rim[i] = x[FCL + i], sol.sideBearing[i] = x[FSL + i], sol.wheel[i] = x[WL + i];
        sol.friction[i] = x[PHIL + i];
        sol.compression[i] = quantity[size_t(kCompression + i)];
        sol.spring[i] = P.evaluate(i, x);
        sol.wheelLift[i] = std::max(0.0, quantity[size_t(kTreadLift + i)]);
        sol.wedgeAnchor[i] =
            mode.wedge[i] == WedgeState::Stick ? in.wedgeAnchor[i] : sol.compression[i] - sol.friction[i] / g.kBristle;
    }
    sol.lateralAnchor = mode.lateralWedge == WedgeState::Stick
                            ? in.lateralAnchor
                            : sol.lateral - sol.lateralFriction / (2 * g.kBristleLateral);
    double worst = 0;  // a NaN check leaves it as it is, as std::max does
    checkInequalities(g, in, mode, [&quantity](int q) { return Checked{quantity[size_t(q)]}; },
                      [&worst](Checked value, Checked minimum, double unit) {
                          worst = std::max(worst, (minimum.value - value.value) / unit);
                          return true;
                      });
    sol.violation = worst;
    sol.consistent = worst <= kConsistentViolation;
    return sol;
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
      kBristle(car.calcVerticalBristleStiffness()), Kh(car.springLateralRate),
      gibClearance(car.gibClearance), Kgib(car.gibRate), Fh(car.lateralFriction),
      kBristleLateral(car.calcLateralBristleStiffness()),
      kPin(car.contactStiffnessScale * car.centerPinStiffness) {}

TruckSolution solveTruckMode(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode,
                             TruckSubstitution substitution) {
    const Kinematics k = makeKinematics(g, in);
    std::array<Linear, 2> P;
    for (int i : {0, 1}) P[i] = makeSpringForce(g, k.compression[i], mode.spring[i]);
    Eigen::Matrix<double, N, N> A;
    Eigen::Matrix<double, N, 1> b;
    assembleSystem(g, in, mode, k, P, A, b);
    truck_equilibrium_detail::ModeFactorWithRoom room;
    keepFactor(ScaledLu(A), room.factor);
    const SpringForces springs{{&P[0].row, &P[1].row}, {P[0].c, P[1].c}};
    return solveFactored(g, in, mode, k, springs, room.factor, b, substitution);
}

namespace {
/// A⁻¹ (unscaled) from the factorization, every column at once: solveScaled's steps
/// on the identity, each substitution a row operation over the factors' nonzero
/// entries. For the screen's rows only: its rounding differs from solveScaled's, which
/// the screen's error bound covers (test ReducedModel.ScreenErrorBoundCoversTheSolve).
Eigen::Matrix<double, N, N, Eigen::RowMajor> calcInverse(const ModeFactor& f) {
    Eigen::Matrix<double, N, N, Eigen::RowMajor> c = Eigen::Matrix<double, N, N, Eigen::RowMajor>::Zero();
    for (int i = 0; i < N; ++i) c(f.p[i], i) = f.rowScale[i] > 0 ? 1 / f.rowScale[i] : 1.0;
    const double* value = f.getValues();
    for (int i = 1; i < N; ++i)
        for (int k = f.lowerStart[i]; k < f.lowerStart[i + 1]; ++k) c.row(i) -= value[k] * c.row(f.column[k]);
    for (int i = N - 1; i >= 0; --i) {
        for (int k = f.upperStart[i]; k < f.upperStart[i + 1]; ++k) c.row(i) -= value[k] * c.row(f.column[k]);
        c.row(i) /= f.diagonal[i];
    }
    Eigen::Matrix<double, N, N, Eigen::RowMajor> inverse;
    for (int i = 0; i < N; ++i) inverse.row(f.q[i]) = getColumnScale()[f.q[i]] * c.row(i);
    return inverse;
}
}  // namespace

namespace {
/// The mode's matrix A alone: it depends on the mode and the geometry only, `in` (with k
/// its kinematics) fills b alone, which is discarded.
Eigen::Matrix<double, N, N> assembleMatrix(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode,
                                           const Kinematics& k) {
    std::array<Linear, 2> P;
    for (int i : {0, 1}) P[i] = makeSpringForce(g, k.compression[i], mode.spring[i]);
    Eigen::Matrix<double, N, N> A;
    Eigen::Matrix<double, N, 1> b;
    assembleSystem(g, in, mode, k, P, A, b);
    return A;
}
}  // namespace

Eigen::Matrix<double, 15, 15> calcScaledModeMatrix(const TruckGeometry& g, const TruckMode& mode) {
    const TruckInputs in;
    Eigen::Matrix<double, N, 1> rowScale;
    return scaleSystem(assembleMatrix(g, in, mode, makeKinematics(g, in)), rowScale);
}

// ---- TruckModeCache -------------------------------------------------------

struct TruckModeCache::Factor : ModeFactor {};
static_assert(sizeof(TruckModeCache::Factor) == sizeof(ModeFactor), "its values right after it, as ModeFactor's");

struct TruckModeCache::SpringRows {
    std::array<std::array<Row, 3>, 2> row;  ///< [side][SpringSegment]
    explicit SpringRows(const TruckGeometry& g) {
        const Kinematics k = makeKinematics(g, TruckInputs{});  // the rows do not depend on the inputs
        for (int i : {0, 1})
            for (int seg = 0; seg < 3; ++seg)
                row[size_t(i)][size_t(seg)] = makeSpringForce(g, k.compression[i], SpringSegment(seg)).row;
    }
};

TruckModeCache::TruckModeCache(const TruckGeometry& g)
    : geometry_(g),
      arena_(std::make_unique<HugePageArena>()),
      slots_(arena_->makeArray<std::atomic<Factor*>>(kClassCount)),
      screenHints_(arena_->makeArray<std::atomic<std::int8_t>>(kModeCount)),
      springRows_(arena_->make<SpringRows>(g)),
      neighbourOrders_(arena_->makeArray<std::atomic<const NeighbourOrder*>>(kModeCount)) {}

int TruckModeCache::getScreenHint(int modeIndex) const {
    return int(screenHints_[modeIndex].load(std::memory_order_relaxed)) - 1;
}

void TruckModeCache::setScreenHint(int modeIndex, int quantity) const {
    if (!isCheckedAtLeastZero(quantity)) quantity = -1;
    screenHints_[modeIndex].store(std::int8_t(quantity + 1), std::memory_order_relaxed);
}

std::shared_ptr<const TruckModeCache> TruckModeCache::getShared(const TruckGeometry& g) {
    static_assert(sizeof(TruckGeometry) % sizeof(double) == 0, "TruckGeometry holds doubles alone (compared bytewise)");
    static std::mutex mutex;
    static std::deque<std::shared_ptr<const TruckModeCache>> kept;  // most recent last
    const std::lock_guard<std::mutex> lock(mutex);
    for (auto it = kept.begin(); it != kept.end(); ++it)
        if (std::memcmp(&(*it)->geometry_, &g, sizeof g) == 0) {
            std::shared_ptr<const TruckModeCache> found = *it;
            kept.erase(it);
            kept.push_back(found);
            return found;
        }
    kept.push_back(std::make_shared<const TruckModeCache>(g));
    if (int(kept.size()) > kSharedGeometries) kept.pop_front();
    return kept.back();
}

TruckModeCache::~TruckModeCache() = default;  // the factorizations are trivially destructible, in arena_

const TruckModeCache::Factor& TruckModeCache::getFactor(int modeIndex, const TruckMode& mode,
                                                        const TruckInputs& in) const {
    std::atomic<Factor*>& slot = slots_[getClassIndex(modeIndex)];
    if (const Factor* f = slot.load(std::memory_order_acquire)) return *f;
    const Kinematics k = makeKinematics(geometry_, in);  // its rows, not its constants, reach A and the screen
    const ScaledLu scaled(assembleMatrix(geometry_, in, mode, k));
    // The factorization and its entries' values, in as much room as they take; a thread that
    // loses the race below leaves its copy unused.
    Factor& made = *new (arena_->allocate(ModeFactor::getBytes(scaled.lu.getMatrixLU()), alignof(Factor))) Factor;
    keepFactor(scaled, made);
    if (made.invertible) {
        const Eigen::Matrix<double, N, N, Eigen::RowMajor> inverse = calcInverse(made);
        Eigen::Matrix<double, kCheckedCount, N, Eigen::RowMajor> rows;
        rows.setZero();  // G·A⁻¹ over G's nonzeros (one to four per row)
        for (int q = 0; q < kCheckedCount; ++q) {
            if (q < kRimGap) {
                rows.row(q) = inverse.row(getCheckedUnknown(q));
                continue;
            }
            const Row& g = getCheckedKinematics(k, q).row;
            for (int j = 0; j < N; ++j)
                if (g[j] != 0) rows.row(q) += g[j] * inverse.row(j);
        }
        made.setCheckRows(rows);
    }
    Factor* expected = nullptr;
    if (slot.compare_exchange_strong(expected, &made, std::memory_order_acq_rel)) return made;
    return *expected;  // another thread stored the same factorization first
}

namespace {
/// The checked quantities from the right-hand side b alone: h·b plus the quantity's
/// Kinematics constant c, h its row of checkRows (single precision), with the error bound
/// (kScreenRelativeError + kScreenRowRounding)·|h|·|b| + kScreenRelativeError·|c| plus
/// kScreenForceFloor (forces) or kScreenLengthFloor (lengths).
struct ScreenValues {
    const std::array<double, kCheckedCount>& constant;  ///< each quantity's Kinematics constant (0 for forces)
    const TruckModeCache::Factor& f;
    double b[16];  ///< the right-hand side, padded with a 0 (ModeFactor::ScreenRow)
    ScreenValues(const std::array<double, kCheckedCount>& c, const TruckModeCache::Factor& factor,
                 const Eigen::Matrix<double, N, 1>& rhs)
        : constant(c), f(factor) {
        for (int j = 0; j < N; ++j) b[j] = rhs[j];
        b[N] = 0;
    }
    Checked operator()(int q) const { return Checked{f.checkRows[size_t(q)].dot(b) + constant[size_t(q)], q}; }
    /// The part of calcError(q) that covers the rows' single-precision rounding.
    double calcRowRounding(int q) const { return kScreenRowRounding * f.checkRows[size_t(q)].dotAbs(b); }
    double calcError(int q) const {
        return (kScreenRelativeError + kScreenRowRounding) * f.checkRows[size_t(q)].dotAbs(b) +
               kScreenRelativeError * std::abs(constant[size_t(q)]) +
               (q < kRimGap ? kScreenForceFloor : kScreenLengthFloor);
    }
    double getError(const Checked& v) const { return (v.errorOf >= 0 ? calcError(v.errorOf) : 0.0) + v.errorAdded; }
    /// Whether the check "v ≥ minimum" fails by more than kConsistentViolation beyond the
    /// error bounds (a check whose value alone passes needs no bound).
    bool isCertainlyViolated(const Checked& v, const Checked& minimum, double unit) const {
        const double excess = minimum.value - v.value;
        if (!(excess / unit > kConsistentViolation)) return false;
        return (excess - (getError(minimum) + getError(v))) / unit > kConsistentViolation;
    }
};

/// What every mode of one search shares: the kinematics and the three spring laws per side.
struct SearchContext {
    const TruckGeometry& g;
    const TruckInputs& in;
    const TruckModeCache& cache;
    Kinematics k;
    std::array<std::array<double, 3>, 2> springConstant;  // [side][segment]: all the right-hand sides need
    std::array<double, kCheckedCount> checkedConstant{};   // each checked quantity's constant, for the screen
    SearchContext(const TruckGeometry& geometry, const TruckInputs& inputs, const TruckModeCache& c)
        : g(geometry), in(inputs), cache(c), k(makeKinematics(geometry, inputs)) {
        for (int i : {0, 1})
            for (int seg = 0; seg < 3; ++seg)
                springConstant[i][seg] = calcSpringConstant(g, k.compression[i].c, SpringSegment(seg));
        for (int q = kRimGap; q < kCheckedCount; ++q) checkedConstant[size_t(q)] = getCheckedKinematics(k, q).c;
    }
    RhsTable rhs{g, in, k};  // after k
    /// The mode's spring laws, made when a solution is built (its spring forces).
    SpringForces getSprings(const TruckMode& mode) const {
        const TruckModeCache::SpringRows& rows = cache.getSpringRows();
        const int s0 = int(mode.spring[0]), s1 = int(mode.spring[1]);
        return {{&rows.row[0][size_t(s0)], &rows.row[1][size_t(s1)]}, {springConstant[0][s0], springConstant[1][s1]}};
    }
    Eigen::Matrix<double, N, 1> getRhs(const TruckMode& mode) const {
        Eigen::Matrix<double, N, 1> b;
        rhs.fill(mode, {springConstant[0][int(mode.spring[0])], springConstant[1][int(mode.spring[1])]}, b);
        return b;
    }
    /// index: the mode's TruckModeCache::getIndex.
    TruckSolution solve(const TruckMode& mode, int index) const {
        return solveFactored(g, in, mode, k, getSprings(mode), cache.getFactor(index, mode, in), getRhs(mode));
    }
    TruckSolution solve(const TruckMode& mode) const { return solve(mode, TruckModeCache::getIndex(mode)); }
    /// Whether the mode's checks fail beyond doubt: a violation above
    /// kConsistentViolation by more than the screen's error bound on the quantities,
    /// each computed as checkRows·b + c instead of from the solution. Then the solve
    /// finds the mode inconsistent too; otherwise nothing is concluded.
    ///
    /// The answer is whether any check fails so, in whatever order they are tried: the
    /// screen first tries the check "q ≥ 0" that last failed for this mode
    /// (TruckModeCache::getScreenHint), then every check in checkInequalities' order.
    bool isCertainlyInconsistent(const TruckMode& mode, int index) const {
        const TruckModeCache::Factor& f = cache.getFactor(index, mode, in);
        if (!f.invertible) return true;
        const Eigen::Matrix<double, N, 1> b = getRhs(mode);
        const ScreenValues value{checkedConstant, f, b};
        const int hint = cache.getScreenHint(index);
        if (hint >= 0 && value.isCertainlyViolated(value(hint), Checked{}, getUnit(hint)))
            return true;
        int failed = -2;  // none
        checkInequalities(g, in, mode, value, [&failed, &value](Checked v, Checked minimum, double unit) {
            if (!value.isCertainlyViolated(v, minimum, unit)) return true;
            failed = isCheckedAtLeastZero(v.errorOf) ? v.errorOf : -1;  // "v ≥ 0" on the quantity itself
            return false;
        });
        if (failed == -2) return false;
        if (failed != hint) cache.setScreenHint(index, failed);
        return true;
    }
};

/// Lower bounds on a mode's violation from its spring, wedge, gib and lateral-wedge
/// choices alone, before any solve. Every check of one side's spring segment and
/// wedge tests the same computed compression Z_i, and every gib and lateral-wedge
/// check the same Y, each as "value inside an interval" with a unit:
///   Z: free (−∞, 0], linear [0, travel], bottomed [travel, ∞), unit 0.1 mm;
///      slip up (−∞, Z_old], slip down [Z_old, ∞), unit 0.1 mm;
///      stick [Z_a − F_V/k_b, Z_a + F_V/k_b] (its check is |Φ| ≤ F_V with the stick
///      row Φ = k_b (Z − Z_a)), unit 10 kN / k_b;
///   Y: gibs open [−c, c], gib + [c, ∞), gib − (−∞, −c], unit 0.1 mm; lateral slip
///      up [Y_old, ∞), down (−∞, Y_old]; stick Y_a ± F_H/k_bH, unit 10 kN / (2 k_bH).
/// Two choices whose intervals are a gap G apart cannot both hold: at any value the
/// larger of the two violations d₁/u₁, d₂/u₂ (d₁ + d₂ ≥ G) is at least G/(u₁ + u₂).
/// kBoundSlack (in violation units: 0.01 N, 10⁻¹⁰ m) covers the rounding that separates
/// the solved Φ from k_b (Z − Z_a) and Z − Z_old from its computed difference, many
/// orders above what the solves show (test ReducedModel.ChoiceBoundsNeverExceedTheViolation).
/// A mode whose bound is at least the best violation found so far can neither be
/// consistent nor replace the best, so the search skips its solve: same answer, bit for bit.
struct ChoiceBounds {
    static constexpr double kBoundSlack = 1e-6;
    std::array<std::array<std::array<double, 3>, 3>, 2> vertical{};  // [side][spring segment][wedge state]
    std::array<std::array<double, 3>, 3> lateral{};                 // [lateral wedge][gib]

    struct Interval {
        double lo, hi, unit;
    };
    static double pairBound(const Interval& a, const Interval& b) {
        const double gap = std::max(a.lo - b.hi, b.lo - a.hi);
        return gap > 0 ? std::max(0.0, gap / (a.unit + b.unit) - kBoundSlack) : 0.0;
    }

    /// Where side i's spring segment ([SpringSegment]) and wedge state ([WedgeState]) ask
    /// its compression Z to lie.
    struct CompressionIntervals {
        std::array<Interval, 3> spring, wedge;
    };
    static CompressionIntervals makeCompressionIntervals(const TruckGeometry& g, const TruckInputs& in, int i) {
        constexpr double inf = std::numeric_limits<double>::infinity(), length = 1e-4, force = 1e4;
        const double stick = g.Fv / g.kBristle;
        return {{{{-inf, 0, length}, {0, g.travel, length}, {g.travel, inf, length}}},
                {{{in.wedgeAnchor[i] - stick, in.wedgeAnchor[i] + stick, force / g.kBristle},
                  {-inf, in.compressionOld[i], length},
                  {in.compressionOld[i], inf, length}}}};
    }

    ChoiceBounds(const TruckGeometry& g, const TruckInputs& in) {
        constexpr double inf = std::numeric_limits<double>::infinity(), length = 1e-4, force = 1e4;
        for (int i : {0, 1}) {
            const CompressionIntervals z = makeCompressionIntervals(g, in, i);
            for (int s = 0; s < 3; ++s)
                for (int w = 0; w < 3; ++w) vertical[i][s][w] = pairBound(z.spring[s], z.wedge[w]);
        }
        const double stickY = g.Fh / g.kBristleLateral;
        const Interval lateralWedge[3] = {
            {in.lateralAnchor - stickY, in.lateralAnchor + stickY, force / (2 * g.kBristleLateral)},
            {in.lateralOld, inf, length},
            {-inf, in.lateralOld, length}};
        const Interval gib[3] = {{-g.gibClearance, g.gibClearance, length}, {g.gibClearance, inf, length},
                                 {-inf, -g.gibClearance, length}};
        for (int w = 0; w < 3; ++w)
            for (int c = 0; c < 3; ++c) lateral[w][c] = pairBound(lateralWedge[w], gib[c]);
    }
    double getBound(const TruckMode& m) const {
        return std::max({vertical[0][int(m.spring[0])][int(m.wedge[0])], vertical[1][int(m.spring[1])][int(m.wedge[1])],
                         lateral[int(m.lateralWedge)][int(m.gib)]});
    }
};

/// z + α θ = β for two rows (α₁ ≠ α₂): (z, θ).
std::pair<double, double> solvePair(double a1, double b1, double a2, double b2) {
    const double theta = (b1 - b2) / (a1 - a2);
    return {b1 - a1 * theta, theta};
}

constexpr double kKinematicRelativeError = 1e-9;

/// The margins of side i's three wedge checks on a kinematic compression Z (WedgeState order),
/// given Z's own margin eZ and a bound on |Z − Z_a|: the stick check is |Φ| ≤ F_V on the solved
/// Φ = k_b (Z − Z_a), the slips' on Z − Z_old.
std::array<double, 3> calcWedgeMargins(const TruckGeometry& g, const TruckInputs& in, int i, double eZ,
                                       double fromAnchor) {
    const double slip = eZ + kKinematicRelativeError * std::abs(in.compressionOld[i]);
    return {eZ + kKinematicRelativeError * (std::abs(in.wedgeAnchor[i]) + fromAnchor) + kScreenForceFloor / g.kBristle,
            slip, slip};
}

/// The bolster position a support with two closed contacts fixes (their gap rows = 0; a
/// gap row is −z_b − α θ_b + c), with the other contacts' gap rows.
struct FixedBolster {
    double z = 0, roll = 0;
    std::array<const Linear*, 2> open{};
    FixedBolster(const Kinematics& k, CarBodySupport support) {
        std::array<const Linear*, 2> closed{};
        int nc = 0, no = 0;
        for (int i : {0, 1}) {
            (closesRim(support, i) ? closed[size_t(nc++)] : open[size_t(no++)]) = &k.rimGap[i];
            (closesSideBearing(support, i) ? closed[size_t(nc++)] : open[size_t(no++)]) = &k.padGap[i];
        }
        auto alpha = [](const Linear& gap) { return gap.row[TB] / gap.row[ZB]; };
        std::tie(z, roll) = solvePair(alpha(*closed[0]), closed[0]->c, alpha(*closed[1]), closed[1]->c);
    }
};

bool fixesBolster(CarBodySupport s) {
    return s == CarBodySupport::TwoPointCenterPlate || s == CarBodySupport::SideBearingAndCornerLeft ||
           s == CarBodySupport::SideBearingAndCornerRight;
}

/// Each side's compression Z where the bolster and the wheelset (both wheels on the
/// rails: tread rows = 0) are fixed, and its error margin.
KinematicCompressions calcCompressions(const Kinematics& k, const FixedBolster& bolster) {
    const auto wheelset = solvePair(k.treadLift[0].row[TW], -k.treadLift[0].c, k.treadLift[1].row[TW], -k.treadLift[1].c);
    KinematicCompressions out;
    for (int i : {0, 1}) {
        const Linear& c = k.compression[i];
        const double terms[5] = {c.row[ZW] * wheelset.first, c.row[TW] * wheelset.second, c.row[ZB] * bolster.z,
                                 c.row[TB] * bolster.roll, c.c};
        double Z = 0, size = 0;
        for (double t : terms) Z += t, size += std::abs(t);
        out.value[size_t(i)] = Z;
        out.margin[size_t(i)] = kKinematicRelativeError * size + kScreenLengthFloor;
    }
    return out;
}

/// The modes whose closed contacts and wheels on the rails leave the bolster and the
/// wheelset one degree of freedom t between them:
///   - a support with two closed contacts (the bolster fixed) and one wheel lifted: the
///     wheel on the rail holds the wheelset to a roll about it, t = θ_w (families 0–5:
///     support two-point, side bearing and corner L, R; left, right wheel lifted);
///   - a support with one closed contact (corner, side bearing) and both wheels on the
///     rails (the wheelset fixed): the contact holds the bolster to a roll about it,
///     t = θ_b (families 6–9: corner L, R, side bearing L, R).
/// Every kinematic check of such a mode (the lifted tread ≥ 0, the open gaps ≥ 0, each
/// side's compression Z in its spring segment's and wedge's intervals) is affine in t, so
/// each asks t to lie in an interval. A mode whose intervals do not meet cannot be
/// consistent, whatever its forces: the first pass leaves it out unsolved.
///
/// The intervals are widened by what a consistent mode may miss them by (kConsistentViolation
/// in the check's unit) and by an error margin for the distance between a check's value at
/// the solved t and the solved value: kKinematicRelativeError of the size of the terms,
/// taken at |t| = kFamilyParameterBound, plus the screen's floors (test
/// ReducedModel.OneParameterFamiliesMatchTheSolve). A margin that grows with |t| covers
/// every consistent t only where some interval of the mode is two-sided and lies within
/// |t| ≤ kFamilyParameterBound with its margin: then every t that meets it within its
/// own margin, at any |t|, lies there too (the margin grows by 1e-9 of |t|). So a mode is
/// ruled out only when its intervals do not meet and one of them is such.
constexpr int kOneParameterFamilies = 10;
constexpr double kFamilyParameterBound = 1.0;  ///< [rad]

/// The family of (support, wheels), or −1.
int getOneParameterFamily(CarBodySupport s, WheelContact w) {
    using S = CarBodySupport;
    if (fixesBolster(s) && w != WheelContact::Both) {
        const int support = s == S::TwoPointCenterPlate ? 0 : s == S::SideBearingAndCornerLeft ? 1 : 2;
        return 2 * support + (w == WheelContact::LiftLeft ? 0 : 1);
    }
    if (w != WheelContact::Both) return -1;
    switch (s) {
    case S::CornerLeft: return 6;
    case S::CornerRight: return 7;
    case S::SideBearingLeft: return 8;
    case S::SideBearingRight: return 9;
    default: return -1;
    }
}

struct OneParameterFamily {
    /// An interval of t, widened; bounded: two-sided and within ±kFamilyParameterBound.
    struct Range {
        double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
        bool bounded = false;
    };
    /// A kinematic quantity along the family: a + b·t, and the size of the terms of a.
    struct Affine {
        double a = 0, b = 0, size = 0;
    };
    Range base;  ///< the lifted tread, the open gaps
    std::array<std::array<std::array<Range, 3>, 3>, 2> side{};  ///< [side][spring segment][wedge state], as made
    std::uint32_t made = 0;                                      ///< which of side are made (bit 9i + 3·segment + wedge)
    /// Each side's widened Z intervals (lo, hi) of its spring segments and of its wedge states.
    std::array<std::array<std::array<double, 2>, 3>, 2> springZ{}, wedgeZ{};
    /// The quantities along the family and their margins at |t| = kFamilyParameterBound:
    /// the checks "≥ 0" (the lifted tread, or the open gaps) and each side's compression.
    std::array<Affine, 3> atLeastZero{};
    std::array<double, 3> atLeastZeroMargin{};
    std::array<int, 3> atLeastZeroQuantity{};  ///< its CheckedQuantity
    int atLeastZeroCount = 0;
    std::array<Affine, 2> compression{};
    std::array<double, 2> compressionMargin{};

    OneParameterFamily(const TruckGeometry& g, const TruckInputs& in, const Kinematics& k, int family) {
        using S = CarBodySupport;
        // The positions (z_b, θ_b, z_w, θ_w) along the family: p0 + t·d.
        std::array<double, 4> p0{}, d{};
        std::array<const Linear*, 3> checks{};
        if (family < 6) {
            const S support = family < 2 ? S::TwoPointCenterPlate : family < 4 ? S::SideBearingAndCornerLeft
                                                                               : S::SideBearingAndCornerRight;
            const int lifted = family % 2, onRail = 1 - lifted;
            const FixedBolster bolster(k, support);
            const Linear& tread = k.treadLift[size_t(onRail)];  // = 0: z_w = (−c − row_θw·t)/row_zw
            p0 = {bolster.z, bolster.roll, -tread.c / tread.row[ZW], 0};
            d = {0, 0, -tread.row[TW] / tread.row[ZW], 1};
            atLeastZeroQuantity[size_t(atLeastZeroCount)] = kTreadLift + lifted;
            checks[size_t(atLeastZeroCount++)] = &k.treadLift[size_t(lifted)];  // the open gaps do not move: supportOut
        } else {
            const std::pair<double, double> wheelset =
                solvePair(k.treadLift[0].row[TW], -k.treadLift[0].c, k.treadLift[1].row[TW], -k.treadLift[1].c);
            const int closedSide = family % 2;
            const bool corner = family < 8;
            const Linear& closed = corner ? k.rimGap[size_t(closedSide)] : k.padGap[size_t(closedSide)];
            p0 = {-closed.c / closed.row[ZB], 0, wheelset.first, wheelset.second};  // gap = 0: z_b = (−c − row_θb·t)/row_zb
            d = {-closed.row[TB] / closed.row[ZB], 1, 0, 0};
            for (int i : {0, 1}) {
                if (!(corner && i == closedSide)) {
                    atLeastZeroQuantity[size_t(atLeastZeroCount)] = kRimGap + i;
                    checks[size_t(atLeastZeroCount++)] = &k.rimGap[size_t(i)];
                }
                if (!(!corner && i == closedSide)) {
                    atLeastZeroQuantity[size_t(atLeastZeroCount)] = kPadGap + i;
                    checks[size_t(atLeastZeroCount++)] = &k.padGap[size_t(i)];
                }
            }
        }
        auto along = [&](const Linear& q) {
            Affine f;
            const int unknowns[4] = {ZB, TB, ZW, TW};
            f.a = q.c, f.size = std::abs(q.c);
            for (int u = 0; u < 4; ++u) {
                const double term = q.row[unknowns[u]] * p0[size_t(u)];
                f.a += term, f.size += std::abs(term), f.b += q.row[unknowns[u]] * d[size_t(u)];
            }
            return f;
        };
        auto margin = [](const Affine& f) {
            return kKinematicRelativeError * (f.size + std::abs(f.b) * kFamilyParameterBound) + kScreenLengthFloor;
        };
        const double length = 1e-4;
        for (int j = 0; j < atLeastZeroCount; ++j) {
            const Affine f = along(*checks[size_t(j)]);
            atLeastZero[size_t(j)] = f, atLeastZeroMargin[size_t(j)] = margin(f);
            base = intersect(base, makeZRange(f, -(margin(f) + kConsistentViolation * length),
                                              std::numeric_limits<double>::infinity()));
        }
        for (int i : {0, 1}) {
            const Affine Z = along(k.compression[size_t(i)]);
            const double eZ = margin(Z), zMax = Z.size + std::abs(Z.b) * kFamilyParameterBound;  // |Z| over the range
            compression[size_t(i)] = Z, compressionMargin[size_t(i)] = eZ;
            const ChoiceBounds::CompressionIntervals intervals = ChoiceBounds::makeCompressionIntervals(g, in, i);
            // |Z − Z_a| at its largest over the range.
            const std::array<double, 3> wedgeMargin = calcWedgeMargins(g, in, i, eZ, std::abs(in.wedgeAnchor[i]) + zMax);
            for (size_t j = 0; j < 3; ++j) {
                const ChoiceBounds::Interval& spring = intervals.spring[j];
                const double springSlack = eZ + kConsistentViolation * spring.unit;
                springZ[size_t(i)][j] = {spring.lo - springSlack, spring.hi + springSlack};
                const ChoiceBounds::Interval& wedge = intervals.wedge[j];
                const double wedgeSlack = wedgeMargin[j] + kConsistentViolation * wedge.unit;
                wedgeZ[size_t(i)][j] = {wedge.lo - wedgeSlack, wedge.hi + wedgeSlack};
            }
        }
    }

    /// Side i's range for a spring segment and a wedge state, made on first use.
    const Range& getSide(int i, SpringSegment segment, WedgeState wedge) {
        const size_t seg = size_t(segment), w = size_t(wedge);
        const std::uint32_t bit = std::uint32_t(1) << (9 * i + 3 * int(seg) + int(w));
        Range& r = side[size_t(i)][seg][w];
        if (!(made & bit)) {
            r = makeZRange(compression[size_t(i)], std::max(springZ[size_t(i)][seg][0], wedgeZ[size_t(i)][w][0]),
                           std::min(springZ[size_t(i)][seg][1], wedgeZ[size_t(i)][w][1]));
            made |= bit;
        }
        return r;
    }

    /// Where both hold (bounded is rulesOut's test of the side ranges alone).
    static Range intersect(const Range& x, const Range& y) { return {std::max(x.lo, y.lo), std::min(x.hi, y.hi), false}; }
    /// The t where lo ≤ a + b·t ≤ hi (the bounds already widened).
    static Range makeZRange(const Affine& f, double lo, double hi) {
        Range r;
        if (std::isnan(lo) || std::isnan(hi) || !std::isfinite(f.a) || !std::isfinite(f.b)) return r;  // decides nothing
        if (!(lo <= hi)) {  // empty already: any t fails; not bounded, so alone it rules nothing out
            r.lo = std::numeric_limits<double>::infinity(), r.hi = -std::numeric_limits<double>::infinity();
            return r;
        }
        if (f.b == 0) {
            if (f.a < lo || f.a > hi) r.lo = std::numeric_limits<double>::infinity(), r.hi = -r.lo;
            return r;
        }
        double t1 = (lo - f.a) / f.b, t2 = (hi - f.a) / f.b;
        if (f.b < 0) std::swap(t1, t2);
        if (std::isnan(t1) || std::isnan(t2)) return Range{};
        r.lo = t1, r.hi = t2;
        r.bounded = std::isfinite(t1) && std::isfinite(t2) && t1 >= -kFamilyParameterBound && t2 <= kFamilyParameterBound;
        return r;
    }
    bool rulesOut(const TruckMode& m) {
        const Range& r0 = getSide(0, m.spring[0], m.wedge[0]);
        const Range& r1 = getSide(1, m.spring[1], m.wedge[1]);
        if (!(r0.bounded || r1.bounded)) return false;
        return std::max({base.lo, r0.lo, r1.lo}) > std::min({base.hi, r0.hi, r1.hi});
    }
};

/// Where a mode's closed contacts fix the bolster, and its wheels on the rails fix the
/// wheelset, the checks of the open gaps, the spring segments and the wedges follow from the
/// kinematics alone, before any solve:
///   - two closed contacts (center plate two-point; side bearing and corner on one side)
///     give z_b and θ_b from their two gap rows = 0; the open rim and pad gaps must be ≥ 0;
///   - both wheels on the rails give z_w and θ_w from the two tread rows = 0;
///   - with both, each side's compression Z is known, and with it whether Z lies in the
///     intervals its spring segment and wedge state ask of it (ChoiceBounds's intervals).
/// A mode whose check is violated beyond kConsistentViolation plus an error margin is not
/// consistent, so the first pass leaves it out unsolved, as it does the screen's (same
/// answer, bit for bit). The margin (kKinematicRelativeError of the size of the terms, and the
/// screen's floors) covers the distance between these values and a solve's, which satisfies
/// the same rows up to its rounding (test ReducedModel.KinematicCompressionsMatchTheSolve).
struct KinematicBounds {
    std::array<bool, 8> supportOut{};  // open gaps certainly violated
    std::array<std::array<std::array<std::array<bool, 3>, 3>, 2>, 8> sideOut{};  // [support][side][segment][wedge], both wheels on
    KinematicBounds(const TruckGeometry& geometry, const TruckInputs& inputs, const Kinematics& kinematics)
        : g(geometry), in(inputs), k(kinematics) {
        using S = CarBodySupport;
        const double lengthUnit = 1e-4;
        for (S support : {S::TwoPointCenterPlate, S::SideBearingAndCornerLeft, S::SideBearingAndCornerRight}) {
            const size_t si = size_t(support);
            const FixedBolster bolster(k, support);
            for (const Linear* gap : bolster.open) {
                const double zTerm = gap->row[ZB] * bolster.z, rollTerm = gap->row[TB] * bolster.roll;
                const double margin =
                    kKinematicRelativeError * (std::abs(zTerm) + std::abs(rollTerm) + std::abs(gap->c)) + kScreenLengthFloor;
                // an open gap ≥ 0, certainly violated
                supportOut[si] = supportOut[si] || (-(zTerm + rollTerm + gap->c) - margin) / lengthUnit > kConsistentViolation;
            }
            const KinematicCompressions Z = calcCompressions(k, bolster);
            for (int i : {0, 1}) {
                const double z = Z.value[size_t(i)], eZ = Z.margin[size_t(i)];
                const ChoiceBounds::CompressionIntervals intervals = ChoiceBounds::makeCompressionIntervals(g, in, i);
                // Z certainly outside an interval: by more than the margin [m], in the interval's unit.
                auto outside = [&](const ChoiceBounds::Interval& interval, double margin) {
                    return (std::max(interval.lo - z, z - interval.hi) - margin) / interval.unit > kConsistentViolation;
                };
                std::array<bool, 3> segment{}, wedge{};
                for (size_t seg = 0; seg < 3; ++seg) segment[seg] = outside(intervals.spring[seg], eZ);
                // The stick interval's ends are Z_a ± F_V/k_b; the slips' end is Z_old.
                const std::array<double, 3> wedgeMargin = calcWedgeMargins(g, in, i, eZ, std::abs(z - in.wedgeAnchor[i]));
                for (size_t w = 0; w < 3; ++w) wedge[w] = outside(intervals.wedge[w], wedgeMargin[w]);
                for (size_t seg = 0; seg < 3; ++seg)
                    for (size_t w = 0; w < 3; ++w) sideOut[si][size_t(i)][seg][w] = segment[seg] || wedge[w];
            }
        }
    }
    /// The one-parameter families, each made when a mode of it is first asked about.
    const TruckGeometry& g;
    const TruckInputs& in;
    const Kinematics& k;
    /// Raw storage: constructing ten empty families per search cost more than the bounds save.
    static_assert(std::is_trivially_destructible_v<OneParameterFamily>);
    alignas(OneParameterFamily) unsigned char familyStorage[kOneParameterFamilies][sizeof(OneParameterFamily)];
    std::uint32_t familiesMade = 0;
    bool rulesOut(const TruckMode& m) {
        const size_t s = size_t(m.support);
        if (supportOut[s]) return true;
        if (fixesBolster(m.support) && m.wheels == WheelContact::Both)
            return sideOut[s][0][size_t(m.spring[0])][size_t(m.wedge[0])] ||
                   sideOut[s][1][size_t(m.spring[1])][size_t(m.wedge[1])];
        const int f = getOneParameterFamily(m.support, m.wheels);
        if (f < 0) return false;
        void* storage = familyStorage[f];
        if (!(familiesMade & (1u << f))) {
            new (storage) OneParameterFamily(g, in, k, f);
            familiesMade |= 1u << f;
        }
        return std::launder(static_cast<OneParameterFamily*>(storage))->rulesOut(m);
    }
};

constexpr int kMaxNeighbours = 7 + 7 * 2;

/// findNeighbourModes without allocating; returns the count.
int fillNeighbourModes(const TruckMode& m, std::array<TruckMode, kMaxNeighbours>& out) {
    int n = 0;
    auto push = [&](auto setter, int count) {
        for (int v = 0; v < count; ++v) {
            TruckMode c = m;
            setter(c, v);
            if (!(c == m)) out[n++] = c;
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
    return n;
}
}  // namespace

std::optional<KinematicCompressions> calcKinematicCompressions(const TruckGeometry& g, const TruckInputs& in,
                                                               CarBodySupport support) {
    if (!fixesBolster(support)) return std::nullopt;
    const Kinematics k = makeKinematics(g, in);
    const FixedBolster bolster(k, support);
    KinematicCompressions out = calcCompressions(k, bolster);
    out.zBolster = bolster.z, out.rollBolster = bolster.roll;
    return out;
}

std::optional<OneParameterKinematics> calcOneParameterKinematics(const TruckGeometry& g, const TruckInputs& in,
                                                                 const TruckMode& mode, double t) {
    const int f = getOneParameterFamily(mode.support, mode.wheels);
    if (f < 0) return std::nullopt;
    const OneParameterFamily family(g, in, makeKinematics(g, in), f);
    OneParameterKinematics out;
    out.wheelsetRoll = f < 6;
    for (int j = 0; j < family.atLeastZeroCount; ++j) {
        const auto& q = family.atLeastZero[size_t(j)];
        out.atLeastZero.push_back(q.a + q.b * t);
        out.atLeastZeroMargin.push_back(family.atLeastZeroMargin[size_t(j)]);
        out.atLeastZeroQuantity.push_back(family.atLeastZeroQuantity[size_t(j)]);
    }
    for (int i : {0, 1}) {
        const auto& Z = family.compression[size_t(i)];
        out.compression[size_t(i)] = Z.a + Z.b * t;
        out.compressionMargin[size_t(i)] = family.compressionMargin[size_t(i)];
    }
    return out;
}

bool isRuledOutByKinematics(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode) {
    const Kinematics k = makeKinematics(g, in);
    KinematicBounds bounds(g, in, k);
    return bounds.rulesOut(mode);
}

TruckSolution solveTruckMode(const TruckInputs& in, const TruckMode& mode, const TruckModeCache& cache) {
    return SearchContext(cache.getGeometry(), in, cache).solve(mode);
}

TruckCheckedQuantities calcCheckedQuantities(const TruckInputs& in, const TruckMode& mode,
                                             const TruckModeCache& cache) {
    TruckCheckedQuantities out;
    const SearchContext context(cache.getGeometry(), in, cache);
    const TruckModeCache::Factor& f = cache.getFactor(mode, in);
    if (!f.invertible) return out;
    const Eigen::Matrix<double, N, 1> b = context.getRhs(mode);
    const Eigen::Matrix<double, N, 1> x = solveScaled(f, b);
    const SolvedValues solved{context.k, x};
    const ScreenValues screened{context.checkedConstant, f, b};
    for (int q = 0; q < kCheckedCount; ++q) {
        out.solved.push_back(solved(q).value);
        const Checked s = screened(q);
        out.screened.push_back(s.value);
        out.screenError.push_back(screened.getError(s));
        out.screenRowRounding.push_back(screened.calcRowRounding(q));
    }
    return out;
}

std::vector<TruckMode> findNeighbourModes(const TruckMode& m) {
    std::array<TruckMode, kMaxNeighbours> a;
    const int n = fillNeighbourModes(m, a);
    return std::vector<TruckMode>(a.begin(), a.begin() + n);
}

TruckSolution findTruckEquilibrium(const TruckGeometry& g, const TruckInputs& in, const TruckMode& previous) {
    const TruckModeCache cache(g);
    return findTruckEquilibrium(in, previous, cache);
}

double calcChoiceBound(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode) {
    return ChoiceBounds(g, in).getBound(mode);
}

namespace {
/// The search order's neighbour part: every mode that differs from `previous` in one
/// choice, then, for each of those in turn, every mode that differs from it in one
/// choice (but `previous` itself). Stops when consider(mode) returns true; returns
/// whether it did.
template <class Consider>
bool visitNeighbours(const TruckMode& previous, Consider&& consider) {
    std::array<TruckMode, kMaxNeighbours> first, second;
    const int nFirst = fillNeighbourModes(previous, first);
    for (int i = 0; i < nFirst; ++i)
        if (consider(first[i])) return true;
    for (int i = 0; i < nFirst; ++i) {
        const int nSecond = fillNeighbourModes(first[i], second);
        for (int j = 0; j < nSecond; ++j)
            if (!(second[j] == previous) && consider(second[j])) return true;
    }
    return false;
}

}  // namespace

// Named, not anonymous: TruckModeCache::NeighbourOrder holds these.
namespace truck_equilibrium_detail {
/// A mode in 10 bytes, with its TruckModeCache::getIndex, for the search orders.
struct PackedMode {
    std::uint8_t support, wheels, wedge0, wedge1, spring0, spring1, lateralWedge, gib;
    std::uint16_t index;
    static PackedMode pack(const TruckMode& m) {
        return {std::uint8_t(m.support), std::uint8_t(m.wheels), std::uint8_t(m.wedge[0]), std::uint8_t(m.wedge[1]),
                std::uint8_t(m.spring[0]), std::uint8_t(m.spring[1]), std::uint8_t(m.lateralWedge), std::uint8_t(m.gib),
                std::uint16_t(TruckModeCache::getIndex(m))};
    }
    TruckMode unpack() const {
        TruckMode m;
        m.support = CarBodySupport(support), m.wheels = WheelContact(wheels);
        m.wedge = {WedgeState(wedge0), WedgeState(wedge1)};
        m.spring = {SpringSegment(spring0), SpringSegment(spring1)};
        m.lateralWedge = WedgeState(lateralWedge), m.gib = GibContact(gib);
        return m;
    }
};
}  // namespace truck_equilibrium_detail
using truck_equilibrium_detail::PackedMode;

/// A list of modes kept in TruckModeCache's arena.
struct TruckModeCache::NeighbourOrder {
    const PackedMode* modes;
    std::size_t count;
    const PackedMode* begin() const { return modes; }
    const PackedMode* end() const { return modes + count; }
};

const TruckModeCache::NeighbourOrder& TruckModeCache::getNeighbourOrder(const TruckMode& previous) const {
    std::atomic<const NeighbourOrder*>& slot = neighbourOrders_[getIndex(previous)];
    if (const NeighbourOrder* order = slot.load(std::memory_order_acquire)) return *order;
    std::vector<PackedMode> list;
    std::bitset<kModeCount> seen;
    seen.set(size_t(getIndex(previous)));
    visitNeighbours(previous, [&](const TruckMode& m) {
        const PackedMode packed = PackedMode::pack(m);
        if (!seen.test(packed.index)) seen.set(packed.index), list.push_back(packed);
        return false;
    });
    auto* modes = static_cast<PackedMode*>(
        arena_->allocate(sizeof(PackedMode) * std::max<std::size_t>(1, list.size()), alignof(PackedMode)));
    std::uninitialized_copy(list.begin(), list.end(), modes);
    const NeighbourOrder* made =
        new (arena_->allocate(sizeof(NeighbourOrder), alignof(NeighbourOrder))) NeighbourOrder{modes, list.size()};
    const NeighbourOrder* expected = nullptr;
    if (slot.compare_exchange_strong(expected, made, std::memory_order_acq_rel)) return *made;
    return *expected;  // another thread made the same order first (this copy stays unused in the arena)
}

namespace {
/// The search order's first consistent mode, or false when no mode is consistent.
/// Every mode of the order (the previous mode, its one-choice neighbours, their
/// one-choice neighbours, every mode) is either consistent or not whatever came
/// before it, so the search can leave out, unsolved, what cannot be consistent:
///   - a mode it has already considered (the two-choice lists repeat each one-choice
///     neighbour and each two-choice mode twice, the enumeration repeats them all);
///   - a mode whose choice bound exceeds kConsistentViolation (its violation is at
///     least the bound); in the enumeration the bound's three factors (each side's
///     spring and wedge, the gibs and lateral wedges) are tested before the mode is
///     built, so a ruled-out combination costs one table look-up;
///   - with screen, a mode the screen finds certainly inconsistent
///     (SearchContext::isCertainlyInconsistent: about a tenth of a solve's work).
/// The first consistent mode it finds is the first consistent mode of the order: what
/// the exhaustive search returns, bit for bit (test
/// ReducedModel.PrunedModeSearchIsBitIdenticalToTheExhaustiveSearch).
bool findFirstConsistent(const SearchContext& context, const ChoiceBounds& bounds, const TruckMode& previous,
                         bool screen, TruckSearchCounts& n, TruckSolution& found) {
    KinematicBounds kinematic(context.g, context.in, context.k);
    auto test = [&](const TruckMode& m, int index) {
        if (bounds.getBound(m) > kConsistentViolation) {
            ++n.skipped;
            return false;
        }
        if (screen && kinematic.rulesOut(m)) {
            ++n.kinematic;
            return false;
        }
        if (screen && context.isCertainlyInconsistent(m, index)) {
            ++n.screened;
            return false;
        }
        ++n.solves;
        TruckSolution solved = context.solve(m, index);
        if (!solved.consistent) return false;
        found = solved;
        return true;
    };
    const TruckModeCache::NeighbourOrder& neighbours = context.cache.getNeighbourOrder(previous);
    for (const PackedMode& m : neighbours)
        if (test(m.unpack(), m.index)) return true;
    // The enumeration leaves out what the neighbour part considered.
    std::bitset<TruckModeCache::kModeCount> seen;
    seen.set(size_t(TruckModeCache::getIndex(previous)));
    for (const PackedMode& m : neighbours) seen.set(m.index);
    auto consider = [&](const TruckMode& m) {
        const int index = TruckModeCache::getIndex(m);
        if (seen.test(size_t(index))) return false;
        seen.set(size_t(index));
        return test(m, index);
    };
    ++n.enumerations;
    // enumerateTruckModes' order, with the bound's factors tested first.
    std::array<std::array<std::array<bool, 3>, 3>, 2> sideOk{};
    std::array<std::array<bool, 3>, 3> lateralOk{};
    for (int s = 0; s < 3; ++s)
        for (int w = 0; w < 3; ++w) {
            for (int i : {0, 1}) sideOk[i][s][w] = bounds.vertical[i][s][w] <= kConsistentViolation;
            lateralOk[s][w] = bounds.lateral[s][w] <= kConsistentViolation;
        }
    TruckMode m;
    for (int support = 0; support < 8; ++support)
        for (int wheels = 0; wheels < 3; ++wheels) {
            m.support = CarBodySupport(support);
            m.wheels = WheelContact(wheels);
            for (int sp = 0; sp < 9; ++sp) {
                const int s0 = (sp / 3 + 1) % 3, s1 = (sp % 3 + 1) % 3;  // linear first
                for (int f = 0; f < 9; ++f) {
                    const int w0 = f / 3, w1 = f % 3;
                    if (!sideOk[0][s0][w0] || !sideOk[1][s1][w1]) {
                        n.skipped += 9;
                        continue;
                    }
                    m.spring = {SpringSegment(s0), SpringSegment(s1)};
                    m.wedge = {WedgeState(w0), WedgeState(w1)};
                    for (int lat = 0; lat < 9; ++lat) {
                        if (!lateralOk[lat / 3][lat % 3]) {
                            ++n.skipped;
                            continue;
                        }
                        m.lateralWedge = WedgeState(lat / 3);
                        m.gib = GibContact(lat % 3);
                        if (consider(m)) return true;
                    }
                }
            }
        }
    return false;
}
}  // namespace

TruckSolution findTruckEquilibrium(const TruckInputs& in, const TruckMode& previous, const TruckModeCache& cache,
                                   TruckSearchCounts* counts, TruckSearchPruning pruning) {
    // 1. The previous mode; 2. every mode that differs from it in one choice,
    // then in two (contacts often open and close together); 3. every mode.
    // First consistent wins; else the smallest violation (the first of equals).
    const SearchContext context(cache.getGeometry(), in, cache);
    TruckSearchCounts local;
    TruckSearchCounts& n = counts ? *counts : local;
    ++n.searches;
    ++n.solves;
    TruckSolution best = context.solve(previous);
    if (best.consistent) return best;
    const ChoiceBounds bounds(cache.getGeometry(), in);
    const bool prune = pruning != TruckSearchPruning::Exhaustive;
    if (prune) {
        TruckSolution found;
        if (findFirstConsistent(context, bounds, previous, pruning == TruckSearchPruning::Screened, n, found))
            return found;
    }
    // No mode is consistent (or Exhaustive): the smallest violation, the first of
    // equals in the search order. A mode whose bound is at least best.violation
    // (> kConsistentViolation here) is neither consistent nor a smaller violation.
    auto consider = [&](const TruckMode& m) {
        if (prune && bounds.getBound(m) >= best.violation) {
            ++n.skipped;
            return false;
        }
        ++n.solves;
        TruckSolution s = context.solve(m);
        if (s.consistent || s.violation < best.violation) best = s;
        return s.consistent;
    };
    if (visitNeighbours(previous, consider)) return best;
    if (!prune) ++n.enumerations;  // the pruned search counted it in findFirstConsistent
    static const std::vector<TruckMode> modes = enumerateTruckModes();
    for (const TruckMode& m : modes)
        if (consider(m)) return best;
    return best;
}

}  // namespace rockroll
