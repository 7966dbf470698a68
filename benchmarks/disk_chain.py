#!/usr/bin/env python3
"""A vertical chain of N disks on the rigid plane (issue 51): the scene of
prm/disk_stack.prm with N bodies instead of three, N - 1 two-body pairs
(each disk's arc out of the disk below) and the foundation under the
lowest disk (Contact > Type = pairs). Body 1, on top, is the lower half of
its cylinder and carries P = 0.4 per unit thickness on its flat top; every
body has E = 200, nu = 0.3, R = 1; symmetry x = 0.

For each N it writes the scene, runs it once and prints DoFs, Newton
iterations, the broad phase's evaluated (point, face) pairs of the last
evaluation, the wall time of the run and of the contact terms, the worst
Hertz error of a and p0 over the pairs, and the worst body balance
|sum of contact forces + load| / (P/2).

  python3 benchmarks/disk_chain.py --binary build/signorini --out chain
  python3 benchmarks/disk_chain.py --quick ...   (N = 2, 3 on a coarse mesh)
  python3 benchmarks/disk_chain.py --modes chain,all,every --bodies 2,4,8
      (the search's cost: the neighbours' pairs, one search over every
      body, or every ordered pair as a part of its own)
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time


def scene(n, global_refinements, local_refinements, mode="chain"):
    """The parameter text of a chain of n bodies; mode: 'chain' lists the
    n - 1 pairs of neighbours, 'all' lets every body touch every other
    ('Two-body pairs = all' over the n arcs: one search), 'every' lists
    all n (n - 1) ordered pairs as parts of their own (one search each)."""
    lines = ["set Dimension = 2", "set Scene name = disk_chain_%d" % n,
             "subsection Mesh",
             "  set Global refinements = %d" % global_refinements,
             "  set Local refinements = %d" % local_refinements,
             "  set Local refinement center = " +
             "; ".join("0, %d" % (2 * k) for k in range(n)),
             "  set Local refinement radius = 0.1", "end"]
    fixed = []
    for b in range(1, n + 1):
        offset = 10 * (b - 1)
        lines += ["subsection Body %d" % b, "  set Active = true",
                  "  set Material id = %d" % (b - 1), "  subsection Geometry"]
        if b == 1:
            lines += ["    set Shape = quarter disk",
                      "    set Center = 0, %d" % (2 * n - 1)]
        else:
            lines += ["    set Shape = half disk", "    set Center = 0, 0",
                      "    set Boundary id offset = %d" % offset,
                      "    subsection Placement",
                      "      set Rotation angle = 90",
                      "      set Translation = 0, %d" % (2 * (n - b) + 1),
                      "    end"]
        lines += ["    set Radius = 1", "  end", "  subsection Material",
                  "    set Model = neo-Hookean",
                  "    set Young's modulus = 200",
                  "    set Poisson's ratio = 0.3", "  end", "end"]
        fixed.append("%d: x" % (offset + 1))
    arcs = [10 * b for b in range(n)]
    if mode == "chain":
        pairs = ", ".join("%d:%d" % (10 * (b - 1), 10 * b) for b in range(1, n))
    elif mode == "all":
        pairs = "all\n    set Contact boundaries = " + ", ".join(map(str, arcs))
    else:
        pairs = ", ".join("%d:%d" % (c, t) for c in arcs for t in arcs if c != t)
    hertz = []
    for k in range(1, n + 1 if mode == "chain" else 0):
        if k > 8:  # 'Pair K' subsections exist for K <= 8
            break
        second = "1" if k < n else "0"
        hertz += ["    subsection Pair %d" % k,
                  "      subsection Hertz reference",
                  "        set Line load = 0.4", "        set Radius = 1",
                  "        set Second radius = " + second,
                  "        set Modelled fraction = 0.5",
                  "        set Peak pressure from = fit",
                  "      end", "    end"]
    lines += ["subsection Boundary conditions",
              "  set Fixed boundaries = " + ", ".join(fixed),
              "  set Traction boundaries = 2",
              "  set Traction = 0; -0.2*t", "end",
              "subsection Load stepping", "  set Number of steps = 2", "end",
              "subsection Contact", "  set Type = pairs",
              "  subsection Pairs",
              "    set Two-body pairs = " + pairs,
              "    set Foundation boundary ids = %d" % (10 * (n - 1))] + hertz + [
              "  end",
              "  subsection Two bodies", "    set Contact form = integral",
              "  end", "  subsection Foundation", "    set Shape = plane",
              "  end", "end",
              "subsection Solver", "  set Method = newton-penalty",
              "  subsection Newton", "    set Residual tolerance = 1e-9",
              "  end", "  subsection Penalty",
              "    set Penetration tolerance = 1e-3",
              "    set Load step reduction = 10", "  end", "end",
              "subsection Output", "  set Format = none",
              "  set Verbosity = quiet", "end"]
    return "\n".join(lines) + "\n"


def main():
    here = os.getcwd()
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--binary", default="build/signorini")
    parser.add_argument("--out", default="disk_chain")
    parser.add_argument("--bodies", default="2,4,8,16")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--modes", default="chain",
                        help="comma-separated: chain (the neighbours' pairs), "
                        "all (Two-body pairs = all: one search), every (all "
                        "ordered pairs as parts: one search each)")
    args = parser.parse_args()
    binary = os.path.join(here, args.binary)
    out = os.path.join(here, args.out)
    os.makedirs(out, exist_ok=True)
    bodies = [2, 3] if args.quick else [int(b) for b in args.bodies.split(",")]
    refinements = (2, 3) if args.quick else (3, 5)
    modes = args.modes.split(",")
    print("| mode | bodies | parts | DoFs | Newton its | evaluated pairs (last) "
          "| contact [s] | contact per Newton it [ms] | run [s] "
          "| worst a, p0 error | worst balance |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for n, mode in [(n, m) for n in bodies for m in modes]:
        folder = os.path.join(out, "%s_%d" % (mode, n))
        prm = os.path.join(out, "%s_%d.prm" % (mode, n))
        with open(prm, "w") as f:
            f.write(scene(n, *refinements, mode).replace(
                "set Scene name", "set Output directory = %s\nset Scene name"
                % folder, 1))
        start = time.time()
        code = subprocess.call([binary, prm], stdout=subprocess.DEVNULL)
        seconds = time.time() - start
        if code != 0:
            print("disk_chain.py: %d bodies: exit %d" % (n, code))
            sys.exit(1)
        with open(os.path.join(folder, "summary.json")) as f:
            summary = json.load(f)
        q = {k: v["value"] for k, v in summary["quantities"].items()}
        errors = [summary["quantities"][k]["relative error"]
                  for k in summary["quantities"]
                  if k.endswith("_hertz_a") or k.endswith("_hertz_p0")]
        error = "%.2f%%" % (100 * max(errors)) if errors else "n/a"
        parts = len(summary["contact"].get("pairs", []))
        balance = max(abs(q["body%d_contact_force_y" % b]
                          - (0.2 if b == 1 else 0.)) / 0.2
                      for b in range(1, n + 1))
        with open(os.path.join(folder, "load_steps.csv")) as f:
            rows = [line.strip().split(",") for line in f]
        pairs = rows[-1][rows[0].index("evaluated_pairs")]
        wall = summary["wall time [s]"]
        contact = wall.get("contact", float("nan"))
        its = summary["newton iterations"]
        print("| %s | %d | %d | %d | %d | %s | %.2f | %.2f | %.1f | %s | %.1e |" % (
            mode, n, parts, summary["mesh"]["dofs"], its, pairs, contact,
            1e3 * contact / max(its, 1), seconds, error, balance))


if __name__ == "__main__":
    main()
