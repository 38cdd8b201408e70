"""Shared fixtures of the Python tests (run by ctest: python/CMakeLists.txt section of the top
CMakeLists.txt sets PYTHONPATH=build/python, ROCKROLL_BIN and ROCKROLL_SOURCE_DIR)."""
import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("ROCKROLL_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
ROCKROLL_BIN = pathlib.Path(os.environ.get("ROCKROLL_BIN", SOURCE_DIR / "build" / "bin" / "rockroll"))
LOADED = str(SOURCE_DIR / "scenarios" / "70ton-loaded.toml")


@pytest.fixture
def cli(tmp_path):
    """Runs build/bin/rockroll with `args` in tmp_path; returns (exit code, stdout, stderr)."""
    def run(*args):
        p = subprocess.run([str(ROCKROLL_BIN), *map(str, args)], cwd=tmp_path, capture_output=True, text=True)
        return p.returncode, p.stdout, p.stderr
    return run


@pytest.fixture
def cli_json(cli):
    """The one JSON document `rockroll ... --json` prints (exit 0 required)."""
    def run(*args):
        code, out, err = cli(*args, "--json")
        assert code == 0, err
        return json.loads(out)
    return run


def without_run_specifics(j):
    """A summary (or any command's JSON) without what differs between two identical runs:
    wall time and the command line that produced it (and the git commit, which is "-dirty"
    for a target built before a commit and another after it)."""
    if isinstance(j, list):
        return [without_run_specifics(x) for x in j]
    j = dict(j)
    j.pop("wall_time_s", None)
    if "provenance" in j:
        j["provenance"] = {k: v for k, v in j["provenance"].items() if k not in ("command", "git_commit")}
    return j
