#!/usr/bin/env python3
"""SDNL32 report: DY of the tip (node 11) of runs 1 (the deck's tip velocity), 1 with the exact
tip velocity -3.8 x 0.783, 1 with the static correction, and 2 (k = 45,000 N/m) against the
reference rows of run 1; prints the effects of the deck's velocity typo and of the static
correction at each row and writes the figure.

    sdnl32_report.py RESULTS_DIR [--figure regression/sdnl32/tip_dy.png]"""
import argparse
import os

import numpy as np

ROWS = [(1, -2.66), (2, -4.33), (3, -4.92), (4, -4.78), (5, -3.82), (6, -2.87), (7, -2.71),
        (8, -3.09), (9, -3.41), (10, -3.36), (11, -2.64), (12, -0.742)]


def history(d, name):
    with open(os.path.join(d, name + ".history.csv")) as f:
        cols = f.readline().strip().split(",")
        data = np.loadtxt(f, delimiter=",", ndmin=2)
    return data[:, 0], data[:, cols.index("N11:DY")]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("results")
    ap.add_argument("--figure")
    a = ap.parse_args()
    runs = {n: history(a.results, n) for n in ("run1", "run1_exact_tip", "run1_static", "run2")}
    print("| t [ms] | reference [1e-3 m] | run 1 (deck tip velocity) | run 1, exact tip velocity | typo effect | "
          "run 1 + static correction | its effect | run 2 (k = 45,000) |")
    print("|---|---|---|---|---|---|---|---|")
    for ms, ref in ROWS:
        v = {n: np.interp(ms * 1e-3, t, y) * 1e3 for n, (t, y) in runs.items()}
        eff = (v["run1_exact_tip"] - v["run1"]) / abs(v["run1"]) * 100
        st = (v["run1_static"] - v["run1"]) / abs(v["run1"]) * 100
        print("| %d | %.3f | %.5f | %.5f | %+.3f %% | %.5f | %+.3f %% | %.5f |" % (
            ms, ref, v["run1"], v["run1_exact_tip"], eff, v["run1_static"], st, v["run2"]))
    if a.figure:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4))
        for n, style in (("run1", "-"), ("run1_exact_tip", "--"), ("run2", "-.")):
            t, y = runs[n]
            ax.plot(t * 1e3, y * 1e3, style, label=n)
        ax.plot([r[0] for r in ROWS], [r[1] for r in ROWS], "ko", label="reference rows (run 1)")
        ax.set_xlabel("t [ms]")
        ax.set_ylabel("DY of node 11 [mm]")
        ax.set_title("SDNL32: beam tip on an elastic stop (k = 18,000 and 45,000 N/m)")
        ax.grid(True, alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(a.figure, dpi=110)
        print("figure:", a.figure)


if __name__ == "__main__":
    main()
