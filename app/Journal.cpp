#include "app/Journal.h"
#include "app/Provenance.h"
#include "app/SummaryJson.h"
#include "scenarios/ScenarioLoader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace rockroll::app {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

std::string formatHexDouble(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x < 0 ? "-inf" : "inf";
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, std::fabs(x), std::chars_format::hex);
    return std::string(std::signbit(x) ? "-0x" : "0x") + std::string(buffer, r.ptr);
}

double parseHexDouble(std::string_view text) {
    const std::string original(text);
    if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (text == "inf") return std::numeric_limits<double>::infinity();
    if (text == "-inf") return -std::numeric_limits<double>::infinity();
    const bool negative = !text.empty() && text.front() == '-';
    if (negative) text.remove_prefix(1);
    if (text.size() < 3 || text.substr(0, 2) != "0x" || text[2] == '-' || text[2] == '+')
        throw std::invalid_argument(fmt::format("\"{}\" is not a hex float (expected e.g. 0x1.8p+1)", original));
    text.remove_prefix(2);
    double x = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), x, std::chars_format::hex);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size())
        throw std::invalid_argument(fmt::format("\"{}\" is not a hex float (expected e.g. 0x1.8p+1)", original));
    return negative ? -x : x;
}

Json toHexJson(const std::vector<double>& v) {
    Json a = Json::array();
    for (double x : v) a.push_back(formatHexDouble(x));
    return a;
}

std::vector<double> fromHexJson(const Json& a) {
    if (!a.is_array()) throw std::invalid_argument("expected an array of hex floats");
    std::vector<double> v;
    v.reserve(a.size());
    for (const auto& x : a) {
        if (!x.is_string()) throw std::invalid_argument("expected an array of hex floats (strings)");
        v.push_back(parseHexDouble(x.get_ref<const std::string&>()));
    }
    return v;
}

Json toJson(const RestartState& s) {
    return Json{{"model", s.model},
                {"y", toHexJson(s.y)},
                {"distance_m", formatHexDouble(s.distance)},
                {"speed_m_per_s", formatHexDouble(s.speed)}};
}

RestartState restartStateFromJson(const Json& j) {
    RestartState s;
    s.model = j.at("model").get<std::string>();
    s.y = fromHexJson(j.at("y"));
    s.distance = parseHexDouble(j.at("distance_m").get<std::string>());
    s.speed = parseHexDouble(j.at("speed_m_per_s").get<std::string>());
    return s;
}

namespace {
double numberOrNaN(const Json& j, const char* key) {
    const Json& v = j.at(key);
    return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>();
}
}  // namespace

RunSummary summaryFromJson(const Json& j) {
    RunSummary s;
    s.model = j.at("model").get<std::string>();
    s.car = j.at("car").get<std::string>();
    s.speedMph = j.at("speed_mph").get<double>();
    s.amplitudeIn = numberOrNaN(j, "amplitude_in");
    s.durationS = j.at("duration_s").get<double>();
    s.maxRollDeg = j.at("max_roll_deg").get<double>();
    s.steadyRollAmplitudeDeg = j.at("steady_roll_amplitude_deg").get<double>();
    s.peakToPeakRollDeg = j.at("peak_to_peak_roll_deg").get<double>();
    s.maxPitchDeg = numberOrNaN(j, "max_pitch_deg");
    s.maxYawDeg = numberOrNaN(j, "max_yaw_deg");
    s.maxCarBodyTwistDeg = numberOrNaN(j, "max_car_body_twist_deg");
    s.maxWheelLiftIn = j.at("max_wheel_lift_in").get<double>();
    s.maxWheelLoadLb = j.at("max_wheel_load_lb").get<double>();
    s.minWheelLoadRatio = j.at("min_wheel_load_ratio").get<double>();
    // Added fields: a journal written by an earlier release lacks them.
    if (j.contains("max_single_wheel_load_lb")) s.maxSingleWheelLoadLb = numberOrNaN(j, "max_single_wheel_load_lb");
    if (j.contains("wheel_load_basis")) s.wheelLoadBasis = j.at("wheel_load_basis").get<std::string>();
    if (j.contains("worst_energy_balance_error")) s.worstEnergyBalanceError = numberOrNaN(j, "worst_energy_balance_error");
    if (j.contains("criteria_from_s")) s.criteriaFromS = j.at("criteria_from_s").get<double>();
    if (j.contains("steady")) {
        const Json& st = j.at("steady");
        s.steady.windowS = st.at("window_s").get<double>();
        s.steady.cycles = getJsonInteger<int>(st, "cycles");
        s.steady.rollDeg = st.at("max_roll_deg").get<double>();
        s.steady.wheelLiftIn = st.at("max_wheel_lift_in").get<double>();
        s.steady.truckSideWheelLoadLb = st.at("max_truck_side_wheel_load_lb").get<double>();
        s.steady.sideBearingLoadLb = st.at("max_side_bearing_load_lb").get<double>();
        s.steady.centerPlateLoadLb = st.at("max_center_plate_load_lb").get<double>();
    }
    s.maxSideBearingLoadLb = j.at("max_side_bearing_load_lb").get<double>();
    s.maxCenterPlateLoadLb = j.at("max_center_plate_load_lb").get<double>();
    s.rawMaxWheelLoadLb = j.at("raw_max_wheel_load_lb").get<double>();
    s.rawMinWheelLoadRatio = j.at("raw_min_wheel_load_ratio").get<double>();
    s.rawMaxSideBearingLoadLb = j.at("raw_max_side_bearing_load_lb").get<double>();
    s.rawMaxCenterPlateLoadLb = j.at("raw_max_center_plate_load_lb").get<double>();
    s.staticWheelLoadLb = j.at("static_wheel_load_lb").get<double>();
    s.staticCenterPlateLoadLb = j.at("static_center_plate_load_lb").get<double>();
    s.regime = j.at("regime").get<std::string>();
    s.stoppedAtS = j.at("stopped_at_s").is_null() ? -1.0 : j.at("stopped_at_s").get<double>();
    s.stopReason = j.at("stop_reason").is_null() ? std::string() : j.at("stop_reason").get<std::string>();
    s.centerPlateSeparationLongestS = j.at("center_plate_separation_longest_s").get<double>();
    s.centerPlateSeparationTotalS = j.at("center_plate_separation_total_s").get<double>();
    s.wheelLiftLongestS = j.at("wheel_lift_longest_s").get<double>();
    s.energyBalanceError = numberOrNaN(j, "energy_balance_error");
    s.maxWheelUnloading = numberOrNaN(j, "max_wheel_unloading");
    s.rawMaxWheelUnloading = numberOrNaN(j, "raw_max_wheel_unloading");
    s.maxLOverV = numberOrNaN(j, "max_l_over_v");
    s.rawMaxLOverV = numberOrNaN(j, "raw_max_l_over_v");
    s.maxTruckSideLOverV = numberOrNaN(j, "max_truck_side_l_over_v");
    s.rawMaxTruckSideLOverV = numberOrNaN(j, "raw_max_truck_side_l_over_v");
    s.maxCarBodyVerticalAccelG = numberOrNaN(j, "max_car_body_vertical_accel_g");
    s.rawMaxCarBodyVerticalAccelG = numberOrNaN(j, "raw_max_car_body_vertical_accel_g");
    s.maxCarBodyLateralAccelG = numberOrNaN(j, "max_car_body_lateral_accel_g");
    s.rawMaxCarBodyLateralAccelG = numberOrNaN(j, "raw_max_car_body_lateral_accel_g");
    for (const Json& t : j.at("trucks")) {
        TruckLoads loads;
        loads.truck = t.at("truck").get<std::string>();
        loads.maxCenterPlateLoadLb = t.at("max_center_plate_load_lb").get<double>();
        loads.minCenterPlateLoadLb = t.at("min_center_plate_load_lb").get<double>();
        loads.maxSideBearingLoadLb[0] = t.at("max_side_bearing_L_load_lb").get<double>();
        loads.maxSideBearingLoadLb[1] = t.at("max_side_bearing_R_load_lb").get<double>();
        s.trucks.push_back(loads);
    }
    for (const Json& c : j.at("criteria")) {
        Criterion k;
        k.name = c.at("name").get<std::string>();
        k.value = numberOrNaN(c, "value");
        k.limit = c.at("limit").get<double>();
        k.unit = c.at("unit").get<std::string>();
        s.criteria.push_back(k);
    }
    s.filter = j.at("filter").get<std::string>();
    s.simTimeS = j.at("sim_time_s").get<double>();
    s.wallTimeS = j.at("wall_time_s").get<double>();
    s.steps = getJsonInteger<long>(j, "steps");
    return s;
}

Json makeJournalHeader(const std::string& kind, const Json& identity, const std::string& command) {
    return Json{{"journal", kind}, {"version", 1}, {"identity", identity}, {"command", command}};
}

ParsedJournal parseJournal(std::string_view text, const std::string& fileName) {
    ParsedJournal out;
    size_t lineNo = 0;
    while (!text.empty()) {
        ++lineNo;
        const size_t end = text.find('\n');
        const bool last = end == std::string_view::npos || end + 1 == text.size();
        const std::string_view line = text.substr(0, end);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
        Json j = Json::parse(line.begin(), line.end(), nullptr, false);
        const bool whole = !j.is_discarded() && j.is_object() && end != std::string_view::npos;
        if (!whole) {
            // Only the last line can be cut off by a kill; there it is dropped and its point run again.
            if (last && lineNo > 1) {
                out.droppedTornLine = true;
                break;
            }
            throw ScenarioError(fmt::format("{}:{}: not a complete JSON object on one line; expected a rockroll "
                                            "journal (one JSON object a line)",
                                            fileName, lineNo));
        }
        if (lineNo == 1) {
            if (!j.contains("journal") || !j["journal"].is_string() || !j.contains("identity") ||
                !j.contains("version") || j["version"] != 1)
                throw ScenarioError(fmt::format("{}:1: not a rockroll journal header; expected "
                                                "{{\"journal\": KIND, \"version\": 1, \"identity\": ...}}",
                                                fileName));
            out.header = std::move(j);
        } else {
            out.points.push_back(std::move(j));
        }
    }
    if (lineNo == 0) throw ScenarioError(fmt::format("{}: empty; expected a rockroll journal header on line 1", fileName));
    return out;
}

ParsedJournal readJournal(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw ScenarioError(fmt::format("{}: cannot read the journal", file.string()));
    std::ostringstream text;
    text << in.rdbuf();
    return parseJournal(text.str(), file.string());
}

namespace {
/// A short text of a JSON value: strings as themselves (a long one cut to its first line).
std::string describe(const Json& v) {
    if (!v.is_string()) return v.dump();
    std::string s = v.get<std::string>();
    if (const size_t nl = s.find('\n'); nl != std::string::npos) s = s.substr(0, nl) + " ...";
    if (s.size() > 120) s = s.substr(0, 117) + "...";
    return "\"" + s + "\"";
}

}  // namespace

std::optional<std::string> describeJsonDifference(const Json& a, const Json& b, const std::string& path) {
    if (a.is_number() && b.is_number())  // 14 read back from text is unsigned, 14 built in C++ is signed
        return a == b ? std::nullopt
                      : std::optional<std::string>(fmt::format("{} is {} there, {} here", path, describe(a), describe(b)));
    if (a.type() != b.type()) return fmt::format("{} is {} there, {} here", path, describe(a), describe(b));
    if (a.is_object()) {
        for (const auto& [key, value] : b.items()) {
            const std::string sub = path.empty() ? key : path + "." + key;
            if (!a.contains(key)) return fmt::format("{} is missing there, {} here", sub, describe(value));
            if (auto d = describeJsonDifference(a.at(key), value, sub)) return d;
        }
        for (const auto& [key, value] : a.items())
            if (!b.contains(key))
                return fmt::format("{} is {} there, missing here", path.empty() ? key : path + "." + key, describe(value));
        return std::nullopt;
    }
    if (a.is_array()) {
        for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
            if (auto d = describeJsonDifference(a[i], b[i], fmt::format("{}[{}]", path, i))) return d;
        if (a.size() != b.size()) return fmt::format("{} has {} items there, {} here", path, a.size(), b.size());
        return std::nullopt;
    }
    if (a.is_string() && a != b) {
        // Multi-line text (the resolved scenario TOML): name the first line that differs.
        const std::string sa = a.get<std::string>(), sb = b.get<std::string>();
        std::istringstream la(sa), lb(sb);
        std::string x, y;
        for (int line = 1;; ++line) {
            const bool ga = bool(std::getline(la, x)), gb = bool(std::getline(lb, y));
            if (!ga && !gb) break;
            if (!ga || !gb || x != y)
                return sa.find('\n') == std::string::npos
                           ? fmt::format("{} is {} there, {} here", path, describe(a), describe(b))
                           : fmt::format("{} line {} is \"{}\" there, \"{}\" here", path, line, ga ? x : "",
                                         gb ? y : "");
        }
    }
    if (a != b) return fmt::format("{} is {} there, {} here", path, describe(a), describe(b));
    return std::nullopt;
}

void checkJournalIdentity(const ParsedJournal& journal, const Json& expected, const std::string& fileName) {
    if (auto d = describeJsonDifference(journal.header.at("identity"), expected, ""))
        throw ScenarioError(fmt::format("--resume: {} is the journal of another {}: {}; expected the same scenario, "
                                        "model, speeds, options and --set as the interrupted run (and the same "
                                        "rockroll build), or --force to start over",
                                        fileName, journal.header.at("journal").get<std::string>(), *d));
}

namespace {
void writeWhole(int fd, const std::string& text, const fs::path& file) {
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw std::runtime_error(fmt::format("cannot write {}: {}", file.string(), std::strerror(errno)));
        done += size_t(n);
    }
    if (::fsync(fd) != 0) throw std::runtime_error(fmt::format("cannot fsync {}: {}", file.string(), std::strerror(errno)));
}

void syncDirectory(const fs::path& dir) {
    const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}
}  // namespace

JournalWriter::JournalWriter(const fs::path& file, const Json& header, const std::vector<Json>& points) : file_(file) {
    std::string text = header.dump() + "\n";
    for (const Json& p : points) text += p.dump() + "\n";
    const fs::path tmp = file.string() + ".tmp";
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error(fmt::format("cannot write {}: {}", tmp.string(), std::strerror(errno)));
    try {
        writeWhole(fd, text, tmp);
    } catch (...) {
        ::close(fd);
        throw;
    }
    ::close(fd);
    fs::rename(tmp, file);
    syncDirectory(file.parent_path());
    fd_ = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd_ < 0) throw std::runtime_error(fmt::format("cannot append to {}: {}", file.string(), std::strerror(errno)));
}

JournalWriter::~JournalWriter() {
    if (fd_ >= 0) ::close(fd_);
}

void JournalWriter::append(const Json& point) {
    const std::string line = point.dump() + "\n";
    std::lock_guard lock(mutex_);
    writeWhole(fd_, line, file_);
}

// ---- speed sweeps ------------------------------------------------------------------

Json makeSweepIdentity(const std::vector<SweepSpec>& specs) {
    Json sweeps = Json::array();
    for (const SweepSpec& spec : specs) {
        Json p = makeProvenance(spec.scenario, "");
        p.erase("command");  // how it was started (--jobs, --resume) does not change the results
        p["sweep"] = {{"from_mph", spec.fromMph},
                      {"to_mph", spec.toMph},
                      {"step_mph", spec.stepMph},
                      {"direction", spec.direction == SweepDirection::Up ? "up" : "down"},
                      {"fresh", spec.fresh},
                      {"ramp_time_s", spec.rampTime}};
        sweeps.push_back(std::move(p));
    }
    return Json{{"sweeps", sweeps}};
}

namespace {
Json runStartToJson(const RunStart& start) {
    return Json{{"from", start.from ? toJson(*start.from) : Json(nullptr)},
                {"ramp_time_s", formatHexDouble(start.rampTime)},
                {"static_reference", toHexJson(start.staticReference)}};
}
RunStart runStartFromJson(const Json& j) {
    RunStart start;
    if (!j.at("from").is_null()) start.from = restartStateFromJson(j.at("from"));
    start.rampTime = parseHexDouble(j.at("ramp_time_s").get<std::string>());
    start.staticReference = fromHexJson(j.at("static_reference"));
    return start;
}
}  // namespace

Json toJournalJson(const SweepPoint& p, size_t sweep, size_t index) {
    Json j{{"sweep", sweep},
           {"direction", p.direction},
           {"index", index},
           {"speed_mph", p.speedMph},
           {"speed_mph_hex", formatHexDouble(p.speedMph)},
           {"start", p.start},
           {"failed", p.failed}};
    if (p.failed) j["error"] = p.error;
    else j["summary"] = toJson(p.summary);
    j["next"] = runStartToJson(p.next);
    return j;
}

SweepPoint sweepPointFromJournal(const Json& j) {
    SweepPoint p;
    p.speedMph = parseHexDouble(j.at("speed_mph_hex").get<std::string>());
    p.direction = j.at("direction").get<std::string>();
    p.start = j.at("start").get<std::string>();
    p.failed = j.at("failed").get<bool>();
    if (p.failed) p.error = j.at("error").get<std::string>();
    else p.summary = summaryFromJson(j.at("summary"));
    p.next = runStartFromJson(j.at("next"));
    return p;
}

std::vector<std::vector<SweepPoint>> collectSweepPoints(const ParsedJournal& journal, const std::vector<SweepSpec>& specs,
                                                        const std::string& fileName) {
    std::vector<std::vector<SweepPoint>> done(specs.size());
    std::vector<std::vector<double>> speeds;
    for (const SweepSpec& spec : specs) speeds.push_back(getSweepSpeeds(spec));
    for (size_t n = 0; n < journal.points.size(); ++n) {
        const Json& j = journal.points[n];
        const size_t line = n + 2;
        try {
            const size_t sweep = getJsonInteger<size_t>(j, "sweep"), index = getJsonInteger<size_t>(j, "index");
            if (sweep >= specs.size())
                throw std::invalid_argument(fmt::format("sweep {} of a batch of {}", sweep, specs.size()));
            SweepPoint p = sweepPointFromJournal(j);
            const std::string direction = specs[sweep].direction == SweepDirection::Up ? "up" : "down";
            if (index != done[sweep].size())
                throw std::invalid_argument(fmt::format("point {} of sweep {}, expected point {} next",
                                                        index, sweep, done[sweep].size()));
            if (index >= speeds[sweep].size() || p.direction != direction || p.speedMph != speeds[sweep][index])
                throw std::invalid_argument(fmt::format("{} mph {} is not point {} of sweep {} ({} mph {})", p.speedMph,
                                                        p.direction, index, sweep,
                                                        index < speeds[sweep].size() ? speeds[sweep][index] : -1.0,
                                                        direction));
            done[sweep].push_back(std::move(p));
        } catch (const ScenarioError&) {
            throw;
        } catch (const std::exception& e) {
            throw ScenarioError(fmt::format("{}:{}: not a point of this sweep: {}", fileName, line, e.what()));
        }
    }
    return done;
}

}  // namespace rockroll::app
