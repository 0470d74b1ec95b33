#!/usr/bin/env python3
"""A thick-walled elastic-perfectly plastic sphere under internal pressure (docs/verification/
plastic-sphere.md): inner radius A = 50 mm, outer B = 100 mm, E = 200 GPa, nu = 0.3, J2 with
sigma_y = 250 MPa and no hardening, small strain; the inner pressure grows quasi-statically to
316 MPa, which spreads the plastic front from the inner surface (first yield at 145.8 MPa) to
c = 0.8 B (input/plastic_sphere_axisymmetric.xml and input/plastic_sphere_3d.xml, 40 steps).
The reference is Hill's closed form (tools/oracles/plastic_sphere.py): the outer radius' motion
u(B) = sigma_y (1 - nu) c^3 / (E B^2), c from p = 2 sigma_y ln(c / A) + 2 sigma_y / 3 (1 - c^3 /
B^3), exact whatever the plastic zone's compressibility.

Checked at every step, on a mesh series (axisymmetric QUAD8: 2, 4, 8, 16 elements across the
wall; 3D TET10 octant: h = 25 and 12.5 mm):
  - the oracle's two branches meet at first yield and its front inverts its pressure (1e-12);
  - the error of u(B) (the largest over the ramp, relative to its largest value) falls with the
    mesh: observed order at least 1.5 axisymmetric (quadratic elements; the plastic front, where
    the strain's slope jumps, crosses elements as it moves, which caps the order at about 2),
    at least 1 in 3D (two unstructured tetrahedral meshes);
  - the finest mesh's error is at most twice its Richardson estimate (the last two meshes'
    difference / (2^2 - 1)): a return map that yielded at the wrong stress would fail this;
  - the energy balance closes to 1e-7 of the external work: the plastic work is measured by
    the trapezoidal rule the external work is, so what is left is Newton's residual;
  - the plastic work is positive and rises once the front has started, and is zero before;
  - 2 ranks give the 1-rank histories to 1e-8 of the peak (solver tolerance).
usage: plastic_sphere.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
sys.path.insert(0, os.path.join(src, "tools", "oracles"))
import chocrun  # noqa: E402
import plastic_sphere  # noqa: E402

A, B, E, NU, Y, P_END, RAMP = 0.05, 0.1, 200e9, 0.3, 250e6, 316e6, 10.0
os.makedirs(work, exist_ok=True)
failures = []

d = plastic_sphere.self_check()
print(f"oracle self check: {d:.2e} (at most 1e-12)")
if not d <= 1e-12:
    failures.append(f"oracle self check {d:.2e}")


def run(deck, mesh, label, np_=1):
    dk = chocrun.load_deck(os.path.join(src, "input", deck))
    chocrun.set_param(dk, "Mesh/File", mesh)
    chocrun.set_param(dk, "Analyses/pressurize/Exodus Interval", 0)
    out = os.path.join(work, label)
    chocrun.run(choc, chocrun.write_deck(dk, os.path.join(work, label + ".xml")), out, ranks=np_)
    s = chocrun.require_completed(chocrun.read_summary(out, "pressurize"))
    h = chocrun.read_history(out, "pressurize")
    newton = chocrun.summary_value(s, "newton")["iterations"]
    print(f"{label}: {chocrun.summary_value(s, 'unknowns')} unknowns, {newton} Newton iterations in "
          f"{len(h['time']) - 1} steps, plastic work {h['energy:dissipated'][-1]:.4g} J, stored "
          f"{h['energy:strain'][-1]:.4g} J, balance {h['energy:balance'][-1]:.2e} J")
    return h


def reference(times):
    p = P_END * np.minimum(np.asarray(times) / RAMP, 1.0)
    return np.array([plastic_sphere.outer_displacement(x, A, B, E, NU, Y) for x in p]), p


def series(label, runs, column, min_order):
    ref, _ = reference(runs[0]["time"])
    scale = float(np.max(np.abs(ref)))
    x = [np.asarray(h[column]) for h in runs]
    errors = [float(np.max(np.abs(xi - ref))) / scale for xi in x]
    estimate = float(np.max(np.abs(x[-1] - x[-2]))) / scale / 3
    orders = [math.log2(e0 / e1) for e0, e1 in zip(errors, errors[1:])]
    print(f"{label} {column}: errors {', '.join(f'{e:.2e}' for e in errors)} of the largest u(B) "
          f"(observed orders {', '.join(f'{o:.2f}' for o in orders)}); finest {errors[-1]:.2e}, "
          f"Richardson estimate {estimate:.2e}")
    if not min(orders) >= min_order:
        failures.append(f"{label}: observed order {min(orders):.2f} (at least {min_order})")
    if not errors[-1] <= 2 * estimate:
        failures.append(f"{label}: finest error {errors[-1]:.2e} above twice its estimate {estimate:.2e}")


def energy(label, h):
    work = h["energy:strain"] + h["energy:dissipated"] + h["energy:kinetic"]  # = the external work
    balance = float(np.max(np.abs(h["energy:balance"])))
    print(f"{label}: |balance| at most {balance:.2e} J of {work[-1]:.4g} J of work")
    if not balance <= 1e-7 * work[-1]:
        failures.append(f"{label}: energy balance {balance:.2e} J above 1e-7 of the work {work[-1]:.4g} J")
    _, p = reference(h["time"])
    first = plastic_sphere.first_yield(A, B, Y)
    wp = np.asarray(h["energy:dissipated"])
    before = float(np.max(np.abs(wp[p <= first])))
    if not (before <= 1e-9 * work[-1] and wp[-1] > 0 and np.all(np.diff(wp[p > first]) > 0)):
        failures.append(f"{label}: plastic work {before:.2e} J before first yield, {wp[-1]:.3e} J at the end, "
                        "not rising after it")


axi = []
for n in (2, 4, 8, 16):
    msh = chocrun.gmsh("thick_sphere_axisymmetric.geo", os.path.join(work, f"axi_{n}.msh"), 2,
                       "-order", 2, "-setnumber", "n", n)
    axi.append(run("plastic_sphere_axisymmetric.xml", msh, f"axisymmetric_n{n}"))
series("axisymmetric QUAD8", axi, "OUTER_EQUATOR:DX", 1.5)
energy("axisymmetric QUAD8, 16 across", axi[-1])

two = run("plastic_sphere_axisymmetric.xml", os.path.join(work, "axi_8.msh"), "axisymmetric_n8_np2", np_=2)
for col in ("OUTER_EQUATOR:DX", "INNER_EQUATOR:DX", "energy:dissipated"):
    peak = float(np.max(np.abs(axi[2][col])))
    diff = float(np.max(np.abs(np.asarray(two[col]) - np.asarray(axi[2][col])))) / peak
    print(f"2 ranks against 1, {col}: {diff:.1e} of the peak (at most 1e-8)")
    if not diff <= 1e-8:
        failures.append(f"2 ranks: {col} differs by {diff:.1e} of its peak")

solid = []
for h in (0.025, 0.0125):
    msh = chocrun.gmsh("thick_sphere_octant.geo", os.path.join(work, f"octant_{h}.msh"), 3,
                       "-order", 2, "-setnumber", "h", h)
    solid.append(run("plastic_sphere_3d.xml", msh, f"3d_h{h}"))
series("3D TET10", solid, "OUTER_X:DX", 1.0)
energy("3D TET10, h = 12.5 mm", solid[-1])


def plot(path):
    """The inner pressure against the outer radius' motion: Hill's closed form and the finest
    meshes' steps."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.2))
    p = np.linspace(0, P_END, 200)
    ax.plot([plastic_sphere.outer_displacement(x, A, B, E, NU, Y) * 1e6 for x in p], p / 1e6, "k-",
            label="Hill's closed form (elastic-perfectly plastic)")
    for h, col, mark, lab in ((axi[-1], "OUTER_EQUATOR:DX", "o", "choc, axisymmetric QUAD8 (16 across)"),
                              (solid[-1], "OUTER_X:DX", "s", "choc, 3D TET10 octant (h = 12.5 mm)")):
        ax.plot(np.asarray(h[col]) * 1e6, P_END * np.minimum(np.asarray(h["time"]) / RAMP, 1) / 1e6, mark,
                mfc="none", label=lab)
    ax.axhline(plastic_sphere.first_yield(A, B, Y) / 1e6, color="0.6", ls=":", label="first yield")
    ax.axhline(plastic_sphere.collapse(A, B, Y) / 1e6, color="0.6", ls="--", label="collapse")
    ax.set_xlabel("outer radius' motion u(B) [um]")
    ax.set_ylabel("inner pressure [MPa]")
    ax.set_title("Thick-walled sphere, J2, sigma_y = 250 MPa, B = 2 A")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right")
    chocrun.save_figure(fig, path)


plot(os.path.join(work, "plastic_sphere.png"))
chocrun.finish(failures, "plastic sphere: OK")
