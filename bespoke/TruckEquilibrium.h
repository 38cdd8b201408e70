#pragma once
// The reduced model's massless truck (report §2.2): bolster and equivalent
// wheelset in force and moment equilibrium at every instant, with rigid car
// body–bolster contacts and rigid rails.
//
// Unknowns (small angles, cross-section plane): bolster z_b, θ_b, y_b; wheelset
// z_w, θ_w; rim forces F_cL, F_cR; side-bearing forces F_sL, F_sR; wheel forces
// W_L, W_R; wedge friction forces on the bolster Φ_L, Φ_R; the lateral wedges'
// force Φ_H and the center-pin force F_h. Fifteen equations:
//
//   bolster   Σ F_z:  −(F_cL + F_cR + F_sL + F_sR) + (P_L + Φ_L) + (P_R + Φ_R) − W_B = 0
//   bolster   Σ M:    −a_c (F_cL − F_cR) − a_s (F_sL − F_sR) + l_s ((P_L + Φ_L) − (P_R + Φ_R)) + h_cp·F_h = 0
//   wheelset  Σ F_z:  W_L + W_R − (P_L + Φ_L) − (P_R + Φ_R) − W_W = 0
//   wheelset  Σ M:    (g/2)(W_L − W_R) − l_s ((P_L + Φ_L) − (P_R + Φ_R)) + h_st·F_h = 0
//   each rim / side bearing:   closed → gap = 0,        open → force = 0
//   each wheel:                on rail → tread z = rail z, lifted → W = 0
//   each wedge:                stick → Φ = k_b (Z − Z_a),  slip → Φ = ∓F_V
//   center pin:       F_h = −k_pin (y_plate − y_b + θ_b h_cp)
//   bolster  Σ F_y:   −F_h − 2 f₂(Y) − Φ_H = 0,   Y = y_b − y_seat,  y_seat = −θ_w h_st
//   lateral wedges:   stick → Φ_H = 2 k_bH (Y − Y_a),  slip → Φ_H = ±2 F_H
//
// (f₂: K_h·Y, plus K_gib·(|Y| − c_gib)·sign Y in gib contact; the wheelset is
// held laterally at rail height by the wheel(s) in contact. W_B, W_W: the
// bolster's and the equivalent wheelset's weights, 0 in the report's massless
// truck; `[reduced] truck_weight = true` sets them (TruckGeometry). Each acts
// through its body's reference point, so with nominal arms it adds no moment.)
//
// with P_i the spring force of the assumed segment (free: 0, linear: K_v Z,
// bottomed: K_v·travel + K_b (Z − travel)), Z_i = z_seat,i − z_bolster end,i the
// compression, F_h the lateral center-pin force (solved first, a 1-D problem),
// h_cp the center plate above the springs and h_st the spring top above the rail.
// A wedge is an elasto-plastic element, as in the Simbody model: a stiff
// bristle k_b = F_V / (bristle deflection) in series with the slider, whose
// anchor Z_a (the compression at which the wedge carries no force) the truck
// remembers between steps. A rigid stick constraint would make the bolster,
// held at two points by the car body, statically indeterminate; the bristle
// keeps every mode determinate. The kinematic rule X_r = Ẋ_r·Δt gives the
// sliding direction: Ż = (Z − Z_old)/Δt.
//
// A mode fixes every choice above. A mode is consistent when its solution
// satisfies every inequality: closed-contact and wheel forces ≥ 0, open gaps and
// lifts ≥ 0, each spring's Z inside its segment, |Φ| ≤ F_V in stick, and the
// sliding direction matching the sign of Φ in slip. findTruckEquilibrium tries
// the previous mode first, then its neighbours, then every mode in a fixed order,
// skipping the solve of modes that a bound from their choices alone rules out.
#include "mbmodel/CarParameters.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rockroll {

class HugePageArena;

enum class CarBodySupport { TwoPointCenterPlate, CornerLeft, CornerRight, SideBearingAndCornerLeft,
                            SideBearingAndCornerRight, SideBearingLeft, SideBearingRight, None };
enum class WheelContact { Both, LiftLeft, LiftRight };
enum class WedgeState { Stick, SlipUp, SlipDown };  ///< bolster end moving up (Z falling) or down relative to the seat
enum class SpringSegment { Free, Linear, Bottomed };
enum class GibContact { Open, Positive, Negative };  ///< lateral deflection Y inside, above +c or below −c

struct TruckMode {
    CarBodySupport support = CarBodySupport::TwoPointCenterPlate;
    WheelContact wheels = WheelContact::Both;
    std::array<WedgeState, 2> wedge{WedgeState::Stick, WedgeState::Stick};
    std::array<SpringSegment, 2> spring{SpringSegment::Linear, SpringSegment::Linear};
    WedgeState lateralWedge = WedgeState::Stick;  ///< SlipUp = Y increasing
    GibContact gib = GibContact::Open;
    bool operator==(const TruckMode& o) const {  // C++17 too (ROCKROLL_SYSTEM_SIMBODY): no defaulted ==
        return support == o.support && wheels == o.wheels && wedge == o.wedge && spring == o.spring &&
               lateralWedge == o.lateralWedge && gib == o.gib;
    }
    std::string describe() const;
};

/// Every mode, in the order the search tries them.
std::vector<TruckMode> enumerateTruckModes();

/// Car-body points the truck sees (ground frame, small angles), and the input.
struct TruckInputs {
    std::array<double, 2> rimZ{0, 0};      ///< car body's rim points (left, right) [m]
    std::array<double, 2> padZ{0, 0};      ///< car body's side-bearing pads [m]
    std::array<double, 2> railZ{0, 0};     ///< rail tops under the equivalent wheelset [m]
    double plateY = 0;                     ///< car body's center-plate point, lateral [m]
    double lateralOld = 0, lateralAnchor = 0;    ///< Y and the lateral wedges' anchor Y_a [m]
    std::array<double, 2> compressionOld{0, 0};  ///< Z at the last accepted step [m]
    std::array<double, 2> wedgeAnchor{0, 0};     ///< Z_a of each wedge at the last accepted step [m]
};

/// A mode is consistent when its largest inequality violation (forces in 10 kN, lengths
/// in 0.1 mm) is at most this.
inline constexpr double kConsistentViolation = 1e-9;

struct TruckSolution {
    TruckMode mode;
    double zBolster = 0, rollBolster = 0, zWheelset = 0, rollWheelset = 0, yBolster = 0;
    double pinForce = 0;              ///< F_h, on the car body [N]
    double lateral = 0, lateralFriction = 0, lateralAnchor = 0;  ///< Y, Φ_H, Y_a
    std::array<double, 2> rim{0, 0}, sideBearing{0, 0}, wheel{0, 0}, friction{0, 0}, spring{0, 0};
    std::array<double, 2> compression{0, 0}, wheelLift{0, 0};
    std::array<double, 2> wedgeAnchor{0, 0};  ///< Z_a after this solution (moves while slipping)
    double violation = 0;  ///< 0 when consistent; otherwise the largest inequality violation [N or m scaled]
    bool consistent = false;
};

/// Geometry and laws of the massless truck, from the car parameters.
struct TruckGeometry {
    double a_c = 0, a_s = 0, l_s = 0, halfGauge = 0;
    double cpAboveSprings = 0, sbAboveSprings = 0, springTopAboveRail = 0, wheelRadius = 0;
    double clearance = 0;  ///< side bearing
    double Kv = 0, travel = 0, Kb = 0, Fv = 0;
    double kBristle = 0;   ///< wedge bristle stiffness F_V / friction_bristle_deflection
    double Kh = 0, gibClearance = 0, Kgib = 0, Fh = 0, kBristleLateral = 0, kPin = 0;
    /// Weights carried by the truck (no inertia): 0 in the report's formulation.
    double bolsterWeight = 0;   ///< W_B [N]
    double wheelsetWeight = 0;  ///< W_W, the equivalent wheelset: 2 wheelsets and 2 side frames [N]
    explicit TruckGeometry(const CarParameters& car);
};

/// How a solve substitutes through the factors: over their nonzero entries (what the
/// model uses), or over every entry (the reference it must equal bit for bit).
enum class TruckSubstitution { Sparse, Dense };

/// Solves one mode: the 12 linear equations above, and the consistency checks.
/// Returns a solution with consistent = false if the mode's system is singular.
TruckSolution solveTruckMode(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode,
                             TruckSubstitution substitution = TruckSubstitution::Sparse);

/// The mode's matrix as the solves factor it (FullPivotLu): unknowns in mm, mrad and
/// 10 kN, each row divided by its largest |coefficient|.
Eigen::Matrix<double, 15, 15> calcScaledModeMatrix(const TruckGeometry& g, const TruckMode& mode);

/// Per-mode factorizations of the truck's equations for one geometry. A mode's
/// matrix depends on the mode and the geometry only (the inputs enter the right-hand
/// side alone), so each matrix is factored once, on first use, and reused: the
/// solutions are bit-identical to solveTruckMode's. Modes that differ only in the
/// direction of a slip (±F_V, ±2F_H) or the side of the gib contact (±K_gib·c) differ
/// in the right-hand side alone and share one factorization (getMatrixClass; test
/// ReducedModel.CachedSolveOfEveryModeIsBitIdenticalToTheDirectSolve). Thread-safe (lock-free slots).
class TruckModeCache {
public:
    static constexpr int kModeCount = 8 * 3 * 9 * 9 * 9;
    explicit TruckModeCache(const TruckGeometry& g);
    /// A cache for g shared by every model of the process whose truck has the same
    /// geometry, bit for bit (the last kSharedGeometries geometries asked for are
    /// kept): a study over speeds, amplitudes or tracks factors each matrix once.
    static std::shared_ptr<const TruckModeCache> getShared(const TruckGeometry& g);
    static constexpr int kSharedGeometries = 4;
    ~TruckModeCache();
    TruckModeCache(const TruckModeCache&) = delete;
    TruckModeCache& operator=(const TruckModeCache&) = delete;
    const TruckGeometry& getGeometry() const { return geometry_; }
    /// 0 … kModeCount − 1, in enumerateTruckModes() order.
    static int getIndex(const TruckMode& m) {
        constexpr int linearFirst[3] = {2, 0, 1};  // free, linear, bottomed -> 2, 0, 1
        const int sp = 3 * linearFirst[int(m.spring[0])] + linearFirst[int(m.spring[1])];
        const int f = 3 * int(m.wedge[0]) + int(m.wedge[1]);
        const int lat = 3 * int(m.lateralWedge) + int(m.gib);
        return (((int(m.support) * 3 + int(m.wheels)) * 9 + sp) * 9 + f) * 9 + lat;
    }
    /// The mode whose matrix m's is: slips up, gib +.
    static TruckMode getMatrixClass(const TruckMode& m) {
        TruckMode c = m;
        for (WedgeState& w : c.wedge)
            if (w == WedgeState::SlipDown) w = WedgeState::SlipUp;
        if (c.lateralWedge == WedgeState::SlipDown) c.lateralWedge = WedgeState::SlipUp;
        if (c.gib == GibContact::Negative) c.gib = GibContact::Positive;
        return c;
    }
    /// The number of matrix classes: the modes whose wedges stick or slip up, lateral
    /// wedges likewise, gibs open or at +.
    static constexpr int kClassCount = 8 * 3 * 9 * 2 * 2 * 2 * 2;
    /// The index 0 … kClassCount − 1 of getMatrixClass(m) from getIndex(m): modes share it
    /// exactly when they share their matrix class. The index's last two base-9 digits hold
    /// the wedges and the lateral wedge and gib, one bit of class each.
    static int getClassIndex(int modeIndex) {
        static constexpr auto kLastDigits = [] {
            std::array<std::uint8_t, 81> t{};  // [3·w0 + w1][3·lateral + gib], base 9
            for (int f = 0; f < 9; ++f)
                for (int lat = 0; lat < 9; ++lat)
                    t[size_t(9 * f + lat)] = std::uint8_t(8 * std::min(f / 3, 1) + 4 * std::min(f % 3, 1) +
                                                          2 * std::min(lat / 3, 1) + std::min(lat % 3, 1));
            return t;
        }();
        return modeIndex / 81 * 16 + kLastDigits[size_t(modeIndex % 81)];
    }
    struct Factor;
    const Factor& getFactor(const TruckMode& mode, const TruckInputs& anyInputs) const {
        return getFactor(getIndex(mode), mode, anyInputs);
    }
    /// getFactor with the mode's getIndex already known.
    const Factor& getFactor(int modeIndex, const TruckMode& mode, const TruckInputs& anyInputs) const;
    /// The spring forces' rows in the unknowns, by side and segment: like the matrices, a
    /// function of the geometry alone (the inputs reach the constants).
    struct SpringRows;
    const SpringRows& getSpringRows() const { return *springRows_; }
    /// The checked quantity (TruckCheckedQuantities' order) of the check "q ≥ 0" that the
    /// search's screen last found certainly violated for the mode of this index, or −1;
    /// the screen tries it first. It orders the screen's work and never its answer, so
    /// threads may race on it (relaxed atomics; test
    /// ReducedModel.ScreenHintsOrderTheWorkNotTheAnswer). A quantity that no mode checks as
    /// "q ≥ 0" (the frictions, the compressions, the lateral deflection) is stored as −1.
    int getScreenHint(int modeIndex) const;
    void setScreenHint(int modeIndex, int quantity) const;
    /// The neighbour part of the search order from `previous` (its one-choice neighbours,
    /// then theirs) with each mode once, where it first comes, and without `previous`: the
    /// modes the search's first pass considers, in its order. It depends on `previous`
    /// alone; each is made on first use and kept here, in the arena that holds the
    /// factorizations, so a run's search takes its memory from as few fresh blocks as it
    /// can (lock-free slots; test ReducedModel.PrunedModeSearchIsBitIdenticalToTheExhaustiveSearch).
    struct NeighbourOrder;
    const NeighbourOrder& getNeighbourOrder(const TruckMode& previous) const;

private:
    TruckGeometry geometry_;
    /// Where the slots and the factorizations live: 2 MB blocks, huge pages where the
    /// system gives them (mbmodel/HugePageMemory.h). Allocated one by one, the ~1 000
    /// factorizations of one run cost a page fault each on first touch, more than the
    /// factoring itself on a virtual machine (bench/README.md, "Bespoke models").
    std::unique_ptr<HugePageArena> arena_;
    std::atomic<Factor*>* slots_;  ///< kClassCount, by getClassIndex, in arena_; null until factored
    std::atomic<std::int8_t>* screenHints_;  ///< kModeCount, in arena_: the hint + 1 (0: none)
    const SpringRows* springRows_;  ///< in arena_
    std::atomic<const NeighbourOrder*>* neighbourOrders_;  ///< kModeCount, by getIndex, in arena_; null until made
};

/// solveTruckMode with the cache's factorization (bit-identical).
TruckSolution solveTruckMode(const TruckInputs& in, const TruckMode& mode, const TruckModeCache& cache);

/// The quantities a mode's consistency checks read (rim, side-bearing and wheel forces,
/// wedge frictions, lateral friction, rim and pad gaps, tread lifts, compressions, lateral
/// deflection: 18), from the mode's solution and from the search's screen, with the
/// screen's error bound and the part of it that covers the screen's single-precision
/// rows (kScreenRowRounding). Empty when the mode's matrix is singular.
struct TruckCheckedQuantities {
    std::vector<double> solved, screened, screenError, screenRowRounding;
};
TruckCheckedQuantities calcCheckedQuantities(const TruckInputs& in, const TruckMode& mode, const TruckModeCache& cache);

/// The compressions (left, right) that a support with two closed contacts (center plate
/// two-point, side bearing and corner on one side) and both wheels on the rails fix from the
/// kinematics alone, and the margin the search allows them against a solve's; none for the
/// other supports. The search's first pass leaves out, unsolved, a mode whose spring, wedge
/// or open-gap check these values fail beyond the margin (TruckEquilibrium.cpp, KinematicBounds).
struct KinematicCompressions {
    std::array<double, 2> value{0, 0}, margin{0, 0};  ///< [m]
    double zBolster = 0, rollBolster = 0;              ///< what the closed contacts fix [m, rad]
};
std::optional<KinematicCompressions> calcKinematicCompressions(const TruckGeometry& g, const TruckInputs& in,
                                                               CarBodySupport support);

/// The modes whose closed contacts and wheels on the rails leave the bolster and the wheelset
/// one degree of freedom t: a support with two closed contacts and one wheel lifted (t = θ_w,
/// the wheelset rolling about the wheel on the rail), or one closed contact and both wheels on
/// the rails (t = θ_b, the bolster rolling about the contact). The quantities the search's
/// first pass checks along it, at t: the checks "≥ 0" (the lifted tread, or the open gaps;
/// atLeastZeroQuantity indexes TruckCheckedQuantities) and the compressions, each with the
/// margin the search allows them against a solve's for |t| ≤ 1 rad (TruckEquilibrium.cpp,
/// OneParameterFamily). None for the other modes.
struct OneParameterKinematics {
    bool wheelsetRoll = false;  ///< t is θ_w (else θ_b)
    std::vector<double> atLeastZero, atLeastZeroMargin;  ///< [m]
    std::vector<int> atLeastZeroQuantity;
    std::array<double, 2> compression{0, 0}, compressionMargin{0, 0};  ///< [m]
};
std::optional<OneParameterKinematics> calcOneParameterKinematics(const TruckGeometry& g, const TruckInputs& in,
                                                                 const TruckMode& mode, double t);

/// Whether the search's first pass leaves the mode out unsolved on its kinematics alone
/// (calcKinematicCompressions, calcOneParameterKinematics): then it is not consistent.
bool isRuledOutByKinematics(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode);

/// The modes that differ from m in exactly one choice.
std::vector<TruckMode> findNeighbourModes(const TruckMode& m);

/// What mode searches did (counts add up over calls).
struct TruckSearchCounts {
    long searches = 0;      ///< findTruckEquilibrium calls
    long solves = 0;        ///< modes solved
    long skipped = 0;       ///< modes ruled out by their choice bound, unsolved
    long kinematic = 0;     ///< modes ruled out by the kinematics of their closed contacts, unsolved
    long screened = 0;      ///< modes ruled out by the screen, unsolved
    long enumerations = 0;  ///< searches that reached the enumeration of every mode
};

/// ChoiceBounds: skip the solve of a mode whose spring/wedge or gib/lateral-wedge
/// choices alone bound its violation from below by at least the best violation
/// found so far (calcChoiceBound); the answer is the same, bit for bit.
/// Screened: ChoiceBounds, and, while looking for the first consistent mode, skip the
/// solve of a mode whose checks its closed contacts' kinematics decide
/// (calcKinematicCompressions, calcOneParameterKinematics) or the screen finds violated beyond its error bound
/// (each checked quantity as one row times the right-hand side, TruckModeCache);
/// the answer is the same, bit for bit.
/// Exhaustive: solve every mode the search reaches (for checking).
enum class TruckSearchPruning { Screened, ChoiceBounds, Exhaustive };

/// The screen's error bound on a checked quantity q = h·b + c:
/// kScreenRelativeError·(|h|·|b| + |c|) (the size of its terms), plus a floor for the
/// solve's own rounding, which reaches forces whose terms are all small (an open
/// contact's force, solved as ~1e-8 N where the system carries 1e5 N): kScreenForceFloor
/// [N] for forces, kScreenLengthFloor [m] for lengths; in violation units 1e-8 each, so
/// the screen leaves to the solve only modes within 1e-8 of consistency. The bound must
/// cover the screen's rounding and the solve's (test ReducedModel.ScreenErrorBoundCoversTheSolve).
inline constexpr double kScreenRelativeError = 1e-10, kScreenForceFloor = 1e-4, kScreenLengthFloor = 1e-12;
/// The screen keeps h in single precision, rounded to nearest: each entry h̃ is within
/// 2⁻²⁴·|h| ≤ 2⁻²⁴/(1 − 2⁻²⁴)·|h̃| < kScreenRowRounding·|h̃| of h, so h̃·b is within
/// kScreenRowRounding·(|h̃|·|b|) of h·b, a bound the screen adds to the one above. (An
/// entry below single precision's normal range, |h| < 1.2e-38, is off by at most 1e-45,
/// far below the floors; one above its range becomes infinite, and a check on an
/// infinite or NaN value is never found violated.)
inline constexpr double kScreenRowRounding = 6e-8;

/// The mode search: the previous mode, then its neighbours, then every mode;
/// the first consistent one, or (none consistent) the one with the smallest violation.
/// With ChoiceBounds it skips, unsolved, the modes it has already considered and those
/// whose bound rules out consistency (same answer, bit for bit).
TruckSolution findTruckEquilibrium(const TruckGeometry& g, const TruckInputs& in, const TruckMode& previous);
/// The same search with the cache's factorizations (same result, bit for bit).
TruckSolution findTruckEquilibrium(const TruckInputs& in, const TruckMode& previous, const TruckModeCache& cache,
                                   TruckSearchCounts* counts = nullptr,
                                   TruckSearchPruning pruning = TruckSearchPruning::Screened);

/// A lower bound on solveTruckMode(g, in, mode).violation from the mode's spring,
/// wedge, gib and lateral-wedge choices alone: pairs of choices on one side (or on
/// the lateral deflection) that ask the same compression (deflection) to lie in
/// intervals a gap apart (TruckEquilibrium.cpp, ChoiceBounds).
double calcChoiceBound(const TruckGeometry& g, const TruckInputs& in, const TruckMode& mode);

}  // namespace rockroll
