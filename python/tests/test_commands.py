"""rockroll.sweep, steady, orbits and modes: the data their `--json` command lines print."""
import pytest
import rockroll

from conftest import LOADED, SOURCE_DIR, without_run_specifics


def test_sweep_is_the_command_lines(cli_json):
    points = rockroll.sweep(LOADED, model="reduced", from_mph=15, to_mph=16, step_mph=0.5, amplitude_in=[0.75],
                            direction="both", duration_s=1, jobs=2)
    expected = cli_json("sweep", LOADED, "--model", "reduced", "--from-mph", 15, "--to-mph", 16, "--step-mph", 0.5,
                        "--amplitude-in", 0.75, "--direction", "both", "--duration-s", 1, "--jobs", 2)
    assert len(points) == 6
    assert [(p["direction"], p["speed_mph"], p["start"]) for p in points] == [
        ("up", 15, "rest"), ("up", 15.5, "continued"), ("up", 16, "continued"),
        ("down", 16, "rest"), ("down", 15.5, "continued"), ("down", 15, "continued")]
    assert without_run_specifics(points) == without_run_specifics(expected)


def test_sweep_accepts_scenarios_and_several_amplitudes():
    sc = rockroll.load(LOADED, model="reduced", duration="1 s")
    points = rockroll.sweep([sc], from_mph=15, to_mph=15.5, step_mph=0.5, amplitude_in=[0.5, 1.0], direction="up",
                            fresh=True)
    assert [(p["amplitude_in"], p["speed_mph"], p["start"]) for p in points] == [
        (0.5, 15, "rest"), (0.5, 15.5, "rest"), (1.0, 15, "rest"), (1.0, 15.5, "rest")]
    assert all(not p["failed"] for p in points)
    assert points[0]["provenance"]["overrides"] == [{"key": "run.model", "value": "reduced"},
                                                    {"key": "run.duration", "value": "1 s"}]
    with pytest.raises(ValueError, match="direction"):
        rockroll.sweep(sc, from_mph=15, to_mph=16, step_mph=1, direction="sideways")


def test_steady_is_the_command_lines(cli_json):
    result = rockroll.steady(LOADED, from_mph=14, to_mph=18, amplitude_in=0.75, stability="none")
    expected = cli_json("steady", LOADED, "--from-mph", 14, "--to-mph", 18, "--amplitude-in", 0.75,
                        "--stability", "none")
    assert without_run_specifics(result) == without_run_specifics(expected)
    assert result["branches"] and result["branches"][0]["stable"] is None
    with pytest.raises(ValueError, match="must exceed"):
        rockroll.steady(LOADED, from_mph=18, to_mph=14, stability="none")


def test_modes_is_the_command_lines(cli_json):
    result = rockroll.modes(SOURCE_DIR / "scenarios" / "100ton-loaded.toml", model="halfcar")
    expected = cli_json("modes", SOURCE_DIR / "scenarios" / "100ton-loaded.toml", "--model", "halfcar")
    assert without_run_specifics(result) == without_run_specifics(expected)
    assert result["modes"][0]["frequency_hz"] > 0
    with pytest.raises(rockroll.ScenarioError, match="modes need a Simbody model"):
        rockroll.modes(LOADED, model="eom")


def test_orbits_is_the_command_lines(cli_json):
    args = dict(model="eom", amplitude_in=0.25, from_mph=12, to_mph=11.75, step_mph=0.25, start_duration_s=10)
    result = rockroll.orbits(LOADED, **args)
    expected = cli_json("orbits", LOADED, "--model", "eom", "--amplitude-in", 0.25, "--from-mph", 12, "--to-mph", 11.75,
                        "--step-mph", 0.25, "--start-duration-s", 10)
    strip = lambda j: {k: v for k, v in without_run_specifics(j).items() if k not in ("points", "start")}
    assert strip(result) == strip(expected)
    assert [p["roll_amplitude_deg"] for p in result["points"]] == [p["roll_amplitude_deg"] for p in expected["points"]]
    assert [p["speed_mph"] for p in result["points"]] == [12, 11.75]
    with pytest.raises(ValueError, match="iterate"):
        rockroll.orbits(LOADED, model="reduced", from_mph=12, to_mph=11, iterate="yes")
    with pytest.raises(ValueError, match="settle_periods"):
        rockroll.orbits(LOADED, from_mph=12, to_mph=11, settle_periods=-1)
    with pytest.raises(ValueError, match="start_speed_ramp_s"):
        rockroll.orbits(LOADED, from_mph=12, to_mph=11, start_speed_ramp_s=0)
    with pytest.raises(ValueError, match="newton_steps"):
        rockroll.orbits(LOADED, from_mph=12, to_mph=11, newton_steps=0)
    with pytest.raises(ValueError, match="fd_step_scale"):
        rockroll.orbits(LOADED, from_mph=12, to_mph=11, fd_step_scale=0)
