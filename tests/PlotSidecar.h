#pragma once

#include "tests/TextFile.h"
// Reads back a plot's sidecar NAME.png.json (python/rockroll_plots/figures.py save):
// each line it lists must come from the CSV columns it names, rows and values alike.
// Used by the validate tests and the `rockroll plot` tests.
#include "tests/CsvReader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace rockroll::test {

/// Checks DIR/PNG.json against the CSV files it names (relative to csvDir, default
/// DIR): every line's x and y columns exist, the rows it selects (`where` matches,
/// x and y not empty) are as many as it drew, and its sampled drawn values are those
/// columns times the stated scale. Returns the errors.
inline std::vector<std::string> checkPlotSidecar(const std::filesystem::path& dir, const std::string& png,
                                                 const std::filesystem::path& csvDir = {}) {
    std::vector<std::string> errors;
    const std::filesystem::path data = csvDir.empty() ? dir : csvDir;
    if (!std::filesystem::exists(dir / (png + ".json")))
        return {png + ": no sidecar " + png + ".json (python/rockroll_plots/figures.py writes one)"};
    nlohmann::json side;
    try {
        side = nlohmann::json::parse(readTextFile(dir / (png + ".json")));
    } catch (const std::exception& e) {
        return {png + ".json: " + e.what()};
    }
    if (!side["lines"].is_array() || side["lines"].empty()) return {png + ".json: no lines"};
    std::map<std::string, CsvTable> tables;
    for (const auto& l : side["lines"]) {
        const std::string csv = l.at("csv").get<std::string>(), x = l.at("x").get<std::string>(),
                          y = l.at("y").get<std::string>();
        const std::string what = png + ": " + y + " against " + x + " from " + csv;
        if (!tables.count(csv)) try {
                tables[csv] = parseCsvTable(readTextFile(data / csv));
            } catch (const std::exception& e) {
                errors.push_back(what + ": " + e.what());
                continue;
            }
        const CsvTable& t = tables[csv];
        const int xi = t.find(x), yi = t.find(y);
        if (xi < 0 || yi < 0) {
            errors.push_back(what + ": no such column");
            continue;
        }
        std::vector<const std::vector<std::string>*> rows;
        for (const auto& r : t.rows) {
            bool match = !r[xi].empty() && !r[yi].empty();
            for (const auto& [col, value] : l.at("where").items()) {
                const int c = t.find(col);
                match = match && c >= 0 && r[c] == value.get<std::string>();
            }
            if (match) rows.push_back(&r);
        }
        if (rows.size() != l.at("points").get<size_t>()) {
            errors.push_back(what + ": drew " + l.at("points").dump() + " points, the CSV has " + std::to_string(rows.size()));
            continue;
        }
        if (!rows.empty() && l.at("samples").empty()) errors.push_back(what + ": no samples");
        const double xs = l.at("x_scale").get<double>(), ys = l.at("y_scale").get<double>();
        for (const auto& smp : l.at("samples")) {
            const size_t i = smp.at("index").get<size_t>();
            if (i >= rows.size()) {
                errors.push_back(what + ": sample index out of range");
                continue;
            }
            const auto xv = parseNumber((*rows[i])[xi]), yv = parseNumber((*rows[i])[yi]);
            const double dx = smp.at("x").get<double>(), dy = smp.at("y").get<double>();
            auto near = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); };
            if (!xv || !yv || !near(dx, *xv * xs) || !near(dy, *yv * ys))
                errors.push_back(what + ": point " + std::to_string(i) + " drawn at (" + std::to_string(dx) + ", " +
                                 std::to_string(dy) + "), the CSV has (" + (*rows[i])[xi] + ", " + (*rows[i])[yi] + ")");
        }
    }
    return errors;
}

}  // namespace rockroll::test
