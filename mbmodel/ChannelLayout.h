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

}  // namespace rockroll
