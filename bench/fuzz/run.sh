#!/usr/bin/env bash
# Builds the libFuzzer harnesses bench/fuzz/fuzz_*.cpp (preset `fuzz`: clang, ASan + UBSan,
# into build-fuzz/) and runs each for RUNS executions (default 1,000,000), seeded from the
# project's own files (scenarios/, scenarios/cars/, scenarios/tracks/, tests/data/bad/).
#   bench/fuzz/run.sh [RUNS] [HARNESS...]     e.g. bench/fuzz/run.sh 1000000 fuzz_track_csv
#   FUZZ_JOBS=2 runs two harnesses at a time; FUZZ_MAX_SECONDS=S stops each after S seconds;
#   FUZZ_BUILD=0 runs the harnesses already in build-fuzz/fuzz/ without building (a commit
#   changes app/BuildInfo.h, so a build would relink every harness).
# Needs Debian's clang and libclang-rt-<version>-dev (fuzzing only; not in build.sh's list).
# Writes, under build-fuzz/fuzz-out/:
#   crashes/<harness>/   crash-*, timeout-* (over 10 s), oom-* (over 2 GB) inputs: none expected;
#                        each one found becomes a regression test (docs/building.md)
#   corpus/<harness>/    the corpus grown by the run (kept for the next run)
#   logs/<harness>.log   libFuzzer's log, ending with its final stats
#   summary.tsv          harness, executions, exec/s, seconds, result
# Exits 1 if any harness found a crash, a hang or an out-of-memory input.
set -euo pipefail
cd "$(dirname "$0")/../.."
runs="${1:-1000000}"
shift || true
if [ "${FUZZ_BUILD:-1}" != 0 ]; then
  cmake --preset fuzz >/dev/null
  cmake --build build-fuzz -j"$(nproc)" --target fuzz >&2
fi
out=build-fuzz/fuzz-out
mkdir -p "$out/crashes" "$out/corpus" "$out/logs" "$out/seeds"
if [ $# -gt 0 ]; then harnesses=("$@"); else
  harnesses=()
  for f in build-fuzz/fuzz/fuzz_*; do harnesses+=("$(basename "$f")"); done
fi

# Seeds, by harness: the project's own files of the format each reads.
seed() {  # seed HARNESS FILE...
  local dir="$out/seeds/$1"; shift
  mkdir -p "$dir"
  for f in "$@"; do [ -f "$f" ] && cp "$f" "$dir/$(echo "$f" | tr / _)"; done
  return 0
}
rm -rf "$out/seeds"
seed fuzz_scenario_text scenarios/*.toml tests/data/bad/*.toml
seed fuzz_scenario scenarios/*.toml tests/data/bad/*.toml
# A scenario with the files it names appended: [track] file and [car] file read the
# parts after "#@track.csv" and "#@car.toml" (bench/fuzz/fuzz_scenario.cpp).
for csv in scenarios/tracks/*.csv; do
  for toml in scenarios/measured-*.toml; do
    sed 's|^file = .*|file = "track.csv"|' "$toml" > "$out/seeds/fuzz_scenario/with-$(basename "$csv" .csv)-$(basename "$toml")"
    { echo "#@track.csv"; cat "$csv"; } >> "$out/seeds/fuzz_scenario/with-$(basename "$csv" .csv)-$(basename "$toml")"
  done
done
for car in scenarios/cars/*.toml; do
  { sed 's|^base = .*|file = "car.toml"|' scenarios/70ton-loaded.toml; echo "#@track.csv"; echo "#@car.toml"; cat "$car"; } \
    > "$out/seeds/fuzz_scenario/with-car-$(basename "$car")"
done
seed fuzz_track_csv scenarios/tracks/*.csv tests/data/bad/*.csv
seed fuzz_car scenarios/cars/*.toml
seed fuzz_mit1976 scenarios/reference/mit1976.toml
mkdir -p "$out/seeds/fuzz_override"
printf 'run.speed=16.5 mph\ncar.side_bearing_clearance=0.25 in\n' > "$out/seeds/fuzz_override/speed-clearance"
printf 'model=reduced\naccuracy=1e-6\nrails=4\n' > "$out/seeds/fuzz_override/bare"
printf 'track.amplitude="1.0 in"\nrun.duration=5 s\nintegrator.method=rk4\n' > "$out/seeds/fuzz_override/track"
# A summary.json as `rockroll run` writes it, reduced to what --from-summary reads.
mkdir -p "$out/seeds/fuzz_summary"
/usr/bin/python3 - "$out/seeds/fuzz_summary" scenarios/*.toml <<'PY'
import json, os, sys
for path in sys.argv[2:]:
    doc = {"start": "rest", "provenance": {"scenario_file": path, "scenario_sha256": "0" * 64,
           "scenario_toml": open(path).read(), "car_overrides": {"roll_damping": "0"},
           "overrides": [{"key": "run.speed", "value": "15 mph"}]}}
    open(os.path.join(sys.argv[1], os.path.basename(path) + ".json"), "w").write(json.dumps(doc, indent=2))
PY

# Sweep journals as `rockroll sweep --out` writes them (app/Journal.h): a header, finished
# points (one with its summary and the state the next speed starts from, one failed), and
# the same with a last line cut off by a kill.
mkdir -p "$out/seeds/fuzz_journal"
/usr/bin/python3 - "$out/seeds/fuzz_journal" <<'PY'
import json, os, sys
h = lambda x: float(x).hex()
header = {"journal": "sweep", "version": 1, "identity": {"sweeps": [{"model": "reduced", "sweep": {
          "from_mph": 13, "to_mph": 17, "step_mph": 0.5, "direction": "up", "fresh": False, "ramp_time_s": 1}}]},
          "command": "rockroll sweep scenarios/70ton-loaded.toml --model reduced --out out"}
summary = {k: 0.5 for k in ("speed_mph", "amplitude_in", "duration_s", "max_roll_deg", "steady_roll_amplitude_deg",
           "peak_to_peak_roll_deg", "max_wheel_lift_in", "max_wheel_load_lb", "min_wheel_load_ratio",
           "max_side_bearing_load_lb", "max_center_plate_load_lb", "raw_max_wheel_load_lb", "raw_min_wheel_load_ratio",
           "raw_max_side_bearing_load_lb", "raw_max_center_plate_load_lb", "static_wheel_load_lb",
           "static_center_plate_load_lb", "center_plate_separation_longest_s", "center_plate_separation_total_s",
           "wheel_lift_longest_s", "energy_balance_error", "max_wheel_unloading", "raw_max_wheel_unloading",
           "max_l_over_v", "raw_max_l_over_v", "max_car_body_vertical_accel_g", "raw_max_car_body_vertical_accel_g",
           "max_car_body_lateral_accel_g", "raw_max_car_body_lateral_accel_g", "sim_time_s", "wall_time_s")}
summary.update({"model": "reduced", "car": "70-ton loaded", "regime": "rocking", "stopped_at_s": None,
                "stop_reason": None, "filter": "none", "steps": 1234, "max_l_over_v": None,
                "trucks": [{"truck": "F", "max_center_plate_load_lb": 1.5e4, "min_center_plate_load_lb": 0.0,
                            "max_side_bearing_L_load_lb": 2e3, "max_side_bearing_R_load_lb": 0.0}],
                "criteria": [{"name": "wheel unloading", "value": 0.4, "limit": 0.9, "unit": "1"}]})
nxt = {"from": {"model": "reduced", "y": [h(0.01), h(-0.25), h(1e-300), "inf"], "distance_m": h(123.25),
       "speed_m_per_s": h(6.7056)}, "ramp_time_s": h(0), "static_reference": [h(9.81), h(-1.5)]}
points = [{"sweep": 0, "direction": "up", "index": 0, "speed_mph": 13, "speed_mph_hex": h(13), "start": "rest",
           "failed": False, "summary": summary, "next": nxt},
          {"sweep": 0, "direction": "up", "index": 1, "speed_mph": 13.5, "speed_mph_hex": h(13.5),
           "start": "previous", "failed": True, "error": "numerical failure at t = 1.5 s",
           "next": {"from": None, "ramp_time_s": h(1), "static_reference": []}}]
lines = [json.dumps(header)] + [json.dumps(p) for p in points]
with open(os.path.join(sys.argv[1], "sweep.jsonl"), "w") as f: f.write("\n".join(lines) + "\n")
with open(os.path.join(sys.argv[1], "torn.jsonl"), "w") as f: f.write("\n".join(lines[:2]) + "\n" + lines[2][:40])
PY

printf 'harness\texecutions\texec_per_s\tseconds\tresult\n' > "$out/summary.tsv"
fuzz_one() {  # fuzz_one HARNESS: one line of summary.tsv; returns 1 on a finding
  local h=$1 seeds=() start rc seconds execs rate result
  mkdir -p "$out/crashes/$h" "$out/corpus/$h" "$out/seeds/$h"
  [ -n "$(ls -A "$out/seeds/$h")" ] && seeds=("$out/seeds/$h")
  [ ${#seeds[@]} -eq 0 ] && seeds=("$out/seeds/fuzz_scenario_text")  # a harness without seeds of its own: text seeds
  echo "fuzz: $h, $runs runs" >&2
  start=$(date +%s.%N)
  rc=0
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "build-fuzz/fuzz/$h" -runs="$runs" -max_total_time="$max_seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=16384 -print_final_stats=1 -artifact_prefix="$out/crashes/$h/" "$out/corpus/$h" "${seeds[@]}" \
    > "$out/logs/$h.log" 2>&1 || rc=$?
  seconds=$(awk "BEGIN { print $(date +%s.%N) - $start }")
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$out/logs/$h.log" | grep -o '[0-9]*$' || echo 0)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$out/logs/$h.log" | grep -o '[0-9]*$' || echo 0)
  if [ "$rc" -eq 0 ]; then result=ok; else result="FOUND (exit $rc): $(ls "$out/crashes/$h" | tr '\n' ' ')"; fi
  printf '%s\t%s\t%s\t%.0f\t%s\n' "$h" "$execs" "$rate" "$seconds" "$result" >> "$out/summary.tsv"
  echo "fuzz: $h: $execs executions, $rate exec/s, $result" >&2
  [ "$rc" -eq 0 ]
}
# FUZZ_JOBS harnesses at a time (default 1); FUZZ_MAX_SECONDS caps each (default 0: no cap,
# RUNS decides; a capped harness reports the executions it reached).
jobs="${FUZZ_JOBS:-1}" max_seconds="${FUZZ_MAX_SECONDS:-0}"
status=0
pids=()
for h in "${harnesses[@]}"; do
  fuzz_one "$h" &
  pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then
    wait "${pids[0]}" || status=1
    pids=("${pids[@]:1}")
  fi
done
for p in "${pids[@]}"; do wait "$p" || status=1; done
column -t -s $'\t' "$out/summary.tsv"
exit $status
