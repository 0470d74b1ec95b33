#!/usr/bin/env python3
"""Fails when a function defined in the given source files is longer than the limit.

Usage: function_length.py LIMIT FILE... [--run-limit N]
A function is a definition that starts at the beginning of a line (namespace scope, the
project's style) and ends at the matching closing brace at the beginning of a line; its
length counts the lines from its signature to that brace. With --run-limit, the bodies of
'::run(' definitions must be at most N lines as well (the analyses' run() as named steps).
"""
import re
import sys


def functions(path):
    lines = open(path, encoding="utf-8").read().split("\n")
    out, i = [], 0
    while i < len(lines):
        line = lines[i]
        opens_scope = re.match(r"(namespace|class|struct|enum|union|extern|template|#|//|\s|$|})", line)
        if not opens_scope and "(" in line:
            # The signature may span several lines; the body opens with '{' ending a line.
            j = i
            while j < len(lines) and not lines[j].rstrip().endswith("{") and not lines[j].rstrip().endswith(";"):
                j += 1
            if j < len(lines) and lines[j].rstrip().endswith("{"):
                k = j + 1
                while k < len(lines) and not lines[k].startswith("}"):
                    k += 1
                out.append((line.strip(), i + 1, k - i + 1, k - j - 1))
                i = k
        i += 1
    return out


def main(argv):
    limit = int(argv[1])
    run_limit = None
    files = []
    args = argv[2:]
    while args:
        a = args.pop(0)
        if a == "--run-limit":
            run_limit = int(args.pop(0))
        else:
            files.append(a)
    bad = 0
    count = 0
    for f in files:
        for sig, start, length, body in functions(f):
            count += 1
            if length > limit:
                print(f"{f}:{start}: {length} lines (limit {limit}): {sig}")
                bad += 1
            if run_limit is not None and "::run(" in sig and body > run_limit:
                print(f"{f}:{start}: run() body has {body} lines (limit {run_limit}): {sig}")
                bad += 1
    print(f"{count} functions in {len(files)} files, {bad} over the limits")
    if count == 0:
        print("no function found: the pattern no longer matches the sources")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
