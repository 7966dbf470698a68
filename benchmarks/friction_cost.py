#!/usr/bin/env python3
"""What Coulomb friction costs (issue 50): the Cattaneo-Mindlin scenes (2D
and 3D) with friction (P, then Q in one step, and as committed) against the
same mesh frictionless with P only (the issue's yardstick: at most 2x), and the
sliding block with
friction against the same path frictionless. The two runs of a pair
alternate, --runs times each; the table gives the medians of the whole
process's wall time, the iterations and the ratio. Writes the table into
doc/friction.md between its FRICTION_COST markers (not with --quick or
--no-doc) and prints it.

    python3 benchmarks/friction_cost.py [--binary build/signorini]
                                        [--runs 3] [--out DIR]
                                        [--quick] [--no-doc]

--quick runs the sliding block pair once: a check of the script.
"""

import argparse
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_common as bc  # noqa: E402

# (name, scene, overrides with friction, overrides without)
# P over t in [0, 1] in two steps, then Q/(mu P) = 0.75 in one (t = 1.5).
ONE_Q_STEP = {"Boundary conditions": {
                  "Prescribed displacement": "0.01158*max(t - 1, 0); -0.0116*min(t, 1)"},
              "Load stepping": {"End time": 1.5, "Number of steps": 3}}
P_ONLY = {"Contact/Friction": {"Coefficient": 0},
          "Contact/Friction/Mindlin reference": {"Active": "false"},
          "Load stepping": {"End time": 1, "Number of steps": 2}}
REFINED = {"Mesh": {"Local refinements": 6}}
# 3D: the quarter ball pressed over 0 <= t <= 2 in two steps, then
# Q/(mu P) = 0.75 in one (the scene's dq is the ratio per unit time).
ONE_Q_STEP_3D = {"Boundary conditions": {"Function constants": "muP=0.09696, dq=0.75"},
                 "Load stepping": {"End time": 3, "Number of steps": 3}}
P_ONLY_3D = {"Contact/Friction": {"Coefficient": 0},
             "Contact/Friction/Mindlin reference": {"Active": "false"},
             "Load stepping": {"End time": 2, "Number of steps": 2}}

PAIRS = [
    ("Cattaneo-Mindlin 2D: P in 2 steps, Q/(mu P) = 0.75 in 1 / frictionless P only",
     "cattaneo_mindlin_2d.prm", ONE_Q_STEP, P_ONLY),
    ("the same refined once", "cattaneo_mindlin_2d.prm", {**ONE_Q_STEP, **REFINED},
     {**P_ONLY, **REFINED}),
    ("Cattaneo-Mindlin 2D as committed (P in 2 steps, Q in 6) / frictionless P only",
     "cattaneo_mindlin_2d.prm",
     {}, P_ONLY),
    ("the same refined once", "cattaneo_mindlin_2d.prm", REFINED, {**P_ONLY, **REFINED}),
    ("Cattaneo-Mindlin 3D: P in 2 steps, Q/(mu P) = 0.75 in 1 / frictionless P only",
     "cattaneo_mindlin_3d.prm", ONE_Q_STEP_3D, P_ONLY_3D),
    ("Cattaneo-Mindlin 3D as committed (P in 2 steps, Q in 3) / frictionless P only",
     "cattaneo_mindlin_3d.prm", {}, P_ONLY_3D),
    ("sliding block mu = 0.3 / the same path frictionless",
     "sliding_block.prm", {}, {"Contact/Friction": {"Coefficient": 0}}),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(bc.ROOT, "build", "signorini"))
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--out", default=None)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--no-doc", action="store_true")
    args = bc.absolute_paths(parser.parse_args(), "binary", "out")
    bc.require_binary("friction_cost.py", args.binary)
    info = bc.machine_info()
    bc.warn_if_busy(info)
    pairs = PAIRS[-1:] if args.quick else PAIRS
    runs = 1 if args.quick else args.runs
    out = args.out or tempfile.mkdtemp(prefix="friction_cost_")
    rows = []
    for name, scene, with_f, without_f in pairs:
        times = {"with": [], "without": []}
        its = {}
        for r in range(runs):
            for label, overrides in (("with", with_f), ("without", without_f)):
                work = os.path.join(out, f"{scene[:-4]}_{label}_{len(rows)}_{r}")
                os.makedirs(work, exist_ok=True)
                wall, summary = bc.run_variant(args.binary, scene, work, overrides)
                times[label].append(wall)
                its[label] = bc.iterations(summary)
        t_with = statistics.median(times["with"])
        t_without = statistics.median(times["without"])
        rows.append([name, bc.fmt(its["with"], "d"), bc.fmt(its["without"], "d"),
                     bc.fmt_time(t_with), bc.fmt_time(t_without),
                     f"{t_with / t_without:.2f}"])
        print(f"{name}: {t_with:.2f} s / {t_without:.2f} s", flush=True)
    table = bc.markdown_table(
        ["pair", "iterations with", "without", "median wall with", "without",
         "ratio"], rows)
    text = bc.stamp(info, sys.argv, args.binary, args.quick) + "\n\n" + table + "\n"
    print(text)
    if not args.quick and not args.no_doc:
        bc.replace_block(os.path.join(bc.ROOT, "doc", "friction.md"), "FRICTION_COST", text)


if __name__ == "__main__":
    main()
