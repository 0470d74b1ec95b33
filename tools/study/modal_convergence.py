#!/usr/bin/env python3
"""The first 10 frequencies of a cantilever block, TET10 and HEX20, against mesh refinement.

usage: tools/study/modal_convergence.py [--build DIR] [--out DIR] [--levels 1 2 4] [--reference 8]
                                        [--poisson NU]

Meshes meshes/cantilever_block.geo with gmsh at n elements across (5 n along) for each level,
in HEX20 and in TET10, runs a 10-mode Modal analysis of each with choc (Anasazi shift-invert,
KLU2), and compares every frequency with the reference: the finest HEX20 mesh (--reference
n). Prints, per element type and level, the unknowns (from modes.summary.json), the largest relative error of the 10
frequencies and the observed order between successive levels (theory for quadratic elements:
frequencies converge as h^4, the square of the energy-norm rate h^2); writes
OUT/modal_convergence.csv. Not a test: a study (figures in README.md, "Meshes and elements").
"""
import argparse
import csv
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

TOP = chocrun.TOP

MODAL = """<ParameterList name="modes">
    <Parameter name="Type" type="string" value="Modal"/>
    <Parameter name="Number of Modes" type="int" value="10"/>
    <Parameter name="Tolerance" type="double" value="1e-12"/>
    <Parameter name="Write Exodus" type="bool" value="false"/>
  </ParameterList>"""


def block_deck(label, mesh, nu, analysis):
    """An input for meshes/cantilever_block.geo's mesh: steel, clamped face, one analysis."""
    return f"""<ParameterList name="cantilever">
  <Parameter name="Title" type="string" value="cantilever block, {label}"/>
  <ParameterList name="Mesh"><Parameter name="File" type="string" value="{mesh}"/></ParameterList>
  <ParameterList name="Model">
    <ParameterList name="Materials"><ParameterList name="steel">
      <Parameter name="Young's Modulus" type="double" value="2e11"/>
      <Parameter name="Poisson's Ratio" type="double" value="{nu}"/>
      <Parameter name="Density" type="double" value="7800"/>
    </ParameterList></ParameterList>
    <ParameterList name="Blocks"><ParameterList name="block">
      <Parameter name="Material" type="string" value="steel"/>
    </ParameterList></ParameterList>
    <ParameterList name="Dirichlet"><ParameterList name="clamp">
      <Parameter name="Node Set" type="string" value="clamped"/>
      <Parameter name="Components" type="string" value="all"/>
    </ParameterList></ParameterList>
  </ParameterList>
  <ParameterList name="Analyses">{analysis}</ParameterList>
</ParameterList>
"""


def mesh_block(out, n, hexa):
    """meshes/cantilever_block.geo meshed by gmsh at n elements across (quadratic elements)."""
    mesh = os.path.join(out, f"block_{'hex20' if hexa else 'tet10'}_n{n}.msh")
    if not os.path.exists(mesh):
        subprocess.run(["gmsh", "-3", "-order", "2", "-setnumber", "n", str(n), "-setnumber", "hex",
                        "1" if hexa else "0", "-format", "msh41",
                        os.path.join(TOP, "meshes", "cantilever_block.geo"), "-o", mesh],
                       check=True, stdout=subprocess.DEVNULL)
    return mesh


def run_case(build, out, n, hexa, nu):
    label = f"{'HEX20' if hexa else 'TET10'}_n{n}"
    work = os.path.join(out, label)
    os.makedirs(work, exist_ok=True)
    mesh = mesh_block(work, n, hexa)
    deck = os.path.join(work, "modes.xml")
    with open(deck, "w") as f:
        f.write(block_deck(label, mesh, nu, MODAL))
    r = chocrun.run(chocrun.choc_path(build), deck, work, ok=None)
    if r.returncode != 0:
        sys.exit(f"modal_convergence: {label} failed ({r.returncode}): {r.stderr.strip()}")
    unknowns = chocrun.summary_value(chocrun.read_summary(work, "modes"), "unknowns")
    with open(os.path.join(work, "modes.modes.csv")) as f:
        freqs = [float(r["frequency_hz"]) for r in csv.DictReader(f)]
    return label, unknowns, freqs


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(TOP, "build"))
    ap.add_argument("--out", default=os.path.join(TOP, "results", "modal_convergence"))
    ap.add_argument("--levels", type=int, nargs="+", default=[1, 2, 4])
    ap.add_argument("--reference", type=int, default=8)
    ap.add_argument("--poisson", type=float, default=0.3)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    _, ref_unknowns, ref = run_case(a.build, a.out, a.reference, True, a.poisson)
    print(f"reference: HEX20, n = {a.reference}, {ref_unknowns} unknowns; frequencies [Hz]: "
          + " ".join(f"{f:.2f}" for f in ref))
    rows = []
    for hexa in (True, False):
        previous = None
        for n in a.levels:
            label, unknowns, freqs = run_case(a.build, a.out, n, hexa, a.poisson)
            err = max(abs(f - r) / r for f, r in zip(freqs, ref))
            order = (math.log(previous / err) / math.log(2.0)) if previous else float("nan")
            rows.append({"element": label.split("_")[0], "n": n, "unknowns": unknowns,
                         "max_rel_error": err, "observed_order": order})
            print(f"{label:10s} {unknowns:7d} unknowns  max relative error of 10 frequencies "
                  f"{err:.3e}  order {'' if math.isnan(order) else f'{order:.2f}'}")
            previous = err
    with open(os.path.join(a.out, "modal_convergence.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
