#pragma once
// Track vertical input: rail-top heights against track position (report §2.2,
// eqs 1–2; docs/model.md §3).
//
// Staggered rectified sine (report eqs 1–2), started at the phase where both
// rails are equal so the rails are continuous (only their slope kinks):
//
//     σ = s + L_r/4,   z_R(s) = A·|sin(πσ/L_r)| − A/√2,   z_L(s) = A·|sin(πσ/L_r + π/2)| − A/√2
//
// for 0 ≤ s ≤ N·L_r (N = 0: no end), and level (0) outside. Alternatively a
// table of measured cross-level c(s) (right minus left), optionally with a mean
// profile p(s): z_R = p + c/2, z_L = p − c/2, linearly interpolated between rows
// (heights continuous, slopes constant between rows). A table that does not start
// (end) level rises from (returns to) level linearly over `taper` before its first
// (after its last) row, so the rails never step; outside that, level. With `repeat`
// the table repeats end to end with period (last − first distance); its last row
// must then equal its first.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rockroll {

struct RailPoint {
    std::array<double, 2> z{0, 0};      ///< left, right rail-top heights [m]
    std::array<double, 2> slope{0, 0};  ///< dz/ds [-]
};

struct MeasuredTrackSample {
    double distance = 0;    ///< s [m]
    double crossLevel = 0;  ///< right − left [m]
    double profile = 0;     ///< mean rail height [m]
};

struct TrackSpec {
    double amplitude = 0;            ///< A [m]
    double railLength = 39 * 0.3048; ///< L_r [m]
    int rails = 0;                   ///< N rail lengths of perturbation; 0 = unlimited
    bool mirror = false;             ///< swap left and right rails
    std::vector<MeasuredTrackSample> measured;  ///< replaces the rectified sine if not empty
    double taper = 20 * 0.3048;      ///< run-in/run-out of a measured table not level at its ends [m]
    bool repeat = false;             ///< the measured table repeats without end
};

/// Default of TrackSpec::taper as scenario files write it.
inline constexpr const char* kDefaultTaperText = "20 ft";

/// A measured track as CSV text (`source` names it in errors): `#` lines and blank lines
/// are comments; the first other line is the header, naming each column with its length
/// unit in brackets (in, ft, mm, m): `distance [ft], left [in], right [in]` and optionally
/// `alignment [in]`, in any order; then one row per distance, increasing strictly, every
/// cell a finite number. left and right are rail-top heights, positive up. The rows are
/// placed so the table starts at s = 0 (at s = taper when its first row is not level, so
/// its taper starts at 0). std::invalid_argument naming the line and column otherwise,
/// or when alignment is not zero (the models take vertical rail input only), or when the
/// text is larger than kMaxTrackFileBytes or has more than kMaxTrackRows data rows.
/// Input size limits of a measured track (docs/cli.md, "Input size limits"): its CSV's bytes
/// and its data rows; readTrackCsv refuses more. 100,000 rows (19 miles at 1 ft spacing) keep
/// a run's summary.json, whose provenance carries every row for --from-summary, under the
/// 16 MiB a summary file may have (measured: 9.5 MB, 8 s and 120 MB to run; 1,000,000 rows
/// gave a 96 MB summary, 74 s and 1 GB).
inline constexpr std::uintmax_t kMaxTrackFileBytes = std::uintmax_t(16) << 20;
inline constexpr size_t kMaxTrackRows = 100'000;

std::vector<MeasuredTrackSample> readTrackCsv(std::string_view text, const std::string& source, double taper);

/// Distance the car has travelled along the track, s(t). A run at constant
/// speed V: s = s₀ + V·t. A run continuing a speed sweep starts from the
/// previous run's distance and speed V₀ and ramps linearly to V over T_ramp, so
/// neither the rails' heights nor their vertical velocities (slope·ṡ) jump.
/// T_ramp = 0 steps the speed at once (the rails' vertical velocities jump; their
/// heights do not).
struct TrackMotion {
    double speed = 0;          ///< V [m/s]
    double startDistance = 0;  ///< s₀ [m]
    double startSpeed = -1;    ///< V₀ [m/s]; < 0: V from t = 0
    double rampTime = 1.0;     ///< T_ramp [s]; 0: V from t = 0

    double calcSpeed(double t) const {
        if (startSpeed < 0 || t >= rampTime) return speed;
        return startSpeed + (speed - startSpeed) * t / rampTime;
    }
    double calcDistance(double t) const {
        if (startSpeed < 0 || rampTime <= 0) return startDistance + speed * t;
        const double tr = t < rampTime ? t : rampTime;
        const double ramp = startSpeed * tr + 0.5 * (speed - startSpeed) * tr * tr / rampTime;
        return startDistance + ramp + (t > rampTime ? speed * (t - rampTime) : 0.0);
    }
};

class TrackInput {
public:
    explicit TrackInput(TrackSpec spec);
    RailPoint calcRails(double s) const;
    /// Cross-level z_R − z_L at s [m].
    double calcCrossLevel(double s) const {
        const RailPoint p = calcRails(s);
        return p.z[1] - p.z[0];
    }
    const TrackSpec& getSpec() const { return spec_; }
    /// The level lead-in: the distance s from 0 up to which the rails stay level
    /// (0 for the rectified sine, which starts to move just after s = 0; for a
    /// measured table, its leading level rows; 0 for a track that is level throughout) [m].
    double calcLeadInDistance() const;

private:
    RailPoint calcRectifiedSine(double s) const;
    RailPoint calcMeasured(double s) const;
    TrackSpec spec_;
};

}  // namespace rockroll
