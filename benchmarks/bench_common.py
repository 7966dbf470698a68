"""Shared helpers of the benchmark scripts.

Writes variant parameter files (an 'include' of a committed scene followed by
'set' overrides), runs the program (optionally under mpirun), reads the run's
summary.json and describes the machine. Paths given on a script's command
line are the caller's: absolute_paths() resolves them against the folder the
script was started from, before any run changes its working directory.
Python 3 standard library only.
"""

import argparse
import datetime
import hashlib
import json
import math
import os
import platform
import shlex
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRM = os.path.join(ROOT, "prm")

# The phases of summary.json's timing block that the tables show, in order.
# Older programs write the block as "wall time [s]", newer ones as "timing";
# "contact" only exists in programs that time the contact evaluation apart.
PHASES = ["setup", "assembly", "contact", "linear solve", "line search",
          "sparsity pattern", "postprocessing", "output", "total"]


# A benchmark whose peer program is not installed exits with this status
# after saying what is missing (the automake convention for a skipped test).
EXIT_SKIPPED = 77


def absolute(path):
    """@p path resolved against the caller's working directory (None and ''
    stay as they are). A bare program name (no '/') is left to PATH."""
    if not path:
        return path
    return os.path.abspath(os.path.expanduser(path))


def absolute_paths(args, *names):
    """Resolve the argparse attributes @p names of @p args (paths the
    caller gave: binary, scene, output folders) against the caller's
    folder, so that runs started in another folder (mpirun in a run's
    work folder) still find them."""
    for name in names:
        value = getattr(args, name, None)
        if isinstance(value, str):
            setattr(args, name, absolute(value))
    return args


def require_binary(script, binary):
    """Exit with a message naming @p binary if it is not an executable."""
    if not os.access(binary, os.X_OK) or os.path.isdir(binary):
        sys.exit(f"{script}: no executable {binary} (build first: bash "
                 "scripts/setup.sh, or pass --binary)")


def skip(script, what):
    """Say that @p script cannot run because @p what is missing, and exit
    with EXIT_SKIPPED."""
    print(f"{script}: skipped: {what}", file=sys.stderr)
    sys.exit(EXIT_SKIPPED)


# --------------------------------------------------------------------------
# Parameter files

def variant_text(scene, output_dir, overrides):
    """The text of a parameter file that includes @p scene (absolute path)
    and sets @p overrides: {"Mesh": {"Global refinements": 3},
    "Solver/Linear solver": {"Type": "cg-amg"}, "": {"Scene name": "x"}}.
    Output goes to @p output_dir, without fields and quietly."""
    lines = [f"include {os.path.abspath(scene)}",
             f"set Output directory = {os.path.abspath(output_dir)}"]
    merged = {"Output": {"Format": "none", "Verbosity": "quiet"}}
    for section, entries in overrides.items():
        merged.setdefault(section, {}).update(entries)
    for section, entries in merged.items():
        parts = [p for p in section.split("/") if p]
        indent = ""
        for p in parts:
            lines.append(f"{indent}subsection {p}")
            indent += "  "
        for key, value in entries.items():
            lines.append(f"{indent}set {key} = {value}")
        for _ in parts:
            indent = indent[:-2]
            lines.append(f"{indent}end")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------
# Running

def _binary_stamp(binary):
    try:
        st = os.stat(binary)
        return f"{os.path.realpath(binary)}:{st.st_size}:{int(st.st_mtime)}"
    except OSError:
        return binary


class Runner:
    """Runs variants of scenes, one at a time, into folders below @p out_root.

    A run is identified by its parameter text, MPI ranks, threads and the
    binary (path, size, time stamp); the same run asked for twice in one
    session is run once. With reuse=True a folder left by an earlier session
    with the same key is read instead of running again (to resume an
    interrupted series); with run_missing=False nothing is run at all and a
    run without such a folder comes back without a summary."""

    def __init__(self, binary, out_root, timeout=None, reuse=False,
                 run_missing=True, verbose=True):
        self.binary = os.path.abspath(binary)
        self.out_root = os.path.abspath(out_root)
        self.timeout = timeout
        self.reuse = reuse or not run_missing
        self.run_missing = run_missing
        self.verbose = verbose
        self.cache = {}
        self.wall_seconds = 0.

    def key(self, name, scene, overrides, ranks=1, threads=None):
        folder = os.path.join(self.out_root, name)
        text = variant_text(scene, folder, overrides)
        src = f"{_binary_stamp(self.binary)}\n{ranks}\n{threads}\n{text}"
        return folder, text, hashlib.sha1(src.encode()).hexdigest()[:16]

    def run(self, name, scene, overrides, ranks=1, threads=None):
        """Run one variant in folder out_root/name; return a result dict:
        name, key, folder, exit, wall, message, summary (dict or None),
        max_rss_mb (largest resident set of the program or of one rank,
        measured by the OS), ranks, threads_requested."""
        folder, text, key = self.key(name, scene, overrides, ranks, threads)
        if key in self.cache:
            return self.cache[key]
        prm = os.path.join(self.out_root, name + ".prm")
        key_file = os.path.join(folder, "benchmark_key.json")
        summary_file = os.path.join(folder, "summary.json")
        if self.reuse and os.path.exists(key_file) and os.path.exists(summary_file):
            stored = read_json(key_file) or {}
            if stored.get("key") == key:
                result = dict(stored["result"])
                result["summary"] = read_json(summary_file)
                result["reused"] = True
                self.cache[key] = result
                if self.verbose:
                    print(f"  {name}: read from {folder}", flush=True)
                return result
        if not self.run_missing:
            if self.verbose:
                print(f"  {name}: no earlier result with the same key, not run",
                      flush=True)
            result = {"name": name, "key": key, "folder": folder, "prm": prm,
                      "exit": None, "wall": 0., "message": "not run",
                      "max_rss_mb": None, "ranks": ranks,
                      "threads_requested": threads, "summary": None,
                      "reused": False}
            self.cache[key] = result
            return result

        os.makedirs(self.out_root, exist_ok=True)
        with open(prm, "w") as f:
            f.write(text)
        # A stale summary must not be mistaken for this run's.
        for stale in (summary_file, key_file):
            if os.path.exists(stale):
                os.remove(stale)
        cmd = [self.binary, prm]
        env = dict(os.environ)
        if ranks > 1:
            cmd = ["mpirun", "-np", str(ranks), "--oversubscribe"] + cmd
            env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
            env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
        if threads is not None:
            env["DEAL_II_NUM_THREADS"] = str(threads)
            env["OMP_NUM_THREADS"] = str(threads)
            env["OPENBLAS_NUM_THREADS"] = str(threads)
        if self.verbose:
            print(f"  {name}: running ({ranks} rank(s)"
                  + (f", {threads} thread(s)" if threads else "") + ") ...",
                  end="", flush=True)
        start = time.time()
        code, rss_kb, stderr = _run_process(cmd, env, self.timeout, ROOT)
        wall = time.time() - start
        self.wall_seconds += wall
        message = stderr.strip().splitlines()
        if code is None:
            message.append(f"killed after {self.timeout} s")
        result = {
            "name": name, "key": key, "folder": folder, "prm": prm,
            "command": " ".join(shlex.quote(c) for c in cmd),
            "exit": code, "wall": wall,
            "message": message[-1] if message else "",
            "max_rss_mb": rss_kb / 1024. if rss_kb else None,
            "ranks": ranks, "threads_requested": threads, "reused": False,
            "timed_out": code is None,
        }
        summary = read_json(summary_file) if os.path.exists(summary_file) else None
        if summary is not None:
            with open(key_file, "w") as f:
                json.dump({"key": key, "result": result}, f, indent=1)
        result["summary"] = summary
        if self.verbose:
            status = summary.get("status", "?") if summary else "no summary"
            dofs = summary["mesh"]["dofs"] if summary else "?"
            print(f" {status}, {dofs} DoFs, {wall:.1f} s", flush=True)
            if summary is None or status != "converged":
                print(f"    exit {code}: {result['message'][:200]}", flush=True)
        self.cache[key] = result
        return result


def _run_process(cmd, env, timeout, cwd):
    """Run @p cmd in its own process group; return (exit code or None on
    time-out, max RSS in kB of the process or its largest waited-for
    descendant, stderr text)."""
    with tempfile.TemporaryFile(mode="w+") as err:
        proc = subprocess.Popen(cmd, env=env, cwd=cwd, stdout=subprocess.DEVNULL,
                                stderr=err, start_new_session=True)
        deadline = None if not timeout else time.time() + timeout
        code, rss = None, None
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid == proc.pid:
                code = os.waitstatus_to_exitcode(status) \
                    if hasattr(os, "waitstatus_to_exitcode") else (status >> 8)
                rss = usage.ru_maxrss
                break
            if deadline is not None and time.time() > deadline:
                # Only the process group this function created.
                # (mpirun passes SIGTERM on to its ranks).
                try:
                    os.killpg(proc.pid, signal.SIGTERM)
                except ProcessLookupError:
                    pass
                usage = None
                for _ in range(100):
                    pid, _, usage = os.wait4(proc.pid, os.WNOHANG)
                    if pid == proc.pid:
                        break
                    usage = None
                    time.sleep(0.1)
                if usage is None:
                    try:
                        os.killpg(proc.pid, signal.SIGKILL)
                    except ProcessLookupError:
                        pass
                    _, _, usage = os.wait4(proc.pid, 0)
                rss = usage.ru_maxrss
                code = None
                break
            time.sleep(0.1)
        proc.returncode = code if code is not None else -9
        err.seek(0)
        return code, rss, err.read()


def run_timed(binary, prm, cwd, ranks=1, env=None):
    """Run @p binary on @p prm in @p cwd (under mpirun on @p ranks > 1,
    with OpenMPI allowed to run as root), with @p env added to this
    process's environment; return (wall seconds, CompletedProcess).
    A relative @p binary or @p prm is the caller's, not @p cwd's."""
    cmd = [binary if os.sep not in binary else absolute(binary), absolute(prm)]
    full_env = dict(os.environ, **(env or {}))
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), "--oversubscribe"] + cmd
        full_env.update(OMPI_ALLOW_RUN_AS_ROOT="1",
                        OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.perf_counter()
    out = subprocess.run(cmd, cwd=cwd, env=full_env, capture_output=True,
                         text=True)
    return time.perf_counter() - start, out


def peer_parser(doc, peer):
    """The argument parser of a peer benchmark (its description the first
    line of @p doc): --binary, --peer (default ../shared/peers/@p peer
    beside the project) and --runs."""
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build",
                                                         "signorini"))
    parser.add_argument("--peer", default=os.path.join(
        ROOT, "..", "shared", "peers", peer))
    parser.add_argument("--runs", type=int, default=3)
    return parser


def run_variant(binary, scene, work, overrides, ranks=1, extra=""):
    """Write @p work/run.prm (the committed prm/@p scene with
    @p overrides, see variant_text, and the text @p extra after them), run
    it in @p work; return (wall seconds, its summary.json). Exit codes 0
    and 4 (a quantity outside its requested tolerance, which coarse
    benchmark meshes give) are accepted; any other raises."""
    prm = os.path.join(work, "run.prm")
    with open(prm, "w") as f:
        f.write(variant_text(os.path.join(PRM, scene), work, overrides) + extra)
    wall, out = run_timed(binary, prm, work, ranks)
    if out.returncode not in (0, 4):
        raise RuntimeError(f"signorini {scene} failed ({out.returncode}):\n"
                           f"{out.stdout[-2000:]}\n{out.stderr[-2000:]}")
    return wall, read_json(os.path.join(work, "summary.json"))


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


# --------------------------------------------------------------------------
# Reading summary.json

def timing(summary):
    """The timing block (seconds per phase), whatever its key."""
    if not summary:
        return {}
    for key in ("timing", "wall time [s]"):
        if isinstance(summary.get(key), dict):
            return {k: v for k, v in summary[key].items()
                    if isinstance(v, (int, float)) and not isinstance(v, bool)
                    and k not in ("peak memory MB", "peak memory [MB]")}
    return {}


def peak_memory_mb(summary):
    """The program's own peak memory, if it reports one."""
    if not summary:
        return None
    for key in ("peak memory MB", "peak memory [MB]"):
        if key in summary:
            return summary[key]
    for block in ("timing", "wall time [s]"):
        t = summary.get(block)
        if isinstance(t, dict):
            for key in ("peak memory MB", "peak memory [MB]"):
                if key in t:
                    return t[key]
    return None


def iterations(summary):
    """The run's iteration count: Newton's or Ipopt's, else that of
    whichever solver wrote a top-level "... iterations" entry (the interior
    point method)."""
    if not summary:
        return None
    for key in ("newton iterations", "ipopt iterations"):
        if key in summary:
            return summary[key]
    return next((v for k, v in summary.items() if k.endswith(" iterations")),
                None)


def step_iterations(summary):
    out = []
    for step in (summary or {}).get("steps", []):
        out.append(step.get("newton iterations", step.get("ipopt iterations")))
    return out


def linear_iterations(summary):
    return sum(step.get("linear iterations", 0) or 0
               for step in (summary or {}).get("steps", []))


def converged(result):
    s = result.get("summary")
    return bool(s) and s.get("status") == "converged"


# --------------------------------------------------------------------------
# Fits and formatting

def fit_exponent(xs, ys):
    """Least squares slope of log y against log x (None if fewer than two
    usable points)."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys)
           if x and y and x > 0 and y > 0]
    if len(pts) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    if sxx == 0:
        return None
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx


def fmt(value, spec=".3g", missing="–"):
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return missing
    if isinstance(value, str):
        return value
    return format(value, spec)


def fmt_time(t):
    if t is None:
        return "–"
    if t >= 100:
        return f"{t:.0f}"
    if t >= 10:
        return f"{t:.1f}"
    if t >= 0.1:
        return f"{t:.2f}"
    return f"{t:.2g}"


def markdown_table(header, rows):
    lines = ["| " + " | ".join(header) + " |",
             "|" + "|".join("---" for _ in header) + "|"]
    for r in rows:
        lines.append("| " + " | ".join(str(c) for c in r) + " |")
    return "\n".join(lines)


# --------------------------------------------------------------------------
# Machine and provenance

def machine_info():
    info = {"model": platform.processor() or platform.machine(),
            "cpus": os.cpu_count(), "memory_gb": None}
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        fields = {}
        for line in out.splitlines():
            if ":" in line:
                k, v = line.split(":", 1)
                fields[k.strip()] = v.strip()
        info["model"] = fields.get("Model name", info["model"])
        info["cpus"] = int(fields.get("CPU(s)", info["cpus"]))
        cores = fields.get("Core(s) per socket")
        sockets = fields.get("Socket(s)")
        if cores and sockets:
            info["cores"] = int(cores) * int(sockets)
        info["threads_per_core"] = fields.get("Thread(s) per core")
        info["hypervisor"] = fields.get("Hypervisor vendor")
    except (OSError, ValueError):
        pass
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    info["memory_gb"] = int(line.split()[1]) / 1024. ** 2
    except OSError:
        pass
    info["os"] = platform.platform()
    try:
        info["load"] = os.getloadavg()
    except OSError:
        info["load"] = None
    return info


def git_revision():
    # A benchmark may run a frozen copy of the binary while the tree moves
    # on: SIGNORINI_BINARY_COMMIT then names the commit it was built from.
    if os.environ.get("SIGNORINI_BINARY_COMMIT"):
        return os.environ["SIGNORINI_BINARY_COMMIT"]
    try:
        rev = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                             capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain",
                                "--untracked-files=no"],
                               capture_output=True, text=True).stdout.strip()
        return rev + (" (with uncommitted changes)" if dirty else "")
    except OSError:
        return "unknown"


def machine_line(info):
    mem = f"{info['memory_gb']:.0f} GB" if info.get("memory_gb") else "? GB"
    cores = info.get("cores", info.get("cpus"))
    extra = f", {info['hypervisor']} guest" if info.get("hypervisor") else ""
    return (f"{info['model']}, {cores} cores ({info['cpus']} CPUs){extra}, "
            f"{mem} memory, {info['os']}")


def stamp(info, argv, binary, quick=False):
    cmd = " ".join(shlex.quote(a) for a in argv)
    load = info.get("load")
    load_text = (f"; load average at start {load[0]:.2f}" if load else "")
    return (f"Measured {datetime.datetime.now():%Y-%m-%d %H:%M} on {machine_line(info)}"
            f"{load_text}; commit {git_revision()}; binary `{binary}`.\n"
            f"Command: `{cmd}`"
            + ("\n\n**Quick mode: small sizes only, for checking the script; "
               "the numbers say nothing about scaling.**" if quick else ""))


def warn_if_busy(info):
    load = info.get("load")
    if load and info.get("cpus") and load[0] > 0.5:
        print(f"warning: the 1-minute load average is {load[0]:.2f} on "
              f"{info['cpus']} CPUs: other processes compete for the cores and "
              "the times will be too large and noisy", file=sys.stderr)


def replace_block(path, tag, text):
    """Put @p text between '<!-- tag BEGIN -->' and '<!-- tag END -->' in
    the file @p path if it has those markers; else append a marked block
    (creating the file if needed)."""
    begin, end = f"<!-- {tag} BEGIN -->", f"<!-- {tag} END -->"
    content = ""
    if os.path.exists(path):
        with open(path) as f:
            content = f.read()
    block = f"{begin}\n{text.rstrip()}\n{end}"
    if begin in content and end in content:
        head, rest = content.split(begin, 1)
        _, tail = rest.split(end, 1)
        content = head + block + tail
    else:
        content = (content.rstrip() + "\n\n" if content else "") + block + "\n"
    with open(path, "w") as f:
        f.write(content)
