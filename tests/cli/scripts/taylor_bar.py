#!/usr/bin/env python3
"""The Taylor bar (docs/verification/taylor-bar.md): a copper cylinder, R = 3.2 mm, L = 32.4 mm,
J2 with sigma_y = 400 MPa and linear hardening H = 100 MPa (E = 117 GPa, nu = 0.35, rho = 8930),
finite strain, at 227 m/s onto a rigid frictionless wall (Lagrange, forward increments), 80 us by
central differences; axisymmetric QUAD4 (input/taylor_bar_axisymmetric.xml, meshes of 0.8 and
0.4 mm). Published final length 21.4-21.5 mm; final impact-face radius 7.11 (Zienkiewicz et al.
1998), 7.12 (Simo 1992), 7.22 mm (Foulk et al., converged Q1/P0).

Checked:
  - every run completes (exit 0), and no energy is created: the balance stays at or below
    1e-6 of E0 (it falls where the contact's forward increments stop the nodes that strike the
    wall, an inelastic impact of each; measured -0.1 to -0.3 %), and the plastic work is at least
    97 % of E0 at the end (the bar nearly at rest; the rest is the elastic energy left, the
    kinetic energy and those node impacts); with the face held on the wall (below) no node impact
    hides the scheme's own error, 1.1e-5 E0 at the deck's step and 4e-7 at half of it: 1e-4;
  - F-bar removes the bilinear element's volumetric locking: on 0.4 mm the standard QUAD4's
    radius lies below F-bar's by more than F-bar's own mesh error |R(0.4) - R(0.8)| (locked
    plastic flow cannot spread the face; measured 6.14 against 7.29 mm, error estimate 0.12 mm):
    a difference the discretisation of the same element cannot explain;
  - the F-bar meshes' final length lies within the published 21.4-21.5 mm widened by the mesh's
    own error estimate |L(0.4) - L(0.8)|, and so does the radius within 7.11-7.22 mm widened by
    |R(0.4) - R(0.8)|: a model that disagreed with the published bars by more than its
    discretisation error would fail this (docs/verification/taylor-bar.md says what finer meshes
    show);
  - the published runs hold the impact face on the wall (no lift-off); with the face held so
    (DY = 0 on IMPACT instead of the contact), the radius extrapolated from 0.8 and 0.4 mm,
    R(0.4) + (R(0.4) - R(0.8)) / (2^p - 1), lies within the issue's 0.5 % of Foulk et al.'s
    7.22 mm for p = 1 and for p = 1.4 (the orders the finer meshes show: 1.1 held, 1.35-1.4 on
    contact); the contact's own extrapolation lies 2 % above it (measured 7.36-7.41 mm), so this
    fails if the held face spread as the contact's does;
  - 2 ranks give the 1-rank histories to 1e-8 of the peaks (0.8 mm mesh).
usage: taylor_bar.py CHOC SOURCE_DIR WORK_DIR"""
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

R0, L0 = 3.2e-3, 32.4e-3
os.makedirs(work, exist_ok=True)
failures = []


def run(n, label, fbar=True, ranks=1, held=False):
    msh = os.path.join(work, f"bar_{n}.msh")
    chocrun.gmsh("taylor_bar_axisymmetric.geo", msh, 2, "-setnumber", "n", n)
    d = chocrun.load_deck(os.path.join(src, "input", "taylor_bar_axisymmetric.xml"))
    chocrun.set_param(d, "Mesh/File", msh)
    chocrun.set_param(d, "Analyses/impact/Exodus Interval", 0)
    if not fbar:
        chocrun.set_param(d, "Model/Blocks/BAR/Formulation", "standard")
    if held:  # the face held on the wall: DY = 0 on IMPACT in place of the contact pair
        chocrun.hold_on_wall(d, "Analyses/impact", "IMPACT", "DY", "central differences",
                             chocrun.get_param(d, "Analyses/impact/Time Step"), 8e-5)
    out = os.path.join(work, label)
    chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, label + ".xml")), out, ranks=ranks)
    chocrun.require_completed(chocrun.read_summary(out, "impact"))
    h = chocrun.read_history(out, "impact")
    e0 = h["energy:total"][1]  # after the first contact step (see the balance's E0)
    # the length between the rear face and the impact face (the bar may have left the wall)
    r, length = (R0 + h["EDGE:DX"][-1]) * 1e3, (L0 + h["REAR:DY"][-1] - h["CENTRE:DY"][-1]) * 1e3
    bal = np.asarray(h["energy:balance"])
    print(f"{label}: radius {r:.4f} mm, length {length:.4f} mm, plastic work {h['energy:dissipated'][-1]:.4g} J "
          f"of E0 = {e0:.4g} J, balance in [{bal.min() / e0:.2e}, {bal.max() / e0:.2e}] E0")
    # Held on the wall no node strikes it after the start, so the balance shows the scheme's own
    # error: up to 1.1e-5 E0 at the deck's step (0.8 mm), 4e-7 E0 at half of it (1.3e-5 with
    # the critical step estimated at every step: not the estimate's interval); 1e-4 E0 allowed.
    if not bal.max() <= (1e-4 if held else 1e-6) * e0:
        failures.append(f"{label}: energy created, balance up to {bal.max() / e0:.2e} E0")
    if fbar and not h["energy:dissipated"][-1] >= 0.97 * e0:
        failures.append(f"{label}: plastic work {h['energy:dissipated'][-1]:.4g} J below 97 % of E0")
    return r, length, h


r4, l4, h4 = run(4, "fbar_0.8mm")
r8, l8, _ = run(8, "fbar_0.4mm")
rs, _, _ = run(8, "standard_0.4mm", fbar=False)
print(f"locking: standard QUAD4 {rs:.4f} mm against F-bar {r8:.4f} mm ({rs / r8 - 1:+.1%}); "
      f"F-bar's mesh error estimate {abs(r8 - r4):.4f} mm")
if not rs < r8 - abs(r8 - r4):
    failures.append(f"standard QUAD4 radius {rs:.4f} mm not below F-bar's {r8:.4f} mm by more than its mesh error")
for what, v8, v4, lo, hi in (("length", l8, l4, 21.4, 21.5), ("radius", r8, r4, 7.11, 7.22)):
    est = abs(v8 - v4)
    print(f"{what} on 0.4 mm: {v8:.4f} mm, mesh estimate {est:.4f} mm, published {lo}-{hi} mm")
    if not lo - est <= v8 <= hi + est:
        failures.append(f"{what} {v8:.4f} mm outside the published {lo}-{hi} mm widened by {est:.4f} mm")

rh4, _, _ = run(4, "held_0.8mm", held=True)
rh8, _, _ = run(8, "held_0.4mm", held=True)
for p in (1.0, 1.4):
    held, free = rh8 + (rh8 - rh4) / (2 ** p - 1), r8 + (r8 - r4) / (2 ** p - 1)
    print(f"extrapolated radius (order {p}): face held {held:.4f} mm ({held / 7.22 - 1:+.2%} from 7.22 mm), "
          f"contact {free:.4f} mm ({free / 7.22 - 1:+.2%})")
    if not abs(held / 7.22 - 1) <= 0.005:
        failures.append(f"face held: extrapolated radius {held:.4f} mm (order {p}) not within 0.5 % of 7.22 mm")

_, _, h4b = run(4, "fbar_0.8mm_np2", ranks=2)
failures += chocrun.ranks_agree(h4, h4b, ("EDGE:DX", "REAR:DY", "energy:dissipated"))
chocrun.finish(failures, "Taylor bar: OK")
