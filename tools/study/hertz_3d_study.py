#!/usr/bin/env python3
"""Hertz's impact in 3D (docs/verification/hertz.md): input/hertz_3d.xml (the quarter
sphere by central differences) on meshes of size h near the first point of contact
(meshes/hertz_quarter.geo), measured against Hertz by tools/oracles/hertz.py (option fraction
0.25). Prints per mesh the unknowns, the critical step (both from the run's summary.json), the
peak force, contact duration, largest approach and rebound velocity (% from Hertz), the largest
energy balance and the run time, and plots the force histories over Hertz's curve
(OUT/force_3d.png).
    hertz_3d_study.py [--build build] [--out results/hertz_3d] [--sizes 1.4e-4 1e-4 7e-5]"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

chocrun.add_tool_path("oracles")
import hertz  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/hertz_3d")
    ap.add_argument("--sizes", type=float, nargs="+", default=[1.4e-4, 1e-4, 7e-5])
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    h = hertz.hertz()
    source = chocrun.load_deck(chocrun.input_path("hertz_3d.xml"))
    analysis = chocrun.only_analysis(source)
    print("| h near O | unknowns | critical step | peak force | duration | approach | rebound | "
          "energy balance, max | run |")
    print("|---|---|---|---|---|---|---|---|---|")
    runs = {}
    for size in a.sizes:
        tag = f"h{size * 1e3:g}mm"
        mesh = os.path.abspath(os.path.join(a.out, f"{tag}.msh"))
        chocrun.gmsh("hertz_quarter.geo", mesh, 3, "-order", 2, "-setnumber", "h", repr(size))
        chocrun.set_param(source, "Mesh/File", mesh)
        path = chocrun.write_deck(source, os.path.join(a.out, f"{tag}.xml"))
        out = os.path.join(a.out, tag)
        wall = chocrun.run(choc, path, out).wall
        s = chocrun.require_completed(chocrun.read_summary(out, analysis))
        unknowns = chocrun.summary_value(s, "unknowns")
        critical = chocrun.summary_value(s, "critical_step")
        m = hertz.measure(chocrun.history_path(out, analysis), h, 0.25)
        runs[tag] = m
        cells = [f"{m[q][0]:.6g} ({100 * (m[q][0] / m[q][1] - 1):+.2f}%)"
                 for q in ("peak force", "contact duration", "largest approach", "rebound velocity")]
        print(f"| {size * 1e3:g} mm | {unknowns} | {float(critical):.3g} s | " + " | ".join(cells) +
              f" | {100 * m['_balance']:+.2g}% of E0 | {wall:.0f} s |", flush=True)
    hertz.plot_forces(h, {f"choc 3D, TET10 of {tag[1:]} near O": m for tag, m in runs.items()},
                      os.path.join(a.out, "force_3d.png"), "contact force, whole sphere [kN]")

if __name__ == "__main__":
    main()
