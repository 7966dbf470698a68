#!/usr/bin/env python3
"""Direct solvers and MPI ranks on one contact scene, alternating.

Runs a scene (default: prm/hertz_peer.prm, rigid Hertz as the FreeFEM peer
sets it up) with each (direct solver, ranks) variant in turn, run after run
(A B C A B C ...), and prints per variant the median whole-process wall time
with its range, the medians of the run's own `linear solve` and `assembly`
timers, the iterations, and the ratio of each median to the first variant's.
Every run's quantities must agree with the first variant's (p0 and a to the
given tolerance), so that a faster solver is not a different answer.

    python3 benchmarks/direct_solvers.py --sizes 3:5,3:6 --runs 3 \\
        --variants Amesos_Mumps@1,Amesos_Mumps@1x2,PETSc_Mumps@1,Amesos_Klu@2,PETSc_Mumps@2

A variant is SOLVER@RANKS or SOLVER@RANKSxTHREADS (threads per rank,
default 1, through DEAL_II_NUM_THREADS); SOLVER is a value of `Solver >
Linear solver > Direct solver`. --method sets `Solver > Method` (default interior-point).
--markdown FILE puts the table between the DIRECT-SOLVERS markers there.
--quick: one run of each of PETSc_Mumps@1 and Amesos_Klu@2 at size 3:4
(checks the script in a few seconds, says nothing).
"""
import argparse
import os
import statistics
import sys
import tempfile

import bench_common

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(binary, scene, work, glob, local, method, solver, ranks, threads):
    """One run; returns (wall s, summary)."""
    overrides = {"Mesh": {"Global refinements": glob,
                          "Local refinements": local},
                 "Solver": {"Method": method},
                 "Solver/Linear solver": {"Type": "direct",
                                          "Direct solver": solver}}
    os.makedirs(work, exist_ok=True)
    prm = os.path.join(work, "run.prm")
    with open(prm, "w") as f:
        f.write(bench_common.variant_text(scene, work, overrides))
    wall, out = bench_common.run_timed(
        binary, prm, work, ranks, {"DEAL_II_NUM_THREADS": str(threads)})
    summary = bench_common.read_json(os.path.join(work, "summary.json"))
    if out.returncode not in (0, 4) or not summary:
        raise RuntimeError(f"{solver}@{ranks}x{threads} failed ({out.returncode}):\n"
                           f"{out.stdout[-2000:]}\n{out.stderr[-2000:]}")
    return wall, summary


def quantity(summary, name):
    q = summary.get("quantities", {}).get(name)
    return q["value"] if isinstance(q, dict) else q


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build",
                                                         "signorini"))
    parser.add_argument("--scene", default=os.path.join(ROOT, "prm",
                                                        "hertz_peer.prm"))
    parser.add_argument("--method", default="interior-point")
    parser.add_argument("--sizes", default="3:5,3:6",
                        help="GLOBAL:LOCAL refinements, comma separated")
    parser.add_argument("--variants", default="Amesos_Mumps@1,Amesos_Mumps@1x2,"
                        "PETSc_Mumps@1,Amesos_Klu@2,PETSc_Mumps@2")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--agree", type=float, default=1e-6,
                        help="largest relative difference of a and p0 "
                        "from the first variant's")
    parser.add_argument("--markdown", default=None)
    parser.add_argument("--quick", action="store_true")
    args = bench_common.absolute_paths(parser.parse_args(), "binary", "scene",
                                       "markdown")
    if args.quick:
        args.sizes, args.runs = "3:4", 1
        args.variants = "PETSc_Mumps@1,Amesos_Klu@2"

    binary = args.binary
    bench_common.require_binary("direct_solvers.py", binary)
    variants = []
    for v in args.variants.split(","):
        solver, _, layout = v.partition("@")
        ranks, _, threads = (layout or "1").partition("x")
        variants.append((solver, int(ranks), int(threads or 1)))
    sizes = [tuple(int(x) for x in s.split(":")) for s in args.sizes.split(",")]
    info = bench_common.machine_info()
    bench_common.warn_if_busy(info)
    lines = [bench_common.stamp(info, sys.argv, binary, args.quick), "",
             f"Scene `{os.path.relpath(args.scene, ROOT)}`, `Solver > Method "
             f"= {args.method}`, threads per rank through `DEAL_II_NUM_THREADS`,"
             f" {args.runs} alternated runs per variant, whole process; "
             "`linear solve` and `assembly` are the run's own timers (largest "
             "over the ranks).", "",
             "| DoFs | solver | ranks x threads | iterations | wall s median "
             "(min-max) | linear solve s | assembly s | wall / first | agrees |",
             "|---|---|---|---|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory(prefix="direct_") as tmp:
        for glob, local in sizes:
            walls = {v: [] for v in variants}
            solves = {v: [] for v in variants}
            assembly = {v: [] for v in variants}
            last = {}
            for r in range(args.runs):
                for v in variants:
                    work = os.path.join(tmp, f"{v[0]}_{v[1]}x{v[2]}_{glob}_{local}")
                    wall, s = run(binary, args.scene, work, glob, local,
                                  args.method, v[0], v[1], v[2])
                    walls[v].append(wall)
                    t = bench_common.timing(s)
                    solves[v].append(t.get("linear solve", float("nan")))
                    assembly[v].append(t.get("assembly", float("nan")))
                    last[v] = s
                    print(f"{glob}+{local} {v[0]}@{v[1]}x{v[2]} run {r}: {wall:.2f} s",
                          file=sys.stderr)
            first = statistics.median(walls[variants[0]])
            ref = last[variants[0]]
            for v in variants:
                s = last[v]
                agree = all(
                    abs(quantity(s, k) / quantity(ref, k) - 1.) <= args.agree
                    for k in ("hertz_a", "hertz_p0")
                    if quantity(ref, k) is not None)
                med = statistics.median(walls[v])
                lines.append(
                    f"| {s['mesh']['dofs']} | {v[0]} | {v[1]} x {v[2]} | "
                    f"{bench_common.iterations(s)} | "
                    f"{med:.2f} ({min(walls[v]):.2f}-{max(walls[v]):.2f}) | "
                    f"{statistics.median(solves[v]):.2f} | "
                    f"{statistics.median(assembly[v]):.2f} | "
                    f"{med / first:.2f} | {'yes' if agree else 'NO'} |")
    text = "\n".join(lines)
    print(text)
    if args.markdown:
        bench_common.replace_block(args.markdown, "DIRECT-SOLVERS", text)


if __name__ == "__main__":
    main()
