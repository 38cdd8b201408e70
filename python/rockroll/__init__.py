"""rockroll: freight-car rock and roll (Simbody and the 1976 report's methods), from Python.

    import rockroll
    sc = rockroll.load("scenarios/70ton-loaded.toml", side_bearing_clearance="0.25 in")
    result = rockroll.run(sc, model="halfcar", duration_s=2)
    result.summary["max_roll_deg"], result.history["roll_deg"], result.units["roll_deg"]

Everything goes through the library functions the command line uses, so a result is the
command line's result: ``run`` gives summary.json's content and history.csv's channels (in
full double precision), ``sweep``, ``steady`` and ``modes`` give what their ``--json``
prints. Model runs release the GIL: Python threads run them in parallel.

Errors: ``ScenarioError`` (a ValueError) for bad input, with the message the command line
prints; ``NumericalFailure`` (a RuntimeError, ``.time_s`` when it failed) for a run that
failed numerically.
"""

import numbers as _numbers
import os as _os

import numpy as _np

from ._rockroll import (  # noqa: F401  (re-exported)
    NumericalFailure,
    Scenario,
    ScenarioError,
    __version__,
    git_commit,
    scenario_keys,
    version_string,
)
from . import _rockroll

__all__ = [
    "load", "default_scenario", "from_summary", "run", "sweep", "steady", "orbits", "modes", "Result", "Scenario",
    "ScenarioError", "NumericalFailure", "scenario_keys", "__version__",
]

def _value_text(key, value):
    """An override's value as the text a scenario file or `--set KEY=VALUE` would give."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return value
    if isinstance(value, _numbers.Integral):
        return str(int(value))
    if isinstance(value, _numbers.Real):
        return repr(float(value))  # shortest text that reads back to the same double
    raise TypeError(f"override {key}={value!r}: expected a string (e.g. \"0.25 in\"), a number or a bool")


def _path(path):
    if isinstance(path, Scenario):
        raise TypeError("expected a scenario file path; this is already a Scenario")
    return _os.fspath(path)


def load(path, **overrides):
    """The scenario in the TOML file `path`, with `overrides` applied to the file's keys
    before it is read: the same keys and units as the file, e.g.
    ``side_bearing_clearance="0.25 in"``, ``speed="15 mph"``, ``accuracy=1e-5``. A key is
    a key of the file's schema (``rockroll.scenario_keys()``): its last part alone when it
    names exactly one key, or the full dotted key, e.g. ``**{"run.speed": "15 mph"}``.
    A string value is read as the file would read the same text after ``key =``, and as a
    string when it is not a TOML value ("0.25 in", "halfcar"). Bad keys or values raise
    ScenarioError with the file's message. The scenario records the overrides
    (``.overrides``; runs' provenance lists them)."""
    pairs = [(key, _value_text(key, value)) for key, value in overrides.items()]
    return _rockroll._load(_path(path), pairs)


def default_scenario():
    """The default case (70-ton loaded, 0.75 in, 16.5 mph, full car, 20 s), as `rockroll` runs it."""
    return _rockroll._default_scenario()


def from_summary(path):
    """The scenario a summary.json's provenance describes (as `rockroll run --from-summary`)."""
    return _rockroll._from_summary(_os.fspath(path))


def _scenario(scenario):
    return scenario if isinstance(scenario, Scenario) else load(scenario)


def _call(name, *args, **kwargs):
    """How the call is named in provenance ("command")."""
    shown = [repr(a) if not isinstance(a, Scenario) else f"<{a.source}>" for a in args]
    shown += [f"{k}={v!r}" for k, v in kwargs.items() if v is not None]
    return f"python rockroll.{name}({', '.join(shown)})"


class Result:
    """One run: ``summary`` (dict, summary.json's content, with provenance), ``history``
    (NumPy structured array, one field per channel named as in history.csv, e.g.
    ``roll_deg``, float64), ``channel_table`` (one dict per column, in order: ``name``,
    ``quantity``, ``unit``, ``roles``, ``truck``, as the model declares its channels,
    mbmodel/ChannelLayout.h), ``units`` (channel -> its unit from that table: 's', 'deg',
    'in', 'lb' (pound-force), 'J', 'g' (standard gravity), 'ratio', or '1' for a channel
    declared without one: the wedge slip flags, the reduced model's truck mode code and
    consistency flag; also each field's ``dtype.metadata["unit"]``), and ``stopped``
    ("derailed", "overturned" or None)."""

    def __init__(self, summary, names, data, stopped, channel_table):
        self.summary = summary
        if [c["name"] for c in channel_table] != list(names):
            raise RuntimeError("the history's columns are not the model's channel table")
        self.channel_table = channel_table
        self.units = {c["name"]: c["unit"] or "1" for c in channel_table}
        fields = [(n, _np.dtype(_np.float64, metadata={"unit": self.units[n]})) for n in names]
        dtype = _np.dtype(fields, metadata={"units": dict(self.units)})
        self.history = _np.ascontiguousarray(data).view(dtype).reshape(-1)
        self.stopped = stopped

    @property
    def channels(self):
        return list(self.history.dtype.names)

    def to_pandas(self):
        """The history as a pandas DataFrame (columns = channels, ``df.attrs["units"]``).
        Needs pandas, which rockroll itself does not."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError(
                "Result.to_pandas() needs pandas, which is not installed (apt-get install python3-pandas, "
                "or pip install pandas); Result.history is the same data as a NumPy structured array"
            ) from e
        frame = pandas.DataFrame({n: self.history[n] for n in self.history.dtype.names})
        frame.attrs["units"] = dict(self.units)
        return frame

    def __repr__(self):
        s = self.summary
        return (f"<rockroll.Result {s['model']} {s['car']} {s['speed_mph']:g} mph: max roll {s['max_roll_deg']:.3f} deg, "
                f"regime {s['regime']}, {len(self.history)} samples x {len(self.units)} channels>")


def run(scenario, model=None, speed_mph=None, duration_s=None, amplitude_in=None, max_wall_s=None):
    """Runs one scenario (a Scenario or a file path) like `rockroll run`: the options,
    when given, replace the scenario's own values. Returns a Result. A derailed or
    overturned car stops the run and is a result (``result.stopped``, summary's
    ``regime``), as the command line keeps its history (its exit 5)."""
    sc = _scenario(scenario)
    command = _call("run", sc, model=model, speed_mph=speed_mph, duration_s=duration_s,
                    amplitude_in=amplitude_in, max_wall_s=max_wall_s)
    out = _rockroll._run(sc, model, _float(speed_mph), _float(duration_s), _float(amplitude_in),
                         _float(max_wall_s), command)
    return Result(out["summary"], out["names"], out["data"], out["stop"], out["channels"])


def _float(v):
    return None if v is None else float(v)


def _choice(name, value, allowed):
    if value not in allowed:
        raise ValueError(f"{name}={value!r}: expected one of {', '.join(allowed)}")
    return value


def _positive(name, value):
    value = float(value)
    if not value > 0:
        raise ValueError(f"{name}={value!r}: expected a positive number")
    return value


def sweep(scenarios, from_mph, to_mph, step_mph, model=None, amplitude_in=None, direction="both",
          duration_s=None, jobs=0, max_wall_s=None, fresh=False):
    """Speed sweeps like `rockroll sweep`: for each scenario (one, or a list; Scenario or
    path), each amplitude (a number or a list; default the scenario's own) and each
    direction ("up", "down" or "both"), the speeds from_mph..to_mph by step_mph, each
    starting from the previous one's final state (``fresh=True``: from rest). Returns a
    list of dicts, one per point, as `rockroll sweep --json` prints them (``failed``
    points carry ``error``). Sweeps run on `jobs` threads (0: one per core)."""
    if isinstance(scenarios, (Scenario, str, _os.PathLike)):
        scenarios = [scenarios]
    scs = [_scenario(s) for s in scenarios]
    if amplitude_in is None:
        amplitudes = []
    elif isinstance(amplitude_in, _numbers.Real):
        amplitudes = [float(amplitude_in)]
    else:
        amplitudes = [float(a) for a in amplitude_in]
    for a in amplitudes:
        _positive("amplitude_in", a)
    _choice("direction", direction, ("up", "down", "both"))
    if int(jobs) < 0:
        raise ValueError(f"jobs={jobs!r}: expected 0 (one per core) or more")
    command = _call("sweep", *scs, from_mph=from_mph, to_mph=to_mph, step_mph=step_mph, model=model,
                    amplitude_in=amplitude_in, direction=direction, duration_s=duration_s, jobs=jobs,
                    max_wall_s=max_wall_s, fresh=fresh)
    return _rockroll._sweep(scs, model, amplitudes, _positive("from_mph", from_mph), _positive("to_mph", to_mph),
                            _positive("step_mph", step_mph), direction,
                            None if duration_s is None else _positive("duration_s", duration_s), int(jobs),
                            None if max_wall_s is None else _positive("max_wall_s", max_wall_s), bool(fresh),
                            command)


def steady(scenario, from_mph=10, to_mph=22, amplitude_in=None, stability="fold", twin_periods=5,
           sweep_starts=True):
    """The describing-function steady state against speed, like `rockroll steady --json`:
    a dict with the input, ``paths`` (each continuation and how it was started),
    ``stability_changes`` and ``branches`` (each with ``path``, ``stability`` and
    ``points``). ``stability``: "fold" (checks near both ends and in the middle of each
    stretch between folds), "floquet" (every point, slow) or "none". ``twin_periods``:
    the time-domain twin's run per point for its 20 Hz filtered maxima (0: none).
    ``sweep_starts``: also start paths from the twin's swept steady states."""
    sc = _scenario(scenario)
    _choice("stability", stability, ("fold", "floquet", "none"))
    if isinstance(twin_periods, bool) or not isinstance(twin_periods, int) or not 0 <= twin_periods <= 100:
        raise ValueError(f"twin_periods = {twin_periods!r}: expected an integer in [0, 100]")
    command = _call("steady", sc, from_mph=from_mph, to_mph=to_mph, amplitude_in=amplitude_in, stability=stability,
                    twin_periods=twin_periods, sweep_starts=sweep_starts)
    return _rockroll._steady(sc, None if amplitude_in is None else _positive("amplitude_in", amplitude_in),
                             _positive("from_mph", from_mph), _positive("to_mph", to_mph), stability,
                             int(twin_periods), bool(sweep_starts), command)


def orbits(scenario, from_mph, to_mph, model=None, amplitude_in=None, step_mph=0.25, start_duration_s=30,
           start_sweep_from_mph=None, start_speed_ramp_s=1.0, accuracy=1e-7, refinements=2, newton_steps=20, settle_periods=0,
           iterate=False, fd_step_scale=1.0, jobs=0):
    """Periodic orbits of a time-domain model continued in speed, like `rockroll orbits --json`
    (docs/orbits.md): a dict with ``start``, ``points`` (one per orbit point computed, failed
    ones with ``converged`` False and their ``failure``), ``events``, ``stop_reason`` and
    ``provenance``. The start is a run from rest at from_mph (``start_duration_s``), or a
    speed sweep from ``start_sweep_from_mph`` to from_mph in step_mph steps, then
    ``settle_periods`` forcing periods at from_mph before the first shooting. ``iterate``:
    each orbit by iterating the map (attracting orbits only), as ``--iterate``."""
    sc = _scenario(scenario)
    for name, v, lo, hi in (("refinements", refinements, 0, 8), ("newton_steps", newton_steps, 1, 100),
                            ("settle_periods", settle_periods, 0, 1000), ("jobs", jobs, 0, 1024)):
        if isinstance(v, bool) or not isinstance(v, int) or not lo <= v <= hi:
            raise ValueError(f"{name} = {v!r}: expected an integer in [{lo}, {hi}]")
    if not 1e-12 <= float(accuracy) <= 1e-3:
        raise ValueError(f"accuracy = {accuracy!r}: expected a number in [1e-12, 1e-3]")
    if not isinstance(iterate, bool):
        raise ValueError(f"iterate = {iterate!r}: expected True or False")
    if not 0.01 <= float(fd_step_scale) <= 100:
        raise ValueError(f"fd_step_scale = {fd_step_scale!r}: expected a number in [0.01, 100]")
    if not 0 <= float(start_speed_ramp_s) <= 60:
        raise ValueError(f"start_speed_ramp_s = {start_speed_ramp_s!r}: expected a time in [0 s, 60 s]")
    if start_sweep_from_mph is None and float(start_speed_ramp_s) != 1.0:
        raise ValueError(f"start_speed_ramp_s = {start_speed_ramp_s!r} without start_sweep_from_mph: a start from rest "
                         "has no speed change to ramp")
    command = _call("orbits", sc, from_mph=from_mph, to_mph=to_mph, model=model, amplitude_in=amplitude_in,
                    step_mph=step_mph, start_duration_s=start_duration_s,
                    start_sweep_from_mph=start_sweep_from_mph, start_speed_ramp_s=start_speed_ramp_s,
                    accuracy=accuracy, refinements=refinements, newton_steps=newton_steps,
                    settle_periods=settle_periods, iterate=iterate, fd_step_scale=fd_step_scale, jobs=jobs)
    return _rockroll._orbits(sc, model, None if amplitude_in is None else _positive("amplitude_in", amplitude_in),
                             _positive("from_mph", from_mph), _positive("to_mph", to_mph),
                             _positive("step_mph", step_mph), _positive("start_duration_s", start_duration_s),
                             None if start_sweep_from_mph is None else _positive("start_sweep_from_mph",
                                                                                start_sweep_from_mph),
                             float(start_speed_ramp_s), float(accuracy), refinements, newton_steps,
                             settle_periods, bool(iterate), float(fd_step_scale), jobs, command)


def modes(scenario, model=None):
    """Natural frequencies and damping of the halfcar or fullcar model, linearized about
    static equilibrium, beside the report's Table 1, like `rockroll modes --json`."""
    sc = _scenario(scenario)
    return _rockroll._modes(sc, model, _call("modes", sc, model=model))
