#!/usr/bin/env python3
"""Fails when a tool script's idea of the repository root is not the repository root.

Usage: tool_roots.py REPO_DIR
Shell scripts under tools/ find the checkout from their own place, as
  top="$(cd "$(dirname "$0")/../.." && pwd)"
and Python tools as os.path.dirname(...) nested around __file__ or Path(__file__).parents[k].
A script moved to another folder keeps working when every call passes explicit paths and
breaks only in its documented no-argument form (make-scale-mesh.sh and run-suite.sh did, when
tools/ was split by role). Each such expression is resolved here and must name a folder that
holds CMakeLists.txt and src/, or, for a Python tool's sys.path entry, an existing folder.
"""
import os
import re
import sys

SHELL_TOP = re.compile(r'^\s*(top|root|TOP|ROOT)="\$\(cd "\$\(dirname "\$0"\)(/[./]*)" && pwd\)"', re.M)
PY_TOP = re.compile(r'^(TOP|ROOT|REPO|SRC)\s*=\s*(.+)$', re.M)
PARENTS = re.compile(r'Path\(__file__\)\.resolve\(\)\.parents\[(\d)\]')


def is_repo(path):
    return os.path.isfile(os.path.join(path, "CMakeLists.txt")) and os.path.isdir(os.path.join(path, "src"))


def python_root(expression, script):
    """The folder a Python root expression names, or None when it is not one of the two shapes."""
    m = PARENTS.search(expression)
    if m:
        path = os.path.dirname(script)
        for _ in range(int(m.group(1))):
            path = os.path.dirname(path)
        return path
    if "__file__" not in expression:
        return None
    depth = expression.split("__file__")[0].count("os.path.dirname(")
    path = os.path.abspath(script)
    for _ in range(depth):
        path = os.path.dirname(path)
    return path


def problems(repo):
    found, checked = [], 0
    for folder, _, files in os.walk(os.path.join(repo, "tools")):
        for name in sorted(files):
            script = os.path.join(folder, name)
            text = open(script, encoding="utf-8", errors="replace").read()
            rel = os.path.relpath(script, repo)
            if name.endswith(".sh"):
                for m in SHELL_TOP.finditer(text):
                    checked += 1
                    top = os.path.normpath(os.path.join(folder, m.group(2).lstrip("/")))
                    if not is_repo(top):
                        found.append(f"{rel}: {m.group(1)} resolves to {os.path.relpath(top, repo)}/, "
                                     "not the repository root")
            elif name.endswith(".py"):
                for m in PY_TOP.finditer(text):
                    top = python_root(m.group(2), script)
                    if top is None:
                        continue
                    checked += 1
                    if not is_repo(top):
                        found.append(f"{rel}: {m.group(1)} resolves to {os.path.relpath(top, repo)}/, "
                                     "not the repository root")
    return found, checked


def main():
    repo = os.path.abspath(sys.argv[1])
    found, checked = problems(repo)
    for line in found:
        print(line)
    print(f"tool_roots: {checked} root expressions checked, {len(found)} wrong")
    if checked == 0:
        print("tool_roots: no root expression found: the patterns no longer match the tools")
        return 1
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
