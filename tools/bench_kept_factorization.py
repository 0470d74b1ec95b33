#!/usr/bin/env python3
"""Contact status changes on a kept factorisation (issue 17; 'Linear Solver/Update Budget',
src/solvers/DirectSolver.cpp): the scale scene's bars (tools/make-scale-mesh.sh) with Lagrange
contact and Method = Direct (KLU2), 100 steps of 1e-6 s (two impacts of the bars, contact nodes
opening and closing), at growing sizes, with 'Update Budget' = 0 (refactor at every change of
status, as before) and the default (auto). Prints per size and run the medians over --repeat
runs of the analysis and linear-solve times (from the log), the factorisations, the matrices
solved on a kept factorisation, the GMRES iterations, and the largest difference of the
histories (A:DZ, A:VZ, C:DZ, the contact force, the total energy) between the two, of each peak.

    bench_kept_factorization.py [--build build] [--repeat 3] [--sizes 3x100 5x200 7x300]"""
import argparse
import csv
import os
import re
import statistics
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
COLUMNS = ["A:DZ", "A:VZ", "C:DZ", "interface:force", "energy:total"]


def scene(mesh, budget):
    text = open(os.path.join(ROOT, "input", "scale-3d.xml")).read()
    edits = [('"../meshes/scale_3d.exo"', f'"{mesh}"'),
             ('<Parameter name="Exodus Interval" type="int" value="20"/>',
              '<Parameter name="Exodus Interval" type="int" value="0"/>'),
             ('<Parameter name="Method" type="string" value="Penalty"/>',
              '<Parameter name="Method" type="string" value="Lagrange"/>'),
             ('<Parameter name="Method" type="string" value="CG"/>',
              '<Parameter name="Method" type="string" value="Direct"/>'),
             ('<Parameter name="End Time" type="double" value="2e-5"/>',
              '<Parameter name="End Time" type="double" value="1e-4"/>')]
    if budget is not None:
        edits.append(('<Parameter name="Tolerance" type="double" value="1e-10"/>',
                      f'<Parameter name="Tolerance" type="double" value="1e-10"/>'
                      f'<Parameter name="Update Budget" type="int" value="{budget}"/>'))
    for old, new in edits:
        assert old in text, old
        text = text.replace(old, new)
    return text


def run(choc, path, out):
    log = subprocess.run([choc, "run", path, "-o", out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, check=True).stdout
    t = re.search(r"time: ([0-9.]+) s = assembly [0-9.]+ \+ linear solve ([0-9.]+)", log)
    kept = re.search(r"\((\d+) changes of contact status solved by GMRES", log)
    krylov = re.search(r"Krylov iterations: (\d+)", log)
    unknowns = re.search(r"(\d+) unknowns \(\+", log)
    return {"analysis": float(t.group(1)), "solve": float(t.group(2)),
            "factorisations": int(re.search(r"(\d+) factorisations", log).group(1)),
            "kept": int(kept.group(1)) if kept else 0, "gmres": int(krylov.group(1)) if krylov else 0,
            "unknowns": int(unknowns.group(1))}


def history(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {c: [float(r[c]) for r in rows] for c in COLUMNS}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sizes", nargs="+", default=["3x100", "5x200", "7x300"])
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "bench-kept-factorization"))
    a = ap.parse_args()
    choc = os.path.join(a.build, "choc")
    os.makedirs(a.out, exist_ok=True)
    print("| unknowns | Update Budget | analysis [s] | linear solve [s] | factorisations | solved on a kept one "
          "| GMRES iterations | histories: max difference of a peak |")
    print("|---|---|---|---|---|---|---|---|")
    for size in a.sizes:
        across, along = size.split("x")
        mesh = os.path.join(a.out, f"bars_{across}_{along}.exo")
        subprocess.run([os.path.join(HERE, "make-scale-mesh.sh"), choc, across, along, mesh], check=True,
                       stdout=subprocess.DEVNULL)
        results = {}
        for label, budget in (("0", 0), ("auto", None)):
            path = os.path.join(a.out, f"kept_{size}_{label}.xml")
            with open(path, "w") as f:
                f.write(scene(mesh, budget))
            out = os.path.join(a.out, f"kept_{size}_{label}")
            runs = [run(choc, path, out) for _ in range(a.repeat)]
            results[label] = (runs, history(os.path.join(out, "impact.history.csv")))
        ref = results["0"][1]
        for label in ("0", "auto"):
            runs, h = results[label]
            diff = max(max(abs(x - y) for x, y in zip(h[c], ref[c])) / max(max(abs(y) for y in ref[c]), 1e-300)
                       for c in COLUMNS)
            r = runs[0]
            print(f"| {r['unknowns']:,} | {label} | {statistics.median(x['analysis'] for x in runs):.2f} "
                  f"| {statistics.median(x['solve'] for x in runs):.2f} | {r['factorisations']} | {r['kept']} "
                  f"| {r['gmres']} | {'' if label == '0' else f'{diff:.1e}'} |", flush=True)


if __name__ == "__main__":
    main()
