"""`rockroll plot DIR`: the plots of one output directory of `rockroll run`, `sweep`,
`steady`, `modes`, `study` or `orbits`, each as PNG and SVG with its sidecar (figures.save).
The kind of output is told by the files it holds (KINDS)."""
import math
import os
import re

import matplotlib.pyplot as plt

from .figures import BadInput, finish, mark_x, plot_csv, read_csv, read_json, save

# The files each kind of output directory holds, in the order they are looked for.
KINDS = (("run", ("history.csv", "summary.json")), ("sweep", ("sweep.csv", "sweep.json")),
         ("steady", ("steady.csv", "steady.json")), ("modes", ("modes.csv", "modes.json")),
         ("study", ("study.csv", "study.json")), ("orbits", ("orbits.csv", "orbits.json")))
FORMATS = ("png", "svg")
KLB = 1e-3  # lb -> 1000 lb on the axes


def find_kind(out):
    """The kind of output in `out`; BadInput naming the files looked for when it is none."""
    if not os.path.isdir(out):
        raise BadInput(f"{out}: not a directory")
    for kind, files in KINDS:
        if all(os.path.isfile(os.path.join(out, f)) for f in files):
            return kind
    expected = "; ".join(f"{kind}: {' and '.join(files)}" for kind, files in KINDS)
    raise BadInput(f"{out} is not a rockroll output directory: it holds none of these pairs of files ({expected})")


def _matching(header, pattern):
    """The columns matching a regular expression, in CSV order, with its groups."""
    return [(c, m.groups()) for c in header for m in [re.fullmatch(pattern, c)] if m]


def _need(header, csv_file, columns):
    """BadInput naming the first of `columns` the CSV lacks."""
    for c in columns:
        if c not in header:
            raise BadInput(f"{csv_file}: no column {c}")


def _write(fig, dest, name):
    """The figure as dest/name (PNG) and its SVG twin, with the sidecar."""
    os.makedirs(dest, exist_ok=True)
    save(fig, os.path.join(dest, name), FORMATS)


def _require(header, pattern, what, csv_file):
    cols = _matching(header, pattern)
    if not cols:
        raise BadInput(f"{csv_file}: no {what} column (expected a name matching {pattern})")
    return cols


def plot_run(out, dest):
    """Time histories, one column of panels per truck: roll (with the truck's
    cross-level), every wheel's load (each truck side's pair where the model has no
    single wheels), side bearings, center plate, wheel lift."""
    f = "history.csv"
    header, rows = read_csv(os.path.join(out, f))
    summary = read_json(os.path.join(out, "summary.json"))
    if "t_s" not in header:
        raise BadInput(f"{f}: no column t_s")
    trucks = [g[0] for _, g in _require(header, r"center_plate_([A-Z])_lb", "center-plate", f)]
    _require(header, r"roll_deg", "roll", f)
    fig, axes = plt.subplots(5, len(trucks), figsize=(6 * len(trucks), 14), sharex=True, squeeze=False)
    for j, t in enumerate(trucks):
        col = [axes[i][j] for i in range(5)]

        def draw(ax, y, yscale=1.0, **style):
            plot_csv(ax, f, rows, {}, "t_s", y, yscale=yscale, **style)

        draw(col[0], "roll_deg", label="car-body roll [deg]")
        for c, _ in _matching(header, rf"cross_level_{t}_in"):
            draw(col[0], c, label=f"cross-level, truck {t} [in]", alpha=0.7)
        col[0].set_title(f"truck {t}")
        wheels = _matching(header, rf"wheel_{t}(\d+)_([LR])_lb")
        if wheels:
            for c, (n, side) in wheels:
                draw(col[1], c, KLB, label=f"wheel {t}{n} {side}")
            col[1].set_ylabel("wheel load [1000 lb]")
        else:
            for c, (side,) in _require(header, rf"wheels_{t}_([LR])_lb", f"truck {t} wheel-load", f):
                draw(col[1], c, KLB, label=f"wheels {t} {side} (one truck side)")
            col[1].set_ylabel("wheel load, 2 wheels [1000 lb]")
        for c, (side,) in _require(header, rf"side_bearing_{t}_([LR])_lb", f"truck {t} side-bearing", f):
            draw(col[2], c, KLB, label=f"side bearing {t} {side}")
        col[2].set_ylabel("side bearing [1000 lb]")
        draw(col[3], f"center_plate_{t}_lb", KLB, label=f"center plate {t}")
        col[3].set_ylabel("center plate [1000 lb]")
        for c, (n, side) in _require(header, rf"wheel_lift_{t}(\d+)_([LR])_in", f"truck {t} wheel-lift", f):
            draw(col[4], c, label=f"wheel {t}{n} {side}")
        col[4].set_ylabel("wheel lift [in]")
        col[4].set_xlabel("time [s]")
        for ax in col:
            ax.legend(fontsize=7, loc="upper left")
        finish(col)
    amp = summary.get("amplitude_in")
    track = f"{amp:.2f} in" if isinstance(amp, (int, float)) else "measured track"
    fig.suptitle(f"{summary.get('model', '?')} model, {summary.get('car', '?')}, {track}, "
                 f"{summary.get('speed_mph', float('nan')):.1f} mph")
    _write(fig, dest, "timehistory.png")


def _same_number(cell, value):
    """A CSV cell against a JSON value: both empty/null, or the same number (to 1e-9)."""
    if value is None or cell == "":
        return value is None and cell == ""
    return math.isclose(float(cell), float(value), rel_tol=1e-9)  # a failed point's amplitude is not rounded


def plot_sweep(out, dest):
    """Roll against speed, up and down, for each car, model and amplitude of the sweep,
    with the jump speeds of sweep.json marked; and the maximum loads against speed."""
    f = "sweep.csv"
    header, rows = read_csv(os.path.join(out, f))
    doc = read_json(os.path.join(out, "sweep.json"))
    if not isinstance(doc, dict) or not isinstance(doc.get("jumps"), list):
        raise BadInput("sweep.json: no \"jumps\" list (written by rockroll sweep --out)")
    _need(header, f, ("car", "model", "amplitude_in", "direction", "failed", "speed_mph", "steady_roll_amplitude_deg",
                  "max_roll_deg", "max_wheel_lift_in", "max_wheel_load_lb", "max_side_bearing_load_lb"))
    groups = []
    for r in rows:
        if r["failed"] != "false":
            continue  # drawn from no group (a failed point's amplitude_in is not rounded as the others')
        g = (r["car"], r["model"], r["amplitude_in"])
        if g not in groups:
            groups.append(g)
    fig, (ax, axm) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    figl, axl = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    for k, (car, model, amp) in enumerate(groups):
        color = f"C{k}"
        name = f"{model}, {car}, " + (f"{float(amp):.2f} in" if amp else "measured track")
        for direction, marker in (("up", "^"), ("down", "v")):
            where = {"car": car, "model": model, "amplitude_in": amp, "direction": direction, "failed": "false"}
            if not any(r["direction"] == direction for r in rows if (r["car"], r["model"], r["amplitude_in"]) == (car, model, amp)):
                continue
            style = dict(marker=marker, color=color, linestyle="-" if direction == "up" else "--")
            plot_csv(ax, f, rows, where, "speed_mph", "steady_roll_amplitude_deg", label=f"{name} {direction}", **style)
            plot_csv(axm, f, rows, where, "speed_mph", "max_roll_deg", **style)
            plot_csv(axl[0], f, rows, where, "speed_mph", "max_wheel_lift_in", label=f"{name} {direction}", **style)
            plot_csv(axl[1], f, rows, where, "speed_mph", "max_wheel_load_lb", yscale=KLB, **style)
            plot_csv(axl[2], f, rows, where, "speed_mph", "max_side_bearing_load_lb", yscale=KLB, **style)
        for i, jmp in enumerate(doc["jumps"]):
            if (jmp.get("car"), jmp.get("model")) != (car, model) or not _same_number(amp, jmp.get("amplitude_in")):
                continue
            speed = jmp.get("jump_speed_mph")
            if speed is None:
                continue
            style = dict(color=color, alpha=0.6, linestyle=":" if jmp["direction"] == "up" else "-.")
            for a in (ax, axm):
                mark_x(a, speed, {"json": "sweep.json", "key": "jumps", "index": i, "field": "jump_speed_mph"},
                       label=f"{name} jump {jmp['direction']} {speed:g} mph" if a is ax else None, **style)
    ax.set_title("roll against speed (jump speeds dotted: up, dash-dotted: down)")
    ax.set_ylabel("steady roll amplitude [deg]")
    axm.set_ylabel("max roll [deg]")
    axm.set_xlabel("speed [mph]")
    ax.legend(fontsize=7)
    finish([ax, axm])
    _write(fig, dest, "sweep_roll.png")
    axl[0].set_title("wheel lift and maximum loads against speed")
    axl[0].set_ylabel("max wheel lift [in]")
    axl[1].set_ylabel("max wheel load [1000 lb]")
    axl[2].set_ylabel("max side bearing [1000 lb]")
    axl[2].set_xlabel("speed [mph]")
    axl[0].legend(fontsize=7)
    finish(axl)
    _write(figl, dest, "sweep_loads.png")


# steady.csv's `stability` column (app/CommandResults.cpp makeSteadyJson).
STEADY_STYLE = {"stable": "-", "unstable": "--", "not computed": ":"}


def plot_steady(out, dest):
    """The describing function's roll amplitude and wheel-lift fraction against speed,
    one line per branch, its style by the branch's stability."""
    f = "steady.csv"
    header, rows = read_csv(os.path.join(out, f))
    doc = read_json(os.path.join(out, "steady.json"))
    _need(header, f, ("branch", "stability", "speed_mph", "roll_amplitude_deg", "wheel_lift_fraction"))
    fig, (ax, axl) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    labelled = set()
    for b in sorted({r["branch"] for r in rows}, key=int):
        states = {r["stability"] for r in rows if r["branch"] == b}
        if len(states) != 1 or not states <= STEADY_STYLE.keys():
            raise BadInput(f"{f}: branch {b} has stability {sorted(states)}, expected one of {sorted(STEADY_STYLE)}")
        state = states.pop()
        label = None if state in labelled else state
        labelled.add(state)
        for a, y in ((ax, "roll_amplitude_deg"), (axl, "wheel_lift_fraction")):
            plot_csv(a, f, rows, {"branch": b}, "speed_mph", y, color="k", linestyle=STEADY_STYLE[state],
                     label=label if a is ax else None)
    amp = doc.get("amplitude_in")
    ax.set_title(f"describing function, {doc.get('car', '?')}" + (f", {amp:.2f} in" if isinstance(amp, (int, float)) else ""))
    ax.set_ylabel("roll amplitude [deg]")
    axl.set_ylabel("wheel-lift fraction")
    axl.set_xlabel("speed [mph]")
    ax.legend(fontsize=8)
    finish([ax, axl])
    _write(fig, dest, "steady.png")


def plot_modes(out, dest):
    """Each mode's damping ratio against its frequency (named), and its frequency
    against the report's Table 1 uncoupled estimate where it has one."""
    f = "modes.csv"
    header, rows = read_csv(os.path.join(out, f))
    doc = read_json(os.path.join(out, "modes.json"))
    _need(header, f, ("name", "frequency_hz", "damping_ratio", "table1_formula_hz"))
    fig, (ax, axt) = plt.subplots(1, 2, figsize=(13, 5.5))
    plot_csv(ax, f, rows, {}, "frequency_hz", "damping_ratio", marker="o", linestyle="none", color="C0")
    for r in rows:
        ax.annotate(r["name"], (float(r["frequency_hz"]), float(r["damping_ratio"])), fontsize=7,
                    xytext=(3, 3), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("damping ratio")
    ax.set_title(f"{doc.get('model', '?')} model, {doc.get('car', '?')}: modes")
    line = plot_csv(axt, f, rows, {}, "table1_formula_hz", "frequency_hz", marker="o", linestyle="none", color="C1",
                    label="model against Table 1 formula")
    xs = [v for v in line.get_xdata()] + [v for v in line.get_ydata()]
    if xs:
        lo, hi = min(xs), max(xs)
        axt.plot([lo, hi], [lo, hi], color="k", alpha=0.4, linewidth=0.8, label="equal")
    axt.set_xscale("log")
    axt.set_yscale("log")
    axt.set_xlabel("Table 1 uncoupled estimate [Hz]")
    axt.set_ylabel("model frequency [Hz]")
    axt.legend(fontsize=8)
    finish([ax, axt])
    _write(fig, dest, "modes.png")


# The responses a study plot draws against each varied parameter, where study.csv has them.
STUDY_RESPONSES = (("max_roll_deg", 1.0, "max roll [deg]"),
                   ("peak_to_peak_roll_deg", 1.0, "peak-to-peak roll [deg]"),
                   ("steady_roll_amplitude_deg", 1.0, "steady roll amplitude [deg]"),
                   ("max_wheel_lift_in", 1.0, "max wheel lift [in]"),
                   ("max_wheel_unloading", 1.0, "max wheel unloading"),
                   ("max_side_bearing_load_lb", KLB, "max side bearing [1000 lb]"),
                   ("max_l_over_v", 1.0, "max L/V"))
STUDY_STATUS_STYLE = {"ok": dict(marker="o"), "derailed": dict(marker="x", linestyle="none", markersize=9),
                      "overturned": dict(marker="X", linestyle="none", markersize=9)}


def _monotonic(values):
    return all(a <= b for a, b in zip(values, values[1:])) or all(a >= b for a, b in zip(values, values[1:]))


def plot_study(out, dest):
    """For each varied parameter (study.json "varied"), the responses against it: one
    line per combination of the other varied values (ok points), derailed and
    overturned points as crosses; failed points have no response and are not drawn."""
    f = "study.csv"
    header, rows = read_csv(os.path.join(out, f))
    doc = read_json(os.path.join(out, "study.json"))
    varied = doc.get("varied") if isinstance(doc, dict) else None
    if not isinstance(varied, list) or not varied:
        raise BadInput("study.json: no \"varied\" list of {key, column, unit, values}")
    _need(header, f, ("point", "status"))
    columns = []
    for v in varied:
        if not isinstance(v, dict) or v.get("column") not in header:
            raise BadInput(f"study.json: varied entry {v!r} names no column of {f}")
        columns.append(v)
    for r in rows:
        if r["status"] not in STUDY_STATUS_STYLE and r["status"] != "failed":
            raise BadInput(f"{f}: point {r['point']} has status {r['status']!r}, "
                           f"expected one of ok, failed, derailed, overturned")
    responses = [(y, s, lab) for y, s, lab in STUDY_RESPONSES if y in header and any(r[y] != "" for r in rows)]
    if not responses:
        raise BadInput(f"{f}: none of the response columns {[y for y, _, _ in STUDY_RESPONSES]}")
    for v in columns:
        x = v["column"]
        others = [o["column"] for o in columns if o is not v]
        combos = []
        for r in rows:
            c = tuple(r[o] for o in others)
            if c not in combos:
                combos.append(c)
        fig, axes = plt.subplots(len(responses), 1, figsize=(8, 2.6 * len(responses) + 1), sharex=True, squeeze=False)
        axes = [a[0] for a in axes]
        for k, combo in enumerate(combos):
            base = dict(zip(others, combo))
            name = ", ".join(f"{o} = {val}" for o, val in base.items()) or "all points"
            for status, style in STUDY_STATUS_STYLE.items():
                where = dict(base, status=status)
                if not any(r["status"] == status for r in rows if all(r[o] == val for o, val in base.items())):
                    continue
                for a, (y, scale, _) in zip(axes, responses):
                    xs = [float(r[x]) for r in rows if all(r[c] == val for c, val in where.items()) and r[x] != "" and r[y] != ""]
                    line_style = dict(style)
                    if status == "ok" and not _monotonic(xs):
                        line_style["linestyle"] = "none"  # points in no order along x: markers only
                    plot_csv(a, f, rows, where, x, y, yscale=scale, color=f"C{k % 10}",
                             label=(f"{name} ({status})" if status != "ok" else name) if a is axes[0] else None,
                             **line_style)
        for a, (_, _, lab) in zip(axes, responses):
            a.set_ylabel(lab)
        axes[0].set_title(f"study: responses against {v.get('key', x)}")
        axes[-1].set_xlabel(f"{v.get('key', x)} [{v.get('unit', '')}]")
        axes[0].legend(fontsize=7)
        finish(axes)
        safe = re.sub(r"[^A-Za-z0-9_.-]", "_", x)
        _write(fig, dest, f"study_{safe}.png")


def plot_orbits(out, dest):
    """The periodic orbits' roll amplitude and largest multiplier modulus against speed,
    filled where stable, open where not; points that did not converge draw nothing."""
    f = "orbits.csv"
    header, rows = read_csv(os.path.join(out, f))
    doc = read_json(os.path.join(out, "orbits.json"))
    _need(header, f, ("speed_mph", "converged", "roll_amplitude_deg", "max_multiplier", "stable"))
    fig, (ax, axm) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for stable, fill in (("yes", "full"), ("no", "none")):
        for a, y in ((ax, "roll_amplitude_deg"), (axm, "max_multiplier")):
            plot_csv(a, f, rows, {"converged": "true", "stable": stable}, "speed_mph", y, color="k", marker="o",
                     linestyle="none", fillstyle=fill,
                     label=("stable" if stable == "yes" else "unstable") if a is ax else None)
    axm.axhline(1.0, color="0.5", linewidth=0.8)
    amp = doc.get("amplitude_in")
    ax.set_title(f"periodic orbits, {doc.get('model', '?')}, {doc.get('car', '?')}"
                 + (f", {amp:.2f} in" if isinstance(amp, (int, float)) else "") + f": {doc.get('stop_reason', '')}")
    ax.set_ylabel("roll amplitude [deg]")
    axm.set_ylabel("largest |multiplier|")
    axm.set_xlabel("speed [mph]")
    ax.legend(fontsize=8)
    finish([ax, axm])
    _write(fig, dest, "orbits.png")


PLOTTERS = {"run": plot_run, "sweep": plot_sweep, "steady": plot_steady, "modes": plot_modes, "study": plot_study,
            "orbits": plot_orbits}


def plot_output(out, dest):
    """Plots the output directory `out` into `dest`; returns its kind."""
    kind = find_kind(out)
    PLOTTERS[kind](out, dest)
    return kind
