#!/usr/bin/env python3
"""Fail when a function in source/ is longer than a limit (default 200 lines).

A long function is where a change of one concern lands in the middle of
another; this check keeps them short enough to read whole. A function's
length is counted from the first line of its signature to its closing
brace, comments and blank lines included (what a reader scrolls through).
Lambdas and local classes count with the function that holds them.

Usage:
  scripts/check_function_length.py [--limit 200] [--top N] [ROOT ...]
ROOT defaults to the repository's source/ folder; paths are resolved
against the caller's folder. Prints the functions over the limit (file,
line, length, name) and, with --top N, the N longest; exits 1 if any
function is over the limit. Python 3 standard library only.
"""

import argparse
import os
import re
import sys


def strip_code(text):
    """The text with comments, string and character literals blanked out
    (newlines kept, so that line numbers stay)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if m:
                end = text.find(")" + m.group(1) + '"', i)
                end = n if end < 0 else end + len(m.group(1)) + 2
                out.append(re.sub(r"[^\n]", " ", text[i:end]))
                i = end
            else:
                out.append(c)
                i += 1
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    """(name, first line, last line) of every function defined in path."""
    with open(path, encoding="utf-8", errors="replace") as f:
        code = strip_code(f.read())
    result = []
    # Each open block: its kind and, for a function, its name and start.
    stack = []
    start = 0  # where the current statement/declaration began
    line = 1
    statement_line = None
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
            continue
        if statement_line is None and not c.isspace() and c not in "{};":
            statement_line = line
        if c == "{":
            head = code[start:i]
            outer = [k for k, _, _ in stack]
            in_function = "function" in outer
            if in_function:
                kind = "block"
            elif re.search(r"\bnamespace\b", head) or re.search(r'\bextern\s*$', head):
                kind = "namespace"
            elif re.search(r"\b(class|struct|union|enum)\b[^()]*$", head):
                kind = "class"
            elif re.search(r"\)\s*(const|noexcept|override|final|mutable|\s)*"
                           r"(->[^{]*)?$", head) or re.search(r"\)\s*:\s*[\s\S]*\)$", head):
                kind = "function"
            else:
                kind = "block"  # an initializer list, an array, ...
            name = ""
            if kind == "function":
                m = re.findall(r"((?:[~\w]+(?:<[^()<>]*>)?::)*(?:operator\s*[^\s(]+|[~\w]+))"
                               r"\s*\(", head)
                name = m[0] if m else "?"
            stack.append((kind, name, statement_line or line))
            start = i + 1
            statement_line = None
        elif c == "}":
            if stack:
                kind, name, first = stack.pop()
                if kind == "function":
                    result.append((name, first, line))
            start = i + 1
            statement_line = None
        elif c == ";":
            start = i + 1
            statement_line = None
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("roots", nargs="*")
    parser.add_argument("--limit", type=int, default=200)
    parser.add_argument("--top", type=int, default=0)
    args = parser.parse_args()
    here = os.path.dirname(os.path.abspath(__file__))
    roots = [os.path.abspath(r) for r in args.roots] or \
        [os.path.join(os.path.dirname(here), "source")]
    found = []
    for root in roots:
        if not os.path.exists(root):
            print(f"check_function_length.py: no such folder: {root}", file=sys.stderr)
            return 2
        for folder, _, files in os.walk(root):
            for name in sorted(files):
                if name.endswith((".cc", ".cpp", ".h")):
                    path = os.path.join(folder, name)
                    for fn, first, last in functions(path):
                        found.append((last - first + 1, os.path.relpath(path), first, fn))
    found.sort(reverse=True)
    over = [f for f in found if f[0] > args.limit]
    for length, path, first, fn in found[: max(args.top, 0)]:
        print(f"{length:5d} lines  {path}:{first}  {fn}")
    for length, path, first, fn in over:
        print(f"{path}:{first}: {fn} is {length} lines, over the limit of "
              f"{args.limit}: split it", file=sys.stderr)
    print(f"{len(found)} functions, {len(over)} over {args.limit} lines")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
