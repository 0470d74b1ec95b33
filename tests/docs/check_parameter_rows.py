#!/usr/bin/python3
"""Checks that `choc parameters --format markdown` has a table row for given keys.

usage: check_parameter_rows.py CHOC [SECTION/]KEY[=TYPE]...
SECTION is a section's path as in its heading (`Mesh`, `Analyses/<name> (Type = Transient)`;
none for the top level). Each key must have a row of 5 cells in that section (in any section
when SECTION is '*'), with a type (TYPE when given), a default and a documentation.
"""
import re
import subprocess
import sys

HEADING = re.compile(r"^### (?:`(.*)`|\(top level\))$")


def tables(markdown):
    """{section path: {key: [cells]}}; the top level is ''."""
    sections, current = {}, None
    for line in markdown.splitlines():
        m = HEADING.match(line)
        if m:
            current = sections.setdefault(m.group(1) or "", {})
            continue
        if current is None or not line.startswith("| ") or line.startswith("| key |"):
            continue
        cells = [c.strip().replace("\\", "") for c in re.split(r"(?<!\\)\|", line)[1:-1]]
        current[cells[0]] = cells
    return sections


def problems(sections, spec):
    path, _, key = spec.rpartition("/")
    key, _, wanted_type = key.partition("=")
    where = sections.values() if path == "*" else [sections.get(path, {})]
    rows = [s[key] for s in where if key in s]
    if not rows:
        return [f"no row for '{key}' in section '{path}'"]
    out = []
    for cells in rows:
        if len(cells) != 5 or not all(cells[i] for i in (1, 2, 4)):
            out.append(f"row of '{key}' in '{path}' lacks a cell: {cells}")
        elif wanted_type and cells[1] != wanted_type:
            out.append(f"'{key}' in '{path}' has type '{cells[1]}', expected '{wanted_type}'")
    return out


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    proc = subprocess.run([sys.argv[1], "parameters", "--format", "markdown"],
                          stdout=subprocess.PIPE, text=True)
    if proc.returncode != 0:
        print(f"choc parameters --format markdown exited {proc.returncode}")
        return 1
    sections = tables(proc.stdout)
    failures = [p for spec in sys.argv[2:] for p in problems(sections, spec)]
    for spec in sys.argv[2:]:
        print(("FAIL " if any(spec.rpartition("/")[2].partition("=")[0] in f for f in failures)
               else "ok   ") + spec)
    for f in failures:
        print(f)
    print(f"{len(sections)} sections")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
