#!/usr/bin/env python3
"""Compare the three rigid-contact solvers on the Hertz rigid-plane scene.

Runs prm/default.prm with Ipopt, the program's interior point method and
the penalty continuation (Newton)
at several local refinement levels, reads each run's summary.json and
prints a Markdown table (DOFs, contact nodes inside a, iterations, wall
time, errors of a and p0 against Hertz, total force error, largest
penetration over h). Python standard library only.

    python3 benchmarks/solver_comparison.py [--build build] [--levels 3 4 5]
        [--out output/solver_comparison]
"""
import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(executable, levels, method, out_root):
    name = f"{method}_L{levels}"
    folder = os.path.join(out_root, name)
    os.makedirs(out_root, exist_ok=True)
    prm = os.path.join(out_root, name + ".prm")
    with open(prm, "w") as f:
        f.write(f"include {ROOT}/prm/default.prm\n"
                f"set Output directory = {folder}\n"
                f"subsection Mesh\n  set Local refinements = {levels}\nend\n"
                f"subsection Solver\n  set Method = {method}\nend\n"
                "subsection Output\n  set Format = none\n  set Verbosity = quiet\nend\n")
    code = subprocess.run([executable, prm], check=False,
                          stdout=subprocess.DEVNULL).returncode
    try:
        with open(os.path.join(folder, "summary.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        sys.exit(f"solver_comparison.py: {method} at {levels} local "
                 f"refinements wrote no summary.json (exit {code}): {prm}")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--levels", type=int, nargs="+", default=[3, 4, 5])
    parser.add_argument("--out", default=os.path.join("output", "solver_comparison"))
    args = parser.parse_args()
    # The caller's paths, whatever folder the runs start in.
    args.build, args.out = os.path.abspath(args.build), os.path.abspath(args.out)
    executable = os.path.join(args.build, "signorini")
    if not os.access(executable, os.X_OK):
        sys.exit(f"solver_comparison.py: no executable {executable} (build "
                 "first: bash scripts/setup.sh, or pass --build)")

    rows = []
    for level in args.levels:
        for method in ("ipopt", "interior-point", "newton-penalty"):
            s = run(executable, level, method, args.out)
            q = s["quantities"]
            iterations = s.get("ipopt iterations", s.get("interior_point iterations",
                                                       s.get("newton iterations")))
            stages = sum(len(step.get("penalty stages", [])) for step in s["steps"])
            rows.append({
                "level": level,
                "method": method,
                "status": s["status"],
                "dofs": s["mesh"]["dofs"],
                "inside": int(q["contact_nodes_inside_a"]["value"]),
                "iterations": iterations,
                "stages": stages,
                "time": s["wall time [s]"]["total"],
                "err_a": q["hertz_a"]["relative error"],
                "err_p0": q["hertz_p0"]["relative error"],
                "err_force": q["contact_force_y"]["relative error"],
                "penetration": q["max_penetration_over_h"]["value"],
            })

    print("| local refinements | solver | DOFs | nodes inside a | iterations "
          "(penalty stages) | wall time [s] | a error | p0 error | force error "
          "| max penetration / h |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        it = f"{r['iterations']}" + (f" ({r['stages']})" if r["stages"] else "")
        status = "" if r["status"] == "converged" else f" ({r['status']})"
        print(f"| {r['level']} | {r['method']}{status} | {r['dofs']} | {r['inside']} "
              f"| {it} | {r['time']:.2f} | {100 * r['err_a']:.2f}% "
              f"| {100 * r['err_p0']:.2f}% | {r['err_force']:.1e} "
              f"| {r['penetration']:.1e} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
