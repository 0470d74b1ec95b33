#!/usr/bin/env python3
"""Convergence of the SDNL111 bar wave with mesh refinement, for every element type.

usage: tools/study/bar_convergence.py [--build DIR] [--out DIR] [--levels 25 50 100]
                                      [--elements HEX8 HEX20 ...] [--courant C] [--time-order Q]

The scene of input/sdnl111c_accurate.xml (two steel bars, lateral motion blocked so that the
wave is the 1D oedometric one, Lagrange contact with massless contact nodes, average
acceleration, consistent mass) meshed by gmsh from meshes/sdnl111_3d_bars.geo (HEX8, HEX20,
TET4, TET10) and meshes/sdnl111_2d.geo (QUAD4, QUAD8, TRI3, TRI6, in plane strain and
axisymmetric) with n element layers along each bar for each level. The time step follows the
mesh: dt = C h_n / c, where h_n is the node spacing along the bar (L/n for linear elements,
L/(2n) for quadratic ones) and c the oedometric wave speed, and with --time-order Q > 1 the
step of level n is further reduced by (n0/n)^(Q-1) (n0 the first level), so that the time
error stays below the space error of elements of higher order.

The error of the displacement of point A against the d'Alembert solution (tools/oracles/bar_exact.py,
independent of choc) is measured over the whole run: its maximum and its RMS, both relative to
the peak of the exact displacement, and the observed order between successive levels. The 2D
runs are also compared with the 3D run of the same order (QUAD4 and TRI3 with HEX8, QUAD8 and
TRI6 with HEX20): the largest difference of the two histories, relative to the peak.

The unknowns come from each run's wave.summary.json. Writes OUT/bar_convergence.csv and prints
a table. Not a test: a study (`make study-bar`,
figures in README.md, "Meshes and elements").
"""
import argparse
import csv
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

chocrun.add_tool_path("oracles")
from bar_exact import BarImpactExact  # noqa: E402

TOP = chocrun.TOP
E, NU, RHO, LENGTH, GAP, V0 = 2e11, 0.3, 7800.0, 1.0, 1e-5, -1.0
END_TIME = 1e-3

# element -> (geometry file, gmsh dimension, order, gmsh switch, kinematics list)
ELEMENTS = {
    "HEX8": ("sdnl111_3d_bars.geo", 3, 1, ("hex", 1), ["3D"]),
    "HEX20": ("sdnl111_3d_bars.geo", 3, 2, ("hex", 1), ["3D"]),
    "TET4": ("sdnl111_3d_bars.geo", 3, 1, ("hex", 0), ["3D"]),
    "TET10": ("sdnl111_3d_bars.geo", 3, 2, ("hex", 0), ["3D"]),
    "QUAD4": ("sdnl111_2d.geo", 2, 1, ("quad", 1), ["plane strain", "axisymmetric"]),
    "QUAD8": ("sdnl111_2d.geo", 2, 2, ("quad", 1), ["plane strain", "axisymmetric"]),
    "TRI3": ("sdnl111_2d.geo", 2, 1, ("quad", 0), ["plane strain", "axisymmetric"]),
    "TRI6": ("sdnl111_2d.geo", 2, 2, ("quad", 0), ["plane strain", "axisymmetric"]),
}
# The 3D element a 2D one is compared with (same polynomial order).
PARTNER = {"QUAD4": "HEX8", "TRI3": "HEX8", "QUAD8": "HEX20", "TRI6": "HEX20"}
# Pairs whose discrete systems are the same 1D one: the bilinear and trilinear shape functions
# are tensor products, so a field uniform over the section stays uniform and the section
# integrals of the stiffness and of the mass (weighted by r in axisymmetry) factor out alike.
# Serendipity QUAD8/HEX20 and the triangles do not factor: they agree only to their
# discretisation errors.
EXACT_REDUCTION = {"QUAD4"}


def oedometric_speed():
    return math.sqrt(E * (1 - NU) / (RHO * (1 + NU) * (1 - 2 * NU)))


LAGRANGE = '<Parameter name="Method" type="string" value="Lagrange"/>'


def deck(title, mesh, kinematics, dt, contact_mass, scheme, alpha, end_time=END_TIME, contact=LAGRANGE):
    """The bar-impact input (lateral motion blocked); contact: the Contact sublist's parameters
    before its pairs; contact_mass None leaves the default."""
    axis = "DZ" if kinematics == "3D" else "DY"
    kin = "" if kinematics == "3D" else \
        f'<Parameter name="Kinematics" type="string" value="{kinematics}"/>'
    mass = "" if contact_mass is None else \
        f'<Parameter name="Contact Mass" type="string" value="{contact_mass}"/>'
    steps = math.ceil(end_time / dt - 1e-9)
    return f"""<ParameterList name="bar_convergence">
  <Parameter name="Title" type="string" value="{title}"/>
  <ParameterList name="Mesh"><Parameter name="File" type="string" value="{mesh}"/></ParameterList>
  <ParameterList name="Model">
    {kin}
    <Parameter name="Active Components" type="string" value="{axis}"/>
    <ParameterList name="Materials"><ParameterList name="steel">
      <Parameter name="Young's Modulus" type="double" value="{E}"/>
      <Parameter name="Poisson's Ratio" type="double" value="{NU}"/>
      <Parameter name="Density" type="double" value="{RHO}"/>
    </ParameterList></ParameterList>
    <ParameterList name="Blocks">
      <ParameterList name="POU1"><Parameter name="Material" type="string" value="steel"/></ParameterList>
      <ParameterList name="POU2"><Parameter name="Material" type="string" value="steel"/></ParameterList>
    </ParameterList>
    <ParameterList name="Dirichlet"><ParameterList name="clamped face of bar 2">
      <Parameter name="Node Set" type="string" value="CL_POU2"/>
      <Parameter name="Components" type="string" value="{axis}"/>
    </ParameterList></ParameterList>
  </ParameterList>
  <ParameterList name="Analyses"><ParameterList name="wave">
    <Parameter name="Type" type="string" value="Transient"/>
    <Parameter name="Scheme" type="string" value="{scheme}"/>
    <Parameter name="Alpha" type="double" value="{alpha!r}"/>
    {mass}
    <Parameter name="Time Step" type="double" value="{dt!r}"/>
    <Parameter name="End Time" type="double" value="{steps * dt!r}"/>
    <ParameterList name="Contact">
      {contact}
      <ParameterList name="Pairs"><ParameterList name="interface">
        <Parameter name="Master Side Set" type="string" value="CNT_POU1"/>
        <Parameter name="Slave Side Set" type="string" value="CNT_POU2"/>
      </ParameterList></ParameterList>
    </ParameterList>
    <ParameterList name="Linear Solver"><Parameter name="Method" type="string" value="Direct"/></ParameterList>
    <ParameterList name="Initial Conditions"><ParameterList name="bar 1 moves towards bar 2">
      <Parameter name="Node Set" type="string" value="POU1"/>
      <Parameter name="Field" type="string" value="Velocity"/>
      <Parameter name="Components" type="string" value="{axis}"/>
      <Parameter name="Value" type="double" value="{V0}"/>
    </ParameterList></ParameterList>
    <Parameter name="History" type="string" value="N1:{axis}"/>
    <Parameter name="Exodus Interval" type="int" value="0"/>
  </ParameterList></ParameterList>
</ParameterList>
"""


def mesh_for(out, element, n):
    geo, dim, order, (switch, value), _ = ELEMENTS[element]
    mesh = os.path.join(out, f"{element.lower()}_n{n}.msh")
    if not os.path.exists(mesh):
        subprocess.run(["gmsh", f"-{dim}", "-order", str(order), "-setnumber", "n", str(n),
                        "-setnumber", switch, str(value), "-format", "msh41",
                        os.path.join(TOP, "meshes", geo), "-o", mesh],
                       check=True, stdout=subprocess.DEVNULL)
    return mesh


def run_case(a, element, kinematics, n):
    order = ELEMENTS[element][2]
    spacing = LENGTH / (n * order)
    dt = a.courant * spacing / oedometric_speed() * (a.levels[0] / n) ** (a.time_order - 1)
    label = f"{element}_{kinematics.replace(' ', '_')}_n{n}"
    work = os.path.join(a.out, label)
    os.makedirs(work, exist_ok=True)
    path = os.path.join(work, "wave.xml")
    with open(path, "w") as f:
        f.write(deck(label, mesh_for(a.out, element, n), kinematics, dt, a.contact_mass,
                     a.scheme, a.alpha))
    r = chocrun.run(chocrun.choc_path(a.build), path, work, ok=None)
    if r.returncode != 0:
        sys.exit(f"bar_convergence: {label} failed ({r.returncode}): {r.stderr.strip()}")
    unknowns = chocrun.summary_value(chocrun.read_summary(work, "wave"), "unknowns")
    data = chocrun.read_history(work, "wave")
    column = [c for c in data if c.startswith("N1")][0]
    return {"label": label, "unknowns": unknowns, "dt": dt, "steps": len(data["time"]) - 1,
            "t": data["time"], "u": data[column]}


def errors(run, exact):
    ref = exact.displacement(run["t"])
    peak = exact.peak_displacement()
    d = np.abs(run["u"] - ref)
    return float(d.max() / peak), float(math.sqrt(np.mean(d ** 2)) / peak)


def order(previous, current, ratio):
    if previous is None or previous <= 0 or current <= 0:
        return float("nan")
    return math.log(previous / current) / math.log(ratio)


def fitted_order(rows, key):
    """The slope of log(error) against log(1/n), least squares over every level."""
    x = np.log([r["n"] for r in rows])
    y = np.log([r[key] for r in rows])
    return float(np.polyfit(x, y, 1)[0] * -1.0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(TOP, "build"))
    ap.add_argument("--out", default=os.path.join(TOP, "results", "bar_convergence"))
    ap.add_argument("--levels", type=int, nargs="+", default=[25, 50, 100])
    ap.add_argument("--elements", nargs="+", default=list(ELEMENTS), choices=list(ELEMENTS))
    ap.add_argument("--courant", type=float, default=0.5)
    ap.add_argument("--time-order", type=float, default=1.0)
    ap.add_argument("--scheme", default="average acceleration")
    ap.add_argument("--alpha", type=float, default=-0.1)
    ap.add_argument("--exact-reduction-tolerance", type=float, default=None,
                    help="fail (exit 1) when a QUAD4 history differs from the HEX8 one by more "
                         "than this fraction of the peak displacement")
    ap.add_argument("--contact-mass", default="redistributed", choices=["redistributed", "standard"])
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    c = oedometric_speed()
    section = 0.02 * 0.02
    exact = BarImpactExact(LENGTH, c, RHO * c * section, V0, GAP / abs(V0))
    rows, histories = [], {}
    print(f"{'case':32s} {'unknowns':>8s} {'steps':>6s} {'max err':>9s} {'order':>6s} "
          f"{'RMS err':>9s} {'order':>6s} {'vs 3D':>9s}")
    for element in a.elements:
        for kinematics in ELEMENTS[element][4]:
            prev = (None, None)
            for i, n in enumerate(a.levels):
                run = run_case(a, element, kinematics, n)
                histories[(element, kinematics, n)] = run
                emax, erms = errors(run, exact)
                ratio = n / a.levels[i - 1] if i else 1.0
                partner = histories.get((PARTNER.get(element), "3D", n))
                vs3d = float("nan")
                if partner is not None and len(partner["u"]) == len(run["u"]):
                    vs3d = float(np.abs(partner["u"] - run["u"]).max() / exact.peak_displacement())
                row = {"element": element, "kinematics": kinematics, "n": n,
                       "unknowns": run["unknowns"], "dt": run["dt"], "steps": run["steps"],
                       "max_error": emax, "max_order": order(prev[0], emax, ratio),
                       "rms_error": erms, "rms_order": order(prev[1], erms, ratio),
                       "max_difference_to_3d": vs3d}
                rows.append(row)
                prev = (emax, erms)
                fmt = lambda v: "" if math.isnan(v) else f"{v:.2f}"  # noqa: E731
                print(f"{run['label']:32s} {run['unknowns']:8d} {run['steps']:6d} {emax:9.3e} "
                      f"{fmt(row['max_order']):>6s} {erms:9.3e} {fmt(row['rms_order']):>6s} "
                      f"{'' if math.isnan(vs3d) else f'{vs3d:9.2e}':>9s}", flush=True)
            mine = [r for r in rows if r["element"] == element and r["kinematics"] == kinematics]
            if len(mine) > 2:
                print(f"{element} {kinematics}: fitted order over n = {a.levels}: max error "
                      f"{fitted_order(mine, 'max_error'):.2f}, RMS error "
                      f"{fitted_order(mine, 'rms_error'):.2f}")
    with open(os.path.join(a.out, "bar_convergence.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    if a.exact_reduction_tolerance is not None:
        check_exact_reduction(rows, a.exact_reduction_tolerance)


def check_exact_reduction(rows, tolerance):
    """Exit 1 unless every 2D run of EXACT_REDUCTION matches its 3D partner within tolerance."""
    pairs = [r for r in rows if r["element"] in EXACT_REDUCTION]
    if not pairs:
        sys.exit("bar_convergence: --exact-reduction-tolerance needs QUAD4 and HEX8 runs")
    for r in pairs:
        d = r["max_difference_to_3d"]
        if not d <= tolerance:  # NaN (no partner run) fails too
            sys.exit(f"bar_convergence: {r['element']} {r['kinematics']} n = {r['n']} differs "
                     f"from {PARTNER[r['element']]} by {d:.3e} of the peak (tolerance {tolerance})")
    print(f"bar_convergence: {len(pairs)} QUAD4 runs equal the HEX8 ones within {tolerance} "
          "of the peak")


if __name__ == "__main__":
    main()
