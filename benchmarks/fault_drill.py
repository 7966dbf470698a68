#!/usr/bin/env python3
"""Fault drill (issue "Long runs that survive"): run a scene to the end
without a stop, then run it again and interrupt it N times with SIGTERM at
random moments (fixed seed), restarting it with `signorini --restart DIR`
after each interruption, and check that the stopped-and-restarted run ends
with the same reactions, load steps and iterations as the run without a
stop. Every interruption must leave a valid summary.json (status
"interrupted", or "converged" if the run ended first) and exit with 143.

    python3 benchmarks/fault_drill.py [--build build] [--scene prm/ironing.prm]
                                      [--interrupts 20] [--seed 2026]
                                      [--output build/output/fault_drill]
                                      [--ranks 1,2] [--tolerance 1e-8]

The attempts run on the numbers of MPI ranks of --ranks in turn (the
reference run on the first): each restart continues the checkpoint of the
previous attempt on another number of ranks. On one number of ranks the
run must end with the same numbers to the last digit; on several, with
every load step at the same load time, the same load steps and cuts, and
the quantities within --tolerance relative (another partition rounds
differently); the Newton iterations are reported.

The moments: each interruption comes after a random fraction (uniform in
[0.2, 1.8] / N) of the reference run's wall time, so the N interruptions
spread over the whole path. A signal during the process's start-up (the
loader and MPI, about 0.2 s, before the program can catch it) ends it with
-15; that attempt is valid if it left the output folder as it was. On
several ranks the signal goes to the ranks (mpirun's children), and the
status in summary.json decides (mpirun's exit code is its own). Prints a
table of the interruptions and the verdict, and writes it as JSON into the
output folder.
"""

import argparse
import csv
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def write_scene(folder, scene):
    # A fresh folder: a run left there by an earlier drill would be taken
    # for this one's.
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder, exist_ok=True)
    prm = os.path.join(folder, "scene.prm")
    with open(prm, "w") as out:
        out.write("include %s\n" % os.path.abspath(scene))
        out.write("set Output directory = %s\n" % os.path.join(folder, "run"))
        out.write("subsection Output\n  set Format = none\n  set Verbosity = quiet\nend\n")
    return prm


def status_of(run):
    try:
        with open(os.path.join(run, "summary.json")) as f:
            return json.load(f)["status"]
    except (OSError, ValueError, KeyError):
        return "invalid"


def rows(path):
    try:
        with open(path) as f:
            return list(csv.reader(f))
    except FileNotFoundError:
        return []


def command_on(ranks, args):
    """The command that runs the program with @p args on @p ranks MPI ranks."""
    if ranks == 1:
        return args
    return ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + args


def children(pid):
    """The processes started by @p pid (the ranks under mpirun)."""
    try:
        out = subprocess.run(["pgrep", "-P", str(pid)], capture_output=True,
                             text=True).stdout
    except OSError:
        return []
    return [int(p) for p in out.split()]


def interrupt(process, ranks):
    """SIGTERM to the program: to the process itself on one rank, to the
    ranks (mpirun's children, as a batch system delivers it) on several:
    Open MPI's mpirun kills the ranks 1 s after it forwards a signal, or
    ignores one that comes before they run (doc/robustness.md). Waits up to
    10 s for all of them to exist."""
    if ranks == 1:
        process.send_signal(signal.SIGTERM)
        return
    targets = []
    for _ in range(2000):
        targets = children(process.pid)
        if len(targets) >= ranks or process.poll() is not None:
            break
        time.sleep(0.005)
    for pid in targets:
        try:
            os.kill(pid, signal.SIGTERM)
        except ProcessLookupError:
            pass


def quantity_difference(a, b):
    """The largest relative difference between the quantities of two
    summaries, a vector's component (NAME_x, reaction_x_boundary_2)
    relative to the vector's magnitude: a component that vanishes by
    symmetry is round-off."""
    def vector_of(name):
        for c in ("_x", "_y", "_z"):
            at = name.find(c)
            if at >= 0 and (at + 2 == len(name) or name[at + 2] == "_"):
                return name[:at] + "_?" + name[at + 2:]
        return None
    qa, qb = a["quantities"], b["quantities"]
    if set(qa) != set(qb):
        return 1.
    magnitude = {}
    for name, q in qa.items():
        v = vector_of(name)
        if v:
            magnitude[v] = magnitude.get(v, 0.) + q["value"] ** 2
    worst = 0.
    for name in qa:
        x, y = qa[name]["value"], qb[name]["value"]
        scale = max(abs(x), abs(y))
        v = vector_of(name)
        if v:
            scale = max(scale, magnitude[v] ** 0.5)
        if x != y:
            worst = max(worst, abs(x - y) / scale)
    return worst


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--scene", default=os.path.join(ROOT, "prm", "ironing.prm"))
    parser.add_argument("--interrupts", type=int, default=20)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--output", default=os.path.join(ROOT, "build", "output", "fault_drill"))
    parser.add_argument("--ranks", default="1,2",
                        help="MPI ranks of the reference run and of the attempts in turn "
                             "(a restart continues on the next number); '1' as before")
    parser.add_argument("--tolerance", type=float, default=1e-8,
                        help="with several rank counts: the quantities' relative difference "
                             "allowed (the rank count changes the round-off)")
    args = parser.parse_args()
    # The caller's paths, whatever folder the runs start in.
    args.build, args.scene, args.output = (
        os.path.abspath(p) for p in (args.build, args.scene, args.output))
    ranks = [int(r) for r in args.ranks.split(",")]
    exe = os.path.join(args.build, "signorini")
    if not os.access(exe, os.X_OK):
        sys.exit(f"fault_drill.py: no executable {exe} (build first: bash "
                 "scripts/setup.sh, or pass --build)")
    rng = random.Random(args.seed)

    reference = os.path.join(args.output, "reference")
    prm = write_scene(reference, args.scene)
    start = time.time()
    code = subprocess.call(command_on(ranks[0], [exe, prm]), stdout=subprocess.DEVNULL)
    length = time.time() - start
    if code != 0:
        sys.exit("the reference run failed with exit code %d" % code)
    print("reference run on %d rank(s): %.1f s" % (ranks[0], length))

    drill = os.path.join(args.output, "drill")
    prm = write_scene(drill, args.scene)
    run = os.path.join(drill, "run")
    fresh = [exe, prm]
    command = fresh
    previous = ("not started", 0)
    log = []
    ok = True
    for k in range(args.interrupts):
        delay = rng.uniform(0.2, 1.8) * length / args.interrupts
        n = ranks[k % len(ranks)]
        launched = time.time()
        process = subprocess.Popen(command_on(n, command), stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL)
        if n > 1:
            # On several ranks the moment counts from when the run has
            # started (summary.json written anew: the signal handlers are
            # installed): a rank killed inside MPI_Init left mpirun hanging
            # with the rank unreaped (Open MPI 4.1, 2026-11-28).
            summary = os.path.join(run, "summary.json")
            for _ in range(12000):
                try:
                    if os.path.getmtime(summary) >= launched:
                        break
                except OSError:
                    pass
                if process.poll() is not None:
                    break
                time.sleep(0.005)
        time.sleep(delay)
        interrupt(process, n)
        try:
            code = process.wait(timeout=300)
        except subprocess.TimeoutExpired:
            for pid in children(process.pid) + [process.pid]:
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            code = process.wait()
            print("interruption %2d: the process did not end within 300 s" % (k + 1))
            ok = False
        # A signal that comes while the loader and MPI start (about 0.2 s)
        # ends the process before it can catch it: valid if it wrote
        # nothing, so that the folder is as the previous attempt left it
        # (and the next attempt is the same command). mpirun reports an
        # exit code of its own: on several ranks the status decides.
        started = os.path.isdir(run)
        status = status_of(run) if started else "not started"
        steps = max(len(rows(os.path.join(run, "load_steps.csv"))) - 1, 0)
        if n == 1:
            valid = (status == "interrupted" and code == 143) or \
                    (status == "converged" and code == 0) or \
                    (status == "not started" and code == 143) or \
                    (code == -signal.SIGTERM and (status, steps) == previous)
        else:
            valid = (status == "interrupted" and code != 0) or \
                    (status == "converged" and code == 0) or \
                    (code != 0 and (status, steps) == previous)
        previous = (status, steps)
        ok = ok and valid
        log.append({"interruption": k + 1, "ranks": n, "after [s]": round(delay, 2),
                    "exit code": code, "status": status,
                    "converged steps": steps, "valid": valid})
        print("interruption %2d on %d rank(s) after %5.1f s: exit %3d, %s, %d steps%s"
              % (k + 1, n, delay, code, status, steps, "" if valid else "  INVALID"))
        if status == "converged":
            break
        command = [exe, "--restart", run] if started else fresh
    if status_of(run) != "converged":
        n = ranks[len(log) % len(ranks)]
        code = subprocess.call(command_on(n, command), stdout=subprocess.DEVNULL)
        print("last restart on %d rank(s): exit %d, %s" % (n, code, status_of(run)))

    with open(os.path.join(reference, "run", "summary.json")) as f:
        ref = json.load(f)
    with open(os.path.join(run, "summary.json")) as f:
        end = json.load(f)
    keys = ["load steps", "step cuts", "newton iterations", "final time"]
    same = {}
    one_count = len(set(ranks)) == 1
    if one_count:
        # One number of ranks throughout: the same numbers to the last digit.
        for name in ("reactions.csv", "load_steps.csv"):
            a = rows(os.path.join(reference, "run", name))
            b = rows(os.path.join(run, name))
            same[name] = (a == b)
        same["summary"] = all(ref.get(k) == end.get(k) for k in keys) and \
            quantity_difference(ref, end) == 0.
    else:
        # Several: every converged step on the same load time, and the
        # quantities to the tolerance (another partition, another
        # round-off); the iteration counts are reported.
        steps_ref = rows(os.path.join(reference, "run", "load_steps.csv"))
        steps_end = rows(os.path.join(run, "load_steps.csv"))
        same["load steps"] = [r[:2] for r in steps_ref] == [r[:2] for r in steps_end] \
            and all(ref.get(k) == end.get(k) for k in ("load steps", "step cuts", "final time"))
        difference = quantity_difference(ref, end)
        same["quantities"] = difference <= args.tolerance
        print("largest relative difference of the quantities: %.3g; newton iterations %s "
              "against %s" % (difference, end.get("newton iterations"),
                              ref.get("newton iterations")))
    verdict = ok and all(same.values())
    interrupted = sum(1 for e in log if e["status"] == "interrupted")
    print("%d interruptions; %s the run without a stop: %s (%s)"
          % (interrupted, "identical to" if one_count else "the same as", 
             "yes" if verdict else "NO",
             ", ".join("%s %s" % (k, "yes" if v else "NO") for k, v in same.items())))
    with open(os.path.join(args.output, "fault_drill.json"), "w") as f:
        json.dump({"scene": args.scene, "seed": args.seed, "ranks": ranks,
                   "reference seconds": length, "interruptions": log,
                   "same": same, "load steps": end.get("load steps"),
                   "newton iterations": [ref.get("newton iterations"),
                                         end.get("newton iterations")],
                   "quantity difference": quantity_difference(ref, end),
                   "restarted from": end.get("restarted from", [])}, f, indent=2)
    sys.exit(0 if verdict else 1)


if __name__ == "__main__":
    main()
