#!/usr/bin/env python3
"""Compare the results of two runs of the same input (restart tests).

    compare_results.py DIR_A DIR_B [--names c1 c2] [--tolerance T] [--ignore X ...]

For each analysis name (default: every <name>.history.csv of DIR_A), compares
<name>.history.csv, <name>.exo and <name>.impacts.csv (when present) of both directories:
  - default (bit for bit): the history files are byte-identical and every time value,
    nodal and global variable of the Exodus files is exactly equal;
  - --tolerance T: the same shapes, and every column / variable agrees to T times its
    largest magnitude (restart on another number of ranks: solver tolerance);
  - --ignore X...: history columns, nodal and global variables left out of the --tolerance
    comparison (quantities made of round-off, e.g. a gap around 0, or the strain energy of a
    body translated far, whose summation order depends on the ranks).
  - --vector-peaks: the components of a nodal vector field (DISP_X, DISP_Y, DISP_Z...) are
    compared to T times the largest magnitude of all three, not each to its own (a lateral
    component of 1e-7 m beside a translation of 0.1 m is round-off of the translation).
Prints one line per file and exits 1 on the first difference it reports."""
import argparse
import glob
import os
import sys

import numpy as np


def history(path):
    with open(path) as f:
        names = f.readline().strip().split(",")
        rows = np.loadtxt(f, delimiter=",", ndmin=2)
    return names, rows


IGNORED = set()
VECTOR_PEAKS = False


def compare_history(a, b, tol):
    if tol is None:
        same = open(a, "rb").read() == open(b, "rb").read()
        return None if same else "the files differ"
    na, ra = history(a)
    nb, rb = history(b)
    if na != nb or ra.shape != rb.shape:
        return f"columns or rows differ ({len(na)}x{ra.shape[0]} against {len(nb)}x{rb.shape[0]})"
    for j, name in enumerate(na):
        if name in IGNORED:
            continue
        scale = max(np.max(np.abs(ra[:, j])), 1e-300)
        err = np.max(np.abs(ra[:, j] - rb[:, j])) / scale
        if err > tol:
            return f"column {name} differs by {err:.3e} of its peak (tolerance {tol:g})"
    return None


def compare_impacts(a, b, tol):
    if tol is None:
        return None if open(a, "rb").read() == open(b, "rb").read() else "the files differ"
    ra, rb = open(a).read().splitlines(), open(b).read().splitlines()
    if len(ra) != len(rb):
        return f"{len(ra) - 1} impacts against {len(rb) - 1}"
    va = [[float(x) for x in l.split(",")[2:]] for l in ra[1:]]
    vb = [[float(x) for x in l.split(",")[2:]] for l in rb[1:]]
    if not va:
        return None
    names = ra[0].split(",")[2:]
    for j, name in enumerate(names):  # each column to T of its largest magnitude, as histories
        scale = max(max(abs(r[j]) for r in va), 1e-300)
        worst = max(abs(x[j] - y[j]) for x, y in zip(va, vb)) / scale
        if worst > tol:
            return f"impacts column {name} differs by {worst:.3e} of its peak (tolerance {tol:g})"
    return None


def exodus_arrays(path):
    from netCDF4 import Dataset
    out = {}
    with Dataset(path) as d:
        out["time_whole"] = np.array(d.variables["time_whole"][:])
        if "name_nod_var" in d.variables:
            names = ["".join(c.decode() for c in row if c) for row in d.variables["name_nod_var"][:].data]
            for i, n in enumerate(names):
                out["nodal:" + n.strip()] = np.array(d.variables[f"vals_nod_var{i + 1}"][:])
        if "vals_glo_var" in d.variables:
            values = np.array(d.variables["vals_glo_var"][:])
            names = ["".join(c.decode() for c in row if c) for row in d.variables["name_glo_var"][:].data]
            for i, n in enumerate(names):
                out["global:" + n.strip()] = values[:, i]
    return out


def compare_exodus(a, b, tol):
    xa, xb = exodus_arrays(a), exodus_arrays(b)
    if sorted(xa) != sorted(xb):
        return "the variables differ"
    for k in xa:
        if xa[k].shape != xb[k].shape:
            return f"{k}: shapes {xa[k].shape} and {xb[k].shape}"
        if tol is None:
            if not np.array_equal(xa[k], xb[k]):
                i = np.argmax(np.abs(xa[k] - xb[k]))
                return f"{k} differs (largest at flat index {i}: {xa[k].flat[i]!r} against {xb[k].flat[i]!r})"
        elif k.split(":", 1)[-1] not in IGNORED:
            group = [k]
            if VECTOR_PEAKS and k.startswith("nodal:") and k[-2:] in ("_X", "_Y", "_Z"):
                group = [k[:-1] + c for c in "XYZ" if k[:-1] + c in xa]
            scale = max(max(np.max(np.abs(xa[g])) for g in group), 1e-300)
            err = np.max(np.abs(xa[k] - xb[k])) / scale
            if err > tol:
                return f"{k} differs by {err:.3e} of its peak (tolerance {tol:g})"
    return None


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--names", nargs="*")
    p.add_argument("--tolerance", type=float)
    p.add_argument("--ignore", nargs="*", default=[])
    p.add_argument("--vector-peaks", action="store_true")
    args = p.parse_args()
    IGNORED.update(args.ignore)
    global VECTOR_PEAKS
    VECTOR_PEAKS = args.vector_peaks
    names = args.names or sorted(os.path.basename(f)[:-len(".history.csv")]
                                 for f in glob.glob(os.path.join(args.a, "*.history.csv")))
    if not names:
        print(f"no history in {args.a}")
        return 1
    for n in names:
        for ext, fn in ((".history.csv", compare_history), (".exo", compare_exodus),
                        (".impacts.csv", compare_impacts)):
            fa, fb = os.path.join(args.a, n + ext), os.path.join(args.b, n + ext)
            if ext != ".history.csv" and not os.path.exists(fa) and not os.path.exists(fb):
                continue
            for f in (fa, fb):
                if not os.path.exists(f):
                    print(f"{f}: missing")
                    return 1
            why = fn(fa, fb, args.tolerance)
            print(f"{n}{ext}: " + ("same" if why is None else why))
            if why is not None:
                return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
