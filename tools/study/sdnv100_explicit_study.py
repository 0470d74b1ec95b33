#!/usr/bin/env python3
"""SDNV100 by explicit central differences (docs/verification/sdnv100-explicit.md):
input/sdnv100_explicit.xml on meshes of n HEX8 along (meshes/sdnv100_bar.geo, one across), dt
the largest step below COURANT x h / c that puts the contact instant 2e-5 s on a step (so the
separation, 1e-4 s, is one too), and prints per mesh the whole-history max error and RMS of
DZ(N5), DZ(N100), VZ(N100) and VZ(N5) against d'Alembert (% of each peak; the displacements' from
the run's summary.json, whose exact-solution checks are made to report both rows, the
velocities' recomputed from the history by tools/oracles/bar_exact.py, as choc reports no row
for them), the energy balance (summary) and the wall time (median of --repeat runs of the whole
process).
    sdnv100_explicit_study.py [--build build] [--out results/sdnv100_explicit]
                              [--sizes 40 320 640 1000] [--courant 0.99] [--repeat 3]"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

chocrun.add_tool_path("oracles")
import bar_exact  # noqa: E402

C = 5000.0  # sqrt(E / rho), nu = 0


def deck(mesh, dt):
    d = chocrun.load_deck(chocrun.input_path("sdnv100_explicit.xml"))
    analysis = chocrun.only_analysis(d)
    chocrun.set_param(d, "Mesh/File", mesh)
    chocrun.set_param(d, f"Analyses/{analysis}/Time Step", float(dt))
    chocrun.report_exact_errors(d, analysis)
    return d, analysis


def velocity_errors(xml, out, analysis):
    """{velocity column: (max, RMS) % of the peak} of every exact-solution check's point,
    recomputed from the history (choc writes no row for velocities)."""
    h = chocrun.read_history(out, analysis)
    errors = {}
    for spec in bar_exact.exact_specs_for_analysis(bar_exact.read_input(xml), analysis):
        e = bar_exact.history_error(h["time"], h[spec.vcol], spec.exact.velocity(h["time"]))
        errors[spec.vcol] = (100 * e["max_rel"], 100 * e["rms_rel"])
    return errors


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/sdnv100_explicit")
    ap.add_argument("--sizes", type=int, nargs="+", default=[40, 320, 640, 1000])
    ap.add_argument("--courant", type=float, default=0.99)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    print("| HEX8 along | Courant | N5:DZ | N100:DZ | N100:VZ | N5:VZ | energy balance (J) | run (median) |")
    print("|---|---|---|---|---|---|---|---|")
    for n in a.sizes:
        mesh = chocrun.gmsh("sdnv100_bar.geo", os.path.abspath(os.path.join(a.out, f"bar_{n}.msh")), 3,
                            "-setnumber", "n", n)
        h = 0.2 / n
        steps = math.ceil(2e-5 / (a.courant * h / C))
        dt = 2e-5 / steps
        d, analysis = deck(mesh, dt)
        path = chocrun.write_deck(d, os.path.join(a.out, f"n{n}.xml"))
        out = os.path.join(a.out, f"n{n}")
        # 3: some check NOOK (a coarse mesh misses 0.5 %)
        walls = [chocrun.run(choc, path, out, ok=(chocrun.EXIT_OK, chocrun.EXIT_CHECK_FAILED)).wall
                 for _ in range(a.repeat)]
        s = chocrun.require_completed(chocrun.read_summary(out, analysis), ("completed", "check failed"))
        err = {c: (100 * e["max"], 100 * e["rms"]) for c, e in chocrun.exact_errors(s).items()}
        err.update(velocity_errors(path, out, analysis))
        lo, hi = chocrun.summary_value(s, "energy/balance_min"), chocrun.summary_value(s, "energy/balance_max")
        cells = [" / ".join(f"{x:.3g}" for x in err[c]) for c in ("N5:DZ", "N100:DZ", "N100:VZ", "N5:VZ")]
        print(f"| {n} | {dt * C / h:.3f} | " + " | ".join(cells) +
              f" | [{lo:.3g}, {hi:.2g}] | {chocrun.median(walls):.2f} s |", flush=True)


if __name__ == "__main__":
    main()
