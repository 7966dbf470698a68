#!/usr/bin/env python3
"""The large 3D scenes on 2 ranks: two bodies at 1.6e6 DoFs
(prm/hertz_sphere_block_large.prm, issue 39) or nine bodies at 1.1e6 DoFs
(prm/spheres_on_block_large.prm, issue 51).

--scene two-body (the default) runs the sphere on the elastic block (the
integral form, CG + AMG, the load path on 215 421 DoFs and one cycle that
refines every cell to 1 623 318); --scene many-bodies the eight spheres
pressed into one block (eight pairs, the load path on 144 939 DoFs and one
cycle that refines every cell). Each runs --runs times, whole process, and
reports per run the wall time, the time of each cycle, Newton and CG
iterations, the program's peak memory per rank, a and p0 against Hertz
(the worst pair where there are several) and p0's estimated error; then the
median wall time against the issues' 10 minutes. --quick runs the same
scene on a much coarser mesh, once unless --runs says otherwise (checks the
script, says nothing).

Usage:
  benchmarks/large_3d.py [--scene two-body|many-bodies]
                         [--binary build/signorini] [--runs 3]
                         [--quick] [--markdown FILE]
Python 3 standard library only.
"""

import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_common as bc  # noqa: E402

# scene: (parameter file, overrides of --quick, markdown block, output folder)
SCENES = {
    "two-body": ("hertz_sphere_block_large.prm",
                 {"Mesh": {"Global refinements": 0}},
                 "two-body-large", "two_body_large"),
    "many-bodies": ("spheres_on_block_large.prm",
                    {"Mesh": {"Global refinements": 0, "Local refinements": 3}},
                    "many-bodies-large", "many_bodies_large"),
}
GOAL_SECONDS = 600.


def worst(quantities, suffix, key):
    """The largest |key| over the quantities named suffix or pairK_suffix."""
    values = [abs(v[key]) for name, v in quantities.items()
              if (name == suffix or name.endswith("_" + suffix))
              and isinstance(v, dict) and v.get(key) is not None]
    return max(values) if values else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scene", choices=sorted(SCENES), default="two-body")
    ap.add_argument("--binary", default=os.path.join(bc.ROOT, "build", "signorini"))
    ap.add_argument("--runs", type=int, default=None,
                    help="default 3, with --quick 1")
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--markdown", help="write the table into this file "
                    "between <!-- two-body-large BEGIN/END --> markers "
                    "(many-bodies-large with --scene many-bodies)")
    ap.add_argument("--work", help="default output/two_body_large or "
                    "output/many_bodies_large")
    args = ap.parse_args()
    scene, quick_overrides, marker, folder = SCENES[args.scene]
    if args.work is None:
        args.work = os.path.join(bc.ROOT, "output", folder)
    args = bc.absolute_paths(args, "binary", "work", "markdown")
    bc.require_binary("large_3d.py", args.binary)
    info = bc.machine_info()
    bc.warn_if_busy(info)
    if args.runs is None:
        args.runs = 1 if args.quick else 3
    overrides = quick_overrides if args.quick else {}
    rows, walls = [], []
    for run in range(args.runs):
        work = os.path.join(args.work, f"run{run}")
        os.makedirs(work, exist_ok=True)
        wall, summary = bc.run_variant(args.binary, scene, work, overrides,
                                       ranks=args.ranks)
        cycles = summary["mesh refinement"]["cycles"]
        q = summary["quantities"] \
            if isinstance(summary.get("quantities"), dict) else {}
        walls.append(wall)
        rows.append([
            run + 1,
            " → ".join(f"{c['dofs']:,}".replace(",", " ") for c in cycles),
            " + ".join(f"{c['cycle wall time [s]']:.0f} s" for c in cycles),
            " + ".join(str(c["newton iterations"]) for c in cycles),
            bc.linear_iterations(summary),
            bc.fmt(bc.peak_memory_mb(summary), ".0f"),
            bc.fmt(worst(q, "hertz_a", "relative error"), ".2%"),
            bc.fmt(worst(q, "hertz_p0", "relative error"), ".2%"),
            bc.fmt(worst(q, "hertz_p0", "estimated relative error"), ".2%"),
            f"{wall:.1f} s",
        ])
        print(f"run {run + 1}: {wall:.1f} s", flush=True)
    median = statistics.median(walls)
    header = ["run", "DoFs per cycle", "time per cycle", "Newton its per cycle",
              "CG its", "peak MB per rank", "a vs Hertz", "p0 vs Hertz",
              "p0 estimated", "whole process"]
    text = "\n\n".join([
        bc.stamp(info, sys.argv, args.binary, args.quick),
        bc.markdown_table(header, rows),
        f"**Median {median:.1f} s on {args.ranks} ranks against the goal of "
        f"{GOAL_SECONDS:.0f} s: {'met' if median <= GOAL_SECONDS else 'not met'}.**"])
    print(text)
    if args.markdown:
        bc.replace_block(args.markdown, marker, text)


if __name__ == "__main__":
    main()
