#!/usr/bin/env python3
"""Plots of an accuracy-versus-time study (signorini --study FILE.prm).

Usage: python3 scripts/plot_study.py STUDY_DIR

Reads STUDY_DIR/study.csv and study.json and writes, per quantity:
- error_vs_time.png: relative error against the converged model versus
  wall time (log-log), one curve per variant, the Pareto front (no other
  run is both faster and more accurate) marked;
- error_vs_dofs.png: the same error versus DoFs, with each variant's
  observed rate (slope over its last three points) in the legend.
The accuracy the study asked for is drawn as a horizontal line.
Also writes study_tables.md: the converged model, the first run of each
variant within the accuracy, and every run (the tables of
doc/accuracy-cost.md).
"""
import csv
import json
import math
import os
import sys

try:
    import matplotlib
except ImportError:
    # Debian's python3-matplotlib (scripts/setup.sh) is in Debian's
    # interpreter, which need not be the python3 first on PATH.
    DEBIAN = "/usr/bin/python3"
    if os.access(DEBIAN, os.X_OK) and not os.environ.get("PLOT_STUDY_DEBIAN") \
            and os.path.realpath(sys.executable) != os.path.realpath(DEBIAN):
        os.environ["PLOT_STUDY_DEBIAN"] = "1"
        os.execv(DEBIAN, [DEBIAN] + sys.argv)
    sys.exit("plot_study.py: needs matplotlib: apt-get install "
             "python3-matplotlib (for /usr/bin/python3)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(directory):
    with open(os.path.join(directory, "study.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["status"] == "converged"]
    with open(os.path.join(directory, "study.json")) as f:
        meta = json.load(f)
    return rows, meta


def series(rows, quantity):
    """{variant: [(dofs, wall, error)]} in the order of the runs."""
    out = {}
    for r in rows:
        e = r.get(quantity + "_error_converged", "")
        if e == "":
            continue
        out.setdefault(r["variant"], []).append(
            (float(r["dofs"]), float(r["wall_time"]), float(e)))
    return out


def pareto(points):
    """The points no other point beats in both time and error."""
    front, best = [], math.inf
    for t, e in sorted(points):
        if 0 < e < best:
            front.append((t, e))
            best = e
    return front


def rate(points):
    """Slope of log(error) against log(DoFs) over the last three points."""
    pts = [(d, e) for d, _, e in points if e > 0][-3:]
    if len(pts) < 2:
        return None
    xs = [math.log(d) for d, _ in pts]
    ys = [math.log(e) for _, e in pts]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    if sxx == 0:
        return None
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx


def number(text, spec):
    try:
        return format(float(text), spec)
    except (TypeError, ValueError):
        return "–"


def write_tables(directory, rows, meta):
    quantities = list(meta["converged model"].keys())
    lines = [f"Study `{meta.get('parameter file', '')}`; reference variant "
             f"'{meta.get('reference variant', '')}'; accuracy {meta['accuracy']:g}.",
             "", "| quantity | converged model | obtained by |", "|---|---|---|"]
    for q, m in meta["converged model"].items():
        lines.append(f"| {q} | {m['value']:.8g} | {m.get('method', '')} |")
    lines += ["", f"First run within {meta['accuracy']:g} of the converged model "
              "for every quantity:", "",
              "| variant | run / cycle | DoFs | wall time [s] |", "|---|---|---|---|"]
    for variant, first in meta["first run within the accuracy"].items():
        if first.get("reached"):
            where = first.get("run", first.get("cycle", ""))
            lines.append(f"| {variant} | {where} | {first['dofs']} | "
                         f"{first['wall time [s]']:.3g} |")
        else:
            lines.append(f"| {variant} | not reached | | |")
    reported = meta.get("reported quantities", [])
    header = ["variant", "run / cycle", "DoFs", "iterations", "wall [s]", "peak MB"]
    for q in quantities:
        header += [q, f"{q} error"]
    header += reported
    lines += ["", "Every run and refinement cycle (`study.csv`; wall time since "
              "the start of the run, iterations summed over its cycles so far; "
              "errors against the converged model):", "",
              "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for r in rows:
        where = r["cycle"] if r.get("cycle") not in (None, "", "-1") else r["run"]
        cells = [r["variant"], where, r["dofs"], r["iterations"],
                 number(r["wall_time"], ".3g"), number(r["peak_memory_mb"], ".0f")]
        for q in quantities:
            cells += [number(r.get(q), ".7g"), number(r.get(q + "_error_converged"), ".1e")]
        cells += [number(r.get(q), ".3g") for q in reported]
        lines.append("| " + " | ".join(cells) + " |")
    path = os.path.join(directory, "study_tables.md")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("Tables:", path)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    directory = sys.argv[1]
    rows, meta = read(directory)
    write_tables(directory, rows, meta)
    quantities = list(meta["converged model"].keys())
    accuracy = meta["accuracy"]
    n = len(quantities)
    for name, xlabel, xindex in (("error_vs_time.png", "wall time [s]", 1),
                                 ("error_vs_dofs.png", "DoFs", 0)):
        fig, axes = plt.subplots(1, n, figsize=(6.5 * n, 5), squeeze=False)
        for ax, q in zip(axes[0], quantities):
            data = series(rows, q)
            everything = []
            for variant, pts in data.items():
                pts_pos = [p for p in pts if p[2] > 0]
                if not pts_pos:
                    continue
                label = variant
                if xindex == 0:
                    r = rate(pts)
                    if r is not None:
                        label += f" (rate {r:.2f})"
                ax.loglog([p[xindex] for p in pts_pos], [p[2] for p in pts_pos],
                          "o-", label=label, markersize=4)
                everything += [(p[1], p[2]) for p in pts_pos]
            if xindex == 1:
                front = pareto(everything)
                if front:
                    ax.loglog([t for t, _ in front], [e for _, e in front], "k--",
                              linewidth=1, label="Pareto front")
                    ax.scatter([t for t, _ in front], [e for _, e in front],
                               s=60, facecolors="none", edgecolors="k")
            ax.axhline(accuracy, color="grey", linestyle=":",
                       label=f"accuracy {accuracy:g}")
            ax.set_xlabel(xlabel)
            ax.set_ylabel(f"{q}: relative error vs converged model")
            ax.set_title(q)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
        fig.tight_layout()
        path = os.path.join(directory, name)
        fig.savefig(path, dpi=110)
        print("Plot:", path)


if __name__ == "__main__":
    main()
