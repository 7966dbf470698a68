#!/usr/bin/env python3
"""Hard cases (benchmarks.md section 5, issue "Hard cases stay numerically
stable"): run every scene of prm/hard/ with each solver that applies, at
full size, and report for each run whether it converged, its load steps and
step cuts, Newton or Ipopt iterations, the largest penalty factor, the
smallest J, the largest penetration over the element size and the wall
time. Writes the table to doc/robustness.md (between its TABLE markers) and
prints it.

    python3 benchmarks/hard_cases.py [--build build] [--only NAME ...]
                                     [--timeout SECONDS] [--no-doc]
                                     [--out DIR] [--quick]

The scenes include committed scenes by a path relative to prm/hard/, which
signorini resolves against the including file, so they run from any folder;
the runs start in prm/hard/ and their output goes to
build/output/hard/CASE_METHOD/ (--out DIR: DIR/CASE_METHOD/). --quick runs
the corner case with every solver and the stiff die on the soft block with
the penalty path (6 small runs, a few seconds: checks the script, and
leaves doc/robustness.md alone, as --only does).
"""

import argparse
import datetime
import json
import math
import os
import platform
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HARD = os.path.join(ROOT, "prm", "hard")

# Scene -> the solvers that apply to it (Method entries). "METHOD + CG" is
# the method with `Linear solver > Type = cg-amg` (CG + AMG with its
# fallback to the direct solver) instead of the direct solver; Ipopt
# factorises with its own MUMPS.
CASES = [
    ("ssnv187_nu4999", ["newton", "newton + CG"]),
    ("ssnv187_20x_load", ["newton", "newton + CG"]),
    ("ssnv187_corner", ["newton-penalty", "ipopt", "interior-point",
                        "newton-penalty + CG", "interior-point + CG"]),
    ("hertz_nu4999", ["newton-penalty", "ipopt", "interior-point",
                      "newton-penalty + CG", "interior-point + CG"]),
    ("hertz_tight_penetration", ["newton-penalty", "ipopt", "interior-point",
                                 "newton-penalty + CG", "interior-point + CG"]),
    ("hertz_initial_gap", ["newton-penalty", "ipopt", "interior-point",
                           "newton-penalty + CG", "interior-point + CG"]),
    ("hertz_initial_penetration", ["newton-penalty", "ipopt", "interior-point",
                                   "newton-penalty + CG", "interior-point + CG"]),
    ("stiff_on_soft_block", ["newton-penalty", "ipopt", "newton-penalty + CG"]),
    ("mesh_mismatch", ["newton-penalty", "ipopt", "newton-penalty + CG"]),
    ("ironing_grazing", ["newton-penalty", "ipopt", "newton-penalty + CG"]),
    ("ironing_full", ["newton-penalty", "ipopt", "newton-penalty + CG"]),
    # Coulomb friction (issue 50): mu = 1 and 0.01, a stick-slip reversal.
    ("friction_mu1", ["interior-point", "newton-penalty"]),
    ("friction_mu001", ["interior-point", "newton-penalty"]),
    ("friction_reversal", ["interior-point", "newton-penalty"]),
    ("ssnv128_mu001", ["interior-point", "newton-penalty"]),
]


# --quick: one small rigid case with every solver, one two-body case.
QUICK = ["ssnv187_corner", "stiff_on_soft_block"]


def run_case(executable, name, solver, out_root, timeout):
    method, _, linear = (part.strip() for part in solver.partition("+"))
    tag = method + ("_cg" if linear else "")
    folder = os.path.join(out_root, f"{name}_{tag}")
    os.makedirs(out_root, exist_ok=True)
    wrapper = os.path.join(out_root, f"{name}_{tag}.prm")
    linear_solver = ("  subsection Linear solver\n    set Type = cg-amg\n  end\n"
                     if linear else "")
    with open(wrapper, "w") as f:
        f.write(f"include {os.path.join(HARD, name + '.prm')}\n"
                f"set Output directory = {folder}\n"
                f"subsection Solver\n  set Method = {method}\n{linear_solver}end\n"
                "subsection Output\n  set Format = none\n  set Verbosity = quiet\nend\n")
    start = time.time()
    try:
        proc = subprocess.run([executable, wrapper], cwd=HARD, timeout=timeout,
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                              text=True)
        code, message = proc.returncode, proc.stderr.strip().splitlines()
    except subprocess.TimeoutExpired:
        code, message = None, [f"killed after {timeout} s"]
    wall = time.time() - start
    row = {"case": name, "solver": solver, "exit": code, "wall": wall,
           "message": message[-1] if message else ""}
    summary = os.path.join(folder, "summary.json")
    if code is not None and os.path.exists(summary):
        with open(summary) as f:
            s = json.load(f)
        steps = s.get("steps", [])
        mus = [st["mu"] for step in steps for st in step.get("penalty stages", [])]
        row.update({
            "status": s["status"],
            "steps": s["load steps"],
            "cuts": s["step cuts"],
            "iterations": s.get("ipopt iterations",
                                s.get("interior_point iterations",
                                      s.get("newton iterations"))),
            "mu": max(mus) if mus else None,
            "min_J": min((step["min J"] for step in steps), default=None),
            "penetration": max((step.get("max penetration over h", 0.)
                                for step in steps), default=None),
            "dofs": s["mesh"]["dofs"],
        })
        if s["status"] != "converged":
            row["message"] = s.get("reason", row["message"])
    else:
        row["status"] = "no result"
    return row


def fmt(value, spec):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "–"
    return format(value, spec)


def table(rows):
    lines = ["| case | solver | DoFs | converged | load steps (cuts) | iterations "
             "| largest μ | min J | max penetration / h | wall time [s] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        converged = "yes" if r.get("status") == "converged" else \
            f"**no**: {r.get('message', '')[:160]}"
        lines.append(
            f"| {r['case']} | {r['solver']} | {fmt(r.get('dofs'), 'd')} | {converged} "
            f"| {fmt(r.get('steps'), 'd')} ({fmt(r.get('cuts'), 'd')}) "
            f"| {fmt(r.get('iterations'), 'd')} | {fmt(r.get('mu'), '.2e')} "
            f"| {fmt(r.get('min_J'), '.3f')} | {fmt(r.get('penetration'), '.1e')} "
            f"| {r['wall']:.1f} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--only", nargs="*", help="case names to run")
    parser.add_argument("--timeout", type=float, default=3600.)
    parser.add_argument("--no-doc", action="store_true",
                        help="do not rewrite doc/robustness.md")
    parser.add_argument("--out", help="folder of the runs (default "
                        "BUILD/output/hard)")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    executable = os.path.join(os.path.abspath(args.build), "signorini")
    out_root = os.path.abspath(args.out) if args.out else \
        os.path.join(os.path.abspath(args.build), "output", "hard")
    if not os.access(executable, os.X_OK):
        sys.exit(f"hard_cases.py: no executable {executable}: build first "
                 "(bash scripts/setup.sh)")
    rows = []
    for name, methods in CASES:
        if args.only and name not in args.only:
            continue
        if args.quick:
            if name not in QUICK:
                continue
            methods = methods if name == QUICK[0] else methods[:1]
        for method in methods:
            row = run_case(executable, name, method, out_root, args.timeout)
            rows.append(row)
            print(f"{name:28s} {method:20s} {row.get('status', ''):10s} "
                  f"{row['wall']:7.1f} s", flush=True)
    text = table(rows)
    print(text)
    n_ok = sum(r.get("status") == "converged" for r in rows)
    print(f"{n_ok} converged, {len(rows) - n_ok} not converged")
    if not args.no_doc and not args.only and not args.quick:
        doc = os.path.join(ROOT, "doc", "robustness.md")
        with open(doc) as f:
            content = f.read()
        begin, end = "<!-- TABLE BEGIN -->", "<!-- TABLE END -->"
        head, rest = content.split(begin)
        _, tail = rest.split(end)
        stamp = (f"Measured {datetime.date.today()} on {platform.machine()}, "
                 f"{os.cpu_count()} cores, one MPI rank, by "
                 "`python3 benchmarks/hard_cases.py`.")
        with open(doc, "w") as f:
            f.write(f"{head}{begin}\n{stamp}\n\n{text}\n\n{n_ok} of {len(rows)} "
                    f"runs converged.\n{end}{tail}")
    return 0 if n_ok == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
