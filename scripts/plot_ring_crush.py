#!/usr/bin/env python3
"""Plate reaction against stroke of a ring crush (prm/ring_crush.prm,
issue 51), from the runs' reactions.csv (the plate top's reaction Ry_13,
absolute value) and load_steps.csv (the self-contact force
pair2_self_contact_force) against the plate's stroke 8.7 t, one curve per
run folder (label = folder name). A half model's values are doubled when
its folder name contains 'half' or it is the scene's own folder
(ring_crush), so that the half and the full ring share one scale.

  python3 scripts/plot_ring_crush.py OUT.png RUN_DIR [RUN_DIR ...]
"""
import csv
import os
import sys

try:
    import matplotlib
except ImportError:
    # Debian's python3-matplotlib (scripts/setup.sh) lives in Debian's
    # interpreter, which need not be the python3 first on PATH.
    DEBIAN = "/usr/bin/python3"
    if os.access(DEBIAN, os.X_OK) and not os.environ.get("PLOT_RING_DEBIAN") \
            and os.path.realpath(sys.executable) != os.path.realpath(DEBIAN):
        os.environ["PLOT_RING_DEBIAN"] = "1"
        os.execv(DEBIAN, [DEBIAN] + sys.argv)
    sys.exit("plot_ring_crush.py: needs matplotlib: apt-get install "
             "python3-matplotlib (for /usr/bin/python3)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STROKE = 8.7


def read(path, column):
    """The rows of a CSV file that has @p column (exits with the reason)."""
    try:
        with open(path) as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit("plot_ring_crush.py: cannot read %s: %s" % (path, e))
    if not rows or column not in rows[0]:
        sys.exit("plot_ring_crush.py: %s has no rows with a column %s"
                 % (path, column))
    return rows


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, runs = sys.argv[1], sys.argv[2:]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for run in runs:
        reactions = read(os.path.join(run, "reactions.csv"), "Ry_13")
        rows = read(os.path.join(run, "load_steps.csv"), "time")
        name = os.path.basename(os.path.normpath(run))
        factor = 2. if ("half" in name or name == "ring_crush") else 1.
        line, = ax.plot([STROKE * float(r["time"]) for r in reactions],
                        [factor * abs(float(r["Ry_13"])) for r in reactions],
                        "o-", ms=3, label="%s%s: plate reaction"
                        % (name, " (half x 2)" if factor == 2. else ""))
        stroke = [STROKE * float(r["time"]) for r in rows]
        if rows and "pair2_self_contact_force" in rows[0]:
            self_force = [factor * float(r["pair2_self_contact_force"])
                          for r in rows]
            ax.plot(stroke, self_force, "s--", ms=3, color=line.get_color(),
                    label="%s: self-contact force" % name)
    ax.set_xlabel("plate stroke (plate gap 12.7 - stroke)")
    ax.set_ylabel("force per unit thickness (full ring)")
    ax.set_title("ring crush: the inner surface meets itself")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("wrote %s" % out)


if __name__ == "__main__":
    main()
