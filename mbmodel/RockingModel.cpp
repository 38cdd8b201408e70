#include "mbmodel/RockingModel.h"
#include "contacts/CustomForce.h"


#include <cmath>
#include <fmt/format.h>

using SimTK::State; using SimTK::Vec3; using SimTK::Vector; using SimTK::MobilizedBody; using SimTK::Transform;
using SimTK::Rotation; using SimTK::Mat33; using SimTK::Body; using SimTK::MassProperties; using SimTK::Inertia;
using SimTK::Stage; using SimTK::Force; using SimTK::SimbodyMatterSubsystem; using SimTK::GeneralForceSubsystem;
using SimTK::System; using SimTK::Integrator;

namespace rockroll {

/// Integrates the energy-audit powers as z states: the work of the rails and the
/// dissipation. No force. The z states hold megajoules: Simbody's error control
/// treats z like any other state (CPodes: one relative and absolute tolerance for
/// every y; RK: z relative to max(|z|, 1)), and energies of 10⁴–10⁵ J in joules
/// would drive the step size. In MJ their error estimate, which is of the order
/// of h·P·(accuracy), stays far below the other states' and the steps do not change.
class RockingModel::EnergyMeter : public Force::Custom::Implementation {
public:
    static constexpr double kScale = 1e-6;  // z = energy · kScale
    static constexpr int kNumZ = 2;
    EnergyMeter(const GeneralForceSubsystem& forces, const RockingModel& model) : forces_(forces), model_(model) {}
    void calcForce(const State&, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<Vec3>&, Vector&) const override {}
    SimTK::Real calcPotentialEnergy(const State&) const override { return 0; }
    void realizeTopology(State& s) const override { z0_ = forces_.allocateZ(s, Vector(kNumZ, 0.0)); }
    void realizeAcceleration(const State& s) const override {
        const TruckPowers p = model_.calcPowers(s);
        Vector& zDot = forces_.updZDot(s);
        zDot[z0_] = kScale * p.railInput;
        zDot[z0_ + 1] = kScale * p.dissipated;
    }
    EnergyAccounts get(const State& s) const {
        const Vector& z = forces_.getZ(s);
        return {z[z0_] / kScale, z[z0_ + 1] / kScale};
    }
    void reset(State& s) const {
        for (int i = 0; i < kNumZ; ++i) forces_.updZ(s)[z0_ + i] = 0;
    }
    void mark(State& s) const {
        for (int i = 0; i < kNumZ; ++i) forces_.updZ(s)[z0_ + i] = 1;
    }

private:
    const GeneralForceSubsystem& forces_;
    const RockingModel& model_;
    mutable SimTK::ZIndex z0_;
};

RockingModel::RockingModel(const CarParameters& car, const TrackInput& track, ModelOptions options)
    : car_(car), track_(track), options_(options), matter_(system_), forces_(system_) {
    // Attribution runs get a gravity that can exclude bodies, once the trucks exist (addTrucks).
    if (options_.attribution.isDefault()) Force::UniformGravity(forces_, matter_, Vec3(0, 0, -units::g));
}

void RockingModel::setTwistingCarBody(std::vector<CarBodyPart> parts, const MobilizedBody& twist, double stiffness,
                                      double damping) {
    carBodyParts_ = std::move(parts);
    twist_ = twist;
    torsionalStiffness_ = stiffness;
    torsionalDamping_ = damping;
    Force::MobilityLinearSpring(forces_, twist_, SimTK::MobilizerQIndex(0), stiffness, 0);
    Force::MobilityLinearDamper(forces_, twist_, SimTK::MobilizerUIndex(0), damping);
}

double RockingModel::getCarBodyTwist(const State& s) const { return isCarBodyTwisting() ? twist_.getOneQ(s, 0) : 0.0; }

double RockingModel::calcCarBodyTorque(const State& s) const {
    return isCarBodyTwisting() ? torsionalStiffness_ * twist_.getOneQ(s, 0) + torsionalDamping_ * twist_.getOneU(s, 0)
                               : 0.0;
}

void RockingModel::addTrucks(std::vector<TruckSpec> specs, const std::vector<Vec3>& p_CarBodyPlates) {
    if (carBodyParts_.empty()) carBodyParts_.push_back({carBody_, 0});
    const AttributionSwitches& a = options_.attribution;
    for (size_t i = 0; i < specs.size(); ++i) {
        specs[i].unsprungGravity = a.unsprungGravity;
        specs[i].unsprungMassScale = a.unsprungMassScale;
        specs[i].wheelRail = options_.wheelRail;
        // The part over the truck: the front half carries the trucks ahead of the car's CG.
        const int part = carBodyParts_.size() > 1 && p_CarBodyPlates[i][0] < 0 ? 1 : 0;
        truckPart_.push_back(part);
        const Vec3 p_PartPlate = p_CarBodyPlates[i] - Vec3(carBodyParts_[size_t(part)].x, 0, 0);
        trucks_.push_back(std::make_unique<Truck>(matter_, forces_, carBodyParts_[size_t(part)].body, p_PartPlate, car_,
                                                  std::move(specs[i])));
    }
    if (!a.isDefault()) {
        Force::Gravity gravity(forces_, matter_, -SimTK::ZAxis, units::g);
        for (const auto& truck : trucks_)
            for (int w = 0; w < truck->getNumWheelsets() && !a.unsprungGravity; ++w)
                gravity.setDefaultBodyIsExcluded(truck->getWheelset(w).getMobilizedBodyIndex(), true);
    }
    energyMeter_ = &addCustomForce<EnergyMeter>(forces_, forces_, *this);
    system_.realizeTopology();
    State s = makeStaticState(false);
    staticCarBodyHeight_ = carBody_.getBodyOriginLocation(s)[2];  // the halves' CGs are at one height
    for (const auto& truck : trucks_) {
        StaticWheelLoads loads;
        for (int w = 0; w < truck->getNumWheelsets(); ++w) {
            const WheelRailForces f = truck->getWheelRail(w).calcForces(s);
            loads.push_back({f.vertical[0], f.vertical[1]});
        }
        staticWheelLoads_.push_back(std::move(loads));
    }
    declareChannels();
}

RailInputFunction RockingModel::makeRailInput(std::vector<double> trackOffsets) const {
    // trackOffsets: s_i(0), where the axles are on the track at t = 0.
    TrackMotion motion = options_.motion;
    if (motion.speed == 0) motion.speed = options_.speed;
    return [this, motion, offsets = std::move(trackOffsets)](double t) {
        RailHeights h;
        const double w = 1.0 / double(offsets.size());
        const double s = motion.calcDistance(t), V = motion.calcSpeed(t);
        h.speed = V;
        for (double s0 : offsets) {
            const RailPoint p = track_.calcRails(s + s0);
            for (int i = 0; i < 2; ++i) {
                h.z[i] += w * p.z[i];
                h.zDot[i] += w * p.slope[i] * V;
            }
        }
        return h;
    };
}

State RockingModel::makeDefaultState() const {
    State s = system_.getDefaultState();
    matter_.setUseEulerAngles(s, true);
    system_.realizeModel(s);
    return s;
}

State RockingModel::makeStaticState(bool requireLevelRails) const {
    State s = makeDefaultState();
    s.setTime(0);
    std::vector<double> plateZ;
    for (const auto& truck : trucks_) plateZ.push_back(truck->setStaticState(s));
    setCarBodyPose(s, plateZ);
    resetEnergyAccounts(s);
    if (staticSolve_) solveStaticEquilibrium(s);
    for (const auto& truck : trucks_)
        for (int i = 0; i < truck->getNumWheelsets() && requireLevelRails; ++i) {
            const RailHeights r = truck->getWheelRail(i).getRailHeights(0);
            if (std::abs(r.z[0]) > 1e-12 || std::abs(r.z[1]) > 1e-12)
                throw std::invalid_argument(
                    "the rails under every wheelset must be level at t = 0 (static equilibrium is "
                    "placed on level track); use a level lead-in");
        }
    system_.realize(s, Stage::Velocity);
    return s;
}

void RockingModel::solveStaticEquilibrium(State& s) const {
    // Tolerance on the generalized accelerations [m/s², rad/s²]: roundoff in them is
    // about 1e-12 (forces of 1e6 N on masses of 1e2 kg); 1e-8 is below anything a run sees.
    constexpr double kTolerance = 1e-8, kStep = 1e-7;
    constexpr int kMaxIterations = 100;
    const int n = s.getNU();
    s.updU() = 0;
    // The generalized forces f = M·u̇ at rest: the negative gradient of the potential energy V
    // (at rest, with every friction bristle at its unloaded state, every force is elastic or
    // gravity).
    Vector udot;
    auto calcForces = [&](State& x) {
        system_.realize(x, Stage::Acceleration);
        udot = x.getUDot();
        Vector f;
        matter_.multiplyByM(x, udot, f);
        return f;
    };
    // Moves x by q += N(q)·du from the positions q0 (N at q0); a quaternion, where a caller's
    // state uses one, is renormalized.
    auto move = [this](State& x, const Vector& q0, const Vector& du) {
        x.updQ() = q0;
        system_.realize(x, Stage::Position);
        Vector dq;
        matter_.multiplyByN(x, false, du, dq);
        x.updQ() = q0 + dq;
        matter_.normalizeQuaternions(x);
    };
    Vector f = calcForces(s);
    for (int it = 0; it < kMaxIterations && udot.normInf() >= kTolerance; ++it) {
        const Vector q0 = s.getQ();
        const double V0 = system_.calcPotentialEnergy(s), norm0 = f.norm();
        SimTK::Matrix K(n, n);  // the stiffness −∂f/∂u
        for (int j = 0; j < n; ++j) {
            Vector du(n, 0.0);
            du[j] = kStep;
            move(s, q0, du);
            const Vector plus = calcForces(s);
            move(s, q0, -du);
            K(j) = (calcForces(s) - plus) / (2 * kStep);
        }
        Vector du;
        SimTK::FactorQTZ(K, 1e-12).solve(f, du);
        // Newton's step, halved until the potential energy (or the forces' norm, where the
        // energy no longer resolves the change) falls: a rim point lifting or a side bearing
        // touching makes the forces piecewise linear, and a full step can overshoot.
        double step = 1;
        for (int halvings = 0;; ++halvings) {
            move(s, q0, step * du);
            f = calcForces(s);
            if (system_.calcPotentialEnergy(s) < V0 || f.norm() < norm0 || halvings == 50) break;
            step /= 2;
        }
    }
    if (udot.normInf() >= kTolerance)
        throw std::runtime_error(fmt::format(
            "the static equilibrium of the off-centre car body did not converge in {} Newton steps: largest "
            "generalized acceleration {:.3g} (m/s^2 or rad/s^2) against {:.0e}; with this offset the car may have no "
            "static equilibrium (a wheel lifting off, the body tipping)",
            kMaxIterations, udot.normInf(), kTolerance));
}

void RockingModel::declareChannels() {
    ChannelTable<CarSample>& c = channels_;
    const double in = units::inch, deg = units::degree;
    c.add("roll", "deg", ChannelRole::Roll, [=](const CarSample& s) { return s.angles[0] / deg; });
    c.add("pitch", "deg", ChannelRole::Pitch, [=](const CarSample& s) { return s.angles[1] / deg; });
    c.add("yaw", "deg", ChannelRole::Yaw, [=](const CarSample& s) { return s.angles[2] / deg; });
    c.add("car_body_vertical", "in", [=](const CarSample& s) { return s.verticalFromStatic / in; });
    c.add("car_body_lateral", "in", [=](const CarSample& s) { return s.position[1] / in; });
    if (isCarBodyTwisting()) {
        c.add("car_body_twist", "deg", ChannelRole::CarBodyTwist, [=](const CarSample& s) { return s.twist / deg; });
        c.add("car_body_torque", "lb_in", [=](const CarSample& s) { return s.torque / (units::lbf * in); });
    }
    for (size_t i = 0; i < trucks_.size(); ++i) trucks_[i]->declareChannels(c, int(i));
    declareEnergyChannels(c);
    // Freight channels, after the energy audit's so that the columns above keep their places.
    for (size_t i = 0; i < trucks_.size(); ++i)
        trucks_[i]->declareFreightChannels(c, int(i), staticSolve_ ? staticWheelLoads_[i] : StaticWheelLoads{});
    c.add("car_body_vertical_accel", "g", ChannelRole::CarBodyVerticalAccel,
          [](const CarSample& s) { return s.cgAcceleration[2] / units::g; });
    c.add("car_body_lateral_accel", "g", ChannelRole::CarBodyLateralAccel,
          [](const CarSample& s) { return s.cgAcceleration[1] / units::g; });
    // Over each truck, when the car has more than one (the half car's one truck is under the CG).
    for (size_t i = 0; i < trucks_.size() && trucks_.size() > 1; ++i) {
        const std::string& T = trucks_[i]->getLabel();
        c.add("car_body_vertical_accel_" + T, "g", ChannelRole::CarBodyVerticalAccel,
              [i](const CarSample& s) { return s.trucks[i].carBodyAcceleration[2] / units::g; });
        c.add("car_body_lateral_accel_" + T, "g", ChannelRole::CarBodyLateralAccel,
              [i](const CarSample& s) { return s.trucks[i].carBodyAcceleration[1] / units::g; });
    }
}

CarSample RockingModel::calcSample(const State& s) const {
    system_.realize(s, Stage::Acceleration);
    CarSample c;
    // The car body's CG and roll: its halves' means when it twists (equal halves).
    c.angles = carBody_.getBodyRotation(s).convertRotationToBodyFixedXYZ();
    c.angles[0] = 0;
    c.position = Vec3(0);
    c.cgAcceleration = Vec3(0);
    const double share = 1.0 / double(carBodyParts_.size());
    for (const CarBodyPart& p : carBodyParts_) {
        c.angles[0] += share * p.body.getBodyRotation(s).convertRotationToBodyFixedXYZ()[0];
        c.position += share * p.body.getBodyOriginLocation(s);
        c.cgAcceleration += share * p.body.getBodyOriginAcceleration(s);
    }
    c.verticalFromStatic = c.position[2] - staticCarBodyHeight_;
    c.twist = getCarBodyTwist(s);
    c.torque = calcCarBodyTorque(s);
    for (size_t i = 0; i < trucks_.size(); ++i) {
        c.trucks.push_back(trucks_[i]->calcSample(s));
        const CarBodyPart& p = carBodyParts_[size_t(truckPart_[i])];
        c.trucks.back().carBodyAcceleration = p.body.findStationAccelerationInGround(s, Vec3(trucks_[i]->getX() - p.x, 0, 0));
    }
    const EnergyAccounts a = getEnergyAccounts(s);
    c.energyStored = calcMechanicalEnergy(s);
    c.energyInput = a.input;
    c.energyDissipated = a.dissipated;
    return c;
}

void RockingModel::calcChannels(const State& s, std::vector<double>& out) const {
    channels_.evaluate(calcSample(s), out);
}

RockingModel::EnergyAccounts RockingModel::getEnergyAccounts(const State& s) const { return energyMeter_->get(s); }

void RockingModel::resetEnergyAccounts(State& s) const { energyMeter_->reset(s); }

std::vector<int> RockingModel::getEnergyAuditYIndices() const {
    // Marks the meter's z entries and finds them in Y (z follows q and u there).
    State s = makeDefaultState();
    for (int i = 0; i < s.getNY(); ++i) s.updY()[i] = 0;
    energyMeter_->mark(s);
    std::vector<int> out;
    for (int i = 0; i < s.getNY(); ++i)
        if (s.getY()[i] != 0) out.push_back(i);
    return out;
}

TruckPowers RockingModel::calcPowers(const State& s) const {
    TruckPowers sum;
    // The twisting body's damper, C·θ̇².
    if (isCarBodyTwisting()) sum.dissipated += torsionalDamping_ * SimTK::square(twist_.getOneU(s, 0));
    for (const auto& truck : trucks_) {
        const TruckPowers p = truck->calcPowers(s);
        sum.railInput += p.railInput;
        sum.dissipated += p.dissipated;
    }
    return sum;
}

double RockingModel::calcMechanicalEnergy(const State& s) const {
    system_.realize(s, Stage::Dynamics);
    return system_.calcEnergy(s);
}

}  // namespace rockroll
