#pragma once
// Names of the recorded output channels (each names its unit) and which of them
// feed the run summary.
#include <string>
#include <vector>

namespace rockroll {

struct ChannelLayout {
    std::vector<std::string> names;
    int roll = -1;
    std::vector<int> sideBearing;          ///< one side bearing each [lb]
    std::vector<int> centerPlate;          ///< one truck's plate total each [lb]
    std::vector<int> truckSideWheelLoad;   ///< two wheels, one truck side [lb]
    std::vector<int> singleWheelLoad;      ///< one wheel (or equivalent) [lb]
    std::vector<int> wheelLift;            ///< [in]
    /// One (equivalent) wheelset: its two wheels' lifts [in] and its lateral
    /// displacement from the track centre line at rail-head height [in]
    /// (-1 where the formulation holds the wheelset laterally by construction).
    struct Wheelset {
        int liftLeft = -1, liftRight = -1, lateral = -1;
    };
    std::vector<Wheelset> wheelsets;
    int energyStored = -1, energyInput = -1, energyDissipated = -1;  ///< cumulative [J]

    int add(std::string name) {
        names.push_back(std::move(name));
        return int(names.size()) - 1;
    }
    int find(const std::string& name) const {
        for (size_t i = 0; i < names.size(); ++i)
            if (names[i] == name) return int(i);
        return -1;
    }
};

/// The energy-audit channels (mbmodel/EnergyAudit.h), recorded last by every
/// time-domain model: stored energy (kinetic + gravity + elastic, absolute),
/// work of the rails on the wheels since t = 0, energy dissipated since t = 0.
inline void declareEnergyChannels(ChannelLayout& c) {
    c.energyStored = c.add("energy_stored_J");
    c.energyInput = c.add("energy_input_J");
    c.energyDissipated = c.add("energy_dissipated_J");
}

/// The channels every hand-written half car records first, in this order:
/// roll, car-body vertical and lateral motion, cross-level, center plate, side
/// bearings (left, right) — the names the Simbody half car gives them.
inline void declareHalfCarBodyChannels(ChannelLayout& c) {
    c.roll = c.add("roll_deg");
    c.add("car_body_vertical_in");
    c.add("car_body_lateral_in");
    c.add("cross_level_F_in");
    c.centerPlate.push_back(c.add("center_plate_F_lb"));
    for (const char* side : {"L", "R"}) c.sideBearing.push_back(c.add(std::string("side_bearing_F_") + side + "_lb"));
}

/// The equivalent wheelset's wheel loads (two wheels each) and lifts, left then
/// right; then its lateral displacement when the formulation has one.
inline void declareEquivalentWheelsetChannels(ChannelLayout& c, bool hasLateral) {
    for (const char* side : {"L", "R"}) {
        const int idx = c.add(std::string("wheels_F_") + side + "_lb");
        c.truckSideWheelLoad.push_back(idx);
        c.singleWheelLoad.push_back(idx);
    }
    for (const char* side : {"L", "R"}) c.wheelLift.push_back(c.add(std::string("wheel_lift_F1_") + side + "_in"));
    ChannelLayout::Wheelset w;
    w.liftLeft = c.wheelLift[c.wheelLift.size() - 2];
    w.liftRight = c.wheelLift.back();
    if (hasLateral) w.lateral = c.add("wheelset_lateral_F1_in");
    c.wheelsets.push_back(w);
}

}  // namespace rockroll
