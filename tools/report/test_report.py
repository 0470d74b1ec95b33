#!/usr/bin/env python3
"""ctest of tools/report/make_report.py on one regression case's serial results.

usage: test_report.py CASE_DIR RUN_DIR OUT_DIR

Runs make_report.py on RUN_DIR (the input named by CASE_DIR/case.cfg) writing into OUT_DIR,
then requires: exit 0; the report's check table holds the case's CHECKS rows, all OK, and its
summary says so; a plot per history listed in HISTORIES (a PNG of some size); and, for each of
these runs, the Python errors against the exact solution agree with choc's. Exit 0 or 1.
"""
import os
import re
import shlex
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))


def case_config(path):
    cfg = {}
    for line in open(path):
        m = re.match(r"^([A-Z_]+)=(.*)$", line.strip())
        if m:
            v = shlex.split(m.group(2))
            cfg[m.group(1)] = v[0] if v else ""
    return cfg


def main():
    case_dir, run_dir, out = sys.argv[1:4]
    cfg = case_config(os.path.join(case_dir, "case.cfg"))
    xml = os.path.normpath(os.path.join(case_dir, "..", "..", cfg["INPUT"]))
    name = os.path.splitext(os.path.basename(xml))[0]
    checks, histories = int(cfg["CHECKS"]), cfg.get("HISTORIES", "").split()
    os.makedirs(out, exist_ok=True)
    cmd = [sys.executable, os.path.join(here, "make_report.py"), run_dir, "--input", xml,
           "--output", out]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(p.stdout, end="")
    errors = []
    if p.returncode != 0:
        errors.append(f"make_report.py exited {p.returncode}")
    report = os.path.join(out, "report.md")
    text = open(report).read() if os.path.exists(report) else ""
    section = text.split("## Checks", 1)[-1].split("\n## ", 1)[0]
    rows = [l for l in section.splitlines() if l.startswith(f"| {name} | ")]
    if len(rows) != checks:
        errors.append(f"{len(rows)} check rows for {name} in the report, {checks} expected")
    if any(not l.rstrip().endswith("|") or "| OK |" not in l for l in rows):
        errors.append("a check row is not OK")
    if f"**{checks} checks, 0 NOOK**" not in text:
        errors.append(f"no summary line '{checks} checks, 0 NOOK'")
    exact = text.split("## Displacement of A against the exact solution", 1)[-1].split("\n## ", 1)[0]
    for h in histories:
        png = os.path.join(out, "plots", f"{name}_{h}.png")
        if not os.path.exists(png):
            errors.append(f"missing plot {png}")
        else:
            with open(png, "rb") as f:
                head = f.read(8)
            if head != b"\x89PNG\r\n\x1a\n" or os.path.getsize(png) < 20000:
                errors.append(f"{png} is not a PNG of a plausible size")
        row = [l for l in exact.splitlines() if l.startswith(f"| {name} | {h} | ")]
        if not row or "| agree (" not in row[0]:
            errors.append(f"{h}: Python and C++ errors against the exact solution not shown to "
                          f"agree: {row[0] if row else 'no row'}")
    for e in errors:
        print("test_report: FAIL: " + e)
    if not errors:
        print(f"test_report: {report}: {checks} OK check rows, {len(histories)} plots, "
              "exact-solution errors agree")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
