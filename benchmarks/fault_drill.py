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

The moments: each interruption comes after a random fraction (uniform in
[0.2, 1.8] / N) of the reference run's wall time, so the N interruptions
spread over the whole path. A signal during the process's start-up (the
loader and MPI, about 0.2 s, before the program can catch it) ends it with
-15; that attempt is valid if it left the output folder as it was. Prints a table of the interruptions and the
verdict, and writes it as JSON into the output folder.
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--scene", default=os.path.join(ROOT, "prm", "ironing.prm"))
    parser.add_argument("--interrupts", type=int, default=20)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--output", default=os.path.join(ROOT, "build", "output", "fault_drill"))
    args = parser.parse_args()
    # The caller's paths, whatever folder the runs start in.
    args.build, args.scene, args.output = (
        os.path.abspath(p) for p in (args.build, args.scene, args.output))
    exe = os.path.join(args.build, "signorini")
    if not os.access(exe, os.X_OK):
        sys.exit(f"fault_drill.py: no executable {exe} (build first: bash "
                 "scripts/setup.sh, or pass --build)")
    rng = random.Random(args.seed)

    reference = os.path.join(args.output, "reference")
    prm = write_scene(reference, args.scene)
    start = time.time()
    code = subprocess.call([exe, prm], stdout=subprocess.DEVNULL)
    length = time.time() - start
    if code != 0:
        sys.exit("the reference run failed with exit code %d" % code)
    print("reference run: %.1f s" % length)

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
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL)
        time.sleep(delay)
        process.send_signal(signal.SIGTERM)
        code = process.wait()
        # A signal that comes while the loader and MPI start (about 0.2 s)
        # ends the process before it can catch it: valid if it wrote
        # nothing, so that the folder is as the previous attempt left it
        # (and the next attempt is the same command).
        started = os.path.isdir(run)
        status = status_of(run) if started else "not started"
        steps = max(len(rows(os.path.join(run, "load_steps.csv"))) - 1, 0)
        valid = (status == "interrupted" and code == 143) or \
                (status == "converged" and code == 0) or \
                (status == "not started" and code == 143) or \
                (code == -signal.SIGTERM and (status, steps) == previous)
        previous = (status, steps)
        ok = ok and valid
        log.append({"interruption": k + 1, "after [s]": round(delay, 2),
                    "exit code": code, "status": status,
                    "converged steps": steps, "valid": valid})
        print("interruption %2d after %5.1f s: exit %3d, %s, %d steps%s"
              % (k + 1, delay, code, status, steps, "" if valid else "  INVALID"))
        if status == "converged":
            break
        command = [exe, "--restart", run] if started else fresh
    if status_of(run) != "converged":
        code = subprocess.call(command, stdout=subprocess.DEVNULL)
        print("last restart: exit %d, %s" % (code, status_of(run)))

    same = {}
    for name in ("reactions.csv", "load_steps.csv"):
        a = rows(os.path.join(reference, "run", name))
        b = rows(os.path.join(run, name))
        same[name] = (a == b)
    with open(os.path.join(reference, "run", "summary.json")) as f:
        ref = json.load(f)
    with open(os.path.join(run, "summary.json")) as f:
        end = json.load(f)
    keys = ["load steps", "step cuts", "newton iterations", "final time"]
    same["summary"] = all(ref.get(k) == end.get(k) for k in keys) and \
        all(ref["quantities"][q]["value"] == end["quantities"][q]["value"]
            for q in ref["quantities"])
    verdict = ok and all(same.values())
    interrupted = sum(1 for e in log if e["status"] == "interrupted")
    print("%d interruptions; identical to the run without a stop: %s (%s)"
          % (interrupted, "yes" if verdict else "NO",
             ", ".join("%s %s" % (k, "yes" if v else "NO") for k, v in same.items())))
    with open(os.path.join(args.output, "fault_drill.json"), "w") as f:
        json.dump({"scene": args.scene, "seed": args.seed,
                   "reference seconds": length, "interruptions": log,
                   "identical": same, "load steps": end.get("load steps"),
                   "restarted from": end.get("restarted from", [])}, f, indent=2)
    sys.exit(0 if verdict else 1)


if __name__ == "__main__":
    main()
