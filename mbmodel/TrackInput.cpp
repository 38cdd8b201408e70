#include "mbmodel/TrackInput.h"

#include "mbmodel/Units.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <map>
#include <sstream>
#include <stdexcept>

namespace rockroll {

namespace {
bool isLevel(const MeasuredTrackSample& m) { return m.crossLevel == 0 && m.profile == 0; }

/// Linear between level at `from` and `m` at `to` (either order), at s.
RailPoint calcTaper(const MeasuredTrackSample& m, double from, double to, double s) {
    const double f = (s - from) / (to - from), df = 1 / (to - from);
    RailPoint p;
    p.z = {f * (m.profile - m.crossLevel / 2), f * (m.profile + m.crossLevel / 2)};
    p.slope = {df * (m.profile - m.crossLevel / 2), df * (m.profile + m.crossLevel / 2)};
    return p;
}
}  // namespace

TrackInput::TrackInput(TrackSpec spec) : spec_(std::move(spec)) {
    if (!(spec_.railLength > 0)) throw std::invalid_argument("track rail length must be positive");
    if (spec_.rails < 0) throw std::invalid_argument("track rails must be 0 (unlimited) or positive");
    for (size_t i = 1; i < spec_.measured.size(); ++i)
        if (!(spec_.measured[i].distance > spec_.measured[i - 1].distance))
            throw std::invalid_argument("measured track distances must increase strictly");
    if (!spec_.measured.empty()) {
        if (spec_.measured.size() < 2) throw std::invalid_argument("a measured track needs at least two rows");
        if (!(spec_.taper > 0 && std::isfinite(spec_.taper)))
            throw std::invalid_argument("measured track taper must be a finite positive length");
        const MeasuredTrackSample &first = spec_.measured.front(), &last = spec_.measured.back();
        if (spec_.repeat && (first.crossLevel != last.crossLevel || first.profile != last.profile))
            throw std::invalid_argument("a repeated measured track needs its last row equal to its first "
                                        "(the rails would step where the table starts again)");
    }
}

std::vector<MeasuredTrackSample> readTrackCsv(std::string_view text, const std::string& source, double taper) {
    enum Column { Distance, Left, Right, Alignment };
    static const std::map<std::string, Column> kNames{
        {"distance", Distance}, {"left", Left}, {"right", Right}, {"alignment", Alignment}};
    static const std::map<std::string, double> kLengthUnits{
        {"in", units::inch}, {"ft", units::foot}, {"mm", 1e-3}, {"m", 1.0}};
    auto trim = [](std::string s) {
        const auto b = s.find_first_not_of(" \t\r");
        if (b == std::string::npos) return std::string();
        return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
    };
    auto split = [&](const std::string& line) {
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream in(line);
        while (std::getline(in, cell, ',')) cells.push_back(trim(cell));
        if (!line.empty() && line.back() == ',') cells.emplace_back();
        return cells;
    };
    auto fail = [&](int line, const std::string& what) -> std::invalid_argument {
        return std::invalid_argument(fmt::format("{}:{}: {}", source, line, what));
    };
    const std::string unitList = "in, ft, mm, m";

    std::vector<Column> columns;  // by position
    std::vector<double> factor;   // to m, by position
    std::vector<std::string> headers;
    std::vector<MeasuredTrackSample> rows;
    std::vector<int> rowLines;
    if (text.size() > kMaxTrackFileBytes)
        throw std::invalid_argument(fmt::format("{}: {} bytes; expected at most {} bytes ({} MiB) of track CSV",
                                                source, text.size(), kMaxTrackFileBytes, kMaxTrackFileBytes >> 20));
    // A spreadsheet's UTF-8 byte-order mark is not part of the header (CRLF ends are trimmed
    // with the cells; test MeasuredTrack.SpreadsheetCsvWithByteOrderMarkAndCrlfRuns).
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    std::istringstream in{std::string(text)};
    int lineNo = 0;
    for (std::string raw; std::getline(in, raw);) {
        ++lineNo;
        const std::string line = trim(raw);
        if (line.empty() || line.front() == '#') continue;
        const std::vector<std::string> cells = split(line);
        if (columns.empty()) {  // the header
            for (size_t c = 0; c < cells.size(); ++c) {
                const std::string& h = cells[c];
                const auto open = h.find('['), close = h.rfind(']');
                const std::string name = trim(h.substr(0, open));
                const auto known = kNames.find(name);
                if (known == kNames.end())
                    throw fail(lineNo, fmt::format("column {} \"{}\": expected one of distance, left, right, alignment, "
                                                   "each with its unit in brackets, e.g. \"distance [ft]\"",
                                                   c + 1, h));
                if (std::find(columns.begin(), columns.end(), known->second) != columns.end())
                    throw fail(lineNo, fmt::format("column {} \"{}\": the column '{}' is given twice", c + 1, h, name));
                if (open == std::string::npos || close == std::string::npos || close < open ||
                    !trim(h.substr(close + 1)).empty())
                    throw fail(lineNo, fmt::format("column {} \"{}\": the unit is missing; expected \"{} [unit]\" "
                                                   "with a length unit: {}",
                                                   c + 1, h, name, unitList));
                const std::string unit = trim(h.substr(open + 1, close - open - 1));
                const auto u = kLengthUnits.find(unit);
                if (u == kLengthUnits.end())
                    throw fail(lineNo, fmt::format("column {} \"{}\": unit \"{}\" is not a length unit of a track "
                                                   "file; expected one of: {}",
                                                   c + 1, h, unit, unitList));
                columns.push_back(known->second);
                factor.push_back(u->second);
                headers.push_back(h);
            }
            for (Column required : {Distance, Left, Right})
                if (std::find(columns.begin(), columns.end(), required) == columns.end()) {
                    const char* name = required == Distance ? "distance" : required == Left ? "left" : "right";
                    throw fail(lineNo, fmt::format("the column '{}' is missing; expected a header naming distance, "
                                                   "left and right (alignment optional), each with its length unit "
                                                   "in brackets, e.g. \"distance [ft], left [in], right [in]\"",
                                                   name));
                }
            continue;
        }
        if (cells.size() != columns.size())
            throw fail(lineNo, fmt::format("{} cells; expected {}, one per column of the header ({})", cells.size(),
                                           columns.size(), fmt::join(headers, ", ")));
        double value[4] = {0, 0, 0, 0};
        for (size_t c = 0; c < cells.size(); ++c) {
            const std::string& cell = cells[c];
            double v = 0;
            const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
            if (cell.empty() || ec != std::errc() || end != cell.data() + cell.size() || !std::isfinite(v))
                throw fail(lineNo, fmt::format("column {} ({}) = \"{}\": expected a finite number", c + 1,
                                               headers[c], cell));
            value[columns[c]] = v * factor[c];
        }
        if (value[Alignment] != 0) {
            const size_t c = size_t(std::find(columns.begin(), columns.end(), Alignment) - columns.begin());
            throw fail(lineNo, fmt::format("column {} ({}) = \"{}\": the models take vertical rail input only "
                                           "(lateral alignment is not modelled); expected 0",
                                           c + 1, headers[c], cells[c]));
        }
        if (!rows.empty() && !(value[Distance] > rows.back().distance)) {
            const size_t c = size_t(std::find(columns.begin(), columns.end(), Distance) - columns.begin());
            throw fail(lineNo, fmt::format("column {} ({}) = \"{}\": distances must increase strictly; expected "
                                           "more than the row before (line {})",
                                           c + 1, headers[c], cells[c], rowLines.back()));
        }
        if (rows.size() == kMaxTrackRows)
            throw fail(lineNo, fmt::format("more than {} data rows; expected at most {} (docs/cli.md, \"Input size "
                                           "limits\")",
                                           kMaxTrackRows, kMaxTrackRows));
        MeasuredTrackSample m;
        m.distance = value[Distance];
        m.crossLevel = value[Right] - value[Left];
        m.profile = (value[Left] + value[Right]) / 2;
        rows.push_back(m);
        rowLines.push_back(lineNo);
    }
    if (columns.empty()) throw fail(lineNo, "no header; expected e.g. \"distance [ft], left [in], right [in]\"");
    if (rows.size() < 2)
        throw fail(lineNo, fmt::format("{} data row(s); expected at least two, to interpolate between", rows.size()));
    // The table starts where the car's leading axle is at t = 0 (s = 0), after its taper when not level.
    const double start = rows.front().distance - (isLevel(rows.front()) ? 0.0 : taper);
    for (auto& r : rows) r.distance -= start;
    return rows;
}

RailPoint TrackInput::calcRails(double s) const {
    RailPoint p = spec_.measured.empty() ? calcRectifiedSine(s) : calcMeasured(s);
    if (spec_.mirror) {
        std::swap(p.z[0], p.z[1]);
        std::swap(p.slope[0], p.slope[1]);
    }
    return p;
}

double TrackInput::calcLeadInDistance() const {
    const auto& m = spec_.measured;
    if (m.empty() || !isLevel(m.front())) return 0.0;
    size_t i = 0;
    while (i + 1 < m.size() && isLevel(m[i + 1])) ++i;
    return i + 1 == m.size() ? 0.0 : m[i].distance;  // a level table has no lead-in to leave out
}

RailPoint TrackInput::calcRectifiedSine(double s) const {
    RailPoint p;
    const double L = spec_.railLength, A = spec_.amplitude;
    // The level lead-in includes s = 0 itself, so the car stands in static
    // equilibrium at t = 0 and the rails start to move just after.
    if (s <= 0 || (spec_.rails > 0 && s > spec_.rails * L) || A == 0) return p;
    const double k = M_PI / L;
    const double u = k * (s + L / 4);
    const double base = A / std::sqrt(2.0);
    const double phase[2] = {u + M_PI / 2, u};  // left, right
    for (int i = 0; i < 2; ++i) {
        const double sn = std::sin(phase[i]);
        p.z[i] = A * std::abs(sn) - base;
        p.slope[i] = A * k * std::cos(phase[i]) * (sn >= 0 ? 1 : -1);
    }
    return p;
}


RailPoint TrackInput::calcMeasured(double s) const {
    RailPoint p;
    const auto& m = spec_.measured;
    const double first = m.front().distance, last = m.back().distance, taper = spec_.taper;
    if (s < first) {
        if (isLevel(m.front()) || s <= first - taper) return p;
        return calcTaper(m.front(), first - taper, first, s);
    }
    if (s > last) {
        if (spec_.repeat) {
            s = first + std::fmod(s - first, last - first);
        } else {
            if (isLevel(m.back()) || s >= last + taper) return p;
            return calcTaper(m.back(), last + taper, last, s);
        }
    }
    const auto hi = std::upper_bound(m.begin(), m.end(), s,
                                     [](double x, const MeasuredTrackSample& a) { return x < a.distance; });
    const auto& b = hi == m.end() ? m.back() : *hi;
    const auto& a = hi == m.end() ? *(hi - 2) : *(hi - 1);
    const double f = (s - a.distance) / (b.distance - a.distance);
    const double c = a.crossLevel + f * (b.crossLevel - a.crossLevel);
    const double pr = a.profile + f * (b.profile - a.profile);
    const double dc = (b.crossLevel - a.crossLevel) / (b.distance - a.distance);
    const double dp = (b.profile - a.profile) / (b.distance - a.distance);
    p.z = {pr - c / 2, pr + c / 2};
    p.slope = {dp - dc / 2, dp + dc / 2};
    return p;
}

}  // namespace rockroll
