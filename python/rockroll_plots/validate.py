"""`rockroll validate`'s report figures: reads DIR/validation.json and the CSV files it
lists, writes PNGs (each with its sidecar, figures.save) beside them."""
import os

import matplotlib.pyplot as plt

from .figures import plot_csv, read_csv, read_json, save


def plot_time_histories(out, meta):
    runs = {t["model"]: (t["file"], read_csv(os.path.join(out, t["file"]))[1]) for t in meta.get("timehistories", [])}
    models = [m for m in ("fullcar", "halfcar", "reduced") if m in runs]
    if not models:  # the time-history section failed (reported in REPORT.md): nothing to draw
        return
    fig, axes = plt.subplots(5, len(models), figsize=(5 * len(models), 13), sharex=True, squeeze=False)
    for j, m in enumerate(models):
        f, r = runs[m]

        def draw(ax, y, yscale=1.0, **style):
            plot_csv(ax, f, r, {}, "t_s", y, yscale=yscale, **style)

        ax = axes[0][j]
        draw(ax, "roll_deg", label="roll [deg]")
        draw(ax, "cross_level_F_in", label="cross-level [in]", alpha=0.7)
        ax.set_title(f"{m}: 70-ton loaded, 0.75 in, 16.5 mph")
        ax.legend(loc="upper left", fontsize=8)
        draw(axes[1][j], "car_body_vertical_in")
        axes[1][j].set_ylabel("car body vertical [in]")
        draw(axes[2][j], "side_bearing_F_L_lb", 1e-3, label="left")
        draw(axes[2][j], "side_bearing_F_R_lb", 1e-3, label="right")
        axes[2][j].set_ylabel("side bearing [1000 lb]")
        axes[2][j].legend(fontsize=8)
        draw(axes[3][j], "wheel_lift_F1_L_in", label="left")
        draw(axes[3][j], "wheel_lift_F1_R_in", label="right")
        axes[3][j].set_ylabel("wheel lift [in]")
        draw(axes[4][j], "wheels_F_L_lb", 1e-3, label="left")
        draw(axes[4][j], "wheels_F_R_lb", 1e-3, label="right")
        axes[4][j].set_ylabel("wheel force, 2 wheels [1000 lb]")
        axes[4][j].set_xlabel("time [s]")
    for row in axes:
        for ax in row:
            ax.grid(alpha=0.3)
    save(fig, os.path.join(out, "timehistory.png"))


def plot_sweeps(out, meta):
    by_key = {}
    for s in meta.get("sweeps", []):
        by_key.setdefault(s["key"], []).append(s)
    for key, sweeps in by_key.items():
        fig, ax = plt.subplots(figsize=(7, 4.5))
        figl, axl = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
        for k, s in enumerate(sweeps):
            _, rows = read_csv(os.path.join(out, s["file"]))
            color = f"C{k}"
            for direction, marker in (("up", "^"), ("down", "v")):
                where = {"direction": direction, "failed": "0"}
                style = dict(marker=marker, color=color, linestyle="-" if direction == "up" else "--")
                plot_csv(ax, s["file"], rows, where, "speed_mph", "steady_roll_amplitude_deg",
                         label=f"{s['model']} {direction} (steady amplitude)", **style)
                plot_csv(axl[0], s["file"], rows, where, "speed_mph", "max_wheel_lift_in",
                         label=f"{s['model']} {direction}", **style)
                plot_csv(axl[1], s["file"], rows, where, "speed_mph", "max_wheel_load_lb", yscale=1e-3, **style)
                plot_csv(axl[2], s["file"], rows, where, "speed_mph", "max_side_bearing_load_lb", yscale=1e-3, **style)
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


# The steady CSV's `stable` column: yes | no | not computed.
STABILITY_STYLE = {"yes": ("-", "describing function, stable"),
                   "no": ("--", "describing function, unstable"),
                   "not computed": (":", "describing function (stability not computed)")}


def plot_steady(out, meta):
    sweeps = {}
    for s in meta.get("sweeps", []):
        sweeps.setdefault(s["key"], []).append(s)
    for st in meta.get("steady", []):
        _, rows = read_csv(os.path.join(out, st["file"]))
        fig, ax = plt.subplots(figsize=(7, 4.5))
        labelled = set()
        for b in sorted({r["branch"] for r in rows}, key=int):
            states = {r["stable"] for r in rows if r["branch"] == b}
            if len(states) != 1 or not states <= STABILITY_STYLE.keys():
                raise ValueError(f"{st['file']}: branch {b} has stability {sorted(states)}")
            style, label = STABILITY_STYLE[states.pop()]
            plot_csv(ax, st["file"], rows, {"branch": b}, "speed_mph", "roll_amplitude_deg", color="k",
                     linestyle=style, linewidth=1.5, label=None if label in labelled else label)
            labelled.add(label)
        for k, s in enumerate(sweeps.get(st["sweep_key"], [])):
            _, srows = read_csv(os.path.join(out, s["file"]))
            for direction, marker in (("up", "^"), ("down", "v")):
                plot_csv(ax, s["file"], srows, {"direction": direction, "failed": "0"}, "speed_mph",
                         "steady_roll_amplitude_deg", marker=marker, linestyle="none", color=f"C{k}",
                         label=f"{s['model']} sweep {direction}")
        # Periodic orbits of the time-domain models (section 11), filled where stable.
        for orb in (o for o in meta.get("orbits", []) if o["key"] == st["sweep_key"]):
            _, orows = read_csv(os.path.join(out, orb["file"]))
            marker, color = {"eom": ("o", "C3"), "halfcar": ("s", "C4")}.get(orb["model"], ("D", "C5"))
            for stable, fill in (("yes", "full"), ("no", "none")):
                plot_csv(ax, orb["file"], orows, {"converged": "1", "stable": stable}, "speed_mph",
                         "roll_amplitude_deg", marker=marker, linestyle="none", color=color,
                         fillstyle=fill, markersize=5,
                         label=f"{orb['model']} periodic orbit, {'stable' if stable == 'yes' else 'unstable'}")
        # Figure 31 holds every amplitude; Figure 34 compares the 0.75 in case alone (report §4.3).
        figs = "Figs 31, 34" if abs(st["amplitude_in"] - 0.75) < 1e-9 else "Fig. 31"
        ax.set_title(f"70-ton loaded, {st['amplitude_in']:.2f} in: describing function over the sweeps ({figs})")
        ax.set_xlabel("speed [mph]")
        ax.set_ylabel("roll amplitude [deg]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
        save(fig, os.path.join(out, st["file"].replace(".csv", ".png")))


def plot_validation(out):
    meta = read_json(os.path.join(out, "validation.json"))
    plot_time_histories(out, meta)
    plot_sweeps(out, meta)
    plot_steady(out, meta)
