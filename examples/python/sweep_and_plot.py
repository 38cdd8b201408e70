#!/usr/bin/python3
"""A small speed sweep of the 70-ton loaded car (reduced model, up and down, state carried
from speed to speed), plotted as peak-to-peak roll against speed: the jump resonance.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/sweep_and_plot.py sweep.png

Writes the PNG to the path given; prints one line per point.
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import rockroll  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main(argv):
    if len(argv) != 2:
        print(f"usage: {argv[0]} OUTPUT.png", file=sys.stderr)
        return 2
    out = pathlib.Path(argv[1])
    scenario = rockroll.load(ROOT / "scenarios" / "70ton-loaded.toml", model="reduced")
    points = rockroll.sweep(scenario, from_mph=13, to_mph=19, step_mph=1, amplitude_in=0.75, duration_s=4)

    fig, ax = plt.subplots(figsize=(6, 4))
    for direction, marker in (("up", "o-"), ("down", "s--")):
        done = [p for p in points if p["direction"] == direction and not p["failed"]]
        ax.plot([p["speed_mph"] for p in done], [p["peak_to_peak_roll_deg"] for p in done], marker, label=direction)
        for p in done:
            print(f"{direction:>4} {p['speed_mph']:5.1f} mph  peak-to-peak roll {p['peak_to_peak_roll_deg']:6.2f} deg  "
                  f"{p['regime']}")
    ax.set_xlabel("speed [mph]")
    ax.set_ylabel("peak-to-peak roll [deg]")
    ax.set_title(f"{scenario.car}, {scenario.amplitude_in:g} in cross-level, {points[0]['model']} model")
    ax.grid(True, alpha=0.3)
    ax.legend(title="sweep")
    fig.tight_layout()
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=100)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
