#!/usr/bin/env python3
"""Positive homogeneity of the zero-gap impact: u(t; s v0) = s u(t; v0) for s > 0.

usage: check_scaling.py HISTORY_SLOW HISTORY_FAST V_SLOW V_FAST RTOL
With the link touching at t = 0 (zero gap), the shock law f = max(0, -K d - C d') is positively
homogeneous of degree 1, and so are the modal equations, the projection and the scheme: the
histories of A:DX and A:VX scaled by 1/v agree to round-off, the energies scale with v^2.
"""
import csv, sys


def load(p):
    rows = list(csv.reader(open(p, newline="")))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def main():
    a, b, va, vb, rtol = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
    na, ra = load(a)
    nb, rb = load(b)
    if len(ra) != len(rb):
        sys.exit(f"scaling: {len(ra)} and {len(rb)} rows")
    ok = True
    for col, p in (("A:DX", 1), ("A:VX", 1), ("shock:force", 1), ("energy:total", 2)):
        ia, ib = na.index(col), nb.index(col)
        xa = [r[ia] / va**p for r in ra]
        xb = [r[ib] / vb**p for r in rb]
        peak = max(abs(x) for x in xa)
        err = max(abs(x - y) for x, y in zip(xa, xb)) / peak
        good = err <= rtol
        ok &= good
        print(f"  {col:14s} / v^{p}: max |diff| / peak = {err:.3e} (tolerance {rtol:g}) {'OK' if good else 'FAIL'}")
    if not ok:
        sys.exit("scaling: FAIL")
    print("scaling: OK")


if __name__ == "__main__":
    main()
