#!/usr/bin/env python3
"""The 3D sphere on the rigid plane against the GetFEM peer, side by side.

The peer (../shared/peers/getfem3d, not part of the project) is a GetFEM
script of the scene of prm/hertz_sphere.prm: the neo-Hookean octant of the
ball on the rigid plane, quadratic tetrahedra, an augmented Lagrangian
contact brick solved by GetFEM's Newton method with sequential MUMPS, the
full load in one step. It runs on one core (OMP_NUM_THREADS =
OPENBLAS_NUM_THREADS = 1), as its README prescribes, from a temporary copy
and with Debian's /usr/bin/python3.

For each peer level and each of our sizes (global:local refinements of
prm/hertz_sphere.prm, optionally :radius of the refined ball) the programs
are run in turn, run after run, `--runs` times, as whole processes. The
table gives the median wall times, the iterations and each code's p0
against its OWN converged p0 (issue 39 compares the codes at equal
accuracy, 0.5 % of each one's converged p0):
- the peer's: the nominal p0 of the finest level in the peer's own
  results.csv (level 6, 221 238 DoFs);
- ours: --converged, by default the p0 of prm/hertz_sphere.prm at Global
  refinements = 4 (1 179 831 DoFs), measured on 2026-11-27 at 186a7ac
  (doc/performance.md, "One load step"; 1 and 2 load steps agree to
  1e-13).
The last column divides the peer's median at its cheapest level within the
accuracy by each of our runs' median.

Usage:
  python3 benchmarks/peer_getfem3d.py [--binary build/signorini]
      [--peer ../shared/peers/getfem3d] [--runs 3] [--levels 1,2]
      [--sizes 2:4:0.06,2:5:0.06,2:6] [--ranks 1,2] [--accuracy 0.005]
Needs apt-get install python3-getfem python3-scipy gmsh, and the peer's
folder; without either it says which is missing and exits with status 77
(skipped).
"""

import csv
import json
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
OURS_CONVERGED = 6.930122  # hertz_p0 at 1 179 831 DoFs (see the docstring)
PYTHON = "/usr/bin/python3"


def peer_converged(peer_dir):
    """The nominal p0 of the finest untagged level of the peer's results."""
    with open(os.path.join(peer_dir, "results.csv")) as f:
        rows = [r for r in csv.DictReader(f) if not r["tag"]]
    finest = max(rows, key=lambda r: int(r["dofs_u"]))
    return float(finest["p0_nominal"]), int(finest["dofs_u"])


def peer_version():
    out = subprocess.run(["dpkg-query", "-W", "-f", "${Version}",
                          "python3-getfem"], capture_output=True, text=True)
    return out.stdout.strip() or "unknown"


def run_peer(work, level):
    """One run of the peer at @p level: (wall s, Newton its, p0, DoFs)."""
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    out_dir = os.path.join(work, f"L{level}")
    cmd = [PYTHON, "hertz3d.py", "--level", str(level), "--out", out_dir,
           "--csv", os.path.join(work, "runs.csv")]
    start = time.perf_counter()
    out = subprocess.run(cmd, cwd=work, env=env, capture_output=True,
                         text=True)
    wall = time.perf_counter() - start
    if out.returncode != 0:
        raise RuntimeError(f"peer level {level} failed:\n{out.stdout[-2000:]}"
                           f"\n{out.stderr[-2000:]}")
    with open(os.path.join(out_dir, "summary.json")) as f:
        s = json.load(f)
    return wall, s["newton_its"], s["nominal_ref"]["p_max"], s["dofs_u"]


def run_ours(binary, size, ranks, work):
    """One run of prm/hertz_sphere.prm at @p size 'G:L[:radius]'."""
    f = size.split(":")
    mesh = {"Global refinements": f[0], "Local refinements": f[1]}
    if len(f) > 2:
        mesh["Local refinement radius"] = f[2]
    wall, s = bench_common.run_variant(binary, "hertz_sphere.prm", work,
                                       {"Mesh": mesh}, ranks)
    return (wall, bench_common.iterations(s),
            s["quantities"]["hertz_p0"]["value"], s["mesh"]["dofs"])


def main():
    parser = bench_common.peer_parser(__doc__, "getfem3d")
    parser.add_argument("--levels", default="1,2")
    parser.add_argument("--sizes", default="2:4:0.06,2:5:0.06,2:6")
    parser.add_argument("--ranks", default="1,2",
                        help="comma separated MPI rank counts for our runs")
    parser.add_argument("--accuracy", type=float, default=0.005)
    parser.add_argument("--converged", type=float, default=OURS_CONVERGED)
    args = bench_common.absolute_paths(parser.parse_args(), "binary", "peer")
    try:
        subprocess.run([PYTHON, "-c", "import getfem"], check=True,
                       capture_output=True)
    except (OSError, subprocess.CalledProcessError):
        bench_common.skip("peer_getfem3d.py", "the peer needs GetFEM's Python "
                          f"module, which {PYTHON} cannot import (apt-get "
                          "install python3-getfem python3-scipy gmsh)")
    binary = args.binary
    peer_dir = args.peer
    for needed in ("hertz3d.py", "results.csv"):
        if not os.path.isfile(os.path.join(peer_dir, needed)):
            bench_common.skip("peer_getfem3d.py", f"no peer model in {peer_dir} "
                              f"({needed}; pass --peer DIR)")
    bench_common.require_binary("peer_getfem3d.py", binary)
    p0_peer, peer_finest = peer_converged(peer_dir)
    levels = [int(x) for x in args.levels.split(",") if x]
    sizes = [x for x in args.sizes.split(",") if x]
    ranks = [int(x) for x in args.ranks.split(",") if x]
    info = bench_common.machine_info()
    print(bench_common.stamp(info, sys.argv, binary))
    print(f"peer: GetFEM {peer_version()} (python3-getfem), converged p0 "
          f"{p0_peer} (its {peer_finest}-DoF level); ours: converged p0 "
          f"{args.converged}")

    runs = [("peer", level, 1) for level in levels] + \
        [("ours", size, n) for size in sizes for n in ranks]
    times = {r: [] for r in runs}
    last = {}
    with tempfile.TemporaryDirectory(prefix="getfem3d_") as tmp:
        peer_work = os.path.join(tmp, "peer")
        shutil.copytree(peer_dir, peer_work,
                        ignore=shutil.ignore_patterns("results", "*.csv"))
        for _ in range(args.runs):
            for run in runs:
                kind, size, n = run
                if kind == "peer":
                    res = run_peer(peer_work, size)
                else:
                    work = os.path.join(tmp, f"ours_{size}_{n}")
                    os.makedirs(work, exist_ok=True)
                    res = run_ours(binary, size, n, work)
                times[run].append(res[0])
                last[run] = res

    rows = []
    for run in runs:
        kind, size, n = run
        _, its, p0, dofs = last[run]
        converged = p0_peer if kind == "peer" else args.converged
        rows.append({"run": run, "median": statistics.median(times[run]),
                     "error": p0 / converged - 1., "its": its, "dofs": dofs,
                     "p0": p0})
    within = [r for r in rows if r["run"][0] == "peer"
              and abs(r["error"]) <= args.accuracy]
    yardstick = min((r["median"] for r in within), default=None)
    print("| program | size | ranks | DoFs | iterations | p0 | p0 vs own "
          "converged | wall s (median; min-max) | peer's cheapest within "
          "the accuracy / this |")
    print("|" + "---|" * 9)
    for r in rows:
        kind, size, n = r["run"]
        t = times[r["run"]]
        ratio = "–" if yardstick is None or kind == "peer" or \
            abs(r["error"]) > args.accuracy else f"{yardstick / r['median']:.2f}"
        print(f"| {'GetFEM' if kind == 'peer' else 'signorini'} | "
              f"{'level ' + str(size) if kind == 'peer' else size} | {n} | "
              f"{r['dofs']} | {r['its']} | {r['p0']:.5f} | "
              f"{100 * r['error']:+.2f}% | {r['median']:.2f} "
              f"({min(t):.2f}-{max(t):.2f}) | {ratio} |")


if __name__ == "__main__":
    main()
