#!/usr/bin/python3
"""Writes scenarios/tracks/federal-harmonics-1.25in.csv: jointed track with staggered joints
at the US track-safety "harmonics" limit (49 CFR 213.63, footnote 2, Classes 2-5):

  "However, to control harmonics on Class 2 through 5 jointed track with staggered joints,
   the crosslevel differences shall not exceed 1 1/4 inches in all of six consecutive pairs
   of joints, as created by 7 low joints."

Rule used (docs/cli.md, "Measured track"): 39 ft rails, joints staggered by half a rail; seven
low joints, four on the left rail and three on the right, alternating; each rail between
its low joints the report's rectified sine (eqs 1-2), z = A (|sin(pi (s - s_j) / L)| - 1),
level at mid-rail (z = 0) and A below it at a low joint, with A = 1.25 in / 2, so the
cross-level changes by exactly 1.25 in from each low joint to the next (six consecutive
pairs). Each rail is level before its first and after its last half rail of dips. One rail
of level track leads in; the table runs to 390 ft, level after the last dip. Sampled every
L/100 = 0.39 ft, so every low joint falls on a row. Test: MeasuredTrack.FederalHarmonicsTableObeysItsRule.

Rerun after changing it: /usr/bin/python3 scripts/make-federal-harmonics-track.py
"""
import math
import os

L = 39.0             # rail length [ft]
DIFFERENCE = 1.25    # cross-level difference between consecutive low joints [in]
A = DIFFERENCE / 2   # each rail's dip at its low joint [in]
STEP = L / 100       # [ft]
ROWS = 1000          # 0 .. 390 ft
FIRST_JOINT = L + L / 2  # the first low joint (left rail), after one level rail
LEFT_JOINTS = [FIRST_JOINT + k * L for k in range(4)]
RIGHT_JOINTS = [FIRST_JOINT + L / 2 + k * L for k in range(3)]


def rail(s, joints):
    """Rail-top height [in] at s [ft]: the rectified sine between half a rail before the
    first and half a rail after the last of its low joints, level elsewhere."""
    if s < joints[0] - L / 2 or s > joints[-1] + L / 2:
        return 0.0
    return A * (abs(math.sin(math.pi * (s - joints[0]) / L)) - 1)


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenarios", "tracks",
                       "federal-harmonics-1.25in.csv")
    lines = [
        "# US track-safety 'harmonics' limit on jointed track with staggered joints (49 CFR 213.63, footnote 2,",
        "# Classes 2-5): \"the crosslevel differences shall not exceed 1 1/4 inches in all of six consecutive",
        "# pairs of joints, as created by 7 low joints\". Written by scripts/make-federal-harmonics-track.py, which",
        "# states the rule: 39 ft rails, joints staggered by half a rail, low joints at "
        + ", ".join(f"{s:g}" for s in sorted(LEFT_JOINTS + RIGHT_JOINTS)) + " ft",
        "# (left rail at " + ", ".join(f"{s:g}" for s in LEFT_JOINTS) + "), each rail the report's rectified sine",
        f"# A (|sin(pi (s - s_j) / L)| - 1) with A = {A:g} in between its dips, level elsewhere: the cross-level",
        f"# changes by {DIFFERENCE:g} in from each low joint to the next. Heights positive up.",
        "distance [ft], left [in], right [in]",
    ]
    for i in range(ROWS + 1):
        s = i * STEP
        lines.append(f"{s:.2f}, {rail(s, LEFT_JOINTS):.6f}, {rail(s, RIGHT_JOINTS):.6f}")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {os.path.normpath(out)} ({ROWS + 1} rows)")


if __name__ == "__main__":
    main()
