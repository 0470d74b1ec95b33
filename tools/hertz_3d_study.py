#!/usr/bin/env python3
"""Hertz's impact in 3D (issue 14, README "Hertz's impact"): input/hertz_3d.xml (the quarter
sphere by central differences) on meshes of size h near the first point of contact
(meshes/hertz_quarter.geo), measured against Hertz by tools/hertz.py (option fraction 0.25).
Prints per mesh the unknowns, the critical step, the peak force, contact duration, largest
approach and rebound velocity (% from Hertz), the largest energy balance and the run time, and
plots the force histories over Hertz's curve (OUT/force_3d.png).
    hertz_3d_study.py [--build build] [--out results/hertz_3d] [--sizes 1.4e-4 1e-4 7e-5]"""
import argparse
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import hertz  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/hertz_3d")
    ap.add_argument("--sizes", type=float, nargs="+", default=[1.4e-4, 1e-4, 7e-5])
    a = ap.parse_args()
    choc = os.path.abspath(os.path.join(a.build, "choc"))
    os.makedirs(a.out, exist_ok=True)
    h = hertz.hertz()
    source = open(os.path.join(ROOT, "input", "hertz_3d.xml")).read()
    print("| h near O | unknowns | critical step | peak force | duration | approach | rebound | "
          "energy balance, max | run |")
    print("|---|---|---|---|---|---|---|---|---|")
    runs = {}
    for size in a.sizes:
        tag = f"h{size * 1e3:g}mm"
        mesh = os.path.abspath(os.path.join(a.out, f"{tag}.msh"))
        subprocess.run(["gmsh", "-3", "-order", "2", "-format", "msh41", "-setnumber", "h", repr(size),
                        os.path.join(ROOT, "meshes", "hertz_quarter.geo"), "-o", mesh],
                       check=True, stdout=subprocess.DEVNULL)
        deck = source.replace('value="../meshes/hertz_quarter.msh"', f'value="{mesh}"')
        assert mesh in deck
        path = os.path.join(a.out, f"{tag}.xml")
        with open(path, "w") as f:
            f.write(deck)
        t0 = time.perf_counter()
        p = subprocess.run([choc, "run", path, "-o", os.path.join(a.out, tag)],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        wall = time.perf_counter() - t0
        if p.returncode != 0:
            raise SystemExit(f"h = {size}: choc exited {p.returncode}:\n{p.stdout[-2000:]}")
        unknowns = re.search(r"(\d+) unknowns on", p.stdout).group(1)
        critical = re.search(r"critical step (\S+) s", p.stdout).group(1)
        m = hertz.measure(os.path.join(a.out, tag, "explicit.history.csv"), h, 0.25)
        runs[tag] = m
        cells = [f"{m[q][0]:.6g} ({100 * (m[q][0] / m[q][1] - 1):+.2f}%)"
                 for q in ("peak force", "contact duration", "largest approach", "rebound velocity")]
        print(f"| {size * 1e3:g} mm | {unknowns} | {float(critical):.3g} s | " + " | ".join(cells) +
              f" | {100 * m['_balance']:+.2g}% of E0 | {wall:.0f} s |", flush=True)
    hertz.plot_forces(h, {f"choc 3D, TET10 of {tag[1:]} near O": m for tag, m in runs.items()},
                      os.path.join(a.out, "force_3d.png"), "contact force, whole sphere [kN]")

if __name__ == "__main__":
    main()
