#!/usr/bin/python3
"""Plots for `rockroll validate`: reads results/validation.json and the CSV files
it lists, writes PNGs beside them. Run with Debian's /usr/bin/python3
(python3-matplotlib)."""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return rows


def column(rows, name):
    return [float(r[name]) for r in rows if r.get(name, "") != ""]


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)


def plot_time_histories(out, meta):
    runs = {t["model"]: read_csv(os.path.join(out, t["file"])) for t in meta.get("timehistories", [])}
    models = [m for m in ("fullcar", "halfcar", "reduced") if m in runs]
    fig, axes = plt.subplots(5, len(models), figsize=(5 * len(models), 13), sharex=True, squeeze=False)
    for j, m in enumerate(models):
        r = runs[m]
        t = column(r, "t_s")
        ax = axes[0][j]
        ax.plot(t, column(r, "roll_deg"), label="roll [deg]")
        ax.plot(t, column(r, "cross_level_F_in"), label="cross-level [in]", alpha=0.7)
        ax.set_title(f"{m}: 70-ton loaded, 0.75 in, 16.5 mph")
        ax.legend(loc="upper left", fontsize=8)
        axes[1][j].plot(t, column(r, "car_body_vertical_in"))
        axes[1][j].set_ylabel("car body vertical [in]")
        axes[2][j].plot(t, [v / 1000 for v in column(r, "side_bearing_F_L_lb")], label="left")
        axes[2][j].plot(t, [v / 1000 for v in column(r, "side_bearing_F_R_lb")], label="right")
        axes[2][j].set_ylabel("side bearing [1000 lb]")
        axes[2][j].legend(fontsize=8)
        axes[3][j].plot(t, column(r, "wheel_lift_F1_L_in"), label="left")
        axes[3][j].plot(t, column(r, "wheel_lift_F1_R_in"), label="right")
        axes[3][j].set_ylabel("wheel lift [in]")
        axes[4][j].plot(t, [v / 1000 for v in column(r, "wheels_F_L_lb")], label="left")
        axes[4][j].plot(t, [v / 1000 for v in column(r, "wheels_F_R_lb")], label="right")
        axes[4][j].set_ylabel("wheel force, 2 wheels [1000 lb]")
        axes[4][j].set_xlabel("time [s]")
    for row in axes:
        for ax in row:
            ax.grid(alpha=0.3)
    save(fig, os.path.join(out, "timehistory.png"))


def split(rows, direction):
    return [r for r in rows if r["direction"] == direction and r["failed"] == "0"]


def plot_sweeps(out, meta):
    by_key = {}
    for s in meta.get("sweeps", []):
        by_key.setdefault(s["key"], []).append(s)
    for key, sweeps in by_key.items():
        fig, ax = plt.subplots(figsize=(7, 4.5))
        figl, axl = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
        for k, s in enumerate(sweeps):
            rows = read_csv(os.path.join(out, s["file"]))
            color = f"C{k}"
            for direction, marker in (("up", "^"), ("down", "v")):
                d = split(rows, direction)
                v = column(d, "speed_mph")
                ax.plot(v, column(d, "steady_roll_amplitude_deg"), marker=marker, color=color,
                        linestyle="-" if direction == "up" else "--",
                        label=f"{s['model']} {direction} (steady amplitude)")
                axl[0].plot(v, column(d, "max_wheel_lift_in"), marker=marker, color=color,
                            linestyle="-" if direction == "up" else "--", label=f"{s['model']} {direction}")
                axl[1].plot(v, [x / 1000 for x in column(d, "max_wheel_load_lb")], marker=marker, color=color,
                            linestyle="-" if direction == "up" else "--")
                axl[2].plot(v, [x / 1000 for x in column(d, "max_side_bearing_load_lb")], marker=marker, color=color,
                            linestyle="-" if direction == "up" else "--")
            up, down = s.get("jump_up_mph"), s.get("jump_down_mph")
            if up is not None:
                ax.axvline(up, color=color, alpha=0.5, linestyle=":")
            if down is not None:
                ax.axvline(down, color=color, alpha=0.5, linestyle=":")
            if up is not None and down is not None and down < up:
                ax.axvspan(down, up, color=color, alpha=0.08, label=f"{s['model']} hysteresis band")
        car, amp = sweeps[0]["car"], sweeps[0]["amplitude_in"]
        ax.set_title(f"{car}, {amp:.2f} in: roll against speed (report Fig. {sweeps[0]['figure']})")
        ax.set_xlabel("speed [mph]")
        ax.set_ylabel("steady roll amplitude [deg]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
        save(fig, os.path.join(out, f"sweep_{key}.png"))
        axl[0].set_title(f"{car}, {amp:.2f} in: wheel lift and maximum loads against speed")
        axl[0].set_ylabel("max wheel lift [in]")
        axl[1].set_ylabel("max wheel load [1000 lb]")
        axl[2].set_ylabel("max side bearing [1000 lb]")
        axl[2].set_xlabel("speed [mph]")
        axl[0].legend(fontsize=7)
        for a in axl:
            a.grid(alpha=0.3)
        save(figl, os.path.join(out, f"sweep_loads_{key}.png"))


def plot_steady(out, meta):
    sweeps = {}
    for s in meta.get("sweeps", []):
        sweeps.setdefault(s["key"], []).append(s)
    for st in meta.get("steady", []):
        rows = read_csv(os.path.join(out, st["file"]))
        fig, ax = plt.subplots(figsize=(7, 4.5))
        branches = {}
        for r in rows:
            branches.setdefault(int(r["branch"]), []).append(r)
        stable_key = [k for k in rows[0].keys() if k.startswith("stable")][0] if rows else "stable"
        labelled = set()
        for b, pts in sorted(branches.items()):
            state = pts[0][stable_key]
            style, label = {"1": ("-", "describing function, stable"), "0": ("--", "describing function, unstable")}.get(
                state, (":", "describing function (stability not computed)"))
            ax.plot(column(pts, "speed_mph"), column(pts, "roll_amplitude_deg"), color="k", linestyle=style,
                    linewidth=1.5, label=None if label in labelled else label)
            labelled.add(label)
        for k, s in enumerate(sweeps.get(st["sweep_key"], [])):
            srows = read_csv(os.path.join(out, s["file"]))
            for direction, marker in (("up", "^"), ("down", "v")):
                d = split(srows, direction)
                ax.plot(column(d, "speed_mph"), column(d, "steady_roll_amplitude_deg"), marker=marker,
                        linestyle="none", color=f"C{k}", label=f"{s['model']} sweep {direction}")
        ax.set_title(f"70-ton loaded, {st['amplitude_in']:.2f} in: describing function over the sweeps (Figs 31, 34)")
        ax.set_xlabel("speed [mph]")
        ax.set_ylabel("roll amplitude [deg]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
        save(fig, os.path.join(out, st["file"].replace(".csv", ".png")))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "results"
    with open(os.path.join(out, "validation.json")) as f:
        meta = json.load(f)
    plot_time_histories(out, meta)
    plot_sweeps(out, meta)
    plot_steady(out, meta)


if __name__ == "__main__":
    main()
