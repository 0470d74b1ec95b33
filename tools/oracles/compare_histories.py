#!/usr/bin/env python3
"""Compares history CSV files (choc's <analysis>.history.csv) column by column.

usage: compare_histories.py REFERENCE.csv OTHER.csv [--columns A:DX,A:VX] [--rtol-peak R]

For each column, the largest |other - reference| over the reference's times is divided by the
column's peak |reference| (or by 1 when the peak is 0). Exit 0 when every ratio is at most
--rtol-peak, 1 otherwise, 2 on a malformed or missing file. Rows are matched by time (the
other file may hold more rows, e.g. a full history against a thinned baseline).
"""
import argparse
import csv
import math
import sys


def read(path):
    try:
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        print(f"compare_histories: cannot read {path}: {e.strerror}", file=sys.stderr)
        sys.exit(2)
    if not rows or rows[0][0] != "time":
        print(f"compare_histories: {path} is not a history (first column must be 'time')",
              file=sys.stderr)
        sys.exit(2)
    names = rows[0]
    data = {n: [] for n in names}
    for r in rows[1:]:
        for n, v in zip(names, r):
            data[n].append(float(v))
    return names, data


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("reference")
    ap.add_argument("other")
    ap.add_argument("--columns", default="")
    ap.add_argument("--rtol-peak", type=float, default=1e-9)
    a = ap.parse_args()
    rnames, ref = read(a.reference)
    onames, oth = read(a.other)
    cols = [c for c in a.columns.split(",") if c] or [n for n in rnames if n != "time"]
    index = {}
    for i, t in enumerate(oth["time"]):
        index[round(t, 15)] = i
    worst = 0.0
    ok = True
    for c in cols:
        if c not in ref or c not in oth:
            print(f"compare_histories: column {c} missing", file=sys.stderr)
            return 1
        peak = max((abs(v) for v in ref[c]), default=0.0) or 1.0
        diff = 0.0
        for t, v in zip(ref["time"], ref[c]):
            i = index.get(round(t, 15))
            if i is None:
                print(f"compare_histories: time {t} of {a.reference} missing in {a.other}",
                      file=sys.stderr)
                return 1
            w = oth[c][i]
            if not math.isfinite(w):
                diff = math.inf
                break
            diff = max(diff, abs(w - v))
        rel = diff / peak
        worst = max(worst, rel)
        status = "OK" if rel <= a.rtol_peak else "DIFFERS"
        if rel > a.rtol_peak:
            ok = False
        print(f"  {c:24s} max |diff| / peak = {rel:.3e}  (tolerance {a.rtol_peak:.1e})  {status}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
