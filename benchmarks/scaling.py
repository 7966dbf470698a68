#!/usr/bin/env python3
"""Scaling series: how the time per phase, the Newton iterations and the
memory grow with the number of DoFs, the linear solver and the MPI ranks.

Series (choose with --series, default all):
  a  2D hyperelastic block, no contact: prm/block_squeeze.prm with Q1 on a
     3 x 3 coarse mesh, Global refinements 3..8 (1250 .. 1.18M DoFs), CG+AMG.
  b  Hertz contact on a rigid plane: prm/default.prm (newton-penalty), Global
     refinements 1.. with the scene's 5 local refinement levels kept, so
     every level halves every element size and keeps the grading around the
     contact zone (1154, 3770, 13680, ~53k, ~205k, ~815k DoFs), direct solver.
  c  3D hyperelastic block: prm/ssnv187_3d_neo_hookean.prm (4 x 4 x 4 Q1),
     Global refinements 1..3 (2187 .. 107811 DoFs), CG+AMG.
  d  series a's scene with the direct solver and with CG+AMG, Global
     refinements 4..8 (4802 .. 1.18M DoFs): where AMG overtakes direct.
  e  series a's largest run on 1 rank (1 thread) and on 2 MPI ranks (1
     thread each), CG+AMG; with series a also selected, its own run (1
     rank, the program's default threads) is listed beside them.

For each run: DoFs, cells, ranks x threads, linear solver, Newton
iterations (total and per load step), linear iterations, time per Newton
iteration, time per phase and per phase per Newton iteration, peak memory
(the program's own 'peak memory MB' when summary.json has it, and the
largest resident set of one process as the OS measured it). For a, b, c the
growth exponent of every phase's time in DoFs (least squares of log t
against log N over the runs with at least --fit-min-dofs DoFs); for the
contact phase (when summary.json times it) also against the number of
contact nodes. Then PASS/FAIL lines for the targets: assembly and contact
evaluation grow linearly (exponent 0.9 .. 1.15), total Newton iterations
within 1.5x from the coarsest to the finest run, AMG faster than direct
above 1e5 DoFs, 2 ranks >= 1.6x faster than 1 on the largest 2D run.

    python3 benchmarks/scaling.py [--series a,b,c,d,e] [--quick]
        [--max-dofs N | --max-dofs SERIES=N ...] [--binary build/signorini]
        [--out output/scaling] [--markdown doc/performance.md]
        [--linear-solver a=cg-amg,b=direct,c=cg-amg] [--hertz-local 5]
        [--fit-min-dofs 1e4] [--timeout SECONDS] [--reuse] [--no-run]
        [--dry-run]

--max-dofs N caps every series at N DoFs (predicted before each run from
the sizes already run); --max-dofs b=1e6 sets one series' limit (it may also
raise the default). --markdown FILE puts each series' tables between the
markers '<!-- SCALING-x BEGIN -->' and '<!-- SCALING-x END -->' of FILE
(appended if missing). --reuse reads a run folder left by an earlier
invocation when its parameter text, ranks, threads and binary are the same
(to resume an interrupted series); --no-run only reads such folders. The
exit status is 0 when every run produced a summary, 1 otherwise (a FAIL of
a target does not change it: these are measurements, not tests).
"""

import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bench_common as bc  # noqa: E402

TARGET_EXPONENT = (0.9, 1.15)
TARGET_ITERATION_RATIO = 1.5
TARGET_AMG_ABOVE = 1e5
TARGET_SPEEDUP = 1.6

BLOCK = {
    "scene": os.path.join(bc.PRM, "block_squeeze.prm"),
    "dim": 2,
    "base": {"Discretization": {"Polynomial degree": 1},
             "Body 1/Geometry": {"Subdivisions": "3, 3"}},
    # Q1 on 3 x 3 coarse cells refined r times: (3 2^r + 1)^2 nodes.
    "dofs": lambda r: 2 * (3 * 2 ** r + 1) ** 2,
}

SERIES = {
    "a": dict(BLOCK, title="2D hyperelastic block without contact (block_squeeze, Q1)",
              levels=range(3, 12), quick_levels=(2, 3, 4), max_dofs=1.2e6,
              solver="cg-amg"),
    "b": {"title": "Hertz contact on a rigid plane (default.prm, newton-penalty)",
          "scene": os.path.join(bc.PRM, "default.prm"), "dim": 2,
          # The scene's default is the interior point method; this series
          # measures the penalty path, as it always has.
          "base": {"Solver": {"Method": "newton-penalty"}},
          "levels": range(1, 12), "quick_levels": (1, 2), "max_dofs": 2.5e5,
          "solver": "direct", "contact": True,
          # Measured sizes with the scene's 5 local levels; x3.9 per level
          # beyond (only used to plan; the runs predict from their own sizes).
          "guess": lambda g: {1: 1154, 2: 3770, 3: 13680}.get(g, 13680 * 3.9 ** (g - 3))},
    "c": {"title": "3D hyperelastic block without contact (SSNV187 3D, Q1)",
          "scene": os.path.join(bc.PRM, "ssnv187_3d_neo_hookean.prm"), "dim": 3,
          "base": {}, "levels": range(1, 8), "quick_levels": (0, 1),
          # CG + AMG: the direct solver's time grows about like N^2 on this
          # 3D mesh (MUMPS, pord ordering), which would make the 108k run
          # dominate the whole series; nu = 0.499 slows AMG down too (a
          # few hundred CG iterations per solve) but it stays far cheaper.
          # --linear-solver c=direct runs the direct solver instead.
          "max_dofs": 1.2e5, "solver": "cg-amg",
          "dofs": lambda r: 3 * (4 * 2 ** r + 1) ** 3},
    "d": dict(BLOCK, title="Direct solver against CG + AMG on series a's block",
              levels=range(4, 12), quick_levels=(3, 4), max_dofs=1.2e6),
    "e": dict(BLOCK, title="1 against 2 MPI ranks on series a's largest run"),
}


# --------------------------------------------------------------------------

def parse_args(argv):
    p = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--series", default="a,b,c,d,e",
                   help="comma-separated list of a, b, c, d, e (default all)")
    p.add_argument("--quick", action="store_true",
                   help="small sizes only, to check the script (a few minutes)")
    p.add_argument("--max-dofs", action="append", default=[],
                   metavar="N|SERIES=N",
                   help="cap every series at N DoFs, or set one series' limit")
    p.add_argument("--binary", default=os.path.join(bc.ROOT, "build", "signorini"))
    p.add_argument("--out", default=os.path.join(bc.ROOT, "output", "scaling"),
                   help="folder for the run folders and results.json")
    p.add_argument("--markdown", metavar="FILE",
                   help="write the tables into FILE (e.g. doc/performance.md)")
    p.add_argument("--linear-solver", default="",
                   help="per series, e.g. 'a=cg-amg,b=direct,c=cg-amg' (the defaults) "
                        "(Solver > Linear solver > Type; e uses a's)")
    p.add_argument("--hertz-local", type=int, default=None,
                   help="series b: Mesh > Local refinements (default: the "
                        "scene's 5)")
    p.add_argument("--fit-min-dofs", type=float, default=1e4,
                   help="fit exponents over the runs with at least this many "
                        "DoFs (all runs if fewer than 3 qualify)")
    p.add_argument("--timeout", type=float, default=None,
                   help="seconds per run (default: none; --quick: 300)")
    p.add_argument("--reuse", action="store_true",
                   help="read matching run folders of an earlier invocation")
    p.add_argument("--no-run", action="store_true",
                   help="only read existing run folders (implies --reuse)")
    p.add_argument("--dry-run", action="store_true",
                   help="print the planned runs and exit")
    args = bc.absolute_paths(p.parse_args(argv), "binary", "out", "markdown")
    args.series = [s.strip() for s in args.series.split(",") if s.strip()]
    for s in args.series:
        if s not in SERIES:
            p.error(f"unknown series '{s}' (a, b, c, d, e)")
    args.caps = {k: v.get("max_dofs") for k, v in SERIES.items()}
    for item in args.max_dofs:
        if "=" in item:
            k, v = item.split("=", 1)
            if k.strip() not in SERIES:
                p.error(f"--max-dofs: unknown series '{k}'")
            args.caps[k.strip()] = float(v)
        else:
            n = float(item)
            args.caps = {k: (min(c, n) if c else n) for k, c in args.caps.items()}
    args.solvers = {k: v.get("solver") for k, v in SERIES.items()}
    for item in filter(None, (x.strip() for x in args.linear_solver.split(","))):
        k, v = item.split("=", 1)
        if k not in ("a", "b", "c"):
            p.error(f"--linear-solver: series {k} has no own linear solver")
        args.solvers[k] = v.strip()
    if args.quick and args.timeout is None:
        args.timeout = 300.
    if args.no_run:
        args.reuse = True
    return args


def overrides_for(spec, level, solver, extra=None):
    o = {k: dict(v) for k, v in spec["base"].items()}
    o.setdefault("Mesh", {})["Global refinements"] = level
    if solver:
        o.setdefault("Solver/Linear solver", {})["Type"] = solver
    for k, v in (extra or {}).items():
        o.setdefault(k, {}).update(v)
    return o


def predicted_next(spec, rows, level):
    """Predicted DoFs of @p level from the runs so far (or the series'
    formula)."""
    if "dofs" in spec:
        return spec["dofs"](level)
    sizes = [r["summary"]["mesh"]["dofs"] for r in rows if r.get("summary")]
    if not sizes:
        return spec["guess"](level) if "guess" in spec else None
    if len(sizes) >= 2:
        return sizes[-1] * sizes[-1] / sizes[-2]
    return sizes[-1] * 2 ** spec["dim"]


def run_one(runner, args, name, scene, overrides, ranks=1, threads=None):
    return runner.run(name, scene, overrides, ranks, threads)


def level_series(runner, args, key, levels=None, solver=None, extra=None, plan=None):
    """Run series @p key over its levels (up to its DoF limit); return rows."""
    spec = SERIES[key]
    cap = args.caps[key]
    levels = levels if levels is not None else \
        (spec["quick_levels"] if args.quick else spec["levels"])
    rows = []
    for level in levels:
        guess = predicted_next(spec, [] if plan is not None else rows, level)
        if rows and guess is not None and cap and guess > cap:
            break
        name = f"{key}_{solver or 'scene'}_r{level}"
        if extra and "Local refinements" in extra.get("Mesh", {}):
            name += f"_local{extra['Mesh']['Local refinements']}"
        if plan is not None:
            plan.append((name, level, guess))
            if guess is None:  # unknown sizes: list the first level only
                break
            rows.append({"summary": {"mesh": {"dofs": int(guess)}}})
            continue
        row = run_one(runner, args, name, spec["scene"],
                      overrides_for(spec, level, solver, extra))
        row["level"] = level
        rows.append(row)
        if row.get("timed_out") or not row.get("summary"):
            # Larger runs would time out or fail too (and a failed run
            # gives no size to predict the next one from).
            break
    return rows


# --------------------------------------------------------------------------
# Tables

def phase_names(rows):
    present = set()
    for r in rows:
        present.update(bc.timing(r.get("summary")).keys())
    return [p for p in bc.PHASES if p in present] + \
        sorted(present - set(bc.PHASES) - {"peak memory MB", "peak memory [MB]"})


def run_facts(r):
    s = r.get("summary") or {}
    t = bc.timing(s)
    its = bc.iterations(s)
    per_it = None
    if its and "total" in t:
        per_it = (t["total"] - t.get("setup", 0.)) / its
    steps = bc.step_iterations(s)
    contact = s.get("contact") or {}
    return {
        "level": r.get("level"),
        "dofs": (s.get("mesh") or {}).get("dofs"),
        "cells": (s.get("mesh") or {}).get("cells"),
        "ranks": s.get("mpi ranks", r.get("ranks")),
        "threads": s.get("threads per rank"),
        "solver": (s.get("solver") or {}).get("linear solver"),
        "status": s.get("status", "no result" if not s else "?"),
        "iterations": its,
        "steps": steps,
        "linear": bc.linear_iterations(s),
        "per_it": per_it,
        "timing": t,
        "peak_mb": bc.peak_memory_mb(s),
        "rss_mb": r.get("max_rss_mb"),
        "contact_nodes": contact.get("nodes"),
        "active_nodes": contact.get("active nodes"),
        "wall": r.get("wall"),
        "message": r.get("message", ""),
    }


def steps_text(steps):
    if not steps:
        return ""
    if len(set(steps)) == 1 and len(steps) > 3:
        return f"{len(steps)}×{steps[0]}"
    text = ", ".join(str(x) for x in steps[:12])
    return text + (", …" if len(steps) > 12 else "")


def runs_table(rows, with_contact=False):
    header = ["level", "DoFs", "cells", "ranks × threads", "linear solver",
              "status", "Newton it. (per load step)", "linear it.",
              "s / Newton it.", "total [s]", "peak memory [MB]",
              "max RSS [MB] (OS)"]
    if with_contact:
        header[6:6] = ["contact nodes", "active"]
    body = []
    for r in rows:
        f = run_facts(r)
        cells = [fmt_level(f["level"]), bc.fmt(f["dofs"], "d"),
                 bc.fmt(f["cells"], "d"),
                 f"{bc.fmt(f['ranks'], 'd')} × {bc.fmt(f['threads'], 'd')}",
                 f["solver"] or "–",
                 f["status"] if f["status"] != "converged" else "ok",
                 f"{bc.fmt(f['iterations'], 'd')} ({steps_text(f['steps'])})"
                 if f["steps"] else bc.fmt(f["iterations"], "d"),
                 bc.fmt(f["linear"], "d"), bc.fmt_time(f["per_it"]),
                 bc.fmt_time(f["timing"].get("total")),
                 bc.fmt(f["peak_mb"], ".0f"), bc.fmt(f["rss_mb"], ".0f")]
        if with_contact:
            cells[6:6] = [bc.fmt(f["contact_nodes"], "d"),
                          bc.fmt(f["active_nodes"], "d")]
        body.append(cells)
    return bc.markdown_table(header, body)


def fmt_level(level):
    return "–" if level is None else str(level)


def phases_table(rows):
    phases = [p for p in phase_names(rows) if p != "total"]
    header = ["DoFs"] + [f"{p} [s] (ms / it.)" for p in phases]
    body = []
    for r in rows:
        f = run_facts(r)
        cells = [bc.fmt(f["dofs"], "d")]
        for p in phases:
            t = f["timing"].get(p)
            per = (1e3 * t / f["iterations"]) if (t is not None and f["iterations"]) else None
            cells.append(f"{bc.fmt_time(t)} ({bc.fmt(per, '.3g')})" if t is not None else "–")
        body.append(cells)
    return bc.markdown_table(header, body)


def fit_rows(rows, min_dofs):
    good = [r for r in rows if bc.converged(r)]
    big = [r for r in good if r["summary"]["mesh"]["dofs"] >= min_dofs]
    return (big, True) if len(big) >= 3 else (good, False)


def exponents(rows, min_dofs):
    """{phase: (exponent of t, exponent of t per Newton iteration)} over the
    fitted runs, and a description of those runs."""
    used, restricted = fit_rows(rows, min_dofs)
    out = {}
    facts = [run_facts(r) for r in used]
    n = [f["dofs"] for f in facts]
    for p in phase_names(used):
        t = [f["timing"].get(p) for f in facts]
        t_it = [(x / f["iterations"]) if (x is not None and f["iterations"]) else None
                for x, f in zip(t, facts)]
        out[p] = (bc.fit_exponent(n, t), bc.fit_exponent(n, t_it))
    per_it = [f["per_it"] for f in facts]
    out["(s / Newton it.)"] = (None, bc.fit_exponent(n, per_it))
    if any(f["contact_nodes"] for f in facts) and "contact" in out:
        nodes = [f["contact_nodes"] for f in facts]
        t = [f["timing"].get("contact") for f in facts]
        t_it = [(x / f["iterations"]) if (x is not None and f["iterations"]) else None
                for x, f in zip(t, facts)]
        out["contact, in contact nodes"] = (bc.fit_exponent(nodes, t),
                                            bc.fit_exponent(nodes, t_it))
    if facts:
        what = (f"{len(facts)} runs, {min(n)} .. {max(n)} DoFs"
                + ("" if restricted else f" (all runs: fewer than 3 have ≥ {min_dofs:.0f} DoFs)"))
    else:
        what = "no converged runs"
    return out, what, facts


def exponents_table(exps):
    header = ["phase", "exponent of time", "exponent of time / Newton it."]
    body = [[p, bc.fmt(a, ".2f"), bc.fmt(b, ".2f")] for p, (a, b) in exps.items()]
    return bc.markdown_table(header, body)


# --------------------------------------------------------------------------
# Checks

def check(results, ok, text):
    line = f"{'PASS' if ok else 'FAIL'}  {text}"
    results.append(line)
    return line


def level_checks(key, rows, exps, what, facts):
    lines = []
    lo, hi = TARGET_EXPONENT
    if len(facts) < 2:
        lines.append(f"SKIP  {key}: fewer than two converged runs, nothing to fit")
        return lines
    e = exps.get("assembly", (None, None))[1]
    if e is None:
        lines.append(f"SKIP  {key}: no assembly time in summary.json")
    else:
        check(lines, lo <= e <= hi,
              f"{key}: assembly time per Newton iteration ~ DoFs^{e:.2f} "
              f"(target {lo}..{hi}; {what})")
    if SERIES[key].get("contact"):
        if "contact" not in exps:
            lines.append(f"SKIP  {key}: summary.json has no 'contact' time "
                         "(this binary does not time the contact evaluation apart; "
                         "it is inside 'assembly' and 'line search')")
        else:
            e_nodes = exps.get("contact, in contact nodes", (None, None))[1]
            e_dofs = exps["contact"][1]
            if e_nodes is not None:
                check(lines, lo <= e_nodes <= hi,
                      f"{key}: contact time per Newton iteration ~ (contact nodes)^{e_nodes:.2f}"
                      f" (target {lo}..{hi}; in DoFs: ^{bc.fmt(e_dofs, '.2f')}; {what})")
    first, last = facts[0], facts[-1]
    if first["iterations"] and last["iterations"]:
        ratio = last["iterations"] / first["iterations"]
        check(lines, 1 / TARGET_ITERATION_RATIO <= ratio <= TARGET_ITERATION_RATIO,
              f"{key}: Newton iterations {first['iterations']} at {first['dofs']} DoFs, "
              f"{last['iterations']} at {last['dofs']} DoFs: ratio {ratio:.2f} "
              f"(target within {TARGET_ITERATION_RATIO}x)")
    return lines


# --------------------------------------------------------------------------

def series_level(runner, args, key, plan=None):
    extra = None
    if key == "b" and args.hertz_local is not None:
        extra = {"Mesh": {"Local refinements": args.hertz_local}}
    rows = level_series(runner, args, key, solver=args.solvers[key], extra=extra, plan=plan)
    if plan is not None:
        return None
    exps, what, facts = exponents(rows, args.fit_min_dofs)
    text = [f"### Series {key}: {SERIES[key]['title']}", "",
            runs_table(rows, with_contact=SERIES[key].get("contact", False)), "",
            "Time per phase (and per Newton iteration):", "",
            phases_table(rows), "",
            f"Growth exponents (least squares of log t against log DoFs; {what}):", "",
            exponents_table(exps), ""]
    checks = level_checks(key, rows, exps, what, facts)
    return {"rows": rows, "text": "\n".join(text), "checks": checks}


def series_d(runner, args, plan=None):
    spec = SERIES["d"]
    levels = spec["quick_levels"] if args.quick else spec["levels"]
    cap = args.caps["d"]
    levels = [l for l in levels if not cap or spec["dofs"](l) <= cap] or list(levels)[:1]
    pairs = []
    for level in levels:
        if plan is not None:
            amg = f"a_cg-amg_r{level}" if args.solvers["a"] == "cg-amg" \
                else f"d_cg-amg_r{level}"
            plan.append((amg, level, spec["dofs"](level)))
            plan.append((f"d_direct_r{level}", level, spec["dofs"](level)))
            continue
        # The CG+AMG run is series a's run when a uses CG+AMG (same name
        # and key, so it is run once).
        amg = run_one(runner, args, f"a_cg-amg_r{level}" if args.solvers["a"] == "cg-amg"
                      else f"d_cg-amg_r{level}", spec["scene"],
                      overrides_for(spec, level, "cg-amg"))
        direct = run_one(runner, args, f"d_direct_r{level}", spec["scene"],
                         overrides_for(spec, level, "direct"))
        amg["level"] = direct["level"] = level
        pairs.append((level, amg, direct))
    if plan is not None:
        return None
    header = ["DoFs", "direct: total [s]", "linear solve [s]", "Newton it.",
              "CG+AMG: total [s]", "linear solve [s]", "Newton it.", "CG it.",
              "direct / AMG (total)", "direct / AMG (linear solve)",
              "direct RSS [MB]", "AMG RSS [MB]"]
    body = []
    lines = []
    above = []
    for level, amg, direct in pairs:
        fa, fd = run_facts(amg), run_facts(direct)
        ta, td = fa["timing"].get("total"), fd["timing"].get("total")
        la, ld = fa["timing"].get("linear solve"), fd["timing"].get("linear solve")
        body.append([bc.fmt(fd["dofs"] or fa["dofs"], "d"), bc.fmt_time(td),
                     bc.fmt_time(ld), bc.fmt(fd["iterations"], "d"), bc.fmt_time(ta),
                     bc.fmt_time(la), bc.fmt(fa["iterations"], "d"),
                     bc.fmt(fa["linear"], "d"),
                     bc.fmt(td / ta if (ta and td) else None, ".2f"),
                     bc.fmt(ld / la if (la and ld) else None, ".2f"),
                     bc.fmt(fd["rss_mb"], ".0f"), bc.fmt(fa["rss_mb"], ".0f")])
        n = fd["dofs"] or fa["dofs"] or 0
        if n >= TARGET_AMG_ABOVE and bc.converged(amg) and bc.converged(direct):
            above.append((n, ta, td))
    crossover = None
    for level, amg, direct in reversed(pairs):
        fa, fd = run_facts(amg), run_facts(direct)
        ta, td = fa["timing"].get("total"), fd["timing"].get("total")
        if not (ta and td):
            continue  # a size with one of the two runs missing
        if ta < td:
            crossover = fa["dofs"]
        else:
            break
    if above:
        ok = all(ta < td for _, ta, td in above)
        check(lines, ok, "d: CG+AMG faster than direct (total time) at every size ≥ "
              f"{TARGET_AMG_ABOVE:.0e} DoFs: " + ", ".join(
                  f"{n} DoFs {td / ta:.2f}x" for n, ta, td in above))
    else:
        lines.append(f"SKIP  d: no size ≥ {TARGET_AMG_ABOVE:.0e} DoFs with both runs converged")
    lines.append("INFO  d: CG+AMG is faster from "
                 + (f"{crossover} DoFs on" if crossover else "no measured size on"))
    text = "\n".join([f"### Series d: {spec['title']}", "",
                      bc.markdown_table(header, body), ""])
    rows = [x for _, a, d in pairs for x in (a, d)]
    return {"rows": rows, "text": text, "checks": lines}


def e_name(solver, level, ranks, threads):
    if threads is None and ranks == 1:
        return f"a_{solver}_r{level}"  # series a's own run
    return f"e_{solver}_r{level}_np{ranks}_t{threads}"


def series_e(runner, args, results, plan=None):
    spec = SERIES["e"]
    cap = args.caps["a"]
    levels = SERIES["a"]["quick_levels"] if args.quick else SERIES["a"]["levels"]
    level = None
    for l in levels:
        if not cap or spec["dofs"](l) <= cap or level is None:
            level = l
    if "a" in results:
        done = [r for r in results["a"]["rows"] if bc.converged(r)]
        if done:
            level = done[-1]["level"]
    solver = args.solvers["a"]
    configs = [("1 rank, 1 thread", 1, 1), ("2 ranks, 1 thread each", 2, 1)]
    if "a" in args.series:
        configs.insert(1, ("1 rank, default threads (series a)", 1, None))
    if plan is not None:
        for label, ranks, threads in configs:
            plan.append((e_name(solver, level, ranks, threads), level, spec["dofs"](level)))
        return None
    rows = []
    for label, ranks, threads in configs:
        name = e_name(solver, level, ranks, threads)
        r = run_one(runner, args, name, spec["scene"],
                    overrides_for(spec, level, solver), ranks=ranks, threads=threads)
        r["level"], r["label"] = level, label
        rows.append(r)
    base = run_facts(rows[0])["timing"].get("total")
    header = ["configuration", "DoFs", "ranks × threads", "Newton it.", "linear it.",
              "total [s]", "assembly [s]", "linear solve [s]", "line search [s]",
              "speedup (total) vs 1 × 1", "max RSS per process [MB]"]
    body = []
    for r in rows:
        f = run_facts(r)
        t = f["timing"]
        body.append([r["label"], bc.fmt(f["dofs"], "d"),
                     f"{bc.fmt(f['ranks'], 'd')} × {bc.fmt(f['threads'], 'd')}",
                     bc.fmt(f["iterations"], "d"), bc.fmt(f["linear"], "d"),
                     bc.fmt_time(t.get("total")), bc.fmt_time(t.get("assembly")),
                     bc.fmt_time(t.get("linear solve")), bc.fmt_time(t.get("line search")),
                     bc.fmt(base / t["total"] if (base and t.get("total")) else None, ".2f"),
                     bc.fmt(f["rss_mb"], ".0f")])
    lines = []
    two = run_facts(rows[-1])["timing"].get("total")
    if base and two and all(bc.converged(r) for r in (rows[0], rows[-1])):
        check(lines, base / two >= TARGET_SPEEDUP,
              f"e: speedup of 2 ranks over 1 rank (1 thread): {base / two:.2f}x on "
              f"{run_facts(rows[-1])['dofs']} DoFs (target ≥ {TARGET_SPEEDUP}x)")
        if len(rows) == 3:
            t2 = run_facts(rows[1])["timing"].get("total")
            if t2:
                lines.append(f"INFO  e: speedup of 2 ranks over 1 rank with the default "
                             f"{run_facts(rows[1])['threads']} threads: {t2 / two:.2f}x")
    else:
        lines.append("SKIP  e: the 1- and 2-rank runs did not both converge")
    text = "\n".join([f"### Series e: {spec['title']}", "",
                      bc.markdown_table(header, body), ""])
    return {"rows": rows, "text": text, "checks": lines}


# --------------------------------------------------------------------------

def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    args = parse_args(argv)
    info = bc.machine_info()
    binary = os.path.abspath(args.binary)
    if not args.dry_run and not args.no_run and not os.access(binary, os.X_OK):
        sys.exit(f"scaling.py: no executable {binary} (build first, or pass --binary)")
    runner = bc.Runner(binary, args.out, timeout=args.timeout, reuse=args.reuse,
                       run_missing=not args.no_run)

    if args.dry_run:
        plan = []
        for key in args.series:
            if key in "abc":
                series_level(runner, args, key, plan=plan)
            elif key == "d":
                series_d(runner, args, plan=plan)
            else:
                series_e(runner, args, {}, plan=plan)
        seen = set()
        for name, level, dofs in plan:
            again = " (same run as above)" if name in seen else ""
            seen.add(name)
            print(f"{name:32s} level {level}  ~{bc.fmt(dofs, '.0f')} DoFs{again}")
        return 0

    bc.warn_if_busy(info)
    print(bc.machine_line(info))
    results = {}
    for key in args.series:
        print(f"series {key}: {SERIES[key]['title']}", flush=True)
        if key in "abc":
            results[key] = series_level(runner, args, key)
        elif key == "d":
            results[key] = series_d(runner, args)
        else:
            results[key] = series_e(runner, args, results)
        if args.quick:
            results[key]["checks"].append(
                "INFO  quick mode: the sizes are too small for the targets to mean anything")
        print()
        print(results[key]["text"])
        for line in results[key]["checks"]:
            print(line)
        print(flush=True)

    head = bc.stamp(info, ["python3", "benchmarks/scaling.py"] + argv, binary, args.quick)
    print("Checks:")
    for key in args.series:
        for line in results[key]["checks"]:
            print("  " + line)
    print(f"Time spent running the program: {runner.wall_seconds:.0f} s")

    os.makedirs(args.out, exist_ok=True)
    dump = {k: {"rows": [dict(run_facts(r), name=r.get("name"), folder=r.get("folder"))
                         for r in v["rows"]], "checks": v["checks"]}
            for k, v in results.items()}
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump({"machine": info, "argv": argv, "series": dump}, f, indent=1,
                  default=str)
    if args.markdown:
        for key in args.series:
            body = [head, "", results[key]["text"], "Checks:", ""] + \
                [f"- {line}" for line in results[key]["checks"]]
            bc.replace_block(args.markdown, f"SCALING-{key}", "\n".join(body))
        print(f"Tables written to {args.markdown}")
    missing = [r for v in results.values() for r in v["rows"] if not r.get("summary")]
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
