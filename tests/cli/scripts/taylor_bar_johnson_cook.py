#!/usr/bin/env python3
"""The Johnson-Cook Taylor bar (BENCHMARKS.md section 11; docs/verification/taylor-bar.md): a 42CrMo4
cylinder, R = 3.2 mm, L = 32.4 mm, at 287 m/s onto a rigid frictionless wall, 80 us; Johnson-Cook with
strain rate and adiabatic heating (90 % of the plastic work), finite strain, axisymmetric F-bar QUAD4
(input/taylor_bar_johnson_cook_axisymmetric.xml) on 5 x 51 elements (the published axisymmetric mesh
is 5 x 50) and 8 x 81. Published (DynELA, Abaqus): final length 26.52-26.56 mm, impact-face diameter
11.15-11.22 mm, largest equivalent plastic strain 1.78-1.84, largest temperature 582-597 C.

Checked:
  - every run completes, no energy is created (the balance at or below 1e-6 E0) and the plastic work
    is at least 97 % of E0 at the end;
  - on 5 x 51 (the published mesh's density) the length, the diameter, the largest plastic strain and
    temperature (element averages, which rise with refinement at the face's edge) lie within the
    published spread widened by the mesh's own error estimate |v(8) - v(5)| or 0.5 % (the issue's
    accuracy target for the copper bar), whichever is larger. Measured: the length 0.2 % below the
    spread (26.467 mm; 26.455 on 8 x 81), the diameter within it (11.227 mm; 11.295 on 8 x 81): see
    docs/verification/taylor-bar.md;
  - the temperature is the heat of the plastic work: rho c times the integral of T - T0 over the bar
    (the element averages times the elements' ring volumes) is chi times sum sigma_y d alpha (the
    documented heating), which energy:plastic (the history's plastic work, which never falls by
    more than 1e-9 of its end value in a step: the trapezoid's error at elastic increments,
    measured 5e-12) integrates by the trapezoid of the stress power instead: the two quadratures
    of one integral differ by the flow stress's change within an increment (hardening, rate and
    softening over 40 ns), a per-mille here (measured +1.0e-3 and +1.4e-3): 1 % allowed, the heat
    never below the work's share by more than that; the hottest element is the most
    strained one, and its rise lies between chi/(rho c) times A alpha (the least flow stress) and
    chi/(rho c) times the largest flow stress the law gives at that strain and a rate of 1e6 / s,
    times alpha;
  - with the impact face held on the wall (DY = 0 on IMPACT in place of the contact: the face
    cannot lift off, nor the bar leave the wall at 42 us), as the published runs evidently model
    it, the four figures on 5 x 51 lie within the published spread widened by the mesh's own
    error estimate |v(8) - v(5)| alone (measured within it but the diameter, 0.3 % below);
    the contact's length on 5 x 51 (0.2 % short, mesh estimate 0.04 %) fails this; held, no node
    impact hides the scheme's own energy error, so 1e-4 E0 is allowed for it (copper: 1.1e-5 at
    the deck's step, 4e-7 at half of it);
  - 2 ranks give the 1-rank histories to 1e-8 of the peaks (5 x 51).
usage: taylor_bar_johnson_cook.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

A, B, N, C, RHO, HEAT, CHI, T0 = 806e6, 614e6, 0.168, 0.0089, 7830, 460, 0.9, 20.0
PUBLISHED = {"length": (26.52, 26.56), "diameter": (11.15, 11.22), "strain": (1.78, 1.84),
             "temperature": (582, 597)}
os.makedirs(work, exist_ok=True)
failures = []


def ring_volumes(exo):
    """Each QUAD4's volume of revolution, 2 pi r_centroid area (Pappus), in the reference mesh."""
    import netCDF4
    with netCDF4.Dataset(exo) as d:
        x, y = np.asarray(d.variables["coordx"][:]), np.asarray(d.variables["coordy"][:])
        c = np.asarray(d.variables["connect1"][:]) - 1
    X, Y = x[c], y[c]
    cross = X * np.roll(Y, -1, axis=1) - np.roll(X, -1, axis=1) * Y
    area = 0.5 * cross.sum(axis=1)
    centroid = ((X + np.roll(X, -1, axis=1)) * cross).sum(axis=1) / (6 * area)
    return 2 * math.pi * centroid * np.abs(area)


def run(n, label, ranks=1, held=False):
    msh = os.path.join(work, f"bar_{n}.msh")
    chocrun.gmsh("taylor_bar_axisymmetric.geo", msh, 2, "-setnumber", "n", n)
    d = chocrun.load_deck(os.path.join(src, "input", "taylor_bar_johnson_cook_axisymmetric.xml"))
    chocrun.set_param(d, "Mesh/File", msh)
    if held:  # the face held on the wall: DY = 0 on IMPACT in place of the contact pair
        chocrun.hold_on_wall(d, "Analyses/impact", "IMPACT", "DY", "central differences",
                             chocrun.get_param(d, "Analyses/impact/Time Step"), 8e-5)
    chocrun.set_param(d, "Analyses/impact/Exodus Interval", 1000000)  # the first and the last step
    out = os.path.join(work, label)
    chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, label + ".xml")), out, ranks=ranks)
    chocrun.require_completed(chocrun.read_summary(out, "impact"))
    h = chocrun.read_history(out, "impact")
    fields = chocrun.read_element_fields(os.path.join(out, "impact.exo"), ("EQ_PLASTIC_STRAIN", "TEMPERATURE"))
    strain, temp = fields["EQ_PLASTIC_STRAIN"], fields["TEMPERATURE"]
    v = chocrun.taylor_bar_outcome(label, h, strain, temp, failures, created=1e-4 if held else 1e-6)
    plastic = np.asarray(h["energy:plastic"])
    heat = RHO * HEAT * float(np.sum((temp - T0) * ring_volumes(os.path.join(out, "impact.exo"))))
    print(f"{label}: heat {heat:.6g} J against chi x energy:plastic {CHI * plastic[-1]:.6g} J "
          f"({heat / (CHI * plastic[-1]) - 1:+.1e})")
    if not (abs(heat - CHI * plastic[-1]) <= 1e-2 * CHI * plastic[-1] and np.all(np.diff(plastic) >= -1e-9 * plastic[-1])):
        failures.append(f"{label}: the heat {heat:.9g} J is not chi times the plastic work {plastic[-1]:.9g} J "
                        "(or the plastic work decreases)")
    hottest = int(np.argmax(temp))
    a = float(strain[hottest])
    lo = CHI / (RHO * HEAT) * A * a
    hi = CHI / (RHO * HEAT) * (A + B * a ** N) * (1 + C * math.log(1e6)) * a
    rise = float(temp[hottest]) - T0
    print(f"{label}: hottest element at alpha = {a:.3f} (largest {v['strain']:.3f}), rise {rise:.1f} K "
          f"within [{lo:.1f}, {hi:.1f}] K")
    if not (a >= 0.9 * v["strain"] and lo <= rise <= hi):
        failures.append(f"{label}: the temperature rise {rise:.1f} K is not the heat of the plastic work")
    return v, h


v5, h5 = run(5, "jc_5")
v8, _ = run(8, "jc_8")
for key in ("length", "diameter", "strain", "temperature"):
    lo, hi = PUBLISHED[key]
    est = max(abs(v8[key] - v5[key]), 0.005 * v5[key])
    print(f"{key}: {v5[key]:.4f} (5 x 51), {v8[key]:.4f} (8 x 81), allowance {est:.4f}, published {lo}-{hi}")
    if not lo - est <= v5[key] <= hi + est:
        failures.append(f"{key} {v5[key]:.4f} outside the published {lo}-{hi} widened by {est:.4f}")

w5, _ = run(5, "jc_5_held", held=True)
w8, _ = run(8, "jc_8_held", held=True)
for key in ("length", "diameter", "strain", "temperature"):
    lo, hi = PUBLISHED[key]
    est = abs(w8[key] - w5[key])
    print(f"face held, {key}: {w5[key]:.4f} (5 x 51), {w8[key]:.4f} (8 x 81), allowance {est:.4f}, published {lo}-{hi}")
    if not lo - est <= w5[key] <= hi + est:
        failures.append(f"face held: {key} {w5[key]:.4f} outside the published {lo}-{hi} widened by {est:.4f}")

_, h5b = run(5, "jc_5_np2", ranks=2)
failures += chocrun.ranks_agree(h5, h5b, ("EDGE:DX", "REAR:DY", "energy:dissipated"))
chocrun.finish(failures, "Johnson-Cook Taylor bar: OK")
