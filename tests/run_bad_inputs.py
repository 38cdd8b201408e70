#!/usr/bin/python3
"""Runs every case of tests/data/bad/cases.tsv through the real rockroll binary and
checks its exit code and message (ctest BadInputs.Corpus; docs/cli.md, "Exit codes").

usage: run_bad_inputs.py ROCKROLL_BIN SOURCE_DIR WORK_DIR

A case fails when the program crashes (killed by a signal), hangs (no exit within
the per-case timeout), accepts it (exit 0 where an error is expected), exits with
another code, or prints a vague message: one without each expected substring (the
manifest asks for the key or option and, where a value has a range, the "expected ..."
range), or with a carriage return (a progress bar in a log). Every failing case is
named, then the tally by kind.
"""
import os
import shlex
import subprocess
import sys

TIMEOUT_S = 60  # per case; every case is refused before, or stopped within, a fraction of a second of simulation


def main():
    binary, source, work = sys.argv[1:4]
    manifest = os.path.join(source, "tests", "data", "bad", "cases.tsv")
    os.makedirs(work, exist_ok=True)
    tally = {"ok": 0, "crash": 0, "hang": 0, "accepted": 0, "wrong exit": 0, "vague": 0}
    failures = []
    with open(manifest) as f:
        rows = [l.rstrip("\n").split("\t") for l in f if l.strip() and not l.startswith("#")]
    for name, code, expect, args in rows:
        words = shlex.split(args.replace("$BAD", os.path.join(source, "tests", "data", "bad")).replace("$SRC", source))
        env = dict(os.environ)
        while words and "=" in words[0] and not words[0].startswith("-"):
            key, value = words.pop(0).split("=", 1)
            env[key] = value
        try:
            p = subprocess.run([binary] + words, cwd=work, env=env, capture_output=True, timeout=TIMEOUT_S,
                               stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            tally["hang"] += 1
            failures.append(f"{name}: HANG (no exit within {TIMEOUT_S} s): rockroll {args}")
            continue
        message = (p.stderr + p.stdout).decode("utf-8", "replace")
        first = message.strip().splitlines()[-1] if message.strip() else "(no output)"
        wanted = [w for w in expect.split(" && ") if w]
        missing = [w for w in wanted if w not in message]
        if p.returncode < 0:
            kind, why = "crash", f"killed by signal {-p.returncode}"
        elif p.returncode == 0 and int(code) != 0:
            kind, why = "accepted", "exit 0"
        elif p.returncode != int(code):
            kind, why = "wrong exit", f"exit {p.returncode}, expected {code}"
        elif missing:
            kind, why = "vague", f"message lacks {missing}"
        elif "\r" in message:
            kind, why = "vague", "a carriage return in the log (progress bar without a terminal)"
        else:
            tally["ok"] += 1
            continue
        tally[kind] += 1
        failures.append(f"{name}: {kind.upper()} ({why}): rockroll {args}\n    {first[:400]}")
    for f in failures:
        print(f)
    print(f"{len(rows)} bad inputs: " + ", ".join(f"{k} {v}" for k, v in tally.items()))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
