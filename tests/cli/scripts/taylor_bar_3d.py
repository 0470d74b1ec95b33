#!/usr/bin/env python3
"""The Taylor bar in 3D (docs/verification/taylor-bar.md): the copper bar of input/taylor_bar_3d.xml
(J2, 227 m/s onto a rigid frictionless wall, 80 us, HEX8 F-bar, central differences) on the coarse
O-grid of meshes/taylor_bar_3d.geo with n = 2 (about 1.6 mm elements), against the axisymmetric bar
(QUAD4 F-bar) on the same element size.

Checked:
  - the quarter with its symmetry planes completes, creates no energy (balance at or below 1e-6 E0)
    and ends with at least 97 % of E0 as plastic work;
  - its final impact-face radius and length agree with the axisymmetric bar of the same element
    size within that bar's own mesh error estimate |x(1.6 mm) - x(0.8 mm)| (two discretisations of
    one problem at one element size differ by their discretisation errors);
  - 2 ranks give the 1-rank histories to 1e-8 of their peaks;
  - the whole bar (no symmetry planes), turned as a rigid whole with its wall and its velocity by
    0.7 rad about (0.3, -0.5, 0.81), moves as the bar drawn along y seen in the turned frame,
    R^T u, to 1e-8 of the peak displacement over the first 20 us (the impact and the spreading of
    the plastic zone): frame invariance of the finite-strain plastic element, F-bar and the contact.
usage: taylor_bar_3d.py CHOC SOURCE_DIR WORK_DIR"""
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

R0, L0 = 3.2e-3, 32.4e-3
os.makedirs(work, exist_ok=True)
failures = []
POINTS = ("EDGE", "REAR", "CENTRE")


def finish_run(d, label, ranks=1):
    out = os.path.join(work, label)
    chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, label + ".xml")), out, ranks=ranks)
    chocrun.require_completed(chocrun.read_summary(out, "impact"))
    h = chocrun.read_history(out, "impact")
    e0 = h["energy:total"][1]
    bal = np.asarray(h["energy:balance"])
    print(f"{label}: plastic work {h['energy:dissipated'][-1] / e0:.4f} E0, balance in "
          f"[{bal.min() / e0:.2e}, {bal.max() / e0:.2e}] E0")
    if not bal.max() <= 1e-6 * e0:
        failures.append(f"{label}: energy created, balance up to {bal.max() / e0:.2e} E0")
    return h, e0


def shape(h):
    return (R0 + h["EDGE:DX"][-1]) * 1e3, (L0 + h["REAR:DY"][-1] - h["CENTRE:DY"][-1]) * 1e3


def axisymmetric(n):
    msh = chocrun.gmsh("taylor_bar_axisymmetric.geo", os.path.join(work, f"axi_{n}.msh"), 2, "-setnumber", "n", n)
    d = chocrun.load_deck(os.path.join(src, "input", "taylor_bar_axisymmetric.xml"))
    chocrun.set_param(d, "Mesh/File", msh)
    chocrun.set_param(d, "Analyses/impact/Exodus Interval", 0)
    h, _ = finish_run(d, f"axi_{n}")
    return shape(h)


def three_d(full=0, ranks=1, R=None, end=None):
    d = chocrun.taylor_bar_3d_deck(work, n=2, full=full, R=R, end=end, points=POINTS)
    label = f"bar3d_full{full}_np{ranks}" + ("_turned" if R is not None else "")
    h, _ = finish_run(d, label, ranks)
    return h


# The quarter against the axisymmetric bar at the same element size.
h1 = three_d()
if not h1["energy:dissipated"][-1] >= 0.97 * h1["energy:total"][1]:
    failures.append(f"the quarter: plastic work {h1['energy:dissipated'][-1]:.4g} J below 97 % of E0")
r3, l3 = shape(h1)
(ra, la), (ra4, la4) = axisymmetric(2), axisymmetric(4)
for what, v3, va, va4 in (("radius", r3, ra, ra4), ("length", l3, la, la4)):
    est = abs(va - va4)
    print(f"{what}: 3D quarter {v3:.4f} mm, axisymmetric {va:.4f} mm (mesh error estimate {est:.4f} mm)")
    if not abs(v3 - va) <= est:
        failures.append(f"{what}: 3D {v3:.4f} mm and axisymmetric {va:.4f} mm differ by more than {est:.4f} mm")

h2 = three_d(ranks=2)
failures += chocrun.ranks_agree(h1, h2, ("EDGE:DX", "REAR:DY", "CENTRE:DY", "energy:dissipated"))

# The whole bar, drawn along y and turned.
R = chocrun.rotation_matrix(0.7, (0.3, -0.5, 0.81))
ha = three_d(full=1, end=2e-5)
hb = three_d(full=1, end=2e-5, R=R)
ua = np.stack([np.stack([ha[f"{p}:{c}"] for c in ("DX", "DY", "DZ")], axis=1) for p in POINTS])
ub = np.stack([np.stack([hb[f"{p}:{c}"] for c in ("DX", "DY", "DZ")], axis=1) for p in POINTS])
back = np.einsum("ji,ptj->pti", R, ub)
peak = float(np.max(np.abs(ua)))
diff = float(np.max(np.abs(back - ua))) / peak
print(f"turned as a whole: R^T u against u, {diff:.1e} of the peak displacement {peak:.3e} m (at most 1e-8)")
if not diff <= 1e-8:
    failures.append(f"frame invariance: the turned bar's motion differs by {diff:.1e} of the peak")
chocrun.finish(failures, "Taylor bar 3D: OK")
