#!/usr/bin/env bash
# Profiles one rockroll run with perf (sampling the software cpu-clock: this machine has
# no hardware counters) and writes a text report.
#
#   bench/profile.sh [MODEL] [SECONDS] [OUTDIR]     default: fullcar 10 build-profile/profile
#
# Builds the `profile` CMake preset (Release code, -g, frame pointers) against the
# Release Simbody that ./build.sh builds, runs the default case for SECONDS simulated
# seconds, and writes OUTDIR/MODEL-self.txt (functions by self time) and
# OUTDIR/MODEL-callers.txt (call graph, DWARF unwinding: Simbody has no frame pointers).
set -euo pipefail
cd "$(dirname "$0")/.."
model="${1:-fullcar}"; secs="${2:-10}"; out="${3:-build-profile/profile}"
command -v perf >/dev/null || { echo "profile.sh: perf not found (apt-get install linux-perf)" >&2; exit 1; }
./build.sh
cmake --preset profile >/dev/null
cmake --build --preset profile -j"$(nproc)" >&2
mkdir -p "$out"
perf record -q -e cpu-clock -F 2000 --call-graph dwarf,16384 -o "$out/$model.data" -- \
  build-profile/bin/rockroll run scenarios/70ton-loaded.toml --model "$model" --duration-s "$secs" --out "$out/run-$model" >/dev/null
perf report -q -i "$out/$model.data" --no-children --sort symbol --percent-limit 0.3 --stdio \
  -g none > "$out/$model-self.txt" 2>/dev/null
perf report -q -i "$out/$model.data" --children --sort symbol --percent-limit 2 --stdio \
  -g caller,0.5,callee,function,percent > "$out/$model-callers.txt" 2>/dev/null
echo "profile.sh: wrote $out/$model-self.txt and $out/$model-callers.txt" >&2
head -40 "$out/$model-self.txt"
