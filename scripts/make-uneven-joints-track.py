#!/usr/bin/python3
"""Writes a measured-track CSV of jointed track whose two rails have their own joint geometry:
different dip depths on the left and right rails, a joint stagger other than half a rail, and
each joint's depth scattered about its rail's depth by a seeded random rule. With no options it
writes the shipped scenarios/tracks/uneven-joints.csv (scenarios/uneven-joints.toml).

Rule (docs/cli.md, "Measured track"): rails L long; each rail has a joint every L, the right
rail's joints `stagger` x L after the left's (0.5: the report's staggered joints). Around each
joint j, over half a rail either side, the rail is the report's rectified sine (eqs 1-2) with
that joint's depth d_j: z = -d_j (1 - |sin(pi (s - s_j) / L)|), level (0) at mid-rail and d_j
below it at the joint, so neighbouring dips meet level at mid-rail whatever their depths.
d_j = depth x (1 + scatter x u_j), u_j uniform in [-1, 1] drawn in joint order, left rail
first, from Python's random.Random(seed) (Mersenne Twister, the same sequence on every
platform). The rails are level before their first and after their last dip: one rail of
level track leads in. Sampled every L/100, so every joint falls on a row. Tests:
MeasuredTrack.UnevenJointsTableObeysItsRule, MeasuredTrack.UnevenJointsTableIsItsScriptsOutput.

Rerun after changing it: /usr/bin/python3 scripts/make-uneven-joints-track.py [options]
"""
import argparse
import math
import os
import random


def make_joints(first, stagger, count, rail_length, depth, scatter, rng):
    return [(first + stagger * rail_length + k * rail_length, depth * (1 + scatter * rng.uniform(-1, 1)))
            for k in range(count)]


def rail(s, joints, rail_length):
    """Rail-top height [in] at s [ft]: the dip of the joint within half a rail, else level."""
    for sj, dj in joints:
        if abs(s - sj) <= rail_length / 2 + 1e-9:
            return -dj * (1 - abs(math.sin(math.pi * (s - sj) / rail_length)))
    return 0.0


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--rail-length", type=float, default=39.0, help="L [ft] (default 39)")
    p.add_argument("--joints", type=int, default=12, help="joints on each rail (default 12)")
    p.add_argument("--left-depth", type=float, default=0.75, help="left rail's joint depth [in] (default 0.75)")
    p.add_argument("--right-depth", type=float, default=0.5, help="right rail's joint depth [in] (default 0.5)")
    p.add_argument("--stagger", type=float, default=0.35,
                   help="right joints after the left ones, in rails, in [0, 1) (default 0.35; the report: 0.5)")
    p.add_argument("--scatter", type=float, default=0.25,
                   help="each joint's depth within depth x (1 +- scatter), in [0, 1) (default 0.25)")
    p.add_argument("--seed", type=int, default=1, help="random.Random seed (default 1)")
    p.add_argument("--out", default=os.path.join(here, "..", "scenarios", "tracks", "uneven-joints.csv"))
    a = p.parse_args()
    if not 0 <= a.stagger < 1 or not 0 <= a.scatter < 1 or a.joints < 1 or a.rail_length <= 0:
        p.error("expected 0 <= stagger < 1, 0 <= scatter < 1, joints >= 1 and a positive rail length")
    L = a.rail_length
    rng = random.Random(a.seed)
    first = L + L / 2  # the first left joint, after one rail of level lead-in
    left = make_joints(first, 0.0, a.joints, L, a.left_depth, a.scatter, rng)
    right = make_joints(first, a.stagger, a.joints, L, a.right_depth, a.scatter, rng)
    step = L / 100
    rows = int(round((right[-1][0] + L / 2 + L) / step))
    lines = [
        "# Jointed track with its own geometry on each rail, written by scripts/make-uneven-joints-track.py, which",
        f"# states the rule: {L:g} ft rails, the right rail's joints {a.stagger:g} rail after the left's, each rail the",
        "# report's rectified sine -d_j (1 - |sin(pi (s - s_j) / L)|) around each joint j, level at mid-rail,",
        f"# d_j = depth (1 + {a.scatter:g} u_j), u_j uniform in [-1, 1] from random.Random({a.seed}); depths {a.left_depth:g} in",
        f"# (left) and {a.right_depth:g} in (right). Options: --rail-length {L:g} --joints {a.joints} --left-depth "
        f"{a.left_depth:g} --right-depth {a.right_depth:g} --stagger {a.stagger:g} --scatter {a.scatter:g} --seed {a.seed}",
        "# Joints (distance ft, depth in), left: " + ", ".join(f"{s:g} {d:.4f}" for s, d in left),
        "# right: " + ", ".join(f"{s:g} {d:.4f}" for s, d in right),
        "distance [ft], left [in], right [in]",
    ]
    for i in range(rows + 1):
        s = i * step
        lines.append(f"{s:.2f}, {rail(s, left, L):.6f}, {rail(s, right, L):.6f}")
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {os.path.normpath(a.out)} ({rows + 1} rows)")


if __name__ == "__main__":
    main()
