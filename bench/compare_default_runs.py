#!/usr/bin/python3
"""Compares default-case run summaries with results/validation.json's defaultRuns.

    bench/compare_default_runs.py SUMMARY.json [SUMMARY.json ...]

Each SUMMARY.json is the output of `rockroll run --json` (or an --out directory's
summary.json) of the default case (scenarios/70ton-loaded.toml, 20 s). Every field the
stored default run of the same model has (except wall_time_s) is compared: "identical"
means equal as read from JSON; otherwise the relative change is printed. Exit 1 if any
field differs.
"""
import json
import sys
from pathlib import Path

IGNORED = {"wall_time_s"}


def main(paths):
    stored = json.loads((Path(__file__).resolve().parent.parent / "results/validation.json").read_text())
    by_model = {r["model"]: r for r in stored["defaultRuns"]}
    changed = 0
    for p in paths:
        run = json.loads(Path(p).read_text())
        ref = by_model[run["model"]]
        diffs = []
        for key, want in ref.items():
            if key in IGNORED:
                continue
            got = run.get(key, "<missing>")
            if got != want:
                rel = ""
                if isinstance(got, (int, float)) and isinstance(want, (int, float)) and want:
                    rel = f" ({100 * (got - want) / abs(want):+.4g} %)"
                diffs.append(f"{key}: {want} -> {got}{rel}")
        compared = len([k for k in ref if k not in IGNORED])
        if diffs:
            changed += 1
            print(f"{run['model']}: {len(diffs)} of {compared} fields differ")
            for d in diffs:
                print("  " + d)
        else:
            print(f"{run['model']}: identical in all {compared} fields")
    return 1 if changed else 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1:]))
