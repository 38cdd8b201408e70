#pragma once
// Equation-of-motion half car: the Simbody half car's bodies, element laws and
// parameters with its equations of motion written by hand. A formulation check
// on the Simbody model, and (with the report's §4.1 simplifications) the
// time-domain twin of the describing-function model.
//
// Bodies b ∈ {car body, bolster, equivalent wheelset}, each moving in the track
// cross-section with q_b = [θ_b, y_b, z_b] (roll about +x, lateral, vertical of
// its mass center, ground axes). A station p = (p_y, p_z) of body b is at
//
//     r = R(θ)·p,   R(θ) = [cos θ  −sin θ; sin θ  cos θ],   x_p = (y_b, z_b) + r
//     ẋ_p = (ẏ_b − θ̇_b·r_z,  ż_b + θ̇_b·r_y)
//
// (small angles: r = (p_y − θ·p_z, p_z + θ·p_y), ṙ = θ̇·(−p_z, p_y)). A force
// F = (F_y, F_z) there adds F to the body's force and r_y·F_z − r_z·F_y to its
// roll moment, and with the mass center at the body origin the mass matrix is
// diagonal:
//
//     I_b·θ̈_b = Σ (r_y F_z − r_z F_y),   m_b·ÿ_b = Σ F_y,   m_b·z̈_b = Σ F_z − m_b·g.
//
// Elements and laws are the Simbody half car's (docs/model.md): two center-plate
// rim contacts and a center pin, two side bearings with clearance, vertical and
// lateral spring groups with bottoming and gib stops, a vertical and a lateral
// bristle friction wedge at each bolster end (4 bristle deflections are state),
// and the wheel–rail contacts with lateral restraint by load share.
#include "contacts/BristleFriction.h"
#include "contacts/SpringGroupLaws.h"
#include "contacts/UnilateralContactLaw.h"
#include "contacts/WheelRailLaws.h"
#include "mbmodel/CarParameters.h"
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/TruckStatics.h"

#include <Eigen/Dense>
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace rockroll {

/// Rail-top heights under the equivalent wheelset and their rates (left, right).
struct RailState {
    std::array<double, 2> z{0, 0};     ///< [m]
    std::array<double, 2> zDot{0, 0};  ///< [m/s]
    double speed = 0;                  ///< forward speed V [m/s] (the creepages' denominator)
};
using RailStateFunction = std::function<RailState(double t)>;

/// The report's §4.1 simplifications, each on its own.
struct EomSimplifications {
    bool linearSprings = false;       ///< vertical springs K_v·Z for every Z: no lift-off, no bottoming
    bool lockBolsterLateral = false;  ///< bolster held laterally to the side frames (stiff link, no gib, no lateral wedge)
    bool elasticContacts = false;     ///< no Hunt–Crossley dissipation in rim, side-bearing and wheel contacts
    bool equalLateralShares = false;  ///< wheel–rail lateral restraint split equally, not by load
    bool smallAngles = false;         ///< kinematics linear in the roll angles

    /// All of them: the model the describing function balances harmonically.
    static EomSimplifications describingFunctionTwin() { return {true, true, true, true, true}; }
    bool any() const { return linearSprings || lockBolsterLateral || elasticContacts || equalLateralShares || smallAngles; }
};

class EomHalfCarModel {
public:
    enum BodyIndex { CarBody = 0, Bolster = 1, Wheelset = 2 };
    static constexpr int kNumBodies = 3;
    static constexpr int kNumDofs = 3 * kNumBodies;
    static constexpr int kNumBristles = 4;  ///< vertical L, lateral L, vertical R, lateral R
    static constexpr int kNumStates = 2 * kNumDofs + kNumBristles;
    using State = Eigen::Matrix<double, kNumStates, 1>;  ///< [q (9), q̇ (9), w (4)]

    /// Every element force of one evaluation (sides: 0 = left (+y), 1 = right).
    struct Forces {
        std::array<double, 2> rim{0, 0}, sideBearing{0, 0}, spring{0, 0}, lateralSpring{0, 0};
        std::array<BristleFrictionState, 4> wedge{};
        std::array<double, 2> wheel{0, 0}, wheelLateral{0, 0}, wheelLift{0, 0};
        std::array<double, 2> wheelOffset{0, 0};  ///< tread − rail, lateral [m]
        std::array<double, 2> wheelFlange{0, 0};  ///< flange normal force, creep and flange only [N]
        double pin = 0;  ///< on the car body, +y
        // Energy audit [W]: the rails' work rate Σ N_i·ż_rail,i + Σ F_y,i·ė_i (the
        // lateral restraint is the rails' external force, WheelRailContact.h) and
        // the power dissipated by every element (contact damping, pin, lateral
        // link, wedges), from the element laws.
        double railInputPower = 0, dissipatedPower = 0;
        double elasticEnergy = 0;  ///< [J], every element's

        Eigen::Matrix<double, kNumDofs, 1> generalized = Eigen::Matrix<double, kNumDofs, 1>::Zero();
    };

    /// `wheelRail`: the lateral wheel–rail formulation, as the Simbody half car's
    /// (contacts/WheelRailContact.h), its two wheels per side lumped.
    EomHalfCarModel(const CarParameters& car, RailStateFunction rails, EomSimplifications simplifications = {},
                    WheelRailSettings wheelRail = {});

    /// Static equilibrium on level rails, placed as the Simbody half car places it.
    State makeStaticState() const;
    void calcStateDerivative(double t, const State& y, State& yDot) const;
    Forces calcForces(double t, const State& y) const;

    /// Energy audit: kinetic + gravity + elastic energy of every element
    /// (contacts, springs, pin, lateral link or restraint, bristles) [J].
    double calcStoredEnergy(double t, const State& y) const;
    /// The two energy-audit quadratures' integrands: {rail input power, dissipated power} [W].
    static constexpr int kNumEnergyIntegrals = 2;
    void calcEnergyRates(double t, const State& y, double* rates) const;

    /// What one output time records: the half car's common values, this model's forces and state.
    struct Sample : HalfCarSample {
        Forces forces;
        State y;
    };
    const ChannelLayout& getChannels() const { return channels_.getLayout(); }
    /// energyIntegrals: as calcChannels.
    Sample calcSample(double t, const State& y, const double* energyIntegrals = nullptr) const;
    /// Static load of each wheel of the equivalent wheelset (two real wheels) [N].
    double calcStaticWheelLoad() const;
    /// The truck's static equilibrium (the one definition, mbmodel/TruckStatics.h).
    TruckStatics calcTruckStatics() const;
    /// energyIntegrals: {rail work, dissipated energy} since t = 0 [J] (the
    /// integrals of calcEnergyRates, StiffIntegrator::getQuadrature()); NaN when null.
    void calcChannels(double t, const State& y, std::vector<double>& out,
                      const double* energyIntegrals = nullptr) const;
    std::vector<std::string> getStateNames() const;
    const CarParameters& getCar() const { return car_; }
    double getMass(int body) const { return mass_[body]; }
    double getInertia(int body) const { return inertia_[body]; }

    // Stations (body frame, y and z of the body origin = mass center) [m].
    struct Geometry {
        Eigen::Vector2d plateOnCarBody, bowlOnBolster;            ///< center-plate centers
        double rimRadius = 0;                                      ///< a_c
        std::array<Eigen::Vector2d, 2> padOnCarBody, bearingOnBolster;
        std::array<Eigen::Vector2d, 2> springOnBolster, seatOnWheelset;
        std::array<Eigen::Vector2d, 2> tread;                      ///< on the wheelset
        std::array<double, 2> railY{0, 0};
    };
    const Geometry& getGeometry() const { return geom_; }

    /// Element laws as this model's simplifications leave them.
    struct Laws {
        UnilateralContactLaw rim, sideBearing, wheelVertical;
        VerticalSpringLaw spring;
        LateralSpringLaw lateral;
        double pinStiffness = 0, pinDamping = 0;
        double wheelLateralStiffness = 0, wheelLateralDamping = 0;
        BristleFrictionLaw wedgeVertical, wedgeLateral;
        double sideBearingClearance = 0;
    };
    const Laws& getLaws() const { return laws_; }

private:
    struct Point {
        Eigen::Vector2d x, v, r;  ///< ground position, velocity, arm from the body origin
    };
    Point findStation(const State& y, int body, const Eigen::Vector2d& p) const;
    static void applyForce(Forces& f, int body, const Point& at, const Eigen::Vector2d& force);
    double calcSpringForce(double compression) const;
    double calcSpringEnergy(double compression) const;
    double calcLockedLinkDamping() const;
    void declareChannels();

    CarParameters car_;
    RailStateFunction rails_;
    EomSimplifications simp_;
    WheelRailSettings wheelRail_;
    Geometry geom_;
    Laws laws_;
    std::array<double, 3> mass_{}, inertia_{};
    double staticCarBodyZ_ = 0;
    ChannelTable<Sample> channels_;
};

/// Rail input of the half car's equivalent wheelset from the track: the mean of
/// the rails under axles at track positions s(t) and s(t) − wheelbase (report eqs 6–7).
class TrackInput;
struct TrackMotion;
RailStateFunction makeEquivalentWheelsetInput(const TrackInput& track, const TrackMotion& motion, double wheelbase);

/// A sinusoidal cross-level c(t) = C·sin(ω t) (rails at ±c/2), the describing
/// function's input.
RailStateFunction makeSinusoidalCrossLevel(double amplitude, double omega);

}  // namespace rockroll
