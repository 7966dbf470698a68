#!/usr/bin/env python3
"""Mutation test of the parameter-file input of signorini.

Usage:
  prm_mutation.py EXECUTABLE SOURCE_DIR [--variants N] [--seed S]
                  [--timeout T] [--jobs J] [--memory-limit MB] [--keep DIR]
                  [--only I,J,...] [--list] [--verbose]

The script takes fast committed scenes from SOURCE_DIR/prm, corrupts them
in random ways (deleted, duplicated or truncated lines, swapped values,
wrong types, huge/tiny/negative/non-finite numbers, empty values, unknown
or misspelt keys and subsections, unbalanced subsection/end, broken
syntax, bad expressions and lists, other valid choices of a selection,
missing include/mesh/options files, a file that includes itself, CRLF,
control characters, 100000-character lines, corrupt Gmsh meshes and Ipopt
option files, an output folder that cannot be created, ...), runs the
executable on every variant and checks that it never dies by a signal or
hangs: every variant must end in a clear error or in a valid run.

Variants. Variant i depends only on --seed and i (not on --jobs or on
--variants). The first variants apply each kind of mutation alone, then
each kind of Gmsh corruption alone (so that every kind is tried whatever
the seed); the others apply 1-3 random mutations (mostly one: once a
mutation is an error, the next ones rarely matter). `--list` prints the
variants without running anything, `--only 17` runs variant 17 alone.
Line numbers in the descriptions are those of the scene (without the
header below) at the time of the mutation.

Scenes. The plane-strain SSNV187 scenes (Dirichlet, on a plane with
penalty or Ipopt, Q2 incompressible with Ipopt), block_squeeze and the 3D
cubes take about a second, mostly start-up; hertz_groove and default.prm
are used with coarser meshes (see SCENES) so that a valid run stays
short; the slow scenes (ironing, hertz_stiff_block, hertz_block) are not
used. Each variant file starts with a header that the mutations never
touch: its own `Output directory` in a temporary folder, `Output > Format
= none` and `Verbosity = quiet`; the scene's lines follow, then blocks
that some mutations append (a Gmsh mesh, an Ipopt options file). Before
the variants, every unmutated scene must run (exit 0, or 4 for the
coarsened ones), otherwise the script stops and fails.

Pass criteria per variant:
  * the process exits normally (no signal, no timeout) with 0, 2, 3 or 4
    (1, "internal error", is a failure, and so is any other code);
  * exit 2: the message (stderr + stdout) is not empty; it names an entry
    ("Subsection > Entry", or a top-level entry), a file and line
    ("file:12", "Line <12> of file <...>") or at least the offending file
    ("mesh.msh: ..."); it does not leak internals (a deal.II assertion
    text, a source file:line, std::bad_alloc); if it quotes "The entry
    value V for the entry named K", some `set K = V` line must exist
    (else it misquotes the input); and no output folder was created
    ("nothing written");
  * exit 0/4: summary.json exists, is strict JSON (no NaN/Infinity) and
    says "converged"; exit 3: the same with "failed".

Timeouts and memory. A run is killed after --timeout seconds (default 60)
and may use at most --memory-limit MB of address space (default 4096;
exceeding it usually surfaces as std::bad_alloc, a failure). The value
palettes are chosen so that a correct program cannot legitimately run
long: "huge" integers are all beyond the int range or not integers (the
program must reject them), and swaps or duplicates only move values that
already occur in the scene (at most ~80). Only a few entries can make a
run legitimately long with such values (step counts, refinement levels,
subdivisions, iteration/stage limits, tolerances, minimum step fraction,
dimension, degree, method, contact type: COST_ENTRIES). A timeout is
therefore a failure ("hang"), unless one of the variant's mutations
changed one of these entries: then it is reported as "timeout explained
by ..." and counts as passed. With the defaults, 200 variants take about
2 minutes on 2 cores with --jobs 2 (each run costs ~0.6 s of start-up:
shared libraries and the MPI singleton).

Output: one line per failing variant (scene, exit status, why it failed,
mutations, the last line of the message), then exactly "N passed, M
failed". The exit status is 1 if any variant failed (or if an unmutated
scene does not run), 0 otherwise. With --keep DIR every failing variant's
folder (scene.prm, auxiliary files, what.txt with the mutations, the
command, exit status and full message) is copied to DIR/variant_NNN for
reproduction.

Only the Python 3 standard library is used.
"""

import argparse
import concurrent.futures
import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

# ---------------------------------------------------------------------------
# Scenes: label, file name in prm/, weight, the entries whose value is
# replaced in the committed file before mutating (to keep valid runs short,
# or to switch the solver; each must occur exactly once), and whether the
# scene is the unit square with boundary ids 0-3 and material id 0 (then a
# Gmsh mesh of it can be substituted).
SCENES = [
    ("ssnv187_neo_hookean", "ssnv187_neo_hookean.prm", 4, [], True),
    ("ssnv187_mooney_rivlin", "ssnv187_mooney_rivlin.prm", 3, [], True),
    ("ssnv187_c20", "ssnv187_c20.prm", 3, [], True),
    ("ssnv187_plane", "ssnv187_plane.prm", 4, [], True),
    ("ssnv187_plane_ipopt", "ssnv187_plane.prm", 2,
     [("Method", "ipopt")], True),
    ("ssnv187_incompressible", "ssnv187_incompressible.prm", 3, [], True),
    ("block_squeeze", "block_squeeze.prm", 2, [], False),
    ("ssnv187_3d_neo_hookean", "ssnv187_3d_neo_hookean.prm", 1, [], False),
    ("ssnv187_3d_c20", "ssnv187_3d_c20.prm", 1, [], False),
    ("hertz_groove", "hertz_groove.prm", 1, [("Local refinements", "2")],
     False),
    ("default", "default.prm", 2,
     [("Global refinements", "2"), ("Local refinements", "2")], False),
    # 3D contact and two bodies (issue 52: a foundation out of reach, a
    # radius of 1e308 and a modulus left out went wrong there).
    ("hertz_sphere", "hertz_sphere.prm", 2,
     [("Global refinements", "1"), ("Local refinements", "1")], False),
    ("hertz_block", "hertz_block.prm", 2,
     [("Global refinements", "0"), ("Local refinements", "2")], False),
]

# Entries whose (valid) value can legitimately make a run long.
COST_ENTRIES = {
    "Dimension", "Polynomial degree", "Number of steps", "End time",
    "Minimum step fraction", "Global refinements", "Local refinements",
    "Local refinement radius", "Subdivisions", "Maximum iterations",
    "Maximum stages", "Maximum backtracks", "Maximum shifts",
    "Residual tolerance", "Absolute tolerance", "Energy tolerance",
    "Penetration tolerance", "Tolerance", "Minimum growth",
    "Maximum growth", "Target fraction", "Load step reduction",
    "Initial penalty factor", "Restart each load step",
    "Gauss points per face", "Increment tolerance", "Maximum increment",
    "Backtracking factor", "Armijo parameter", "Initial shift",
    "Relative tolerance", "Method", "Type",
}

# Valid alternatives of the selections (a valid value that may not fit
# the rest of the scene).
SELECTIONS = {
    "Method": ["newton", "newton-penalty", "ipopt", "interior-point",
               "automatic"],
    "Contact > Type": ["none", "rigid foundation", "two bodies"],
    "Linear solver > Type": ["direct", "cg-amg", "minres-amg"],
    "Model": ["neo-Hookean", "ELAS_HYPER", "Saint Venant-Kirchhoff",
              "linear elastic"],
    "Geometry > Shape": ["rectangle", "quarter disk", "half disk", "die"],
    "Foundation > Shape": ["plane", "circle", "sine", "expression"],
    "Source": ["generated", "gmsh"],
    "Component": ["x", "y", "z"],
    "Side": ["lower", "upper"],
    "Incompressible": ["true", "false"],
    "Active": ["true", "false"],
    "Dimension": ["2", "3"],
    "Polynomial degree": ["1", "2"],
}

# Value palettes.
WRONG_FOR_NUMBER = ["abc", "1.2.3", "1,5", "0x1A", "true", "1e", "--1",
                    "2 3", "one", "1O", "\u00bd", "1e+", ".", "+-3", "3,",
                    "1;2"]
WRONG_FOR_WORD = ["3", "-1", "0.5", "1e300", "ELAS HYPER", "Neo-Hookean",
                  "rigid_foundation", "yes please", "newton penalty",
                  "\u00e9lastique"]
WRONG_FOR_BOOL = ["maybe", "2", "truee", "on", "1.0"]
ODD_TEXT = ['"quoted"', "back\\slash", "tab\there",
            "\u00fcn\u00efc\u00f8d\u00e9",
            "a,b", "{}", "a/b/../../c", "  padded  ", "%s%n%d", "x" * 300]
HUGE = ["1e300", "-1e300", "1e20", "1e309", "-1e309", "1e308", "-1e308",
        "1e400", "2147483648",
        "4294967296", "9223372036854775808", "123456789012345678901234567890",
        "1.7976931348623157e308"]
TINY = ["1e-300", "0", "-0", "4.9e-324", "1e-320", "0.0", "-0.0", "1e-20",
        "1e-12"]
NONFINITE = ["nan", "-nan", "NaN", "inf", "-inf", "Inf", "infinity"]
BAD_EXPRESSIONS = ["1/0", "sqrt(-1)", "log(0)", "exp(1000*(t+1))",
                   "1e300*1e300*t", "(t", "t)", "tt", "x*q", "sin", "0*",
                   "", "t^^2", "if(t>0.5, 1/0, 0)", "asin(2)", "1e400"]
BAD_BOUNDARY_SPECS = ["2 y", "2: yy", "2:", ": y", "999: x", "-1: x",
                      "256: x", "2: xyz", "2: y,, 0: x", "2: y 0: x",
                      "2: y; 0: x", "2.5: x", "x: 2", "2: Y"]

GMSH_CORRUPTIONS = [
    "truncate", "delete_line", "node_out_of_range", "node_count",
    "element_type", "nan_coordinate", "inverted_cell", "degenerate_cell",
    "duplicate_node", "empty", "binary", "version_4", "no_end_nodes",
    "huge_coordinate", "no_boundary_lines", "wrong_material",
    "negative_node", "short_element", "missing_file",
]
IPOPT_OPTIONS = [
    "not_an_ipopt_option 3\n", "tol abc\n", "max_iter -5\n",
    "print_level 99\n", "linear_solver ma57\n", "tol\n", "\x00\x01\x02\n",
    "mu_strategy sideways\n", "tol 1e-300\nmax_iter 3\n", "",
    "max_iter 2147483648\n",
]

# ---------------------------------------------------------------------------
# Parsing the parameter file (the subset of deal.II's syntax the scenes use).


class Line:
    def __init__(self, raw, path):
        self.raw = raw
        body, _, comment = raw.partition("#")
        self.comment = comment
        self.indent = raw[: len(raw) - len(raw.lstrip())]
        code = body.strip()
        self.kind = "other"
        self.key = None
        self.value = None
        self.path = tuple(path)
        if not code:
            self.kind = "blank"
        elif code.startswith("subsection ") or code == "subsection":
            self.kind = "subsection"
            path.append(code[len("subsection"):].strip())
            self.path = tuple(path)
        elif code == "end":
            self.kind = "end"
            if path:
                path.pop()
        elif code.startswith("set ") and "=" in code:
            self.kind = "set"
            key, _, value = code[4:].partition("=")
            self.key = key.strip()
            self.value = value.strip()
        elif code.startswith("include"):
            self.kind = "include"

    def with_value(self, value):
        text = self.indent + "set " + self.key + " = " + value
        if self.comment:
            text += "   #" + self.comment
        return text

    def entry(self):
        return " > ".join(self.path + (self.key,))


def parse(lines):
    path = []
    return [Line(raw, path) for raw in lines]


NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def value_kind(value):
    if value == "":
        return "empty"
    if re.fullmatch(r"[+-]?\d+", value):
        return "int"
    if NUMBER.match(value):
        return "float"
    if value in ("true", "false"):
        return "bool"
    if ":" in value:
        return "boundaries"
    parts = [p.strip() for p in value.split(",")]
    if len(parts) > 1 and all(NUMBER.match(p) for p in parts):
        return "list"
    if ";" in value or re.search(r"[*/^()]", value):
        return "expression"
    return "word"


# ---------------------------------------------------------------------------
# Mutations. Each takes (rng, lines, ctx) with lines a list of strings (the
# scene's own lines, without the header) and returns a description, or None
# if it does not apply. ctx collects appended blocks, auxiliary files, and
# whether a cost entry was touched.


class Context:
    def __init__(self, scene):
        self.scene = scene
        self.appended = []        # text blocks appended after the scene
        self.files = {}           # name -> bytes, written beside scene.prm
        self.cost = []            # cost entries the mutations changed
        self.unwritable_output = False
        self.gmsh_corruption = None   # forced kind of Gmsh corruption

    def touched(self, line):
        if line.kind == "set" and line.key in COST_ENTRIES:
            self.cost.append(line.entry())


def pick(rng, lines, kinds):
    parsed = parse(lines)
    candidates = [i for i, l in enumerate(parsed) if l.kind in kinds]
    if not candidates:
        return None, parsed
    return rng.choice(candidates), parsed


def replace_value(rng, lines, ctx, make, what, kinds=None):
    """Replace the value of one random set line by make(rng, old_value)."""
    parsed = parse(lines)
    candidates = [i for i, l in enumerate(parsed)
                  if l.kind == "set" and (kinds is None or
                                          value_kind(l.value) in kinds)]
    if not candidates:
        return None
    i = rng.choice(candidates)
    line = parsed[i]
    new = make(rng, line.value)
    if new is None or new == line.value:
        return None
    lines[i] = line.with_value(new)
    ctx.touched(line)
    return "%s: %s = %r -> %r (line %d)" % (what, line.entry(), line.value,
                                            new, i + 1)


def replace_list_item(rng, value, palette):
    items = value.split(",") if "," in value else [value]
    k = rng.randrange(len(items))
    items[k] = (" " if k else "") + rng.choice(palette)
    return ",".join(items)


def m_delete_line(rng, lines, ctx):
    i, parsed = pick(rng, lines, ("set", "subsection", "end", "include"))
    if i is None:
        return None
    ctx.touched(parsed[i])
    del lines[i]
    return "delete line %d: %r" % (i + 1, parsed[i].raw.strip())


def m_duplicate_line(rng, lines, ctx):
    i, parsed = pick(rng, lines, ("set", "subsection", "end"))
    if i is None:
        return None
    where = i + 1 if rng.random() < 0.7 else rng.randrange(len(lines) + 1)
    lines.insert(where, lines[i])
    return "duplicate line %d %r at %d" % (i + 1, parsed[i].raw.strip(),
                                           where + 1)


def m_swap_values(rng, lines, ctx):
    parsed = parse(lines)
    sets = [i for i, l in enumerate(parsed) if l.kind == "set"]
    if len(sets) < 2:
        return None
    for _ in range(10):
        i, j = rng.sample(sets, 2)
        if parsed[i].value != parsed[j].value:
            break
    a, b = parsed[i], parsed[j]
    lines[i] = a.with_value(b.value)
    lines[j] = b.with_value(a.value)
    ctx.touched(a)
    ctx.touched(b)
    return "swap values: %s = %r <-> %s = %r" % (a.entry(), a.value,
                                                 b.entry(), b.value)


def m_wrong_type(rng, lines, ctx):
    def make(rng, old):
        kind = value_kind(old)
        if kind in ("int", "float"):
            return rng.choice(WRONG_FOR_NUMBER)
        if kind == "list":
            return replace_list_item(rng, old, WRONG_FOR_NUMBER)
        if kind == "bool":
            return rng.choice(WRONG_FOR_BOOL)
        if kind == "word":
            return rng.choice(WRONG_FOR_WORD + ODD_TEXT)
        return rng.choice(WRONG_FOR_NUMBER + WRONG_FOR_WORD)
    return replace_value(rng, lines, ctx, make, "wrong type")


def numeric_mutation(palette, what):
    def mutate(rng, lines, ctx):
        def make(rng, old):
            if value_kind(old) == "list":
                return replace_list_item(rng, old, palette)
            if value_kind(old) == "expression":
                parts = old.split(";")
                k = rng.randrange(len(parts))
                parts[k] = (" " if k else "") + rng.choice(palette) + "*t"
                return ";".join(parts)
            return rng.choice(palette)
        return replace_value(rng, lines, ctx, make, what,
                             ("int", "float", "list", "expression"))
    return mutate


def m_negative(rng, lines, ctx):
    def make(rng, old):
        kind = value_kind(old)
        if kind in ("int", "float"):
            return old[1:] if old.startswith("-") else "-" + old
        if kind == "list":
            items = old.split(",")
            k = rng.randrange(len(items))
            item = items[k].strip()
            items[k] = (" " if k else "") + (item[1:] if item.startswith("-")
                                             else "-" + item)
            return ",".join(items)
        if kind == "expression":
            return ";".join(" -(" + p.strip() + ")" if p.strip() else p
                            for p in old.split(";")).strip()
        return None
    return replace_value(rng, lines, ctx, make, "negate",
                         ("int", "float", "list", "expression"))


def m_empty_value(rng, lines, ctx):
    return replace_value(rng, lines, ctx, lambda rng, old: "", "empty value")


def m_garbage_key(rng, lines, ctx):
    parsed = parse(lines)
    choice = rng.random()
    if choice < 0.4:
        where = rng.randrange(len(lines) + 1)
        key = rng.choice(["Xyzzy", "Youngs modulus", "Poisson ratio",
                          "set", "=", "Number of step", "C30"])
        value = rng.choice(["1", "abc", ""])
        lines.insert(where, "set %s = %s" % (key, value))
        return "insert unknown key %r at line %d" % (key, where + 1)
    sets = [i for i, l in enumerate(parsed) if l.kind == "set"]
    if not sets:
        return None
    i = rng.choice(sets)
    line = parsed[i]
    key = line.key
    how = rng.randrange(4)
    if how == 0:
        k = rng.randrange(len(key))
        new_key = key[:k] + key[k + 1:]
    elif how == 1:
        new_key = key.lower() if key != key.lower() else key.upper()
    elif how == 2:
        new_key = key.replace(" ", "  ", 1) if " " in key else key + "s"
    else:
        new_key = key + " " + rng.choice(["x", "2", "(old)"])
    if new_key == key or not new_key.strip():
        new_key = key + "_"
    lines[i] = line.raw.replace(key, new_key, 1)
    return "rename key %s -> %r (line %d)" % (line.entry(), new_key, i + 1)


def m_truncate_line(rng, lines, ctx):
    i, parsed = pick(rng, lines, ("set", "subsection", "end"))
    if i is None:
        return None
    text = lines[i].rstrip()
    if len(text.strip()) < 2:
        return None
    start = len(text) - len(text.lstrip())
    cut = rng.randrange(start + 1, len(text))
    lines[i] = text[:cut]
    ctx.touched(parsed[i])
    return "truncate line %d to %r" % (i + 1, lines[i].strip())


def m_unbalanced(rng, lines, ctx):
    parsed = parse(lines)
    how = rng.randrange(5)
    ends = [i for i, l in enumerate(parsed) if l.kind == "end"]
    subs = [i for i, l in enumerate(parsed) if l.kind == "subsection"]
    if how == 0 and ends:
        i = rng.choice(ends)
        del lines[i]
        return "delete 'end' at line %d" % (i + 1)
    if how == 1:
        where = rng.randrange(len(lines) + 1)
        lines.insert(where, "end")
        return "insert 'end' at line %d" % (where + 1)
    if how == 2 and subs:
        i = rng.choice(subs)
        del lines[i]
        return "delete %r at line %d" % (parsed[i].raw.strip(), i + 1)
    if how == 3 and subs:
        i = rng.choice(subs)
        name = parsed[i].path[-1]
        new = rng.choice([name + "s", name.lower(), "Body 3", "Materal",
                          name + " > " + name, ""])
        lines[i] = parsed[i].indent + ("subsection " + new).rstrip()
        return "rename subsection %r -> %r (line %d)" % (name, new, i + 1)
    where = rng.randrange(len(lines) + 1)
    lines.insert(where, "subsection " + rng.choice(["Unknown", "Body 1",
                                                     "Solver", "Output"]))
    return "insert unclosed subsection at line %d: %r" % (where + 1,
                                                          lines[where])


def m_syntax(rng, lines, ctx):
    i, parsed = pick(rng, lines, ("set",))
    if i is None:
        return None
    line = parsed[i]
    how = rng.randrange(7)
    ind = line.indent
    if how == 0:
        new = ind + "set %s %s" % (line.key, line.value)
    elif how == 1:
        new = ind + "%s = %s" % (line.key, line.value)
    elif how == 2:
        new = ind + "set %s == %s" % (line.key, line.value)
    elif how == 3:
        new = ind + "SET %s = %s" % (line.key, line.value)
    elif how == 4:
        new = ind + "set = %s" % line.value
    elif how == 5:
        new = ind + "set %s = %s \\" % (line.key, line.value)
    else:
        new = ind + "set %s = %s = %s" % (line.key, line.value, line.value)
    lines[i] = new
    ctx.touched(line)
    return "syntax: line %d %r -> %r" % (i + 1, line.raw.strip(), new.strip())


def m_bad_expression(rng, lines, ctx):
    def make(rng, old):
        parts = old.split(";")
        how = rng.randrange(4)
        if how == 0 and len(parts) > 1:
            return ";".join(parts[:-1])
        if how == 1:
            return old + "; 0"
        k = rng.randrange(len(parts))
        parts[k] = (" " if k else "") + rng.choice(BAD_EXPRESSIONS)
        return ";".join(parts)
    return replace_value(rng, lines, ctx, make, "bad expression",
                         ("expression",))


def m_list(rng, lines, ctx):
    def make(rng, old):
        kind = value_kind(old)
        if kind == "boundaries":
            if rng.random() < 0.5:
                return rng.choice(BAD_BOUNDARY_SPECS)
            first = old.split(",")[0].strip()
            return old + ", " + first      # the same part twice
        items = [s.strip() for s in old.split(",")]
        how = rng.randrange(6)
        if how == 0:
            return ", ".join(items[:-1])
        if how == 1:
            return ", ".join(items + [items[-1]])
        if how == 2:
            return "; ".join(items)
        if how == 3:
            return ",".join(items) + ","
        if how == 4:
            return ", ,".join(items)
        return ", ".join(reversed(items)) + ", " + ", ".join(items)
    return replace_value(rng, lines, ctx, make, "list", ("list", "boundaries"))


def m_valid_alternative(rng, lines, ctx):
    parsed = parse(lines)
    def selection(line):
        if line.kind != "set":
            return None
        if line.path:
            scoped = line.path[-1] + " > " + line.key
            if scoped in SELECTIONS:
                return SELECTIONS[scoped]
        return SELECTIONS.get(line.key)
    candidates = [i for i, l in enumerate(parsed) if selection(l)]
    if not candidates:
        return None
    i = rng.choice(candidates)
    line = parsed[i]
    options = [o for o in selection(line) if o != line.value]
    new = rng.choice(options)
    lines[i] = line.with_value(new)
    ctx.touched(line)
    return "other choice: %s = %r -> %r" % (line.entry(), line.value, new)


def m_missing_file(rng, lines, ctx):
    how = rng.randrange(4)
    if how == 0:
        where = rng.randrange(len(lines) + 1)
        lines.insert(where, "include /nonexistent/missing.prm")
        return "include a missing file at line %d" % (where + 1)
    if how == 1:
        ctx.appended.append("subsection Mesh\n  set Source = gmsh\n"
                            "  set Gmsh file = missing_dir/mesh.msh\nend")
        return "Mesh > Gmsh file = missing_dir/mesh.msh (missing)"
    if how == 2:
        ctx.appended.append("subsection Solver\n  subsection Ipopt\n"
                            "    set Options file = missing.opt\n  end\nend")
        return "Solver > Ipopt > Options file = missing.opt (missing)"
    where = rng.randrange(len(lines) + 1)
    lines.insert(where, "include .")
    return "include a directory at line %d" % (where + 1)


def m_self_include(rng, lines, ctx):
    # At the top level (outside any subsection), where the included copy
    # parses like the file itself.
    parsed = parse(lines)
    top = [0] + [i + 1 for i, l in enumerate(parsed)
                 if not l.path and l.kind in ("end", "set", "blank")]
    where = rng.choice(top)
    lines.insert(where, "include scene.prm")
    return "the file includes itself at line %d" % (where + 1)


def m_weird_text(rng, lines, ctx):
    how = rng.randrange(6)
    if how == 0:
        for i, l in enumerate(lines):
            lines[i] = l + "\r"
        return "CRLF line endings"
    if how == 1:
        for i, l in enumerate(lines):
            lines[i] = l.replace("  ", "\t")
        return "tabs for indentation"
    if how == 2:
        where = rng.randrange(len(lines) + 1)
        lines.insert(where, "\x00\x01\xff\xfe garbage \x7f")
        return "control characters at line %d" % (where + 1)
    if how in (3, 4) and pick(rng, lines, ("set",))[0] is None:
        how = 5
    if how == 3:
        i, parsed = pick(rng, lines, ("set",))
        lines[i] = lines[i].replace("'", "\u2019").replace(" = ", " \u2550 ")
        return "unicode look-alikes in line %d: %r" % (i + 1, lines[i].strip())
    if how == 4:
        i, parsed = pick(rng, lines, ("set",))
        lines[i] = parsed[i].with_value("1" * 100000)
        ctx.touched(parsed[i])
        return "100000-digit value for %s" % parsed[i].entry()
    where = rng.randrange(len(lines) + 1)
    lines.insert(where, "x" * 100000)
    return "100000-character line at %d" % (where + 1)


def m_whole_file(rng, lines, ctx):
    how = rng.randrange(4)
    if how == 0:
        lines[:] = []
        return "empty scene (header only)"
    if how == 1:
        lines[:] = ["# nothing but a comment"]
        return "only a comment"
    if how == 2:
        lines[:] = ["end"] * 3
        return "only 'end' lines"
    lines[:] = lines[: rng.randrange(1, max(2, len(lines)))]
    return "file cut after line %d" % len(lines)


def unit_square_msh(n, boundary_ids, material):
    """Gmsh 2.2 ASCII text of [0,1]^2 with n x n quadrilaterals."""
    nodes = []
    for j in range(n + 1):
        for i in range(n + 1):
            nodes.append((j * (n + 1) + i + 1, i / n, j / n))
    node = lambda i, j: j * (n + 1) + i + 1
    elements = []
    left, right, bottom, top = boundary_ids
    for k in range(n):
        elements.append((1, bottom, [node(k, 0), node(k + 1, 0)]))
        elements.append((1, top, [node(k, n), node(k + 1, n)]))
        elements.append((1, left, [node(0, k), node(0, k + 1)]))
        elements.append((1, right, [node(n, k), node(n, k + 1)]))
    for j in range(n):
        for i in range(n):
            elements.append((3, material,
                             [node(i, j), node(i + 1, j), node(i + 1, j + 1),
                              node(i, j + 1)]))
    out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$Nodes",
           str(len(nodes))]
    out += ["%d %r %r 0" % p for p in nodes]
    out += ["$EndNodes", "$Elements", str(len(elements))]
    for k, (kind, tag, vs) in enumerate(elements):
        out.append("%d %d 2 %d %d %s" % (k + 1, kind, tag, tag,
                                         " ".join(map(str, vs))))
    out += ["$EndElements"]
    return out


def m_corrupt_gmsh(rng, lines, ctx):
    if not ctx.scene[4]:
        return None
    msh = unit_square_msh(2, (0, 1, 2, 3), 0)
    how = ctx.gmsh_corruption or rng.choice(GMSH_CORRUPTIONS)
    first_node = msh.index("$Nodes") + 2
    first_elem = msh.index("$Elements") + 2
    quads = [k for k in range(first_elem, len(msh) - 1)
             if msh[k].split()[1] == "3"]
    segments = [k for k in range(first_elem, len(msh) - 1)
                if msh[k].split()[1] == "1"]
    text = None
    if how == "truncate":
        text = "\n".join(msh)[: rng.randrange(1, len("\n".join(msh)))]
    elif how == "delete_line":
        del msh[rng.randrange(len(msh))]
    elif how == "node_out_of_range":
        k = rng.choice(quads)
        msh[k] = msh[k].rsplit(" ", 1)[0] + " 999"
    elif how == "node_count":
        msh[first_node - 1] = str(int(msh[first_node - 1]) + 5)
    elif how == "element_type":
        k = rng.choice(quads)
        f = msh[k].split()
        f[1] = "99"
        msh[k] = " ".join(f)
    elif how == "nan_coordinate":
        k = rng.randrange(first_node, first_elem - 3)
        f = msh[k].split()
        f[1] = "nan"
        msh[k] = " ".join(f)
    elif how == "huge_coordinate":
        k = rng.randrange(first_node, first_elem - 3)
        f = msh[k].split()
        f[2] = "1e300"
        msh[k] = " ".join(f)
    elif how == "inverted_cell":
        k = rng.choice(quads)
        f = msh[k].split()
        msh[k] = " ".join(f[:5] + list(reversed(f[5:])))
    elif how == "degenerate_cell":
        k = rng.choice(quads)
        f = msh[k].split()
        f[6] = f[5]
        msh[k] = " ".join(f)
    elif how == "duplicate_node":
        k = rng.randrange(first_node, first_elem - 3)
        msh.insert(k, msh[k])
    elif how == "empty":
        text = ""
    elif how == "binary":
        data = bytes(rng.randrange(256) for _ in range(2000))
        ctx.files["mesh.msh"] = data
    elif how == "version_4":
        msh[1] = "4.1 0 8"
    elif how == "no_end_nodes":
        msh.remove("$EndNodes")
    elif how == "no_boundary_lines":
        for k in reversed(segments):
            del msh[k]
        msh[first_elem - 1] = str(len(quads))
    elif how == "wrong_material":
        for k in quads:
            f = msh[k].split()
            f[3] = f[4] = "7"
            msh[k] = " ".join(f)
    elif how == "negative_node":
        k = rng.choice(quads)
        msh[k] = msh[k].rsplit(" ", 1)[0] + " -1"
    elif how == "short_element":
        k = rng.choice(quads)
        msh[k] = msh[k].rsplit(" ", 1)[0]
    if how == "missing_file":
        name = "nowhere.msh"
    else:
        name = "mesh.msh"
        if "mesh.msh" not in ctx.files:
            ctx.files["mesh.msh"] = ((text if text is not None
                                      else "\n".join(msh) + "\n").encode())
    ctx.appended.append("subsection Mesh\n  set Source = gmsh\n"
                        "  set Gmsh file = %s\n  set Global refinements = 0\n"
                        "end" % name)
    return "Gmsh mesh of the unit square: " + how


def m_ipopt_options(rng, lines, ctx):
    content = rng.choice(IPOPT_OPTIONS)
    ctx.files["ipopt.opt"] = content.encode()
    block = ("subsection Solver\n  subsection Ipopt\n"
             "    set Options file = ipopt.opt\n  end\nend")
    if rng.random() < 0.5:
        block = block.replace("  subsection Ipopt",
                              "  set Method = ipopt\n  subsection Ipopt")
        ctx.cost.append("Solver > Method")
    ctx.appended.append(block)
    return "Ipopt options file %r%s" % (content, " with Method = ipopt"
                                        if "Method" in block else "")


def m_unwritable_output(rng, lines, ctx):
    ctx.unwritable_output = True
    return "Output directory below a regular file"


MUTATIONS = [
    (m_delete_line, 10), (m_duplicate_line, 5), (m_swap_values, 8),
    (m_wrong_type, 8), (numeric_mutation(HUGE, "huge"), 8),
    (numeric_mutation(TINY, "tiny"), 7), (m_negative, 6),
    (numeric_mutation(NONFINITE, "non-finite"), 6), (m_empty_value, 4),
    (m_garbage_key, 5), (m_truncate_line, 5), (m_unbalanced, 6),
    (m_syntax, 4), (m_bad_expression, 5), (m_list, 6),
    (m_valid_alternative, 6), (m_missing_file, 3), (m_corrupt_gmsh, 6),
    (m_ipopt_options, 3), (m_weird_text, 3), (m_whole_file, 1),
    (m_self_include, 1), (m_unwritable_output, 1),
]


def make_variant(index, seed, base_texts):
    """Variant `index`: the first ones apply each kind of mutation alone
    (then each Gmsh corruption alone), so that every kind is covered; the
    others apply 1-3 random mutations."""
    rng = random.Random(seed * 1000003 + index)
    weights = [s[2] for s in SCENES]
    n_kinds = len(MUTATIONS)
    for attempt in range(100):
        scene = rng.choices(SCENES, weights)[0]
        lines = base_texts[scene[0]].split("\n")
        ctx = Context(scene)
        descriptions = []
        if index < n_kinds + len(GMSH_CORRUPTIONS):
            if index < n_kinds:
                mutate = MUTATIONS[index][0]
            else:
                mutate = m_corrupt_gmsh
                ctx.gmsh_corruption = GMSH_CORRUPTIONS[index - n_kinds]
            description = mutate(rng, lines, ctx)
            if description:
                descriptions.append(description)
                break
            continue
        # Mostly one mutation: later ones rarely matter once one is an
        # error.
        wanted = rng.choices([1, 2, 3], [6, 3, 2])[0]
        attempts = 0
        while len(descriptions) < wanted and attempts < 50:
            attempts += 1
            mutate = rng.choices([m for m, _ in MUTATIONS],
                                 [w for _, w in MUTATIONS])[0]
            description = mutate(rng, lines, ctx)
            if description:
                descriptions.append(description)
        break
    return {"index": index, "scene": scene[0], "lines": lines, "ctx": ctx,
            "mutations": descriptions}


# ---------------------------------------------------------------------------
# Running and judging.

SIGNAL_NAMES = {getattr(signal, n): n for n in dir(signal)
                if n.startswith("SIG") and not n.startswith("SIG_")}

ENTRY_RE = re.compile(r"[A-Za-z0-9'][A-Za-z0-9' _-]* > [A-Za-z0-9']|"
                      r"error: (Dimension|Scene name|Output directory):")
FILE_LINE_RE = re.compile(r"(\S+:\d+\b)|(Line <\d+> of file <)")
FILE_RE = re.compile(r"error: \S+\.(prm|msh|opt)\b")
LEAK_RE = re.compile(r"An error occurred in line <\d+> of file|Stacktrace|"
                     r"terminate called|Assertion .* failed|bad_alloc|"
                     r"\.(cc|cpp|h):\d+")


def strict_json(path):
    def reject(name):
        raise ValueError("non-finite number " + name)
    with open(path, encoding="utf-8") as f:
        return json.load(f, parse_constant=reject)


def write_variant(variant, folder):
    os.makedirs(folder)
    ctx = variant["ctx"]
    out = os.path.join(folder, "out")
    if ctx.unwritable_output:
        with open(os.path.join(folder, "blocker"), "w") as f:
            f.write("a regular file\n")
        out = os.path.join(folder, "blocker", "out")
    scene = ctx.scene
    header = ["# prm_mutation variant %d: prm/%s%s" % (
        variant["index"], scene[1], "".join(
            ", %s = %s" % kv for kv in scene[3]))]
    header += ["# " + m.replace("\n", " ")[:300] for m in variant["mutations"]]
    header += ["set Output directory = " + out, "subsection Output",
               "  set Format    = none", "  set Verbosity = quiet", "end", ""]
    text = "\n".join(header + variant["lines"])
    for block in ctx.appended:
        text += "\n" + block
    text += "\n"
    with open(os.path.join(folder, "scene.prm"), "wb") as f:
        f.write(text.encode("utf-8", "surrogateescape"))
    for name, data in ctx.files.items():
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)
    return out


def run(executable, folder, timeout, memory_mb):
    env = dict(os.environ)
    env.setdefault("DEAL_II_NUM_THREADS", "1")
    env.setdefault("OMP_NUM_THREADS", "1")
    # One rank: Open MPI's self transport is all it needs, and skipping
    # the probe of the others saves ~0.25 s of the ~0.8 s start-up.
    env.setdefault("OMPI_MCA_pml", "ob1")
    env.setdefault("OMPI_MCA_btl", "self")
    command = [executable, "scene.prm"]
    if memory_mb > 0:
        # The shell sets the limit and is replaced by the program (exec),
        # so a signal still reaches us as the program's own status.
        command = ["sh", "-c", 'ulimit -v %d && exec "$0" "$@"'
                   % (memory_mb * 1024)] + command
    start = time.time()
    proc = subprocess.Popen(command, cwd=folder,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            stdin=subprocess.DEVNULL, env=env,
                            start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
        timed_out = False
    except subprocess.TimeoutExpired:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = proc.communicate()
        timed_out = True
    message = (err + out).decode("utf-8", "replace").strip()
    return proc.returncode, timed_out, message, time.time() - start


QUOTE_RE = re.compile(r"The entry value (.*?) for the entry named (.+?) "
                      r"does not match")


def misquoted_value(message, scene_text):
    """If the message quotes a value for an entry that no `set` line of
    the file gives to that entry, describe the mismatch."""
    found = QUOTE_RE.search(message)
    if not found or "\\\n" in scene_text or "\\\r" in scene_text:
        return ""
    norm = lambda v: " ".join(v.split())
    quoted, key = norm(found.group(1)), found.group(2)
    values = []
    for line in scene_text.split("\n"):
        code = line.split("#", 1)[0].strip()
        if code.startswith("set ") and "=" in code:
            k, _, v = code[4:].partition("=")
            if k.strip() == key:
                values.append(norm(v))
    if values and quoted not in values:
        return "%r, the file has %s" % (quoted, " or ".join(map(repr, values)))
    return ""


def judge(variant, code, timed_out, message, out_dir, scene_text=""):
    """Return (ok, note): note explains a failure or an accepted timeout."""
    if timed_out:
        cost = variant["ctx"].cost
        if cost:
            return True, "timeout explained by a change of " + ", ".join(
                sorted(set(cost)))
        return False, "hang (killed after the timeout)"
    if code < 0:
        return False, "killed by signal %s" % SIGNAL_NAMES.get(-code, -code)
    if code not in (0, 2, 3, 4):
        return False, "exit %d%s" % (code, " (internal error)"
                                     if code == 1 else "")
    if code == 2:
        if not message:
            return False, "exit 2 without a message"
        if LEAK_RE.search(message):
            return False, "exit 2 with an internal text (assertion, " \
                "source line or out of memory)"
        if not (ENTRY_RE.search(message) or FILE_LINE_RE.search(message) or
                FILE_RE.search(message)):
            return False, "exit 2, message names no entry, file or line"
        if os.path.exists(out_dir):
            return False, "exit 2 but the output folder was created"
        quoted = misquoted_value(message, scene_text)
        if quoted:
            return False, "exit 2, the message misquotes the value: " + quoted
        return True, ""
    summary = os.path.join(out_dir, "summary.json")
    if not os.path.isfile(summary):
        return False, "exit %d without summary.json" % code
    try:
        status = strict_json(summary).get("status")
    except (ValueError, UnicodeDecodeError) as e:
        return False, "exit %d, summary.json is not strict JSON: %s" % (code,
                                                                        e)
    expected = "failed" if code == 3 else "converged"
    if status != expected:
        return False, "exit %d but summary.json status %r" % (code, status)
    return True, ""


def keep(folder, target, v, executable, what, note, message, memory_mb):
    """Copy a failing variant to target, with its output folder relative
    to target, and describe it in what.txt."""
    shutil.rmtree(target, ignore_errors=True)
    shutil.copytree(folder, target, ignore=shutil.ignore_patterns("out"))
    scene = os.path.join(target, "scene.prm")
    with open(scene, "rb") as f:
        data = f.read()
    with open(scene, "wb") as f:
        f.write(data.replace((folder + os.sep).encode(), b""))
    limit = ("ulimit -v %d; " % (memory_mb * 1024)) if memory_mb > 0 else ""
    with open(os.path.join(target, "what.txt"), "w", encoding="utf-8") as f:
        f.write("scene: %s (see the first line of scene.prm)\n"
                "mutations:\n  %s\n"
                "command: cd %s && (%s%s scene.prm)\n"
                "result: %s (%s)\nmessage:\n%s\n" % (
                    v["scene"], "\n  ".join(v["mutations"]), target, limit,
                    executable, what, note, message))


def main():
    parser = argparse.ArgumentParser(
        description="Corrupt the committed scenes and check that signorini "
                    "ends every variant with a clear error or a valid run.")
    parser.add_argument("executable")
    parser.add_argument("source_dir")
    parser.add_argument("--variants", type=int, default=200)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--memory-limit", type=int, default=4096,
                        metavar="MB", help="address-space limit of each run "
                        "(0: none); a run that exceeds it fails")
    parser.add_argument("--keep", metavar="DIR",
                        help="copy failing variants to DIR")
    parser.add_argument("--only", help="comma-separated variant numbers")
    parser.add_argument("--list", action="store_true",
                        help="print the variants, run nothing")
    parser.add_argument("--verbose", action="store_true",
                        help="one line per variant, passed or not")
    args = parser.parse_args()

    executable = os.path.abspath(args.executable)
    base_texts = {}
    for name, file_name, _, substitutions, _ in SCENES:
        with open(os.path.join(args.source_dir, "prm", file_name),
                  encoding="utf-8") as f:
            text = f.read()
        for key, value in substitutions:
            text, count = re.subn(r"(?m)^(\s*set\s+%s\s*=\s*)[^#\s]+"
                                  % re.escape(key), r"\g<1>" + value, text)
            if count != 1:
                print("prm_mutation: %s sets %r %d times, expected once"
                      % (name, key, count))
                return 1
        base_texts[name] = text.rstrip("\n")

    variants = [make_variant(i, args.seed, base_texts)
                for i in range(args.variants)]
    if args.only:
        wanted = {int(s) for s in args.only.split(",")}
        variants = [v for v in variants if v["index"] in wanted]
    if args.list:
        for v in variants:
            print("%3d %-28s %s" % (v["index"], v["scene"],
                                    " | ".join(v["mutations"])[:400]))
        return 0

    workdir = tempfile.mkdtemp(prefix="prm_mutation_")
    try:
        return run_all(args, executable, base_texts, variants, workdir)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)


def run_all(args, executable, base_texts, variants, workdir):
    start = time.time()
    failures = 0

    # The unmutated scenes must run (else every variant would "pass").
    def run_base(name):
        v = {"index": -1, "scene": name, "lines": base_texts[name].split("\n"),
             "ctx": Context([s for s in SCENES if s[0] == name][0]),
             "mutations": []}
        folder = os.path.join(workdir, "base_" + name)
        out_dir = write_variant(v, folder)
        code, timed_out, message, seconds = run(executable, folder,
                                                args.timeout,
                                                args.memory_limit)
        return name, code, timed_out, message, seconds

    def run_variant(v):
        folder = os.path.join(workdir, "variant_%03d" % v["index"])
        out_dir = write_variant(v, folder)
        code, timed_out, message, seconds = run(executable, folder,
                                                args.timeout,
                                                args.memory_limit)
        with open(os.path.join(folder, "scene.prm"), encoding="utf-8",
                  errors="replace") as f:
            scene_text = f.read()
        ok, note = judge(v, code, timed_out, message, out_dir, scene_text)
        return v, folder, code, timed_out, message, seconds, ok, note

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for name, code, timed_out, message, seconds in pool.map(
                run_base, [s[0] for s in SCENES]):
            if timed_out or code not in (0, 4):
                failures += 1
                print("FAIL unmutated %s: %s in %.1f s: %s" % (
                    name, "timeout" if timed_out else "exit %d" % code,
                    seconds, message.splitlines()[-1] if message else ""))
            elif args.verbose:
                print("base %-28s exit %d in %.1f s" % (name, code, seconds))
        if failures:
            print("0 passed, %d failed" % failures)
            return 1

        passed = failed = 0
        futures = [pool.submit(run_variant, v) for v in variants]
        for future in futures:
            v, folder, code, timed_out, message, seconds, ok, note = \
                future.result()
            last = message.splitlines()[-1][:300] if message else ""
            what = "timeout" if timed_out else (
                "signal %s" % SIGNAL_NAMES.get(-code, -code) if code < 0
                else "exit %d" % code)
            if ok:
                passed += 1
                if args.verbose or note:
                    print("ok   %3d %-28s %-8s %5.1fs %s%s | %s" % (
                        v["index"], v["scene"], what, seconds,
                        note + " | " if note else "",
                        " | ".join(v["mutations"])[:300], last))
            else:
                failed += 1
                print("FAIL %3d %-28s %s: %s | mutations: %s | message: %s" % (
                    v["index"], v["scene"], what, note,
                    " | ".join(v["mutations"])[:500], last or "(none)"))
                if args.keep:
                    target = os.path.join(args.keep,
                                          "variant_%03d" % v["index"])
                    keep(folder, target, v, executable, what, note, message,
                         args.memory_limit)
            shutil.rmtree(folder, ignore_errors=True)

    print("wall time %.1f s" % (time.time() - start))
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
