#pragma once
// The recorded output channels of a model, each declared once as
// {quantity, unit, role, evaluator} (ChannelTable): the CSV column names
// ("<quantity>_<unit>"), the recorder's values and the summary's inputs (its
// roles) all come from that one declaration.
#include "mbmodel/Units.h"

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockroll {

/// What a channel is to the summary, the criteria and the run monitor. A channel
/// may have several roles (the half car's equivalent-wheelset load is both one
/// truck side's wheels and the single-wheel load of its unloading ratio).
enum class ChannelRole : unsigned {
    None = 0,
    Roll = 1u << 0,                  ///< car-body roll [deg]
    CenterPlate = 1u << 1,           ///< one truck's center-plate total [lb]
    SideBearing = 1u << 2,           ///< one side bearing [lb]
    TruckSideWheelLoad = 1u << 3,    ///< the wheels of one truck side [lb]
    SingleWheelLoad = 1u << 4,       ///< one wheel (or the equivalent wheelset's wheel) [lb]
    WheelLift = 1u << 5,             ///< [in]
    WheelsetLateral = 1u << 6,       ///< wheelset lateral displacement at rail-head height [in]
    WheelUnloading = 1u << 7,        ///< (static − load) / static of one wheel [ratio]
    LOverV = 1u << 8,                ///< lateral / vertical contact force of one wheel [ratio]
    CarBodyVerticalAccel = 1u << 9,  ///< [g]
    CarBodyLateralAccel = 1u << 10,  ///< [g]
    EnergyStored = 1u << 11,         ///< [J]
    EnergyInput = 1u << 12,          ///< [J]
    EnergyDissipated = 1u << 13,     ///< [J]
    TruckSideLOverV = 1u << 14,      ///< ΣL/ΣV of the wheels of one truck side [ratio]
    Pitch = 1u << 15,                ///< car-body pitch [deg]
    Yaw = 1u << 16,                  ///< car-body yaw [deg]
    CarBodyTwist = 1u << 17,         ///< rear half against front half of a twisting car body [deg]
};
constexpr ChannelRole operator|(ChannelRole a, ChannelRole b) { return ChannelRole(unsigned(a) | unsigned(b)); }
constexpr bool hasRole(ChannelRole roles, ChannelRole r) { return (unsigned(roles) & unsigned(r)) != 0; }

/// One channel's declaration, without its evaluator.
struct ChannelInfo {
    std::string quantity;  ///< what and where, e.g. "side_bearing_F_L"
    std::string unit;      ///< "lb", "in", "deg", "g", "J", "ratio"; empty for flags and mode numbers
    ChannelRole roles = ChannelRole::None;
    std::string truck;     ///< the truck it belongs to ("F", "R"); empty for the car body and energies
    /// The CSV column name: the quantity, then its unit.
    std::string getColumn() const { return unit.empty() ? quantity : quantity + "_" + unit; }
};

/// The channels of a model in recording order, and which of them feed the
/// summary (indices into the channel list, derived from the roles by add()).
struct ChannelLayout {
    std::vector<ChannelInfo> channels;
    std::vector<std::string> names;  ///< column names, channels[i].getColumn()
    int roll = -1;
    int pitch = -1, yaw = -1, carBodyTwist = -1;  ///< −1: the model has no such motion
    std::vector<int> sideBearing;          ///< one side bearing each [lb]
    std::vector<int> centerPlate;          ///< one truck's plate total each [lb]
    std::vector<int> truckSideWheelLoad;   ///< two wheels, one truck side [lb]
    std::vector<int> singleWheelLoad;      ///< one wheel (or equivalent) [lb]
    std::vector<int> wheelLift;            ///< [in]
    std::vector<int> wheelUnloading;       ///< [ratio]
    std::vector<int> lOverV;               ///< [ratio]; empty when the model has no lateral wheel forces
    std::vector<int> truckSideLOverV;      ///< [ratio]; the same
    std::vector<int> carBodyVerticalAccel, carBodyLateralAccel;  ///< [g]
    /// One (equivalent) wheelset: its two wheels' lifts [in] and its lateral
    /// displacement from the track centre line at rail-head height [in]
    /// (-1 where the formulation holds the wheelset laterally by construction).
    struct Wheelset {
        int liftLeft = -1, liftRight = -1, lateral = -1;
        /// Flange normal force and the wheel's own L/V, left and right; −1 when the
        /// model has no flange contact (the run monitor's climb rule, RunLimits.h).
        int flange[2] = {-1, -1}, lOverV[2] = {-1, -1};
    };
    std::vector<Wheelset> wheelsets;
    int energyStored = -1, energyInput = -1, energyDissipated = -1;  ///< cumulative [J]

    /// Appends a channel; std::invalid_argument for a column name that is empty,
    /// holds a comma, a quote or white space (the CSV header) or is already taken.
    int add(ChannelInfo info) {
        const std::string column = info.getColumn();
        if (column.empty() || column.find_first_of(",\" \t\r\n") != std::string::npos)
            throw std::invalid_argument("channel name '" + column + "': expected no comma, quote or white space");
        if (find(column) >= 0) throw std::invalid_argument("channel '" + column + "' declared twice");
        const int i = int(channels.size());
        auto roleIs = [&](ChannelRole r) { return hasRole(info.roles, r); };
        if (roleIs(ChannelRole::Roll)) roll = i;
        if (roleIs(ChannelRole::Pitch)) pitch = i;
        if (roleIs(ChannelRole::Yaw)) yaw = i;
        if (roleIs(ChannelRole::CarBodyTwist)) carBodyTwist = i;
        if (roleIs(ChannelRole::CenterPlate)) centerPlate.push_back(i);
        if (roleIs(ChannelRole::SideBearing)) sideBearing.push_back(i);
        if (roleIs(ChannelRole::TruckSideWheelLoad)) truckSideWheelLoad.push_back(i);
        if (roleIs(ChannelRole::SingleWheelLoad)) singleWheelLoad.push_back(i);
        if (roleIs(ChannelRole::WheelLift)) wheelLift.push_back(i);
        if (roleIs(ChannelRole::WheelUnloading)) wheelUnloading.push_back(i);
        if (roleIs(ChannelRole::LOverV)) lOverV.push_back(i);
        if (roleIs(ChannelRole::TruckSideLOverV)) truckSideLOverV.push_back(i);
        if (roleIs(ChannelRole::CarBodyVerticalAccel)) carBodyVerticalAccel.push_back(i);
        if (roleIs(ChannelRole::CarBodyLateralAccel)) carBodyLateralAccel.push_back(i);
        if (roleIs(ChannelRole::EnergyStored)) energyStored = i;
        if (roleIs(ChannelRole::EnergyInput)) energyInput = i;
        if (roleIs(ChannelRole::EnergyDissipated)) energyDissipated = i;
        channels.push_back(std::move(info));
        names.push_back(column);
        return i;
    }
    int find(const std::string& column) const {
        for (size_t i = 0; i < names.size(); ++i)
            if (names[i] == column) return int(i);
        return -1;
    }
};

/// A model's channels with their evaluators: each channel is declared once, by
/// one add() call that gives its name, unit, roles and how to compute it from
/// the model's per-sample values `Sample` (forces computed once per output time).
template <class Sample>
class ChannelTable {
public:
    using Evaluator = std::function<double(const Sample&)>;

    int add(ChannelInfo info, Evaluator evaluate) {
        const int i = layout_.add(std::move(info));
        evaluators_.push_back(std::move(evaluate));
        return i;
    }
    int add(std::string quantity, std::string unit, ChannelRole roles, Evaluator evaluate) {
        return add(ChannelInfo{std::move(quantity), std::move(unit), roles, ""}, std::move(evaluate));
    }
    int add(std::string quantity, std::string unit, Evaluator evaluate) {
        return add(std::move(quantity), std::move(unit), ChannelRole::None, std::move(evaluate));
    }
    /// Groups already declared wheel-lift (and lateral) channels into a wheelset for the run monitor.
    void addWheelset(ChannelLayout::Wheelset w) { layout_.wheelsets.push_back(w); }
    /// The wheelset whose left wheel's lift channel is named `liftLeftQuantity`, or nullptr.
    ChannelLayout::Wheelset* findWheelset(const std::string& liftLeftQuantity) {
        for (auto& w : layout_.wheelsets)
            if (w.liftLeft >= 0 && layout_.channels[size_t(w.liftLeft)].quantity == liftLeftQuantity) return &w;
        return nullptr;
    }

    const ChannelLayout& getLayout() const { return layout_; }
    int size() const { return int(evaluators_.size()); }

    /// One sample of every channel, in declaration order.
    void evaluate(const Sample& sample, std::vector<double>& out) const {
        out.resize(evaluators_.size());
        for (size_t i = 0; i < evaluators_.size(); ++i) out[i] = evaluators_[i](sample);
    }

private:
    ChannelLayout layout_;
    std::vector<Evaluator> evaluators_;
};

/// Unloading ratio of a wheel: (static − load) / static; 0 at rest, 1 when the
/// wheel carries nothing, negative when it carries more than its static load.
inline double calcWheelUnloading(double load, double staticLoad) { return (staticLoad - load) / staticLoad; }

/// L/V of one wheel: the lateral contact force on the wheel over its vertical
/// load, signed (+ toward +y, the left rail). 0 while the wheel carries neither
/// (a lifted wheel, with the lateral restraint split by load share); ±infinity for
/// a lateral force on an unloaded wheel (no model records that: the eom model with
/// equal_lateral_shares, the one that would, records no L/V).
inline double calcLOverV(double lateral, double vertical) {
    if (vertical > 0) return lateral / vertical;
    return lateral == 0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), lateral);
}

/// The energy-audit channels (mbmodel/EnergyAudit.h), recorded after a model's
/// own channels by every time-domain model: stored energy (kinetic + gravity +
/// elastic, absolute), work of the rails on the wheels since t = 0, energy
/// dissipated since t = 0. Sample provides energyStored, energyInput, energyDissipated [J].
template <class Sample>
void declareEnergyChannels(ChannelTable<Sample>& c) {
    c.add("energy_stored", "J", ChannelRole::EnergyStored, [](const Sample& s) { return s.energyStored; });
    c.add("energy_input", "J", ChannelRole::EnergyInput, [](const Sample& s) { return s.energyInput; });
    c.add("energy_dissipated", "J", ChannelRole::EnergyDissipated, [](const Sample& s) { return s.energyDissipated; });
}

/// What every hand-written half car (bespoke/) records at one output time, SI;
/// each model's own sample extends it.
struct HalfCarSample {
    double roll = 0;               ///< car body [rad]
    double verticalFromStatic = 0; ///< car-body CG above its static height [m]
    double lateral = 0;            ///< car-body CG [m]
    double crossLevel = 0;         ///< right − left rail under the equivalent wheelset [m]
    double centerPlate = 0;        ///< both rim contacts [N]
    double sideBearing[2] = {0, 0};
    double wheel[2] = {0, 0};      ///< equivalent wheelset: two wheels of one truck side each [N]
    double wheelLift[2] = {0, 0};  ///< [m]
    double wheelOffset[2] = {0, 0};   ///< tread − rail, lateral [m] (formulations with a wheelset lateral motion)
    double wheelLateral[2] = {0, 0};  ///< lateral contact force on the wheel [N] (the same formulations)
    double wheelFlange[2] = {0, 0};   ///< flange normal force [N] (the creep-and-flange contact)
    double verticalAccel = 0, lateralAccel = 0;  ///< car-body CG, track axes [m/s²]
    double energyStored = 0, energyInput = 0, energyDissipated = 0;  ///< [J]
};

/// The channels every hand-written half car records first, in this order:
/// roll, car-body vertical and lateral motion, cross-level, center plate, side
/// bearings (left, right) — the names the Simbody half car gives them.
template <class Sample>
void declareHalfCarBodyChannels(ChannelTable<Sample>& c) {
    const double in = units::inch, lb = units::lbf;
    c.add("roll", "deg", ChannelRole::Roll, [](const Sample& s) { return s.roll / units::degree; });
    c.add("car_body_vertical", "in", [=](const Sample& s) { return s.verticalFromStatic / in; });
    c.add("car_body_lateral", "in", [=](const Sample& s) { return s.lateral / in; });
    c.add("cross_level_F", "in", [=](const Sample& s) { return s.crossLevel / in; });
    c.add({"center_plate_F", "lb", ChannelRole::CenterPlate, "F"}, [=](const Sample& s) { return s.centerPlate / lb; });
    for (int side : {0, 1})
        c.add({std::string("side_bearing_F_") + (side == 0 ? "L" : "R"), "lb", ChannelRole::SideBearing, "F"},
              [=](const Sample& s) { return s.sideBearing[side] / lb; });
}

/// The equivalent wheelset's wheel loads (two wheels each) and lifts, left then
/// right (each lift followed by its flange force when the formulation has flanges);
/// then its lateral displacement when the formulation has one.
template <class Sample>
void declareEquivalentWheelsetChannels(ChannelTable<Sample>& c, bool hasLateral, bool hasFlange = false) {
    const double in = units::inch, lb = units::lbf;
    for (int side : {0, 1})
        c.add(std::string("wheels_F_") + (side == 0 ? "L" : "R"), "lb",
              ChannelRole::TruckSideWheelLoad | ChannelRole::SingleWheelLoad,
              [=](const Sample& s) { return s.wheel[side] / lb; });
    ChannelLayout::Wheelset w;
    for (int side : {0, 1}) {
        (side == 0 ? w.liftLeft : w.liftRight) =
            c.add(std::string("wheel_lift_F1_") + (side == 0 ? "L" : "R"), "in", ChannelRole::WheelLift,
                  [=](const Sample& s) { return s.wheelLift[side] / in; });
        if (hasFlange)
            w.flange[side] = c.add(std::string("flange_F1_") + (side == 0 ? "L" : "R"), "lb",
                                   [=](const Sample& s) { return s.wheelFlange[side] / lb; });
    }
    if (hasLateral)
        w.lateral = c.add("wheelset_lateral_F1", "in", ChannelRole::WheelsetLateral,
                          [=](const Sample& s) { return (s.wheelOffset[0] + s.wheelOffset[1]) / 2 / in; });
    c.addWheelset(w);
}

/// The freight channels of a hand-written half car, after its energy channels:
/// each equivalent wheel's unloading ratio against `staticWheelLoad` [N], its
/// L/V when the formulation has lateral wheel forces, and the car-body CG's
/// vertical and lateral acceleration [g] (its one truck is under the CG).
template <class Sample>
void declareHalfCarFreightChannels(ChannelTable<Sample>& c, double staticWheelLoad, bool hasLateralForces) {
    for (int side : {0, 1}) {
        const std::string S = side == 0 ? "L" : "R";
        c.add("wheel_unloading_F1_" + S, "ratio", ChannelRole::WheelUnloading,
              [=](const Sample& s) { return calcWheelUnloading(s.wheel[side], staticWheelLoad); });
        if (hasLateralForces) {
            // Its wheel is a truck side's two: its L/V is the truck side's as well.
            const int lv = c.add("l_over_v_F1_" + S, "ratio", ChannelRole::LOverV | ChannelRole::TruckSideLOverV,
                                 [=](const Sample& s) { return calcLOverV(s.wheelLateral[side], s.wheel[side]); });
            if (auto* w = c.findWheelset("wheel_lift_F1_L")) w->lOverV[side] = lv;
        }
    }
    c.add("car_body_vertical_accel", "g", ChannelRole::CarBodyVerticalAccel,
          [](const Sample& s) { return s.verticalAccel / units::g; });
    c.add("car_body_lateral_accel", "g", ChannelRole::CarBodyLateralAccel,
          [](const Sample& s) { return s.lateralAccel / units::g; });
}

}  // namespace rockroll
