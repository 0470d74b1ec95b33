#!/usr/bin/python3
"""Fails when the committed parameter reference differs from `choc parameters --format markdown`.

usage: check_parameters_reference.py CHOC REFERENCE.md
Prints the differences (committed -> generated) and the command that regenerates the file.
"""
import difflib
import os
import subprocess
import sys


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    choc, reference = os.path.abspath(sys.argv[1]), sys.argv[2]
    proc = subprocess.run([choc, "parameters", "--format", "markdown"], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True)
    if proc.returncode != 0:
        print(f"choc parameters --format markdown exited {proc.returncode}:\n{proc.stderr}")
        return 1
    try:
        with open(reference, encoding="utf-8") as f:
            committed = f.read()
    except OSError as e:
        committed = ""
        print(f"cannot read {reference}: {e}")
    regenerate = (f"tools/docs/parameters_reference.sh {os.path.dirname(choc)} "
                  "docs/reference/parameters.md")
    if committed == proc.stdout:
        print(f"{reference} is current")
        return 0
    sys.stdout.writelines(difflib.unified_diff(
        committed.splitlines(keepends=True), proc.stdout.splitlines(keepends=True),
        fromfile=f"{reference} (committed)", tofile="choc parameters --format markdown"))
    print(f"\n{reference} is out of date: the declarations changed. Regenerate it from the "
          f"repository root with\n  {regenerate}\n(`make docs` does it from build/) and "
          "commit it.")
    return 1


if __name__ == "__main__":
    sys.exit(main())
