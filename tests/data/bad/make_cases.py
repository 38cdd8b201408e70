#!/usr/bin/python3
"""Writes the bad-input corpus of tests/data/bad/: one scenario file per file case and
cases.tsv, the manifest read by tests/run_bad_inputs.py (ctest BadInputs.Corpus).

Each manifest row: name, expected exit code, the substrings the message must contain
(separated by " && "), and the command line after `rockroll` ($BAD = this folder,
$SRC = the source tree; leading NAME=VALUE words set the environment). Rerun this
script after changing it: `/usr/bin/python3 tests/data/bad/make_cases.py`.
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# A quick valid case: the reduced model for 0.2 s (which records at its own 200 Hz, so the
# output rate is left at its default). Every file case changes one thing.
BASE = [
    ("", [("description", '"bad-input corpus base case"')]),
    ("car", [("base", '"70ton-loaded"')]),
    ("track", [("amplitude", '"0.75 in"'), ("rail_length", '"39 ft"'), ("rails", "0"), ("entry", '"lead"')]),
    ("run", [("speed", '"16.5 mph"'), ("duration", '"0.2 s"'), ("model", '"reduced"'), ("filter_cutoff", '"20 Hz"')]),
    ("integrator", [("method", '"cpodes"'), ("accuracy", "1e-4")]),
]


def render(tables):
    lines = []
    for name, keys in tables:
        if name:
            lines += ["", f"[{name}]"]
        lines += [f"{k} = {v}" for k, v in keys]
    return "\n".join(lines) + "\n"


def line_of(text, table, key):
    current = ""
    for i, l in enumerate(text.splitlines(), 1):
        if l.startswith("["):
            current = l.strip("[]")
        elif current == table and l.split(" = ")[0] == key:
            return i
    raise KeyError(f"{table}.{key}")


cases = []  # (name, exit, expect, args)
files = {}


def file_case(name, table, key, value, expect_extra="", code=2, delete=False, args="run $BAD/{f} --out out/{n}",
              line=True):
    tables = [(t, list(ks)) for t, ks in BASE]
    entry = next((ks for t, ks in tables if t == table), None)
    if entry is None:
        tables.append((table, []))
        entry = tables[-1][1]
    idx = next((i for i, (k, _) in enumerate(entry) if k == key), None)
    if delete:
        entry.pop(idx)
    elif idx is None:
        entry.append((key, value))
    else:
        entry[idx] = (key, value)
    text = render(tables)
    f = f"{name}.toml"
    files[f] = text
    full = f"{table}.{key}" if table else key
    expect = [f"key '{full}'"] if code == 2 else ["max_wall_time"]
    if not delete and code == 2 and line:
        expect.insert(0, f"{f}:{line_of(text, table, key)}:")
    elif code == 2:
        expect.insert(0, f)
    if expect_extra:
        expect.append(expect_extra)
    if code == 2:
        expect.append("expected")
    cases.append((name, code, " && ".join(expect), args.format(f=f, n=name)))


def text_case(name, text, expect, code=2):
    f = f"{name}.toml"
    files[f] = text
    cases.append((name, code, expect, f"run $BAD/{f} --out out/{name}"))


def cli_case(name, args, expect, code=2):
    cases.append((name, code, expect, args))


# ---- scenario values out of range, non-finite, wrong type or unit -------------------
ranged = {
    ("run", "speed"): ['"500 mph"', '"0 mph"', '"-5 mph"', '"nan mph"', '"inf mph"', "15", '"15 kg"', '"0.01 mph"',
                       '"1e400 mph"', '"151 mph"'],
    ("run", "duration"): ['"1e9 s"', '"0 s"', '"-1 s"', '"nan s"', '"inf s"', '"20 Hz"', "20", '"3601 s"', '"0.001 s"'],
    ("run", "output_rate"): ['"1e9 Hz"', '"0 Hz"', '"-1 Hz"', '"nan Hz"', '"0.5 Hz"', '"500 s"'],
    ("run", "filter_cutoff"): ['"300 Hz"', '"250 Hz"', '"0 Hz"', '"nan Hz"', '"-1 Hz"', "20"],
    ("integrator", "accuracy"): ["1e-14", "0", "-1e-4", "nan", "inf", "0.5", '"1e-4"', "1", "1e-11", "-inf"],
    ("integrator", "max_step"): ['"-1 s"', '"nan s"', '"10 s"', "0.01"],
    ("track", "amplitude"): ['"50 in"', '"-1 in"', '"nan in"', '"inf in"', "0.75", '"0.75 mph"', '"3.1 in"'],
    ("track", "rail_length"): ['"0 ft"', '"-39 ft"', '"nan ft"', '"1e6 ft"', '"39 s"', "39"],
    ("track", "rails"): ["4294967297", "-1", "1.5", '"4"', "nan", "9223372036854775807", "2000000", "inf"],
    ("limits", "flange_climb_time"): ['"0 s"', '"11 s"', '"nan s"'],
    ("wheel_rail", "flange_height"): ['"0 in"', '"4 in"', '"nan in"'],
    ("wheel_rail", "flangeway_clearance"): ['"-1 in"', '"4 in"'],
    ("wheel_rail", "friction"): ["0", "1.5", "nan", '"0.5 in"'],
    ("wheel_rail", "creep_coefficient"): ['"1 N"', '"1e10 N"', '"nan N"', '"1e7 in"', "1e7"],
    ("wheel_rail", "flange_angle"): ['"30 deg"', '"90 deg"', '"nan deg"', "75"],
    ("wheel_rail", "flange_stiffness_scale"): ["0", "1000", "nan"],
    ("limits", "wheels_off_time"): ['"0 s"', '"11 s"', '"nan s"'],
    ("limits", "rollover_angle"): ['"0 deg"', '"91 deg"', '"inf deg"'],
    ("limits", "energy_runaway_fraction"): ["0", "101", "nan"],
    ("limits", "max_wall_time"): ['"0 s"', '"8 days"', '"1e9 s"', '"-1 s"'],
    ("limits", "severe_separation"): ['"-1 s"', '"2 s"'],
    ("attribution", "unsprung_mass_scale"): ["0", "2", "nan", '"1"'],
}
for (table, key), values in ranged.items():
    for i, v in enumerate(values):
        file_case(f"{table}-{key}-{i}", table, key, v)

# car parameters: NaN, infinite, negative, zero where zero means nothing, wrong unit, no unit
car = [("spring_vertical_rate", ['"nan lb/in"', '"inf lb/in"', '"-20840 lb/in"', '"0 lb/in"', '"20840 lb"', "20840"]),
       ("body_and_bolsters_weight", ['"nan lb"', '"-1 lb"', '"0 lb"', '"1e999 lb"']),
       ("roll_inertia", ['"-1 lb*in*s^2"', '"0 kg*m^2"', '"nan kg*m^2"']),
       ("side_bearing_clearance", ['"-0.25 in"', '"nan in"', "0.25"]),
       ("vertical_friction", ['"-4000 lb"', '"inf lb"']),
       ("gauge", ['"0 in"', '"-56.5 in"', '"56.5 deg"']),
       ("wheelbase", ['"nan in"', "true"]),
       ("center_plate_rim_points", ["2.5", '"8"'])]
for key, values in car:
    for i, v in enumerate(values):
        file_case(f"car-{key}-{i}", "car", key, v)

# choices, booleans, unknown and missing keys
file_case("run-model-unknown", "run", "model", '"nosuch"', "one of")
file_case("run-model-number", "run", "model", "5", "one of")
file_case("integrator-method-unknown", "integrator", "method", '"euler"', "one of")
file_case("integrator-method-number", "integrator", "method", "3", "one of")
file_case("track-entry-unknown", "track", "entry", '"sideways"', "lead")
file_case("wheel_rail-lateral-unknown", "wheel_rail", "lateral", '"flanges"', "one of")
file_case("limits-flange_height-renamed", "limits", "flange_height", '"1 in"', "wheel_rail.flange_height")
file_case("track-mirror-string", "track", "mirror", '"yes"', "true or false")
file_case("eom-linear_springs-number", "eom", "linear_springs", '"no"', "true or false")
file_case("reduced-truck_weight-number", "reduced", "truck_weight", "1", "true or false")
file_case("attribution-unsprung_gravity-number", "attribution", "unsprung_gravity", "0", "true or false")
file_case("limits-enabled-string", "limits", "enabled", '"off"', "true or false")
file_case("car-base-unknown", "car", "base", '"nosuch"', "one of")
file_case("car-name-empty", "car", "name", '""', "non-empty")
file_case("run-unknown-key", "run", "sped", '"16 mph"', "no such key")
file_case("car-unknown-key", "car", "side_bearing_clearence", '"0.25 in"', "no such key")
file_case("track-unknown-key", "track", "amplitud", '"0.75 in"', "no such key")
file_case("integrator-unknown-key", "integrator", "acuracy", "1e-4", "no such key")
file_case("limits-unknown-key", "limits", "max_wall", '"1 s"', "no such key")
file_case("top-unknown-key", "", "speed", '"16 mph"', "no such key")
# (a key left out takes its default, docs/cli.md "Keys and defaults"; a car given inline
# by its name alone must give every parameter)
# (switches that do not apply to the model are found when the model is known: no line)
file_case("switch-truck_weight-halfcar", "reduced", "truck_weight", "true", "expected model",
          args="run $BAD/{f} --model halfcar --out out/{n}", line=False)
file_case("switch-mass_scale-reduced", "attribution", "unsprung_mass_scale", "0.5", "expected model", line=False)
file_case("run-output_rate-reduced", "run", "output_rate", '"500 Hz"', "expected 200 Hz for model \"reduced\"",
          line=False)

# whole-file problems
base_text = render(BASE)
text_case("toml-unterminated-string", base_text.replace('"16.5 mph"', '"16.5 mph'), "TOML syntax error")
text_case("toml-duplicate-key", base_text.replace('speed = "16.5 mph"', 'speed = "16.5 mph"\nspeed = "17 mph"'),
          "TOML syntax error")
text_case("toml-binary", "\x00\x01\x02garbage\xff", "TOML syntax error")
text_case("toml-run-not-a-table", render([t for t in BASE if t[0] != "run"]).replace("[car]", 'run = 5\n\n[car]'),
          "key 'run' must be a table")
text_case("toml-unknown-table", base_text + "\n[runn]\nspeed = \"16 mph\"\n", "key 'runn'")
text_case("car-inline-incomplete", base_text.replace('base = "70ton-loaded"', 'name = "my-car"'),
          "key 'car.body_and_bolsters_weight' && present")
text_case("car-file-missing", base_text.replace('base = "70ton-loaded"', 'file = "no-such-car.toml"'),
          "key 'car.file' && cannot open car file")
text_case("measured-not-increasing", base_text.replace("[run]",
          '[[track.measured]]\ndistance = "1 m"\ncross_level = "0.1 in"\n'
          '[[track.measured]]\ndistance = "1 m"\ncross_level = "0.2 in"\n\n[run]'), "increase strictly")
text_case("measured-not-tables", base_text.replace('entry = "lead"', 'entry = "lead"\nmeasured = [1, 2]'),
          "key 'track.measured'")
text_case("measured-nan", base_text.replace("[run]",
          '[[track.measured]]\ndistance = "1 m"\ncross_level = "nan in"\n\n[run]'), "key 'track.measured[0].cross_level'")

# ---- command-line options ---------------------------------------------------------
S = "$SRC/scenarios/70ton-loaded.toml"
B = "$BAD/base.toml"
files["base.toml"] = base_text
for i, v in enumerate(["500", "0", "-1", "nan", "inf", "abc", "0.01", "1e400"]):
    cli_case(f"cli-run-speed-{i}", f"run {B} --speed-mph {v}", "--speed-mph && expected a speed in [0.1 mph, 150 mph]")
for i, v in enumerate(["50", "-1", "nan", "3.5"]):
    cli_case(f"cli-run-amplitude-{i}", f"run {B} --amplitude-in {v}", "--amplitude-in && expected a length in [0 in, 3 in]")
for i, v in enumerate(["1e9", "0", "nan", "-2"]):
    cli_case(f"cli-run-duration-{i}", f"run {B} --duration-s {v}", "--duration-s && expected a time in [0.05 s, 3600 s]")
cli_case("cli-run-duration-too-short", f"run {B} --duration-s 0.001 --out out/short", "--duration-s && expected a time in [0.05 s, 3600 s]")
text_case("run-too-few-samples", base_text.replace('filter_cutoff = "20 Hz"', 'output_rate = "10 Hz"\nfilter_cutoff = "2 Hz"'),
          "key 'run.duration' && expected at least 4 output intervals")
for i, v in enumerate(["0", "nan", "1e9"]):
    cli_case(f"cli-run-max-wall-{i}", f"run {B} --max-wall-s {v}", "--max-wall-s && expected a time in (0 s, 604800 s]")
cli_case("cli-run-model-unknown", f"run {B} --model nosuch", "--model && nosuch && expected one of")
cli_case("cli-run-missing-file", "run $BAD/no-such-file.toml", "no-such-file.toml")
cli_case("cli-run-unknown-flag", f"run {B} --speeed 15", "--speeed")
cli_case("cli-run-no-scenario", "run --out out/none", "either a scenario file or --from-summary")
cli_case("cli-run-scenario-and-summary", f"run {B} --from-summary {B}", "either a scenario file or --from-summary")
cli_case("cli-run-summary-not-json", f"run --from-summary {B}", "summary")
cli_case("cli-run-speed-twice", f"run {B} --speed-mph 15 --speed-mph 16", "--speed-mph")
cli_case("cli-run-extra-positional", f"run {B} {B}", "")
cli_case("cli-unknown-subcommand", "simulate", "simulate")
cli_case("cli-run-speed-no-value", f"run {B} --speed-mph", "--speed-mph")
cli_case("cli-run-out-is-a-file", f"run {B} --out {B}/sub", "base.toml")

SW = f"sweep {B} --from-mph 14 --to-mph 15 --step-mph 1"  # a valid sweep that the options below spoil
for i, v in enumerate(["0", "500", "nan", "-1"]):
    cli_case(f"cli-sweep-from-{i}", f"sweep {B} --from-mph {v} --to-mph 15 --step-mph 1", "--from-mph && expected a speed")
for i, v in enumerate(["0", "200", "inf"]):
    cli_case(f"cli-sweep-to-{i}", f"sweep {B} --from-mph 14 --to-mph {v} --step-mph 1", "--to-mph && expected a speed")
for i, v in enumerate(["0", "-1", "nan", "200"]):
    cli_case(f"cli-sweep-step-{i}", f"sweep {B} --from-mph 14 --to-mph 15 --step-mph {v}", "--step-mph && expected a speed in (0 mph, 150 mph]")
cli_case("cli-sweep-too-many-speeds", f"sweep {B} --from-mph 1 --to-mph 150 --step-mph 0.001", "--step-mph && at most 10000")
cli_case("cli-sweep-reversed", f"sweep {B} --from-mph 16 --to-mph 14 --step-mph 1", "--to-mph && --from-mph")
cli_case("cli-sweep-no-step", f"sweep {B} --from-mph 14 --to-mph 15", "--step-mph")
for i, v in enumerate(["-1", "1.5", "1e6"]):
    cli_case(f"cli-sweep-jobs-{i}", f"{SW} --jobs {v}", "--jobs && expected an integer in [0, 1024]")
cli_case("cli-sweep-direction", f"{SW} --direction sideways", "--direction && expected one of")
cli_case("cli-sweep-amplitude-nan", f"{SW} --amplitude-in 0.5 --amplitude-in nan", "--amplitude-in && expected a length")
cli_case("cli-sweep-issue12-sigabrt", f"sweep {S} --model reduced --duration-s 0.001 --from-mph 14 --to-mph 15 --step-mph 0.5",
         "--duration-s && expected a time in [0.05 s, 3600 s]")
cli_case("cli-sweep-bad-file", f"sweep $BAD/run-speed-0.toml --from-mph 14 --to-mph 15 --step-mph 1", "key 'run.speed'")
cli_case("cli-sweep-model-unknown", f"{SW} --model nosuch", "--model && expected one of")

for i, v in enumerate(["0", "500", "nan"]):
    cli_case(f"cli-steady-from-{i}", f"steady {B} --from-mph {v} --to-mph 15", "--from-mph && expected a speed")
cli_case("cli-steady-reversed", f"steady {B} --from-mph 16 --to-mph 14", "--to-mph && --from-mph")
cli_case("cli-steady-amplitude", f"steady {B} --amplitude-in 9", "--amplitude-in && expected a length")
cli_case("cli-steady-stability", f"steady {B} --stability maybe", "--stability && expected one of")
cli_case("cli-steady-bad-file", "steady $BAD/track-amplitude-0.toml", "key 'track.amplitude'")

cli_case("cli-modes-reduced", f"modes {B} --model reduced", "--model && reduced && expected one of")
cli_case("cli-modes-bad-file", "modes $BAD/car-gauge-0.toml", "key 'car.gauge'")
cli_case("cli-modes-missing-file", "modes $BAD/nothing.toml", "nothing.toml")

for i, v in enumerate(["0", "100", "nan"]):
    cli_case(f"cli-validate-roll-limit-{i}", f"validate --roll-limit-deg {v}", "--roll-limit-deg && expected an angle in (0 deg, 90 deg]")
for i, v in enumerate(["2", "-0.1", "nan"]):
    cli_case(f"cli-validate-wheel-load-{i}", f"validate --wheel-load-limit {v}", "--wheel-load-limit && expected a number in [0, 1]")
cli_case("cli-validate-jobs", "validate --jobs -3", "--jobs && expected an integer")

# ---- limits of the run itself: memory, wall time, failed points ---------------------
cli_case("env-memory-limit", f"ROCKROLL_MAX_MEMORY_MB=1 run {B} --duration-s 100 --out out/memory", "MiB of history && ROCKROLL_MAX_MEMORY_MB")
cli_case("env-memory-limit-not-a-number", f"ROCKROLL_MAX_MEMORY_MB=lots run {B} --out out/memory2", "ROCKROLL_MAX_MEMORY_MB && expected a positive number")
text_case("memory-default-limit", base_text.replace('"0.2 s"', '"3600 s"').replace('"reduced"', '"halfcar"')
          .replace('filter_cutoff = "20 Hz"', 'output_rate = "100000 Hz"\nfilter_cutoff = "20 Hz"'),
          "MiB of history && expected at most 2048 MiB")
file_case("wall-time-run", "limits", "max_wall_time", '"1 us"', "unknown or missing unit")
file_case("wall-time-exceeded", "limits", "max_wall_time", '"0.000001 s"', "wall-time limit", code=3)
file_case("sweep-failed-points", "limits", "max_wall_time", '"0.000001 s"', "FAILED && ETA", code=4,
          args="sweep $BAD/{f} --from-mph 14 --to-mph 15 --step-mph 1 --direction up")

for f, text in files.items():
    with open(os.path.join(HERE, f), "w", encoding="utf-8", errors="surrogateescape") as out:
        out.write(text)
with open(os.path.join(HERE, "cases.tsv"), "w") as out:
    out.write("# name\texit\tmessage must contain (&& separated)\targuments after rockroll\n")
    for name, code, expect, args in cases:
        out.write(f"{name}\t{code}\t{expect}\t{args}\n")
print(f"{len(cases)} cases, {len(files)} files")
