#!/usr/bin/env python3
"""SDND100's friction: the effect of the stick stiffness Kt and of dt on the deck's rows.
Runs input/sdnd100.xml's analysis 'deck' (modal, central differences) with Kt = 4e5, 4e6, 4e7
N/m, dt = 5e-4 and 5e-5 s (sub-stepped when the stick needs it), both friction laws, and prints
per run: the error of the four rows against the deck's rigid-plastic values and against the
exact elastic-plastic motion at that Kt (tools/oracles/friction_oscillator.py), and the mean amplitude
decrement per half period against 2 mu N / K.
    sdnd100_study.py [--build build] [--out results/sdnd100]"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

chocrun.add_tool_path("oracles")
import friction_oscillator as fo  # noqa: E402

ROOT = chocrun.TOP
ROWS = [-4.596e-4, 3.182e-4, -1.768e-4, 3.536e-5]
TIMES = [n * math.pi / 100 for n in (1, 2, 3, 4)]


def variant(kt, dt, law):
    """input/sdnd100.xml's 'modes' and 'deck' with the link's stick stiffness, friction law and dt."""
    d = chocrun.load_deck(chocrun.input_path("sdnd100.xml"))
    chocrun.keep_analyses(d, ["modes", "deck"])
    link = "Analyses/deck/Shock Links/plane"
    chocrun.set_param(d, f"{link}/Tangential Stiffness", float(kt))
    chocrun.set_param(d, f"{link}/Friction Law", law)
    chocrun.set_param(d, "Analyses/deck/Time Step", float(dt))
    chocrun.set_param(d, "Analyses/deck/Stability Check", "substep", create=True)
    return d


def run(choc, d, out):
    chocrun.run(choc, chocrun.write_deck(d, out + ".xml"), out)
    h = chocrun.read_history(out, "deck")
    return h["time"], h["P:DY"]


def decrement(t, y):
    """Mean drop of |DY| * sqrt 2 (the amplitude along the line) between the extremes of the
    first four half periods."""
    ext = []
    for n in range(0, 5):
        window = (t >= (n - 0.25) * math.pi / 100) & (t <= (n + 0.25) * math.pi / 100)
        ext.append(np.max(np.abs(y[window])) * math.sqrt(2))
    return (ext[0] - ext[4]) / 4


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "sdnd100"))
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    lines = ["| Kt [N/m] | dt [s] | law | rows' errors vs the deck (rigid-plastic) [%] | vs the exact motion at Kt [%] | decrement per half period / (2 mu N / K) |",
             "|---|---|---|---|---|---|"]
    for kt in (4e5, 4e6, 4e7):
        seg = fo.motion(kt=kt)
        exact = [fo.position(seg, t) / math.sqrt(2) for t in TIMES]
        for dt in (5e-4, 5e-5):
            for law in ("velocity reversal", "elastic-plastic"):
                out = os.path.join(a.out, "kt%g_dt%g_%s" % (kt, dt, law.split()[0]))
                t, y = run(choc, variant(kt, dt, law), out)
                vals = [np.interp(tt, t, y) for tt in TIMES]
                e_deck = ", ".join("%.3g" % (100 * abs(v - r) / abs(r)) for v, r in zip(vals, ROWS))
                e_exact = ", ".join("%.3g" % (100 * abs(v - r) / abs(r)) for v, r in zip(vals, exact))
                lines.append("| %g | %g | %s | %s | %s | %.4f |" % (kt, dt, law, e_deck, e_exact,
                                                                  decrement(t, y) / 2e-4))
    rigid = [(-1) ** n * (0.85e-3 - 2e-4 * n) / math.sqrt(2) for n in (1, 2, 3, 4)]
    lines.append("")
    lines.append("Rigid-plastic closed form at the row times: %s (the deck's rows, rounded)."
                 % ", ".join("%.4e" % r for r in rigid))
    table = "\n".join(lines)
    print(table)
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "README.md"), "w") as f:
        f.write("# SDND100: stick stiffness and time step\n\n" + table + "\n")


if __name__ == "__main__":
    main()
