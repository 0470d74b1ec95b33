#!/usr/bin/env python3
"""Inflation of a thick-walled neo-Hookean sphere (docs/verification/thick-sphere.md): inner
radius A = 50 mm, outer B = 100 mm, E = 3 MPa, nu = 0.45, a dead inner pressure p0 growing to
3 MPa quasi-statically (input/thick_sphere_axisymmetric.xml and input/thick_sphere_3d.xml, 20
steps), until the inner radius is 1.9 A. The reference is tools/oracles/thick_sphere.py: the
radial equilibrium of the same strain-energy function integrated by Runge-Kutta and shooting
(1e-10), itself checked here against the incompressible closed form at nu -> 1/2 (their
difference must stay below the compressibility mu / lambda).

Checked at every step, on a mesh series (axisymmetric QUAD8: 2, 4, 8 elements across the wall;
3D TET10 octant: h = 25 and 12.5 mm):
  - the error of the inner radius (against the reference, relative to the inflation a - A)
    falls with the mesh at the order of quadratic elements: the observed order of the
    axisymmetric series at least 2, of the 3D pair at least 1 (unstructured tetrahedra);
  - the finest mesh's error is at most twice its Richardson estimate (the last two meshes'
    difference / (2^2 - 1)): a model that disagreed with the reference by more than its
    discretisation error would fail this;
  - the same for the inner pole (spherical symmetry: it moves as the equator) and the outer
    radius;
  - the same pressure as a follower load (Pressures/<name>/Follower: the true pressure on the
    current surface, growing to 700 kPa, below the maximum the sphere can hold, 832.6 kPa), on
    the axisymmetric meshes of 2, 4 and 8 across: the same order and Richardson tests against the
    reference under the true pressure (thick_sphere.follower_inflation);
  - every run completes (exit 0: its energy balance within the monitor's band), and the
    balance is the O(dt^2) error of the trapezoidal work of a nonlinear force: it falls by
    4 (3.5 to 4.5) when dt is halved.
usage: thick_sphere.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
sys.path.insert(0, os.path.join(src, "tools", "oracles"))
import chocrun  # noqa: E402
import thick_sphere  # noqa: E402

A, B, E, NU, P0, RAMP = 0.05, 0.1, 3e6, 0.45, 3e6, 10.0
MU, LAM = thick_sphere.lame(E, NU)
os.makedirs(work, exist_ok=True)
failures = []

d, bound = thick_sphere.closed_form_check()
print(f"oracle: the incompressible closed form against the shooting solver at nu = 0.4999: {d:.2e} "
      f"(at most mu / lambda = {bound:.2e})")
if not d <= bound:
    failures.append(f"oracle: {d:.2e} from the closed form (at most {bound:.2e})")


def reference(times, follower=None):
    """(a, b) of the oracle at each time of the ramp (of the true pressure `follower` if given)."""
    if follower:
        ab = [thick_sphere.follower_inflation(follower * min(t / RAMP, 1.0), A, B, MU, LAM, steps=800)
              for t in times]
        return np.array([x[0] for x in ab]), np.array([x[1] for x in ab])
    ab = [thick_sphere.inflation(P0 * min(t / RAMP, 1.0), A, B, MU, LAM, steps=800) for t in times]
    return np.array([x[0] for x in ab]), np.array([x[1] for x in ab])


def run(deck, analysis, mesh, label, dt=None, follower=None):
    d = chocrun.load_deck(os.path.join(src, "input", deck))
    chocrun.set_param(d, "Mesh/File", mesh)
    if follower:
        chocrun.set_param(d, f"Analyses/{analysis}/Pressures/inner/Value", follower)
        chocrun.set_param(d, f"Analyses/{analysis}/Pressures/inner/Follower", True, create=True)
    chocrun.set_param(d, f"Analyses/{analysis}/Exodus Interval", 0)
    chocrun.remove_sublist(d, f"Analyses/{analysis}/Checks")  # the deck's, for its own mesh
    if dt:
        chocrun.set_param(d, f"Analyses/{analysis}/Time Step", dt)
    out = os.path.join(work, label)
    chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, label + ".xml")), out)
    s = chocrun.require_completed(chocrun.read_summary(out, analysis))
    h = chocrun.read_history(out, analysis)
    print(f"{label}: {chocrun.summary_value(s, 'unknowns')} unknowns, "
          f"{chocrun.summary_value(s, 'newton')['iterations']} Newton iterations in {len(h['time']) - 1} steps, "
          f"energy balance at the end {h['energy:balance'][-1]:.3e} J of {h['energy:strain'][-1]:.4g} J stored")
    return h


def series(label, runs, points, min_order, follower=None):
    """For each (column, radius) point: its radius' error along the mesh series against the
    reference (relative to the reference's largest radial motion), the observed orders, and the
    finest mesh's error against twice its Richardson estimate."""
    times = runs[0]["time"]
    a_ref, b_ref = reference(times, follower)
    for column, radius in points:
        ref = a_ref if radius == A else b_ref
        scale = float(np.max(np.abs(ref - radius)))
        x = [radius + h[column] for h in runs]
        errors = [float(np.max(np.abs(xi - ref))) / scale for xi in x]
        estimate = float(np.max(np.abs(x[-1] - x[-2]))) / scale / 3
        orders = [math.log2(e0 / e1) for e0, e1 in zip(errors, errors[1:])]
        print(f"{label} {column}: errors {', '.join(f'{e:.2e}' for e in errors)} of its radial motion "
              f"(observed orders {', '.join(f'{o:.2f}' for o in orders)}); finest {errors[-1]:.2e}, "
              f"Richardson estimate {estimate:.2e}; at the end {x[-1][-1] / radius:.6f} of its radius "
              f"(reference {ref[-1] / radius:.6f})")
        if not min(orders) >= min_order:
            failures.append(f"{label} {column}: observed order {min(orders):.2f} (at least {min_order})")
        if not errors[-1] <= 2 * estimate:
            failures.append(f"{label} {column}: finest error {errors[-1]:.2e} above twice its estimate {estimate:.2e}")
    p_end = follower if follower else P0 * (A / a_ref[-1]) ** 2
    print(f"{label}: true pressure at the end {p_end:.6g} Pa, inner radius {a_ref[-1] / A:.6f} A")


axi = []
for n in (2, 4, 8):
    msh = chocrun.gmsh("thick_sphere_axisymmetric.geo", os.path.join(work, f"axi_{n}.msh"), 2,
                       "-order", 2, "-setnumber", "n", n)
    axi.append(run("thick_sphere_axisymmetric.xml", "inflate", msh, f"axisymmetric_n{n}"))
series("axisymmetric QUAD8", axi, [("INNER_EQUATOR:DX", A), ("INNER_POLE:DY", A), ("OUTER_EQUATOR:DX", B)], 2.0)

# The follower pressure: the true pressure on the current inner surface, 700 kPa at the end.
FOLLOWER = 7e5
follow = [run("thick_sphere_axisymmetric.xml", "inflate", os.path.join(work, f"axi_{n}.msh"),
              f"axisymmetric_n{n}_follower", follower=FOLLOWER) for n in (2, 4, 8)]
series("axisymmetric QUAD8, follower pressure", follow, [("INNER_EQUATOR:DX", A), ("OUTER_EQUATOR:DX", B)], 2.0,
       follower=FOLLOWER)

# The energy balance: the Newmark family's discrete energy identity holds for forces linear in
# the displacements; for a hyperelastic force the trapezoid of f . du differs from the change of
# the strain energy by O(dt^2) per unit time (either sign). A balance that is this quadrature
# error falls by 4 when dt is halved; one created by an instability would not.
half = run("thick_sphere_axisymmetric.xml", "inflate", os.path.join(work, "axi_4.msh"), "axisymmetric_n4_half_dt", dt=0.25)
b1, b2 = axi[1]["energy:balance"][-1], half["energy:balance"][-1]
print(f"energy balance at the end: {b1:.3e} J at dt = 0.5 s, {b2:.3e} J at dt = 0.25 s (ratio {b1 / b2:.3f}; "
      f"{b1 / axi[1]['energy:strain'][-1]:.1e} of the strain energy)")
if not 3.5 <= b1 / b2 <= 4.5:
    failures.append(f"energy balance {b1:.3e} J -> {b2:.3e} J when dt is halved: not the O(dt^2) quadrature error")

solid = []
for h in (0.025, 0.0125):
    msh = chocrun.gmsh("thick_sphere_octant.geo", os.path.join(work, f"octant_{h}.msh"), 3,
                       "-order", 2, "-setnumber", "h", h)
    solid.append(run("thick_sphere_3d.xml", "inflate", msh, f"3d_h{h}"))
series("3D TET10", solid, [("INNER_X:DX", A), ("INNER_Z:DZ", A), ("OUTER_X:DX", B)], 1.0)



def plot(path):
    """The true pressure against the inner stretch: the reference, the incompressible closed form
    (nu -> 1/2) for comparison, and the finest meshes' steps."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.2))
    p0 = np.linspace(0, P0, 61)
    a = np.array([thick_sphere.inflation(p, A, B, MU, LAM)[0] for p in p0])
    ax.plot(a / A, p0 * (A / a) ** 2 / 1e3, "k-", label="reference (radial equilibrium, nu = 0.45)")
    la = np.linspace(1, a[-1] / A, 61)
    ax.plot(la, [thick_sphere.incompressible_pressure(x, A, B, MU) / 1e3 for x in la], "k:",
            label="incompressible closed form (nu = 1/2)")
    for h, col, mark, lab in ((axi[-1], "INNER_EQUATOR:DX", "o", "choc, axisymmetric QUAD8 (8 across)"),
                              (solid[-1], "INNER_X:DX", "s", "choc, 3D TET10 octant (h = 12.5 mm)")):
        ah = A + h[col]
        ax.plot(ah / A, P0 * np.minimum(h["time"] / RAMP, 1) * (A / ah) ** 2 / 1e3, mark, mfc="none", label=lab)
    ax.set_xlabel("inner radius a / A")
    ax.set_ylabel("true pressure on the inner surface [kPa]")
    ax.set_title("Thick-walled neo-Hookean sphere, B = 2 A, E = 3 MPa")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right")
    chocrun.save_figure(fig, path)


plot(os.path.join(work, "thick_sphere.png"))
chocrun.finish(failures, "thick-walled sphere: OK")
