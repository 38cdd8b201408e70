#!/usr/bin/env bash
# Debian's libsimbody against the Release Simbody build.sh builds, measured in one run:
# the default case on each Simbody model, run alternately by two rockroll binaries
# (build/ links the Release Simbody; build-system/ links Debian's, configured with
# -DROCKROLL_SYSTEM_SIMBODY=ON), with sim s per wall s, their ratio, and whether the
# two give the same answer.
#
#   bench/simbody_builds.sh [SECONDS] [REPEATS]      default 10 s simulated, 2 repeats
set -euo pipefail
cd "$(dirname "$0")/.."
secs="${1:-10}"; reps="${2:-2}"
./build.sh >/dev/null
if ! dpkg-query -W -f='${Status}' libsimbody-dev 2>/dev/null | grep -q "install ok installed"; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get install -y -qq --no-install-recommends libsimbody-dev >&2
fi
cmake -S . -B build-system -DCMAKE_BUILD_TYPE=Release -DROCKROLL_SYSTEM_SIMBODY=ON >/dev/null
cmake --build build-system -j"$(nproc)" --target rockroll >&2
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
for model in halfcar fullcar; do
  for r in $(seq "$reps"); do
    for b in build build-system; do
      "$b/bin/rockroll" run scenarios/70ton-loaded.toml --model "$model" --duration-s "$secs" --out "$tmp/$b-$model-$r" --json > "$tmp/$b-$model-$r.json"
    done
  done
done
/usr/bin/python3 - "$tmp" "$reps" <<'PY'
import json, sys
tmp, reps = sys.argv[1], int(sys.argv[2])
keys = ["max_roll_deg", "max_wheel_lift_in", "max_wheel_load_lb", "max_side_bearing_load_lb", "max_center_plate_load_lb", "steps"]
print("| model | Debian libsimbody, sim s / wall s | Release Simbody, sim s / wall s | ratio | same maxima |")
print("|---|---|---|---|---|")
for model in ["halfcar", "fullcar"]:
    def load(b, r): return json.load(open(f"{tmp}/{b}-{model}-{r}.json"))
    speed = {b: [load(b, r)["sim_time_s"] / load(b, r)["wall_time_s"] for r in range(1, reps + 1)]
             for b in ["build", "build-system"]}
    a, s = load("build", 1), load("build-system", 1)
    same = all(a.get(k) == s.get(k) for k in keys)
    fast, slow = max(speed["build"]), max(speed["build-system"])
    print(f"| {model} | {slow:.1f} | {fast:.1f} | {fast / slow:.2f}x | {'identical' if same else 'differ: ' + ', '.join(f'{k} {s.get(k)} vs {a.get(k)}' for k in keys if a.get(k) != s.get(k))} |")
PY
