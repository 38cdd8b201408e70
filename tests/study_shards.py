#!/usr/bin/python3
"""A parameter study run whole, as 2 shards merged, and killed and resumed, gives the
same study.csv and study.json byte for byte; merge refuses shards that do not make one
study (ctest StudyCli.ShardsMergeToTheUnshardedStudy; docs/studies.md).

usage: study_shards.py ROCKROLL_BIN SOURCE_DIR WORK_DIR

The study is scenarios/studies/side-bearing-clearance.toml with a shorter run (2 s a point),
and for the killed and resumed one a longer (60 s a point).
"""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import time


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def main():
    binary, source, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    with open(os.path.join(source, "scenarios", "studies", "side-bearing-clearance.toml")) as f:
        text = f.read()
    scenario = os.path.join(source, "scenarios", "70ton-loaded.toml")
    text = text.replace('"../70ton-loaded.toml"', json.dumps(scenario)).replace('"4 s"', '"2 s"')
    study = os.path.join(work, "study.toml")
    with open(study, "w") as f:
        f.write(text)

    def run(*args):
        r = subprocess.run([binary, *args], cwd=work, capture_output=True, text=True, timeout=600)
        return r

    r = run("study", study, "--out", "whole", "--jobs", "2")
    if r.returncode != 0:
        fail(f"whole study exited {r.returncode}: {r.stderr}")
    for k in (1, 2):
        r = run("study", study, "--shard", f"{k}/2", "--out", f"shard{k}", "--jobs", "1")
        if r.returncode != 0:
            fail(f"shard {k}/2 exited {r.returncode}: {r.stderr}")
    r = run("merge", "shard2", "shard1", "--out", "merged")
    if r.returncode != 0:
        fail(f"merge exited {r.returncode}: {r.stderr}")
    for name in ("study.csv", "study.json"):
        a = open(os.path.join(work, "whole", name), "rb").read()
        b = open(os.path.join(work, "merged", name), "rb").read()
        if a != b:
            fail(f"merged/{name} differs from whole/{name}")
        print(f"merged/{name} is byte-identical to whole/{name} ({len(a)} bytes)")

    # Read back: one row per point, the varied columns with their units, the summary fields.
    whole = json.load(open(os.path.join(work, "whole", "study.json")))
    rows = list(csv.DictReader(open(os.path.join(work, "whole", "study.csv"))))
    if len(rows) != 8 or whole["study"]["point_count"] != 8 or len(whole["points"]) != 8:
        fail(f"expected 8 points, got {len(rows)} rows and {len(whole['points'])} points")
    header = list(rows[0].keys())
    if header[:4] != ["point", "car.side_bearing_clearance_in", "run.speed_mph", "status"]:
        fail(f"study.csv columns start {header[:4]}")
    for row, p in zip(rows, whole["points"]):
        if int(row["point"]) != p["point"] or float(row["run.speed_mph"]) != p["values"]["run.speed_mph"]:
            fail(f"study.csv row {row['point']} does not match study.json")
        if float(row["max_roll_deg"]) != p["summary"]["max_roll_deg"] or p["summary"]["speed_mph"] != p["values"]["run.speed_mph"]:
            fail(f"point {p['point']}: the summary does not match the varied speed or the CSV")
    if [r["run.speed_mph"] for r in rows[:4]] != ["14", "15", "16", "17"] or rows[4]["car.side_bearing_clearance_in"] != "0.25":
        fail("points are not numbered clearance-major, speed-minor")
    if "wall_time_s" in header:
        fail("study.csv carries the machine's wall time")
    if json.load(open(os.path.join(work, "shard1", "study.json")))["shard"] != {"k": 1, "n": 2}:
        fail("shard1/study.json does not name its shard")
    print(f"study.csv: {len(rows)} rows, columns {', '.join(header[:6])}, ...")

    # Merge refuses a missing shard, the same shard twice, and another study's shard.
    other = os.path.join(work, "other.toml")
    with open(other, "w") as f:
        f.write(text.replace('"0.25 in"', '"0.3 in"'))
    r = run("study", other, "--shard", "2/2", "--out", "other2", "--jobs", "2")
    if r.returncode != 0:
        fail(f"other study exited {r.returncode}: {r.stderr}")
    for args, needle in ((["shard1"], "missing: 1, 3, 5, 7"), (["shard1", "shard1"], "both shard 1/2"),
                         (["shard1", "other2"], "different studies")):
        r = run("merge", *args, "--out", "bad")
        if r.returncode != 2 or needle not in r.stderr:
            fail(f"merge {' '.join(args)}: exit {r.returncode}, expected 2 with '{needle}': {r.stderr}")
        print(f"merge {' '.join(args)} refused: {r.stderr.strip()[:160]}")

    # A derailed or overturned point is a result with its status, and the study carries on.
    over = os.path.join(work, "over.toml")
    with open(over, "w") as f:
        f.write(f'scenario = {json.dumps(scenario)}\nmodel = "reduced"\n[set]\n"run.duration" = "2 s"\n'
                '[vary]\n"limits.rollover_angle" = ["0.5 deg", "30 deg"]\n')
    r = run("study", over, "--out", "over")
    rows = list(csv.DictReader(open(os.path.join(work, "over", "study.csv")))) if r.returncode == 0 else []
    if [row.get("status") for row in rows] != ["overturned", "ok"] or rows[0]["limits.rollover_angle_deg"] != "0.5":
        fail(f"rollover study: exit {r.returncode}, statuses {[row.get('status') for row in rows]}: {r.stderr}")
    print("a point past the rollover limit has status overturned; the next point runs")

    # Killed midway (SIGKILL), resumed with another --jobs: the same files. Its points run
    # 60 s each, so that the study is still running well after its second point is journaled
    # (at 2 s a point the whole study can end between the poll and the kill).
    slow = os.path.join(work, "slow.toml")
    with open(slow, "w") as f:
        f.write(text.replace('"2 s"', '"60 s"'))
    r = run("study", slow, "--out", "whole-slow", "--jobs", "2")
    if r.returncode != 0:
        fail(f"slow whole study exited {r.returncode}: {r.stderr}")
    journal = os.path.join(work, "resumed.partial", "journal.jsonl")
    p = subprocess.Popen([binary, "study", slow, "--out", "resumed", "--jobs", "2"], cwd=work,
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    while p.poll() is None:
        try:
            if open(journal, "rb").read().count(b"\n") >= 3:  # header and 2 points
                break
        except FileNotFoundError:
            pass
        time.sleep(0.02)
    p.send_signal(signal.SIGKILL)
    p.wait()
    if p.returncode != -signal.SIGKILL:
        fail(f"the study ended (exit {p.returncode}) before it could be killed")
    r = run("study", slow, "--out", "resumed", "--jobs", "1", "--resume")
    if r.returncode != 0 or "resuming from" not in r.stderr:
        fail(f"resumed study exited {r.returncode}: {r.stderr}")
    for name in ("study.csv", "study.json"):
        if open(os.path.join(work, "whole-slow", name), "rb").read() != open(os.path.join(work, "resumed", name), "rb").read():
            fail(f"resumed/{name} differs from whole-slow/{name}")
    print("a study killed midway and resumed gives the same files")
    print("1 passed, 0 failed")


if __name__ == "__main__":
    main()
