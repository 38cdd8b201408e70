"""Reading rockroll's CSV files and drawing their columns, with the sidecar that
records what was drawn (see the package docstring)."""
import csv
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


class BadInput(Exception):
    """A file that is not the rockroll output it should be (exit 2)."""


def read_csv(path):
    """Header and rows (dicts) of a CSV file; refuses a file whose rows do not match its header."""
    try:
        with open(path, newline="") as f:
            records = list(csv.reader(f))
    except OSError as e:
        raise BadInput(f"{path}: cannot read: {e.strerror}") from e
    if not records:
        raise BadInput(f"{path}: empty CSV")
    header = records[0]
    if len(set(header)) != len(header):
        raise BadInput(f"{path}: repeated column names {header}")
    rows = []
    for n, rec in enumerate(records[1:], start=2):
        if len(rec) != len(header):
            raise BadInput(f"{path}: line {n} has {len(rec)} fields, header has {len(header)}")
        rows.append(dict(zip(header, rec)))
    return header, rows


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except OSError as e:
        raise BadInput(f"{path}: cannot read: {e.strerror}") from e
    except ValueError as e:
        raise BadInput(f"{path}: not JSON: {e}") from e


def select(rows, where):
    """The rows whose cells equal every value of `where` (column -> CSV text)."""
    return [r for r in rows if all(r[k] == v for k, v in where.items())]


def drawable(rows, where, x, y):
    """The rows plot_csv draws: those matching `where` with a number in both x and y
    (an empty cell, e.g. a failed sweep point or a channel the model lacks, is skipped)."""
    return [r for r in select(rows, where) if r[x] != "" and r[y] != ""]


def _number(path, row, name):
    try:
        return float(row[name])
    except ValueError as e:
        raise BadInput(f"{path}: column {name} holds {row[name]!r}, expected a number") from e


# Lines and markers drawn from data, per figure, for the sidecar written by save().
_drawn = {}
_marked = {}


def plot_csv(ax, csv_file, rows, where, x, y, xscale=1.0, yscale=1.0, **style):
    """Draws column y against column x of the rows of csv_file matching `where`
    (column -> CSV text), skipping rows with an empty x or y cell."""
    for name in (x, y, *where):
        if rows and name not in rows[0]:
            raise BadInput(f"{csv_file}: no column {name}")
    pts = drawable(rows, where, x, y)
    (line,) = ax.plot([_number(csv_file, r, x) * xscale for r in pts],
                      [_number(csv_file, r, y) * yscale for r in pts], **style)
    _drawn.setdefault(id(ax.figure), []).append(
        {"line": line, "csv": csv_file, "where": where, "x": x, "y": y, "x_scale": xscale, "y_scale": yscale})
    return line


def mark_x(ax, x, source, **style):
    """A vertical line at x taken from a JSON file (source: {"json": file, "key": ..., "index": ...}),
    recorded in the sidecar's markers."""
    ax.axvline(x, **style)
    _marked.setdefault(id(ax.figure), []).append(dict(source, x=x))


def save(fig, path, formats=("png",)):
    """Writes the figure as PATH (a .png) and, with "svg" in formats, PATH's .svg
    twin, then the sidecar PATH.json; each through a temporary name."""
    stem = path[: -len(".png")]
    for ext in formats:
        fig.savefig(f"{stem}.tmp.{ext}", dpi=110, bbox_inches="tight", format=ext)
    lines = []
    for d in _drawn.pop(id(fig), []):
        xd, yd = d["line"].get_xdata(), d["line"].get_ydata()
        n = len(xd)
        picks = sorted({0, n // 4, n // 2, (3 * n) // 4, n - 1}) if n else []
        lines.append({"csv": d["csv"], "where": d["where"], "x": d["x"], "y": d["y"], "x_scale": d["x_scale"],
                      "y_scale": d["y_scale"], "label": d["line"].get_label(), "points": n,
                      "samples": [{"index": i, "x": float(xd[i]), "y": float(yd[i])} for i in picks]})
    side = {"png": os.path.basename(path), "lines": lines}
    if "svg" in formats:
        side["svg"] = os.path.basename(stem + ".svg")
    markers = _marked.pop(id(fig), [])
    if markers:
        side["markers"] = markers
    plt.close(fig)
    with open(path + ".json.tmp", "w") as f:
        json.dump(side, f, indent=1)
    for ext in formats:
        os.replace(f"{stem}.tmp.{ext}", f"{stem}.{ext}")
    os.replace(path + ".json.tmp", path + ".json")


def finish(axes):
    """Grid on every panel."""
    for ax in axes:
        ax.grid(alpha=0.3)
