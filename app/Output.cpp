#include "app/Output.h"
#include "mbmodel/CsvWriter.h"

#include <cmath>
#include <fmt/format.h>
#include <fstream>

namespace rockroll::app {

nlohmann::ordered_json toJson(const RunSummary& s) {
    nlohmann::ordered_json j;
    j["model"] = s.model;
    j["car"] = s.car;
    j["speed_mph"] = s.speedMph;
    j["amplitude_in"] = s.amplitudeIn;
    j["duration_s"] = s.durationS;
    j["max_roll_deg"] = s.maxRollDeg;
    j["steady_roll_amplitude_deg"] = s.steadyRollAmplitudeDeg;
    j["peak_to_peak_roll_deg"] = s.peakToPeakRollDeg;
    j["max_wheel_lift_in"] = s.maxWheelLiftIn;
    j["max_wheel_load_lb"] = s.maxWheelLoadLb;
    j["min_wheel_load_ratio"] = s.minWheelLoadRatio;
    j["max_side_bearing_load_lb"] = s.maxSideBearingLoadLb;
    j["max_center_plate_load_lb"] = s.maxCenterPlateLoadLb;
    j["raw_max_wheel_load_lb"] = s.rawMaxWheelLoadLb;
    j["raw_min_wheel_load_ratio"] = s.rawMinWheelLoadRatio;
    j["raw_max_side_bearing_load_lb"] = s.rawMaxSideBearingLoadLb;
    j["raw_max_center_plate_load_lb"] = s.rawMaxCenterPlateLoadLb;
    j["static_wheel_load_lb"] = s.staticWheelLoadLb;
    j["static_center_plate_load_lb"] = s.staticCenterPlateLoadLb;
    j["regime"] = s.regime;
    j["stopped_at_s"] = s.stoppedAtS >= 0 ? nlohmann::ordered_json(s.stoppedAtS) : nlohmann::ordered_json(nullptr);
    j["stop_reason"] = s.stopReason.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.stopReason);
    j["center_plate_separation_longest_s"] = s.centerPlateSeparationLongestS;
    j["center_plate_separation_total_s"] = s.centerPlateSeparationTotalS;
    j["wheel_lift_longest_s"] = s.wheelLiftLongestS;
    j["energy_balance_error"] = std::isfinite(s.energyBalanceError) ? nlohmann::ordered_json(s.energyBalanceError)
                                                                    : nlohmann::ordered_json(nullptr);
    j["filter"] = s.filter;
    j["sim_time_s"] = s.simTimeS;
    j["wall_time_s"] = s.wallTimeS;
    j["steps"] = s.steps;
    return j;
}

/// Writes through a temporary name and renames when complete, so a reader never
/// sees a half-written file.
void writeAtomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
    const std::filesystem::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp);
        if (!out) throw std::runtime_error(fmt::format("cannot write {}", tmp.string()));
        write(out);
        out.flush();
        if (!out) throw std::runtime_error(fmt::format("error while writing {}", tmp.string()));
    }
    std::filesystem::rename(tmp, path);
}

void writeHistoryCsv(std::ostream& out, const TimeHistory& h, const std::vector<std::string>& columns, int digits) {
    const std::vector<std::string>& names = columns.empty() ? h.names : columns;
    std::vector<int> index;
    for (const auto& c : names) index.push_back(h.column(c));
    CsvWriter csv(out, names);
    std::vector<CsvCell> cells;
    for (const auto& row : h.samples) {
        cells.clear();
        for (int k : index) cells.push_back(CsvCell::significant(row.at(k), digits));
        csv.writeRow(cells);
    }
}

}  // namespace rockroll::app
