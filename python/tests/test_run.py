"""rockroll.run: the command line's numbers, its history channels and units, its errors."""
import csv
import io
import sys

import numpy as np
import pytest
import rockroll

from conftest import LOADED, without_run_specifics


@pytest.fixture(scope="module")
def halfcar():
    return rockroll.run(rockroll.load(LOADED), model="halfcar", duration_s=2)


def test_summary_is_the_command_lines(halfcar, cli, tmp_path):
    """The done check: the same max_roll_deg (and every other key) as `rockroll run --json`."""
    code, out, err = cli("run", LOADED, "--model", "halfcar", "--duration-s", "2", "--json", "--out", "run")
    assert code == 0, err
    import json
    expected = json.loads(out)
    assert halfcar.summary["max_roll_deg"] == expected["max_roll_deg"]
    assert without_run_specifics(halfcar.summary) == without_run_specifics(expected)
    assert halfcar.summary["provenance"]["command"].startswith("python rockroll.run(")

    # history.csv: the same channels, in the same order, with the same values to its 7 digits.
    with open(tmp_path / "run" / "history.csv") as f:
        rows = list(csv.reader(f))
    assert list(halfcar.history.dtype.names) == rows[0]
    table = np.array(rows[1:], dtype=float)
    assert table.shape == (len(halfcar.history), len(rows[0]))
    for k, name in enumerate(rows[0]):
        np.testing.assert_allclose(halfcar.history[name], table[:, k], rtol=1e-6, atol=1e-9, err_msg=name)


def test_history_is_a_structured_array_with_units(halfcar):
    h = halfcar.history
    assert h.dtype.names[0] == "t_s" and "roll_deg" in h.dtype.names
    assert all(h.dtype.fields[n][0] == np.float64 for n in h.dtype.names)
    assert h["t_s"][0] == 0 and h["t_s"][-1] == pytest.approx(2)
    assert halfcar.units["t_s"] == "s" and halfcar.units["roll_deg"] == "deg"
    assert halfcar.units["side_bearing_F_L_lb"] == "lb" and halfcar.units["car_body_vertical_in"] == "in"
    assert halfcar.units["energy_stored_J"] == "J" and halfcar.units["wedge_vertical_slip_F_L"] == "1"
    assert halfcar.units["car_body_lateral_accel_g"] == "g" and halfcar.units["l_over_v_F1_L_ratio"] == "ratio"
    assert h["roll_deg"].dtype.metadata["unit"] == "deg"
    assert h.dtype.metadata["units"] == halfcar.units
    assert np.max(np.abs(h["roll_deg"])) == pytest.approx(halfcar.summary["max_roll_deg"], rel=1e-12)
    assert halfcar.stopped is None
    assert "max roll" in repr(halfcar)


@pytest.mark.parametrize("model", ["fullcar", "eom", "reduced"])
def test_every_model_runs_with_every_channel_in_a_unit(model):
    r = rockroll.run(LOADED, model=model, duration_s=0.5)
    assert r.summary["model"] == model
    assert set(r.units.values()) <= {"s", "deg", "in", "lb", "J", "g", "ratio", "1"}
    # Dimensionless channels are flags and codes only; everything else names its unit.
    assert all("_slip_" in n or n.startswith("truck_") for n, u in r.units.items() if u == "1"), r.units
    assert len(r.history) > 100


@pytest.mark.parametrize("model", ["fullcar", "halfcar", "eom", "reduced"])
def test_every_columns_unit_is_the_channel_tables(model, cli, tmp_path):
    """Each history column's unit is its declaration's (mbmodel/ChannelLayout.h), not a
    reading of its name: the table lists every column of history.csv in order, each name
    is its quantity then its unit, and Result.units and the dtype carry that unit."""
    r = rockroll.run(LOADED, model=model, duration_s=0.2)
    code, _, err = cli("run", LOADED, "--model", model, "--duration-s", "0.2", "--out", "run")
    assert code == 0, err
    with open(tmp_path / "run" / "history.csv", newline="") as f:
        header = next(csv.reader(f))
    table = r.channel_table
    assert [c["name"] for c in table] == header == list(r.history.dtype.names)
    for c in table:
        assert c["name"] == (c["quantity"] + "_" + c["unit"] if c["unit"] else c["quantity"]), c
        assert r.units[c["name"]] == (c["unit"] or "1"), c
        assert r.history.dtype.fields[c["name"]][0].metadata["unit"] == r.units[c["name"]]
    by_name = {c["name"]: c for c in table}
    assert by_name["t_s"]["unit"] == "s" and by_name["roll_deg"]["roles"] == ["roll"]
    assert "side_bearing" in by_name["side_bearing_F_L_lb"]["roles"] and by_name["side_bearing_F_L_lb"]["truck"] == "F"
    assert all(c["unit"] == "lb" for c in table if "center_plate" in c["roles"] or "side_bearing" in c["roles"])
    assert all(c["unit"] == "in" for c in table if "wheel_lift" in c["roles"])


def test_to_pandas_needs_pandas(halfcar, monkeypatch):
    try:
        import pandas  # noqa: F401
    except ImportError:
        have_pandas = False
    else:
        have_pandas = True
        frame = halfcar.to_pandas()
        assert list(frame.columns) == list(halfcar.history.dtype.names)
        assert frame.attrs["units"] == halfcar.units
    monkeypatch.setitem(sys.modules, "pandas", None)  # as if it were not installed
    with pytest.raises(ImportError, match="needs pandas, which is not installed"):
        halfcar.to_pandas()
    assert have_pandas or "pandas" not in sys.modules or sys.modules["pandas"] is None


def test_overturning_stops_the_run_and_is_a_result():
    # The report's Figs 8-10 run on the half car overturns at 3.13 s against a 2 deg limit.
    r = rockroll.run(rockroll.load(LOADED, rollover_angle="2 deg"), model="halfcar", duration_s=5)
    assert r.stopped == "overturned"
    assert r.summary["regime"] == "overturned" and r.summary["stopped_at_s"] < 5
    assert r.history["t_s"][-1] < 5


def test_a_value_out_of_its_declared_range_is_refused_as_on_the_command_line():
    with pytest.raises(rockroll.ScenarioError, match=r"key 'track.amplitude' = 50 in: expected a length in \[0 in, 3 in\]"):
        rockroll.run(LOADED, model="halfcar", amplitude_in=50, duration_s=2)


def test_a_numerical_failure_is_a_runtime_error_with_the_cli_message(cli):
    with pytest.raises(rockroll.NumericalFailure) as e:
        rockroll.run(LOADED, model="halfcar", duration_s=2, max_wall_s=1e-9)
    assert isinstance(e.value, RuntimeError)
    assert "wall" in str(e.value) and e.value.time_s >= 0
    code, _, err = cli("run", LOADED, "--model", "halfcar", "--duration-s", "2", "--max-wall-s", "1e-9")
    assert code == 3
    # The CLI's message starts as the exception's (its time and state differ with the wall clock).
    assert err.startswith("rockroll: numerical failure: " + str(e.value).split(" at t = ")[0])


def test_a_scenario_error_from_the_run_carries_the_cli_message(cli, tmp_path):
    with pytest.raises(rockroll.ScenarioError) as e:
        rockroll.run(rockroll.load(LOADED, truck_weight=True), model="halfcar", duration_s=0.1)
    assert "key 'reduced.truck_weight' = true: expected model reduced, not \"halfcar\"" in str(e.value)
    case = tmp_path / "case.toml"
    case.write_text(open(LOADED).read() + "\n[reduced]\ntruck_weight = true\n")
    code, _, err = cli("run", case, "--model", "halfcar", "--duration-s", "0.1")
    assert code == 2
    assert err == f"rockroll: scenario error: {str(e.value).replace(LOADED, str(case))}\n"


def test_bad_run_options_are_value_errors():
    sc = rockroll.load(LOADED)
    with pytest.raises(ValueError, match="duration_s"):
        rockroll.run(sc, duration_s=0)
    with pytest.raises(ValueError, match="speed_mph"):
        rockroll.run(sc, speed_mph=-1)


def test_overrides_are_in_provenance_and_come_back_from_a_summary(tmp_path):
    import json
    sc = rockroll.load(LOADED, side_bearing_clearance="0.25 in", **{"run.model": "halfcar"})
    r = rockroll.run(sc, duration_s=0.5)
    prov = r.summary["provenance"]
    assert prov["overrides"] == [{"key": "car.side_bearing_clearance", "value": "0.25 in"},
                                 {"key": "run.model", "value": "halfcar"}]
    assert prov["car_overrides"] == {"side_bearing_clearance": "0.25 in"}
    path = tmp_path / "summary.json"
    path.write_text(json.dumps(r.summary))
    again = rockroll.from_summary(path)
    assert again.overrides == sc.overrides
    rerun = rockroll.run(again, duration_s=0.5)
    assert np.array_equal(rerun.history.view(np.float64), r.history.view(np.float64))
