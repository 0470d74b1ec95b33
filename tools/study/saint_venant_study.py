#!/usr/bin/env python3
"""Saint-Venant's problem (BENCHMARKS section 15, input/saint_venant.xml): the rigid striker's
accuracy against the closed form as the mesh and the step are refined, and the same striker
meshed elastic: what modelling it rigid costs and gains.

usage: tools/study/saint_venant_study.py [--build DIR] [--out DIR] [--repeat N]

Part 1, the rigid striker (rho A L / M = 1), the bar with 50, 100, 200, 400 HEX8 along its 1 m,
at Courant numbers 0.5 and 0.96 (the step over an element's transit time dz / c): the contact's
end (its last impact's), the rebound velocity, the force's L1 error over the contact, the
largest mean-force error over windows of T/10 clear of the jumps, and the wall time (median of
--repeat runs).
Part 2, the striker meshed elastic (5 HEX8, the same mass, its own Young's modulus E_s from the
steel's 2e11 up to 2e14 Pa; the bar of 100 HEX8; the step 0.96 of the smaller transit time of
the bar's and the striker's elements): the same errors against the rigid-mass closed form, the
step, the steps taken and the wall time, beside the rigid striker's.
Writes OUT/saint_venant.csv and OUT/README.md (the tables); figures in
docs/verification/saint-venant.md. Not a test: a study (`make study-saint-venant`).
"""
import argparse
import csv
import os
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402


def measure(choc, work, repeat, **kw):
    times = []
    for k in range(repeat):
        h, impacts, sv, dz, dt, out = chocrun.saint_venant_run(choc, work, 1.0, **kw)
        times.append(chocrun.read_summary(out, "strike")["wall_seconds"])
    end = max(float(i["end_time"]) for i in impacts)
    t, F = h["time"], h["impact:force"]
    return {"elements": kw.get("along", 100), "courant": kw.get("courant", 0.96),
            "striker": "rigid" if kw.get("striker_modulus") is None else f"elastic E_s = {kw['striker_modulus']:.0e}",
            "dt": dt, "steps": len(t) - 1,
            "end_error_T": (end - sv.duration) / sv.T,
            # the striker's velocity after the contact from its momentum balance (the contact is
            # its only force): v0 - impulse / M, rigid or elastic alike
            "rebound_error": sv.v0 - sum(float(i["impulse"]) for i in impacts) / sv.M - sv.rebound_velocity(),
            "l1": sv.l1_error(t, F),
            "window": float(np.max(np.abs(sv.window_errors(t, F, 2 * dz / sv.c)))),
            "wall_s": statistics.median(times)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/study/saint-venant")
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    choc = os.path.abspath(os.path.join(a.build, "choc"))
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for courant in (0.5, 0.96):
        for along in (50, 100, 200, 400):
            rows.append(measure(choc, a.out, a.repeat, along=along, courant=courant))
            print(rows[-1], flush=True)
    for modulus in (2e11, 2e12, 2e13, 2e14):
        rows.append(measure(choc, a.out, a.repeat, striker_modulus=modulus))
        print(rows[-1], flush=True)
    with open(os.path.join(a.out, "saint_venant.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    lines = ["| striker | elements | Courant | dt [s] | steps | contact end error [T] | rebound error [m/s] "
             "| force L1 error | mean-force error [Z v0] | wall [s] |", "|" + "---|" * 10]
    for r in rows:
        lines.append(f"| {r['striker']} | {r['elements']} | {r['courant']} | {r['dt']:.3e} | {r['steps']} "
                     f"| {r['end_error_T']:+.4f} | {r['rebound_error']:+.2e} | {r['l1']:.4f} | {r['window']:.1e} "
                     f"| {r['wall_s']:.3f} |")
    with open(os.path.join(a.out, "README.md"), "w") as f:
        f.write("# Saint-Venant's problem: the rigid striker against the closed form\n\n" + "\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())
