// The engineer's workflow on the command line (issues 12 item 4 and 13 items 1-2):
// --set KEY=VALUE on every command, --out DIR on run, sweep, steady and modes (every
// file read back here), --force, and SIGINT/SIGTERM leaving nothing half-written.
#include "tests/CliRunner.h"
#include "tests/CsvReader.h"
#include "tests/TestTmp.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
extern char** environ;

namespace {

const std::string kScenario = std::string(ROCKROLL_SCENARIO_DIR) + "/70ton-loaded.toml";

using rockroll::test::CliOutcome;
using rockroll::test::getExitCode;
using rockroll::test::readTextFile;
using rockroll::test::runRockroll;

/// Every number of a CSV table equals the same key of the JSON records, bit for bit
/// (the CSV writes the shortest text that reads back to the double); text cells equal text.
void expectCsvMatchesJson(const rockroll::test::CsvTable& table, const nlohmann::json& records) {
    ASSERT_EQ(table.rows.size(), records.size());
    for (size_t r = 0; r < table.rows.size(); ++r)
        for (size_t c = 0; c < table.columns.size(); ++c) {
            const std::string& key = table.columns[c];
            const std::string& cell = table.rows[r][c];
            SCOPED_TRACE("row " + std::to_string(r + 1) + " column " + key);
            const auto& j = records[r];
            if (!j.contains(key) || j[key].is_null()) {
                EXPECT_EQ(cell, "");
            } else if (j[key].is_number()) {
                EXPECT_EQ(std::stod(cell), j[key].get<double>());
            } else if (j[key].is_boolean()) {
                EXPECT_EQ(cell, j[key].get<bool>() ? "true" : "false");
            } else {
                EXPECT_EQ(cell, j[key].get<std::string>());
            }
        }
}

}  // namespace

TEST(CliWorkflow, SetChangesTheRunAndAppearsInItsProvenance) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    const std::string base = "run '" + kScenario + "' --model halfcar --duration-s 1 --json";
    const CliOutcome plain = runRockroll(dir, base + " --out plain");
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    const CliOutcome set = runRockroll(dir, base + " --out set --set car.side_bearing_clearance=\"0.25 in\" "
                                            "--set run.speed=\"14 mph\"");
    ASSERT_EQ(set.exitCode, 0) << set.err;
    const auto a = nlohmann::json::parse(plain.out), b = nlohmann::json::parse(set.out);
    EXPECT_DOUBLE_EQ(a.at("speed_mph").get<double>(), 16.5);
    EXPECT_NEAR(b.at("speed_mph").get<double>(), 14, 1e-12);
    EXPECT_NE(a.at("max_roll_deg"), b.at("max_roll_deg"));
    const auto& prov = b.at("provenance");
    ASSERT_EQ(prov.at("overrides").size(), 2u);
    EXPECT_EQ(prov.at("overrides")[0].at("key"), "car.side_bearing_clearance");
    EXPECT_EQ(prov.at("overrides")[0].at("value"), "0.25 in");
    EXPECT_EQ(prov.at("overrides")[1].at("key"), "run.speed");
    EXPECT_EQ(prov.at("overrides")[1].at("value"), "14 mph");
    EXPECT_NEAR(prov.at("car_parameters").at("side_bearing_clearance").at("value").get<double>(), 0.25, 1e-12);
    EXPECT_TRUE(a.at("provenance").at("overrides").empty());
    // The summary.json written is what --json printed.
    EXPECT_EQ(nlohmann::json::parse(readTextFile(dir / "set" / "summary.json")), b);
    // Rerunning from that summary reproduces the run, overrides and all.
    const CliOutcome again = runRockroll(dir, "run --from-summary set/summary.json --out again --json");
    ASSERT_EQ(again.exitCode, 0) << again.err;
    const auto c = nlohmann::json::parse(again.out);
    EXPECT_EQ(c.at("max_roll_deg"), b.at("max_roll_deg"));
    EXPECT_EQ(c.at("provenance").at("overrides"), prov.at("overrides"));
    // The text summary lists them too.
    const CliOutcome text = runRockroll(dir, "run '" + kScenario + "' --model halfcar --duration-s 0.2 --out text "
                                       "--set run.speed=\"14 mph\"");
    ASSERT_EQ(text.exitCode, 0) << text.err;
    EXPECT_NE(text.out.find("--set run.speed = 14 mph"), std::string::npos) << text.out;
}

TEST(CliWorkflow, SetErrorsNameFlagKeyValueAndExpectedForm) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    struct Case {
        std::string args;
        std::vector<std::string> expect;
    };
    const std::string run = "run '" + kScenario + "' --model halfcar --duration-s 0.2 ";
    const Case cases[] = {
        {run + "--set car.side_bearing_clearance=\"0.25 furlong\"",
         {"--set \"car.side_bearing_clearance=0.25 furlong\"", "key 'car.side_bearing_clearance'", "expected a length"}},
        {run + "--set car.side_bearing_clerance=\"0.25 in\"",
         {"--set \"car.side_bearing_clerance=0.25 in\"", "no such scenario key", "car.side_bearing_clearance"}},
        {run + "--set run.speed", {"--set \"run.speed\"", "expected KEY=VALUE"}},
        {run + "--set run.speed=\"-3 mph\"", {"--set \"run.speed=-3 mph\"", "key 'run.speed'", "expected"}},
        {run + "--speed-mph 12 --set run.speed=\"14 mph\"", {"--speed-mph and --set \"run.speed=14 mph\""}},
        {"sweep '" + kScenario + "' --from-mph 14 --to-mph 15 --step-mph 1 --set track.amplitude=big",
         {"--set \"track.amplitude=big\"", "key 'track.amplitude'"}},
        {"modes '" + kScenario + "' --set car.gib_rate=\"3 N\"", {"--set \"car.gib_rate=3 N\"", "stiffness"}},
        {"steady '" + kScenario + "' --set integrator.accuracy=abc", {"--set \"integrator.accuracy=abc\""}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.args);
        const CliOutcome o = runRockroll(dir, c.args);
        EXPECT_EQ(o.exitCode, 2) << o.err;
        for (const auto& e : c.expect) EXPECT_NE(o.err.find(e), std::string::npos) << e << "\n" << o.err;
        EXPECT_TRUE(o.out.empty()) << o.out;
    }
}

TEST(CliWorkflow, OutOfEveryCommandReadsBack) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    {
        const CliOutcome o = runRockroll(dir, "run '" + kScenario + "' --model halfcar --duration-s 0.5 --out run");
        ASSERT_EQ(o.exitCode, 0) << o.err;
        const auto table = rockroll::test::parseCsvTable(readTextFile(dir / "run" / "history.csv"));
        EXPECT_GE(table.rows.size(), 200u);  // 0.5 s at 500 Hz
        const auto t = table.numbers(table.columns.at(0));
        EXPECT_NEAR(t.back(), 0.5, 1e-9);
        const auto summary = nlohmann::json::parse(readTextFile(dir / "run" / "summary.json"));
        EXPECT_EQ(summary.at("duration_s"), 0.5);
    }
    {
        const CliOutcome o = runRockroll(dir, "sweep '" + kScenario + "' --model reduced --from-mph 14 --to-mph 15 "
                                        "--step-mph 1 --duration-s 1 --direction up --out sweep --speed-ramp-s 0 "
                                        "--set car.side_bearing_clearance=\"0.25 in\"");
        ASSERT_EQ(o.exitCode, 0) << o.err;
        const auto doc = nlohmann::json::parse(readTextFile(dir / "sweep" / "sweep.json"));
        const auto& json = doc.at("points");
        ASSERT_EQ(json.size(), 2u);
        // --speed-ramp-s 0: the speed steps at once, and the provenance says so.
        EXPECT_EQ(json[1].at("provenance").at("sweep").at("ramp_time_s"), 0.0);
        EXPECT_EQ(json[1].at("criteria_from_s"), 0.0);
        ASSERT_EQ(doc.at("jumps").size(), 1u);  // one sweep: up
        EXPECT_EQ(doc.at("jumps")[0].at("direction"), "up");
        EXPECT_EQ(json[0].at("provenance").at("overrides")[0].at("key"), "car.side_bearing_clearance");
        const auto table = rockroll::test::parseCsvTable(readTextFile(dir / "sweep" / "sweep.csv"));
        EXPECT_EQ(table.find("provenance"), -1);
        ASSERT_NE(table.find("speed_mph"), -1);
        EXPECT_EQ(table.numbers("speed_mph"), (std::vector<double>{14, 15}));
        // The per-truck loads, the criteria and the steady-part maxima are columns named by
        // truck, criterion or "steady_" and unit.
        nlohmann::json flat = nlohmann::json::array();
        for (const auto& p : json) {
            nlohmann::json r = p;
            r.erase("trucks");
            r.erase("criteria");
            r.erase("steady");
            for (const auto& [field, v] : p.at("steady").items()) r["steady_" + field] = v;
            for (const auto& t : p.at("trucks"))
                for (const auto& [field, v] : t.items())
                    if (field != "truck") r["truck_" + t.at("truck").get<std::string>() + "_" + field] = v;
            for (const auto& c : p.at("criteria")) {
                const std::string name = c.at("name"), unit = c.at("unit");
                r["criterion_" + name + "_" + unit] = c.at("value");
                r["criterion_" + name + "_limit_" + unit] = c.at("limit");
                r["criterion_" + name + "_pass"] = c.at("pass");
            }
            flat.push_back(r);
        }
        ASSERT_NE(table.find("truck_F_max_center_plate_load_lb"), -1);
        ASSERT_NE(table.find("criterion_roll_peak_to_peak_deg"), -1);
        ASSERT_NE(table.find("criterion_wheel_unloading_pass"), -1);
        EXPECT_EQ(table.find("trucks"), -1);
        ASSERT_NE(table.find("steady_max_side_bearing_load_lb"), -1);
        EXPECT_EQ(table.find("steady"), -1);
        expectCsvMatchesJson(table, flat);
    }
    {
        const CliOutcome o = runRockroll(dir, "steady '" + kScenario + "' --from-mph 12 --to-mph 14 --stability none "
                                        "--out steady");
        ASSERT_EQ(o.exitCode, 0) << o.err;
        const auto json = nlohmann::json::parse(readTextFile(dir / "steady" / "steady.json"));
        nlohmann::json records = nlohmann::json::array();
        for (size_t b = 0; b < json.at("branches").size(); ++b)
            for (const auto& point : json.at("branches")[b].at("points")) {
                // The force harmonics and the twin's maxima are objects in the JSON and
                // columns named <key>_<field> in the CSV.
                nlohmann::json p = nlohmann::json::object();
                for (const auto& [key, value] : point.items()) {
                    if (value.is_object())
                        for (const auto& [field, v] : value.items()) p[key + "_" + field] = v;
                    else
                        p[key] = value;
                }
                p["branch"] = b;
                p["path"] = json.at("branches")[b].at("path");
                p["stability"] = json.at("branches")[b].at("stability");
                records.push_back(p);
            }
        ASSERT_GT(records.size(), 3u);
        expectCsvMatchesJson(rockroll::test::parseCsvTable(readTextFile(dir / "steady" / "steady.csv")), records);
    }
    {
        const CliOutcome o = runRockroll(dir, "modes '" + kScenario + "' --model halfcar --out modes");
        ASSERT_EQ(o.exitCode, 0) << o.err;
        const auto json = nlohmann::json::parse(readTextFile(dir / "modes" / "modes.json"));
        ASSERT_FALSE(json.at("modes").empty());
        const auto table = rockroll::test::parseCsvTable(readTextFile(dir / "modes" / "modes.csv"));
        expectCsvMatchesJson(table, json.at("modes"));
        EXPECT_GT(table.numbers("frequency_hz").front(), 0);
    }
    for (const char* d : {"run", "sweep", "steady", "modes"}) {
        EXPECT_FALSE(fs::exists(dir / (std::string(d) + ".partial"))) << d;
        for (const auto& e : fs::directory_iterator(dir / d)) EXPECT_NE(e.path().extension(), ".tmp") << e.path();
    }
}

TEST(CliWorkflow, ExistingNonEmptyDirectoryNeedsForce) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    const std::string run = "run '" + kScenario + "' --model halfcar --duration-s 0.2 --out res";
    ASSERT_EQ(runRockroll(dir, run).exitCode, 0);
    std::ofstream(dir / "res" / "notes.txt") << "mine\n";
    const std::string before = readTextFile(dir / "res" / "summary.json");
    const CliOutcome refused = runRockroll(dir, run + " --speed-mph 14");
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_NE(refused.err.find("--out res: the directory exists and is not empty"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("--force"), std::string::npos) << refused.err;
    EXPECT_EQ(readTextFile(dir / "res" / "summary.json"), before);
    EXPECT_TRUE(fs::exists(dir / "res" / "notes.txt"));
    // The same for the other commands, before they compute anything.
    const CliOutcome modes = runRockroll(dir, "modes '" + kScenario + "' --out res");
    EXPECT_EQ(modes.exitCode, 2) << modes.err;
    // --force replaces the directory as a whole.
    const CliOutcome forced = runRockroll(dir, run + " --speed-mph 14 --force");
    ASSERT_EQ(forced.exitCode, 0) << forced.err;
    EXPECT_NE(readTextFile(dir / "res" / "summary.json"), before);
    EXPECT_FALSE(fs::exists(dir / "res" / "notes.txt"));
    EXPECT_FALSE(fs::exists(dir / "res.partial"));
    EXPECT_FALSE(fs::exists(dir / "res.replaced"));
    // An empty directory is fine without --force.
    fs::create_directory(dir / "empty");
    EXPECT_EQ(runRockroll(dir, "run '" + kScenario + "' --model halfcar --duration-s 0.2 --out empty").exitCode, 0);
    EXPECT_TRUE(fs::exists(dir / "empty" / "summary.json"));
}

// An output that cannot be written is bad input, exit 2 (docs/cli.md, "Exit codes"), for every
// command with --out, before anything is computed; the message names the flag and the path.
TEST(CliWorkflow, AnOutputThatCannotBeWrittenExits2) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    std::ofstream(dir / "afile") << "a file, not a directory\n";
    for (const std::string& args :
         {"run '" + kScenario + "' --model halfcar --duration-s 0.2 --out afile/res",
          "sweep '" + kScenario + "' --model reduced --from-mph 14 --to-mph 15 --step-mph 1 --duration-s 1 --out afile/res",
          "steady '" + kScenario + "' --from-mph 12 --to-mph 14 --stability none --out afile/res",
          "modes '" + kScenario + "' --model halfcar --out afile/res"}) {
        SCOPED_TRACE(args);
        const CliOutcome o = runRockroll(dir, args);
        EXPECT_EQ(o.exitCode, 2) << o.err;
        EXPECT_NE(o.err.find("cannot write the output: --out afile/res: cannot create the directory afile/res.partial"),
                  std::string::npos)
            << o.err;
        EXPECT_EQ(o.out, "");
    }
    EXPECT_EQ(readTextFile(dir / "afile"), "a file, not a directory\n");
}

// A shipped data file that cannot be read (here the report's numbers, mit1976.toml, through
// ROCKROLL_MIT1976) is bad input, exit 2, naming the file and the line; a missing one is the
// same error class (mbmodel/DataFiles.h DataFileError; mbmodel/test/test_DataFiles.cpp).
TEST(CliWorkflow, ABrokenDataFileExits2) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    std::ofstream(dir / "mit1976.toml") << "[report]\nyear = { value = 1976, unit = \"\"\n";
    const std::string cmd = "cd '" + dir.string() + "' && ROCKROLL_MIT1976='" + (dir / "mit1976.toml").string() +
                            "' '" + ROCKROLL_BIN + "' validate --quick --out out > stdout.txt 2> stderr.txt";
    EXPECT_EQ(getExitCode(std::system(cmd.c_str())), 2);
    const std::string err = readTextFile(dir / "stderr.txt");
    EXPECT_NE(err.find("rockroll: data file error: " + (dir / "mit1976.toml").string() + ": "), std::string::npos) << err;
    EXPECT_NE(err.find("(line 2)"), std::string::npos) << err;
}

// A run interrupted while it computes: exit 130, its DIR.partial removed, DIR never created.
TEST(CliWorkflow, InterruptLeavesNothingHalfWritten) {
    for (int sig : {SIGINT, SIGTERM}) {
        SCOPED_TRACE(sig == SIGINT ? "SIGINT" : "SIGTERM");
        const fs::path dir = rockroll::test::makeTestTempDir(sig == SIGINT ? "int" : "term");
        const fs::path out = dir / "res", partial = dir / "res.partial";
        const std::string bin = ROCKROLL_BIN;
        std::vector<std::string> args{bin, "run", kScenario, "--duration-s", "100", "--out", out.string()};
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
        posix_spawn_file_actions_addopen(&actions, 2, (dir / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        pid_t pid = 0;
        ASSERT_EQ(posix_spawn(&pid, bin.c_str(), &actions, nullptr, argv.data(), environ), 0);
        posix_spawn_file_actions_destroy(&actions);
        // Wait (without a time limit on the result) until the run has made its DIR.partial.
        for (int i = 0; i < 6000 && !fs::exists(partial); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
        ASSERT_TRUE(fs::exists(partial));
        std::this_thread::sleep_for(std::chrono::milliseconds(200));  // into the integration
        ASSERT_EQ(kill(pid, sig), 0);
        int status = 0;
        ASSERT_EQ(waitpid(pid, &status, 0), pid);
        EXPECT_EQ(getExitCode(status), 130) << readTextFile(dir / "stderr.txt");
        EXPECT_FALSE(fs::exists(partial));
        EXPECT_FALSE(fs::exists(out));
        EXPECT_NE(readTextFile(dir / "stderr.txt").find("interrupted"), std::string::npos);
    }
}

// A scenario of a car, an amplitude and a speed runs: every other key takes its default
// (docs/cli.md, "Keys and defaults"), and --model needs no run.model in the file.
TEST(CliWorkflow, AMinimalScenarioRuns) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    std::ofstream(dir / "five.toml") << "[car]\nbase = \"70ton-loaded\"\n[track]\namplitude = \"0.75 in\"\n[run]\n"
                                        "speed = \"15 mph\"\n";
    const CliOutcome full = runRockroll(dir, "run five.toml --duration-s 0.3");
    ASSERT_EQ(full.exitCode, 0) << full.err;
    EXPECT_EQ(full.err, "");  // nothing set that the model does not use
    const nlohmann::json j = nlohmann::json::parse(readTextFile(dir / "out" / "five-fullcar" / "summary.json"));
    EXPECT_EQ(j["model"], "fullcar");
    EXPECT_EQ(j["speed_mph"], 15.0);
    EXPECT_EQ(j["amplitude_in"], 0.75);
    const nlohmann::json& p = j["provenance"];
    EXPECT_EQ(p["settings_set"], nlohmann::json({"car.base", "run.speed", "track.amplitude"}));
    EXPECT_EQ(p["ignored_settings"], nlohmann::json::array());
    EXPECT_EQ(p["integrator"]["method"], "cpodes");
    EXPECT_EQ(p["integrator"]["accuracy"], 1e-4);
    EXPECT_EQ(p["integrator"]["output_rate_hz"], 500.0);
    const auto history = rockroll::test::parseCsvTable(readTextFile(dir / "out" / "five-fullcar" / "history.csv"));
    const std::vector<double> t = history.numbers("t_s");
    ASSERT_EQ(t.size(), 151u);  // 0.3 s at 500 Hz
    EXPECT_NEAR(t[1] - t[0], 0.002, 1e-12);

    const CliOutcome reduced = runRockroll(dir, "run five.toml --model reduced --duration-s 0.3");
    ASSERT_EQ(reduced.exitCode, 0) << reduced.err;
    const nlohmann::json r = nlohmann::json::parse(readTextFile(dir / "out" / "five-reduced" / "summary.json"));
    EXPECT_EQ(r["model"], "reduced");
    EXPECT_EQ(r["provenance"]["ignored_settings"], nlohmann::json::array());
}

// A key the scenario sets that the model does not use is named on stderr and in the
// provenance's ignored_settings (docs/cli.md, "Which model uses which key"); the reduced
// model records at its own 200 Hz and refuses another output rate that is set.
TEST(CliWorkflow, AModelNamesTheSettingsItIgnores) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    const CliOutcome o =
        runRockroll(dir, "run '" + kScenario + "' --model reduced --set integrator.accuracy=1e-6 --duration-s 0.5 --out red");
    ASSERT_EQ(o.exitCode, 0) << o.err;
    EXPECT_NE(o.err.find("model \"reduced\" does not use integrator.accuracy, integrator.method"), std::string::npos)
        << o.err;
    const nlohmann::json j = nlohmann::json::parse(readTextFile(dir / "red" / "summary.json"));
    const nlohmann::json& p = j["provenance"];
    EXPECT_EQ(p["ignored_settings"], nlohmann::json({"integrator.accuracy", "integrator.method"}));
    EXPECT_EQ(p["integrator"]["output_rate_hz"], 200.0);
    const std::vector<double> t =
        rockroll::test::parseCsvTable(readTextFile(dir / "red" / "history.csv")).numbers("t_s");
    ASSERT_EQ(t.size(), 101u);  // every 0.005 s step of 0.5 s
    EXPECT_NEAR(t[1] - t[0], 0.005, 1e-12);

    // Rerun from its summary: the same keys count as set, so the same ones are ignored.
    const CliOutcome again = runRockroll(dir, "run --from-summary red/summary.json --out red-again");
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(nlohmann::json::parse(readTextFile(dir / "red-again" / "summary.json"))["provenance"]["ignored_settings"],
              p["ignored_settings"]);
    EXPECT_EQ(readTextFile(dir / "red-again" / "history.csv"), readTextFile(dir / "red" / "history.csv"));

    // The half car uses the integrator but not [eom] nor track.entry.
    const CliOutcome half = runRockroll(dir, "run '" + kScenario + "' --model halfcar --set eom.small_angles=true "
                                             "--set track.entry=synchronized --duration-s 0.2 --out half");
    ASSERT_EQ(half.exitCode, 0) << half.err;
    EXPECT_EQ(nlohmann::json::parse(readTextFile(dir / "half" / "summary.json"))["provenance"]["ignored_settings"],
              nlohmann::json({"eom.small_angles", "track.entry"}));
    EXPECT_NE(half.err.find("does not use eom.small_angles, track.entry"), std::string::npos) << half.err;

    // An output rate set for the reduced model: 200 Hz runs, another is refused.
    EXPECT_EQ(runRockroll(dir, "run '" + kScenario + "' --model reduced --set run.output_rate=\"200 Hz\" "
                               "--duration-s 0.2 --out red200").exitCode, 0);
    const CliOutcome refused = runRockroll(dir, "run '" + kScenario + "' --model reduced --set run.output_rate=\"500 Hz\" "
                                                "--duration-s 0.2 --out red500");
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_NE(refused.err.find("--set \"run.output_rate=500 Hz\": "), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("key 'run.output_rate' = 500 Hz: expected 200 Hz for model \"reduced\""),
              std::string::npos) << refused.err;
    EXPECT_FALSE(fs::exists(dir / "red500"));
}

// A rerun into the default output directory (out/<scenario>-<model>) replaces the earlier run
// there and says so; a directory named with --out stays protected without --force.
TEST(CliWorkflow, ARerunReplacesTheDefaultOutputButNotANamedOne) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    std::ofstream(dir / "s.toml") << "[run]\nspeed = \"15 mph\"\n";
    const fs::path out = dir / "out" / "s-reduced";
    ASSERT_EQ(runRockroll(dir, "run s.toml --model reduced --duration-s 0.2").exitCode, 0);
    const std::string first = readTextFile(out / "summary.json");
    const CliOutcome rerun = runRockroll(dir, "run s.toml --model reduced --duration-s 0.2 --speed-mph 14");
    ASSERT_EQ(rerun.exitCode, 0) << rerun.err;
    EXPECT_NE(rerun.err.find("replaced the previous run in out/s-reduced"), std::string::npos) << rerun.err;
    const std::string second = readTextFile(out / "summary.json");
    EXPECT_NE(second, first);
    EXPECT_EQ(nlohmann::json::parse(second)["speed_mph"], 14.0);
    EXPECT_FALSE(fs::exists(dir / "out" / "s-reduced.partial"));
    // A default directory that is not an earlier run's output is left alone.
    fs::create_directories(dir / "out" / "s-eom");
    std::ofstream(dir / "out" / "s-eom" / "notes.txt") << "mine\n";
    const CliOutcome notOurs = runRockroll(dir, "run s.toml --model eom --duration-s 0.2");
    EXPECT_EQ(notOurs.exitCode, 2) << notOurs.err;
    EXPECT_TRUE(fs::exists(dir / "out" / "s-eom" / "notes.txt"));

    // --out DIR: refused the second time, replaced with --force.
    const std::string named = "run s.toml --model reduced --duration-s 0.2 --out mine";
    ASSERT_EQ(runRockroll(dir, named).exitCode, 0);
    const std::string kept = readTextFile(dir / "mine" / "summary.json");
    const CliOutcome refused = runRockroll(dir, named + " --speed-mph 14");
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_NE(refused.err.find("--out mine: the directory exists and is not empty"), std::string::npos) << refused.err;
    EXPECT_EQ(readTextFile(dir / "mine" / "summary.json"), kept);
    const CliOutcome forced = runRockroll(dir, named + " --speed-mph 14 --force");
    ASSERT_EQ(forced.exitCode, 0) << forced.err;
    EXPECT_EQ(forced.err.find("replaced the previous run"), std::string::npos) << forced.err;
    EXPECT_EQ(nlohmann::json::parse(readTextFile(dir / "mine" / "summary.json"))["speed_mph"], 14.0);
}
