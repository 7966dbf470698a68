#!/usr/bin/env python3
"""Rigid Hertz against the FreeFEM+IPOPT peer model, side by side.

The peer (../shared/peers/freefem, not part of the project) is an
independent FreeFEM script of the same scene: the neo-Hookean half disk on
the rigid plane, u_x = 0 on the whole top edge, the full load in one step,
minimised by IPOPT. prm/hertz_peer.prm is our copy of that scene. For each
pair of sizes (a peer mesh level, our global and local refinements of about
the same DoFs), the two programs are run in turn, alternating, `--runs`
times each, as whole processes (wall time of the process: start-up, mesh,
solve and output); the table gives the medians, their ratio, the solver
iterations and p0 against the converged model (p0 = 10.92,
doc/performance.md; the two programs define the contact half-width a
differently, so it is left out).

Usage:
  python3 benchmarks/peer_freefem.py [--binary build/signorini]
      [--peer ../shared/peers/freefem] [--runs 3]
      [--methods ipopt,newton-penalty] [--sizes 6:3:5,8:4:6,...]
      [--ranks 1] [--fields]

--sizes: comma-separated 'peer level:global refinements:local refinements'
  with an optional ':radius' of the locally refined ball (default: the
  scene's 0.2; 10:3:7:0.25 gives 202 692 DoFs against the peer's 2.0e5).
--fields: our runs write their VTU fields as a user's run does (default:
  Output > Format = none, as the peer writes only a profile CSV).
Needs FreeFem++ (Debian package freefem++) and the peer's folder; without
either it says which is missing and exits with status 77 (skipped).
Python 3 standard library only.
"""

import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_common  # noqa: E402

ROOT = bench_common.ROOT
P0_CONVERGED = 10.92


def run_peer(peer_dir, level, work):
    """One run of the peer; returns (wall s, iterations, p0, DoFs)."""
    env = dict(os.environ, FF_LOADPATH="/usr/lib/freefem++")
    cmd = ["FreeFem++", "-nw", "-v", "0", "hertz_rigid.edp", "-DORDER=1",
           "-level", str(level), "-igrade", "0.2", "-out", "profiles",
           "-ipoptopt", "ipopt.opt"]
    start = time.perf_counter()
    out = subprocess.run(cmd, cwd=work, env=env, capture_output=True,
                         text=True)
    wall = time.perf_counter() - start
    result = [l for l in out.stdout.splitlines() if l.startswith("RESULT,")]
    if out.returncode != 0 or not result:
        raise RuntimeError(f"peer level {level} failed:\n{out.stdout[-2000:]}"
                           f"\n{out.stderr[-2000:]}")
    f = result[-1].split(",")
    iterations = None
    for line in out.stdout.splitlines():
        if line.strip().startswith("Number of Iterations"):
            iterations = int(line.split(":")[1])
    # RESULT,level,order,nv,ndof,ncon,status,nhess,clock,clock_ipopt,hf,
    # a_mid,p0h,...
    return wall, iterations, float(f[12]), int(f[4])


def run_ours(binary, method, glob, local, radius, ranks, fields, work):
    """One run of signorini; returns (wall s, iterations, p0, DoFs)."""
    overrides = {"Mesh": {"Global refinements": glob,
                          "Local refinements": local},
                 "Solver": {"Method": method}}
    if radius is not None:
        overrides["Mesh"]["Local refinement radius"] = radius
    extra = ("subsection Output\n  set Format = vtu\n"
             "  set Verbosity = quiet\nend\n") if fields else ""
    wall, s = bench_common.run_variant(binary, "hertz_peer.prm", work,
                                       overrides, ranks, extra)
    q = {k: v["value"] if isinstance(v, dict) else v
         for k, v in s["quantities"].items()}
    return wall, bench_common.iterations(s), q["hertz_p0"], s["mesh"]["dofs"]


def main():
    parser = bench_common.peer_parser(__doc__, "freefem")
    parser.add_argument("--methods", default="ipopt,newton-penalty",
                        help="comma separated; METHOD@RANKS runs that one "
                        "on RANKS MPI ranks (default --ranks)")
    parser.add_argument("--sizes", default="6:3:5,8:4:6,9:4:7")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--fields", action="store_true")
    parser.add_argument("--csv", default=None,
                        help="also write the table's rows here")
    args = bench_common.absolute_paths(parser.parse_args(), "binary", "peer",
                                       "csv")
    if shutil.which("FreeFem++") is None:
        bench_common.skip("peer_freefem.py", "the peer needs FreeFem++, which "
                          "is not installed (apt-get install freefem++ "
                          "libfreefem++)")
    if not os.path.isfile(os.path.join(args.peer, "hertz_rigid.edp")):
        bench_common.skip("peer_freefem.py", f"no peer model in {args.peer} "
                          "(hertz_rigid.edp; pass --peer DIR)")
    binary = args.binary
    bench_common.require_binary("peer_freefem.py", binary)
    methods = [m for m in args.methods.split(",") if m]
    sizes = []
    for s in args.sizes.split(","):
        f = s.split(":")
        sizes.append((int(f[0]), int(f[1]), int(f[2]),
                      float(f[3]) if len(f) > 3 else None))
    info = bench_common.machine_info()
    print(bench_common.stamp(info, sys.argv, binary))

    rows = []
    with tempfile.TemporaryDirectory(prefix="peer_") as tmp:
        peer_work = os.path.join(tmp, "peer")
        shutil.copytree(os.path.abspath(args.peer), peer_work,
                        ignore=shutil.ignore_patterns("logs", "profiles",
                                                      "*.csv"))
        os.makedirs(os.path.join(peer_work, "profiles"), exist_ok=True)
        for level, glob, local, radius in sizes:
            times = {"peer": []}
            times.update({m: [] for m in methods})
            last = {}
            for r in range(args.runs):
                # Alternate: peer, then each of ours, run after run.
                res = run_peer(peer_work, level, peer_work)
                times["peer"].append(res[0])
                last["peer"] = res
                for m in methods:
                    work = os.path.join(tmp, f"{m}_{glob}_{local}")
                    os.makedirs(work, exist_ok=True)
                    method, _, ranks = m.partition("@")
                    res = run_ours(binary, method, glob, local, radius,
                                   int(ranks) if ranks else args.ranks,
                                   args.fields, work)
                    times[m].append(res[0])
                    last[m] = res
            peer_median = statistics.median(times["peer"])
            for name in ["peer"] + methods:
                wall, its, p0, dofs = last[name]
                median = statistics.median(times[name])
                rows.append({
                    "program": "FreeFEM+IPOPT" if name == "peer"
                    else f"signorini {name}",
                    "size": f"level {level}" if name == "peer"
                    else f"{glob}+{local}" + (f" r{radius}" if radius else ""),
                    "DoFs": dofs, "iterations": its,
                    "wall median s": median,
                    "wall min s": min(times[name]),
                    "wall max s": max(times[name]),
                    "peer / this": peer_median / median,
                    "p0 error": p0 / P0_CONVERGED - 1.})
    head = ("| program | size | DoFs | iterations | wall s (median; min-max)"
            " | peer/this | p0 vs converged |")
    print(head)
    print("|" + "---|" * 7)
    for r in rows:
        print(f"| {r['program']} | {r['size']} | {r['DoFs']} | "
              f"{r['iterations']} | {r['wall median s']:.2f} "
              f"({r['wall min s']:.2f}-{r['wall max s']:.2f}) | "
              f"{r['peer / this']:.2f} | {100 * r['p0 error']:+.2f}% |")
    if args.csv:
        with open(args.csv, "w") as f:
            f.write(",".join(rows[0].keys()) + "\n")
            for r in rows:
                f.write(",".join(str(v) for v in r.values()) + "\n")


if __name__ == "__main__":
    main()
