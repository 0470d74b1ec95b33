#!/usr/bin/env python3
"""Hold two snapshots of every input's outputs equal bit for bit (a reshaping's proof).

    same_outputs.py DIR_A DIR_B

DIR_A and DIR_B are written by tools/build/snapshot-outputs.sh. For each input directory
of DIR_A: the same exit code, the same file names, every .csv byte-identical, and every
variable of every Exodus file (coordinates, maps, nodal, element and global variables,
times) exactly equal; the summary JSON's status, exit reason, steps and energies equal
(its timers and memory are measurements, not results). Prints one line per input and
exits 1 when any differs."""
import glob
import json
import os
import sys

import numpy as np

SKIPPED_NETCDF = {"info_records", "qa_records"}
SUMMARY_KEYS = ("status", "exit_reason", "steps", "time_reached", "energy", "iterations")


def exit_code(log):
    lines = open(log, errors="replace").read().splitlines()
    return lines[-1] if lines and lines[-1].startswith("exit ") else "?"


def same_exodus(a, b):
    from netCDF4 import Dataset
    with Dataset(a) as da, Dataset(b) as db:
        if sorted(da.variables) != sorted(db.variables):
            return "the variables differ"
        for name in da.variables:
            if name in SKIPPED_NETCDF:
                continue
            va, vb = np.asarray(da.variables[name][:]), np.asarray(db.variables[name][:])
            if va.shape != vb.shape or not np.array_equal(va, vb):
                return f"variable {name} differs"
    return None


def same_summary(a, b):
    ja, jb = json.load(open(a)), json.load(open(b))
    for k in SUMMARY_KEYS:
        if ja.get(k) != jb.get(k):
            return f"summary key {k} differs ({ja.get(k)!r} against {jb.get(k)!r})"
    return None


def compare_dir(a, b):
    fa = sorted(os.listdir(a)) if os.path.isdir(a) else []
    fb = sorted(os.listdir(b)) if os.path.isdir(b) else []
    if fa != fb:
        return f"files differ: {sorted(set(fa) ^ set(fb))}"
    for f in fa:
        pa, pb = os.path.join(a, f), os.path.join(b, f)
        if f.endswith(".csv"):
            why = None if open(pa, "rb").read() == open(pb, "rb").read() else "differs"
        elif f.endswith(".exo"):
            why = same_exodus(pa, pb)
        elif f.endswith(".summary.json"):
            why = same_summary(pa, pb)
        else:
            continue
        if why:
            return f"{f}: {why}"
    return None


def main():
    a, b = sys.argv[1], sys.argv[2]
    bad = 0
    for log in sorted(glob.glob(os.path.join(a, "*.log"))):
        name = os.path.basename(log)[:-4]
        ea, eb = exit_code(log), exit_code(os.path.join(b, name + ".log")) \
            if os.path.exists(os.path.join(b, name + ".log")) else "missing"
        why = None
        if ea.split(" in ")[0] != eb.split(" in ")[0]:
            why = f"{ea} against {eb}"
        else:
            why = compare_dir(os.path.join(a, name), os.path.join(b, name))
        print(f"{name}: " + ("same" if why is None else why))
        bad += why is not None
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
