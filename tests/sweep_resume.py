#!/usr/bin/python3
"""A sweep killed with SIGKILL midway resumes to the result of an uninterrupted sweep
(ctest SweepResume.KilledSweepResumesToTheSameResult; docs/outputs.md).

usage: sweep_resume.py ROCKROLL_BIN SOURCE_DIR WORK_DIR

1. An uninterrupted sweep (--jobs 2) writes ref/.
2. The same command is killed with SIGKILL once its journal holds some but not all
   points; a cut-off copy of its last line is appended (as a kill mid-write leaves it).
3. Resuming with another sweep (another --to-mph, another --set) is refused (exit 2,
   naming what differs) and leaves the journal as it was; so is starting again
   without --resume or --force.
4. `--resume --jobs 1` finishes it: sweep.csv and sweep.json are compared byte for byte
   with ref/, except each point's wall_time_s (the machine's time, not a result).
5. SIGINT of a running sweep exits 130 and keeps its journal; --resume finishes it
   to the same result.
"""
import csv
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

POLL_S = 0.02


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def count_points(journal):
    try:
        with open(journal, "rb") as f:
            return max(0, f.read().count(b"\n") - 1)  # the header is line 1
    except FileNotFoundError:
        return 0


def without_wall_time(name, data):
    """The file's bytes with every point's wall_time_s blanked (CSV column or JSON key)."""
    text = data.decode()
    if name.endswith(".json"):
        return re.sub(r'"wall_time_s": [^,\n]+', '"wall_time_s": -', text)
    # Every row is one line; only the wall_time_s cell is blanked, each other cell compared as written.
    rows = [next(csv.reader([line])) if line else [] for line in text.split("\n")]
    col = rows[0].index("wall_time_s")
    for row in rows[1:]:
        if len(row) > col:
            row[col] = "-"
    return rows


def compare(ref, out):
    for name in ("sweep.csv", "sweep.json"):
        a = open(os.path.join(ref, name), "rb").read()
        b = open(os.path.join(out, name), "rb").read()
        if without_wall_time(name, a) != without_wall_time(name, b):
            fail(f"{out}/{name} differs from the uninterrupted {ref}/{name}")
        print(f"{out}/{name}: identical to {ref}/{name} ({len(a)} bytes; wall_time_s aside)")
    if os.path.exists(os.path.join(out, "journal.jsonl")):
        fail(f"{out}/journal.jsonl left in the finished directory")


def main():
    binary, source, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scenario = os.path.join(source, "scenarios", "70ton-loaded.toml")
    def make_sweep(to_mph="17", extra=()):
        # 20 s a point: the sweep still runs well after its third point is journaled (at 2 s a
        # point it can end between the poll and the kill)
        return [binary, "sweep", scenario, "--model", "reduced", "--duration-s", "20", "--from-mph", "13",
                "--to-mph", to_mph, "--step-mph", "0.5", "--direction", "both", *extra]

    sweep = make_sweep()
    total = 2 * 9

    def run(args, **kw):
        return subprocess.run(args, cwd=work, capture_output=True, text=True, timeout=300, **kw)

    r = run(sweep + ["--jobs", "2", "--out", "out"])
    if r.returncode != 0:
        fail(f"uninterrupted sweep exited {r.returncode}: {r.stderr}")
    os.rename(os.path.join(work, "out"), os.path.join(work, "ref"))

    # 2. The same command, killed midway.
    journal = os.path.join(work, "out.partial", "journal.jsonl")
    p = subprocess.Popen(sweep + ["--jobs", "2", "--out", "out"], cwd=work, stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL)
    while count_points(journal) < 3 and p.poll() is None:
        time.sleep(POLL_S)
    p.send_signal(signal.SIGKILL)
    p.wait()
    if p.returncode != -signal.SIGKILL:
        fail(f"the sweep ended (exit {p.returncode}) before it could be killed")
    done = count_points(journal)
    if not 3 <= done < total:
        fail(f"journal holds {done} of {total} points after the kill; expected some but not all")
    if os.path.exists(os.path.join(work, "out")):
        fail("a killed sweep left a complete-looking out/")
    with open(journal, "rb") as f:
        last = f.read().rstrip(b"\n").split(b"\n")[-1]
    with open(journal, "ab") as f:
        f.write(last[: len(last) // 2])  # a write cut short by the kill
    before = open(journal, "rb").read()
    print(f"killed with {done} of {total} points in the journal, and a torn line appended")

    # 3. Another sweep, or no --resume, is refused and the journal stays.
    for cmd, expect in ((make_sweep("16.5"), "to_mph"),
                        (make_sweep(extra=["--set", "car.side_bearing_clearance=0.25 in"]), "overrides"),
                        (sweep, None)):
        cmd = cmd + ["--jobs", "1", "--out", "out"] + (["--resume"] if expect else [])
        r = run(cmd)
        needle = expect or "--resume"
        if r.returncode != 2 or needle not in r.stderr or "journal" not in r.stderr:
            fail(f"{' '.join(cmd[1:])}: exit {r.returncode}, expected 2 naming '{needle}': {r.stderr}")
        if open(journal, "rb").read() != before:
            fail(f"a refused resume changed {journal}")
        print(f"refused (exit 2): {r.stderr.strip().splitlines()[-1][:200]}")

    # 4. Resumed with another --jobs: the same result.
    r = run(sweep + ["--jobs", "1", "--out", "out", "--resume"])
    if r.returncode != 0:
        fail(f"resumed sweep exited {r.returncode}: {r.stderr}")
    if f"resuming from {done} finished points" not in r.stderr or "cut-off last line dropped" not in r.stderr:
        fail(f"the resumed sweep did not say it resumed from {done} points and dropped the torn line: {r.stderr}")
    compare(os.path.join(work, "ref"), os.path.join(work, "out"))
    with open(os.path.join(work, "out", "sweep.json")) as f:
        points = json.load(f)["points"]
    if len(points) != total:
        fail(f"sweep.json has {len(points)} points, expected {total}")

    # 5. SIGINT keeps the journal; --resume finishes it.
    shutil.rmtree(os.path.join(work, "out"))
    p = subprocess.Popen(sweep + ["--jobs", "2", "--out", "out"], cwd=work, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, text=True)
    while count_points(journal) < 2 and p.poll() is None:
        time.sleep(POLL_S)
    p.send_signal(signal.SIGINT)
    _, err = p.communicate(timeout=300)
    if p.returncode != 130:
        fail(f"SIGINT: exit {p.returncode}, expected 130: {err}")
    if not 2 <= count_points(journal) < total:
        fail(f"SIGINT left {count_points(journal)} points in the journal; expected it kept for --resume")
    if any(n.endswith(".tmp") for n in os.listdir(os.path.join(work, "out.partial"))):
        fail("SIGINT left a .tmp file")
    r = run(sweep + ["--jobs", "2", "--out", "out", "--resume"])
    if r.returncode != 0:
        fail(f"sweep resumed after SIGINT exited {r.returncode}: {r.stderr}")
    compare(os.path.join(work, "ref"), os.path.join(work, "out"))
    print("1 passed, 0 failed")


if __name__ == "__main__":
    main()
