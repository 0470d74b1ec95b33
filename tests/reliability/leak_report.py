#!/usr/bin/env python3
"""Classifies the LeakSanitizer report of a log (used by sanitize.sh).

usage: leak_report.py LOG SOURCE_DIR
A leaked block whose allocation stack has a frame in choc's own code (a path under
SOURCE_DIR/src or SOURCE_DIR/tests, or a choc:: function) is choc's leak: exit 1 and print it.
Blocks allocated entirely in libraries (Open MPI components dlclose'd at MPI_Finalize show as
"<unknown module>", libc's vasprintf called from them, Trilinos' static registries) are
counted and reported, exit 0. No report at all: exit 0.
"""
import re
import sys


def main():
    log, src = sys.argv[1], sys.argv[2].rstrip("/")
    text = open(log, errors="replace").read()
    blocks = re.split(r"\n(?=(?:Direct|Indirect) leak of )", text)
    ours, libs, lib_bytes = [], 0, 0
    for b in blocks:
        m = re.match(r"(?:Direct|Indirect) leak of (\d+) byte", b)
        if not m:
            continue
        frames = [l for l in b.splitlines() if re.match(r"\s+#\d+ ", l)]
        if any(f"{src}/src/" in f or f"{src}/tests/" in f or "choc::" in f for f in frames):
            ours.append(b.strip())
        else:
            libs += 1
            lib_bytes += int(m.group(1))
    for b in ours:
        print(b[:3000])
    if libs:
        print(f"leak_report: {libs} block(s), {lib_bytes} bytes, allocated in libraries only "
              "(MPI components unloaded at exit, libc, Trilinos registries): not choc's")
    return 1 if ours else 0


if __name__ == "__main__":
    sys.exit(main())
