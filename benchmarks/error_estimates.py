#!/usr/bin/env python3
"""How well the estimated errors of summary.json bracket the true ones.

Runs committed contact scenes with adaptive refinement cycles, takes the
finest cycle as the converged model, and compares each estimable quantity's
estimated error at cycle k with its distance to that reference,
|Q_k - Q_finest|, for the cycles k that have an estimate and lie at least
two cycles below the finest (two halvings of the contact zone's cells: the
reference's own error is then a quarter or less of the error it judges, for
an order of 1 or more). The effectivity is estimate / true error; a pair
is "bracketed" when it lies in [1/3, 3]. Pairs whose estimate and true
error are both below 1e-6 of the quantity (round-off and the solvers'
tolerances, e.g. a resultant that the load fixes) cannot be judged and are
counted apart.

Usage:
  benchmarks/error_estimates.py [--binary build/signorini] [--quick]
                                [--from DIR] [--markdown FILE]
--from DIR reuses the runs of an earlier call (DIR/<scene>/summary.json).
--quick runs fewer cycles (checks the script, says nothing).
Python 3 standard library only.
"""

import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_common as bc  # noqa: E402

# name, committed scene, cycles (full, quick), other overrides
SCENES = [
    ("rigid Hertz 2D (hertz_adaptive)", "hertz_adaptive.prm", (9, 5),
     {"Mesh refinement": {"Maximum level": 20}}),
    ("Hertz on a block 2D, two bodies (hertz_block)", "hertz_block.prm", (5, 3),
     {}),
    ("rigid Hertz 3D (hertz_sphere, 3 local refinements)", "hertz_sphere.prm",
     (4, 3), {"Mesh": {"Local refinements": 3}}),
]


def cycles_of(summary):
    return summary["mesh refinement"]["cycles"]


def pairs(summary, skip_last=2):
    """(cycle, quantity, estimate, true error, scale) for every estimate."""
    cycles = cycles_of(summary)
    reference = cycles[-1]["quantities"]
    out = []
    for c in cycles[:len(cycles) - skip_last]:
        for name, estimate in c.get("estimated errors", {}).items():
            value = c["quantities"][name]
            scale = max(abs(value), abs(reference[name]))
            out.append((c["cycle"], name, estimate,
                        abs(value - reference[name]), scale))
    return out


def verdict(estimate, error, scale):
    if estimate <= 1e-6 * scale and error <= 1e-6 * scale:
        return "negligible"
    if error == 0.:
        return "out"
    eff = estimate / error
    return "in" if 1. / 3. <= eff <= 3. else "out"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--binary", default=os.path.join(bc.ROOT, "build", "signorini"))
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--from", dest="reuse")
    ap.add_argument("--work", default=os.path.join(bc.ROOT, "output", "error_estimates"))
    ap.add_argument("--markdown")
    args = bc.absolute_paths(ap.parse_args(), "binary", "reuse", "work",
                             "markdown")
    if not args.reuse:
        bc.require_binary("error_estimates.py", args.binary)
    info = bc.machine_info()
    work = args.reuse or args.work
    os.makedirs(work, exist_ok=True)
    sections, totals = [], {"in": 0, "out": 0, "negligible": 0}
    # The same from cycle 3 on, where the estimate is the four-mesh fit.
    fit_totals = {"in": 0, "out": 0, "negligible": 0}
    for title, scene, cycles, overrides in SCENES:
        folder = os.path.join(work, os.path.splitext(scene)[0])
        if not args.reuse:
            n = cycles[1] if args.quick else cycles[0]
            o = {k: dict(v) for k, v in overrides.items()}
            o.setdefault("Mesh refinement", {})["Number of cycles"] = n
            prm = os.path.join(work, os.path.splitext(scene)[0] + ".prm")
            with open(prm, "w") as f:
                f.write(bc.variant_text(os.path.join(bc.PRM, scene), folder, o))
            seconds, proc = bc.run_timed(args.binary, prm, work)
            print(f"{title}: {seconds:.1f} s, exit {proc.returncode}", file=sys.stderr)
        summary = bc.read_json(os.path.join(folder, "summary.json"))
        if not summary:
            print(f"{title}: no summary.json in {folder}", file=sys.stderr)
            continue
        rows, counts = [], {"in": 0, "out": 0, "negligible": 0}
        for cycle, name, estimate, error, scale in pairs(summary):
            v = verdict(estimate, error, scale)
            counts[v] += 1
            totals[v] += 1
            if cycle >= 3:
                fit_totals[v] += 1
            eff = estimate / error if error > 0. else math.inf
            s = scale if scale > 0. else 1.
            rows.append((cycle, name, bc.fmt(error / s), bc.fmt(estimate / s),
                         "–" if v == "negligible" else bc.fmt(eff), v))
        last = cycles_of(summary)[-1]
        text = [f"### {title}",
                f"{len(cycles_of(summary)) - 1} cycles, the finest "
                f"{last['dofs']} DoFs in {last['wall time since start [s]']:.0f} s "
                "(the reference); relative errors:", "",
                bc.markdown_table(["cycle", "quantity", "true", "estimated",
                                   "effectivity", "within 3x"], rows), "",
                f"Within a factor 3: {counts['in']} of {counts['in'] + counts['out']}"
                f" (and {counts['negligible']} both below 1e-6).", ""]
        sections.append("\n".join(text))
    judged = totals["in"] + totals["out"]
    share = totals["in"] / judged if judged else float("nan")
    report = "\n".join(
        [bc.stamp(info, sys.argv, args.binary, args.quick), ""] + sections +
        [f"**All scenes: {totals['in']} of {judged} pairs within a factor 3 "
         f"({100 * share:.0f}%), {totals['negligible']} more both below 1e-6.**", ""])
    fit_judged = fit_totals["in"] + fit_totals["out"]
    report += (f"**From cycle 3 on (the four-mesh fit): {fit_totals['in']} of "
               f"{fit_judged} pairs within a factor 3.**\n")
    print(report)
    if args.markdown:
        bc.replace_block(args.markdown, "error-estimates", report)


if __name__ == "__main__":
    main()
