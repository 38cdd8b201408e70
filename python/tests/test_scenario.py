"""rockroll.load and its overrides: the file's keys, units, validation and messages."""
import re
import tomllib

import pytest
import rockroll

from conftest import LOADED


def test_load_reads_the_file():
    sc = rockroll.load(LOADED)
    assert sc.source == LOADED
    assert sc.car == "70ton-loaded"
    assert sc.model == "fullcar"
    assert sc.speed_mph == pytest.approx(16.5, rel=1e-12)
    assert sc.amplitude_in == pytest.approx(0.75, rel=1e-12)
    assert sc.duration_s == 20
    assert len(sc.sha256) == 64
    assert sc.overrides == []


def test_a_bare_key_overrides_the_one_key_it_names():
    sc = rockroll.load(LOADED, side_bearing_clearance="0.25 in", speed="15 mph")
    assert sc.overrides == [("car.side_bearing_clearance", "0.25 in"), ("run.speed", "15 mph")]
    assert sc.car_overrides == {"side_bearing_clearance": "0.25 in"}
    assert sc.speed_mph == pytest.approx(15, rel=1e-12)
    assert tomllib.loads(sc.to_toml())["car"]["side_bearing_clearance"] == "0.00635 m"


def test_full_dotted_keys_and_typed_values():
    sc = rockroll.load(LOADED, **{"run.model": "halfcar", "track.rails": 4, "track.mirror": True,
                                  "integrator.accuracy": 1e-5, "limits.flange_climb_time": "0.05 s"})
    assert sc.model == "halfcar"
    assert sc.overrides == [("run.model", "halfcar"), ("track.rails", "4"), ("track.mirror", "true"),
                            ("integrator.accuracy", "1e-05"), ("limits.flange_climb_time", "0.05 s")]
    toml = tomllib.loads(sc.to_toml())
    assert toml["track"]["rails"] == 4 and toml["track"]["mirror"] is True
    assert toml["integrator"]["accuracy"] == 1e-5
    assert toml["limits"]["flange_climb_time"] == "0.05 s"  # [limits] was not in the file: created


def test_scenario_keys_list_the_schema():
    keys = rockroll.scenario_keys()
    assert "car.side_bearing_clearance" in keys and "run.speed" in keys and "description" in keys
    assert len(keys) == len(set(keys))


def test_an_unknown_key_names_it_and_lists_the_accepted_keys():
    with pytest.raises(rockroll.ScenarioError) as e:
        rockroll.load(LOADED, side_bearing_clearence="0.25 in")
    message = str(e.value)
    assert "'side_bearing_clearence'" in message
    assert "accepted keys: description, car.base," in message and "run.speed" in message
    assert isinstance(e.value, ValueError)


def test_a_bad_value_gives_the_files_own_message(tmp_path):
    """The override goes through the loader exactly as the same key written in the file."""
    text = open(LOADED).read()
    plain = tmp_path / "case.toml"
    plain.write_text(text)
    written = tmp_path / "written.toml"
    written.write_text(text.replace('base = "70ton-loaded"', 'base = "70ton-loaded"\nside_bearing_clearance = "-1 in"'))
    with pytest.raises(rockroll.ScenarioError) as from_file:
        rockroll.load(written)
    with pytest.raises(rockroll.ScenarioError) as from_override:
        rockroll.load(plain, side_bearing_clearance="-1 in")
    # The same message, but for the line: the file's error names it, an override has none.
    assert str(from_override.value) == re.sub(r":\d+: key", ": key", str(from_file.value)).replace(str(written), str(plain))
    assert re.search(re.escape(str(written)) + r":\d+: key 'car.side_bearing_clearance'", str(from_file.value))
    assert "key 'car.side_bearing_clearance' = '-1 in': expected a length ≥ 0 in (finite)" in str(from_override.value)

    with pytest.raises(rockroll.ScenarioError, match=re.escape("key 'run.speed' = 15: expected a string")):
        rockroll.load(LOADED, speed=15)  # a number without its unit, as in the file


def test_a_value_of_another_type_is_a_type_error():
    with pytest.raises(TypeError, match="side_bearing_clearance"):
        rockroll.load(LOADED, side_bearing_clearance=[0.25])


def test_a_missing_file_is_a_scenario_error():
    with pytest.raises(rockroll.ScenarioError, match="cannot open scenario file"):
        rockroll.load("no/such/file.toml")
