#!/usr/bin/env python3
"""The end-moment elastica (BENCHMARKS section 16; input/elastica_moment.xml): a cantilever of
HEX20 solids (finite strain, neo-Hookean, nu = 0, L / h = 50) loaded at its end face by a pure
moment through a distributing coupling, ramped to M = 2 pi EI / L over 200 quasi-static HHT steps.
Exact (the elastica under an end moment): every section has the curvature k = M(t) / EI, the tip
is at (sin kL / k, (1 - cos kL) / k); at the full moment the beam closes into a ring.
Checked, with 32 HEX20 along (the deck) and 64 (gmsh):
  - at every one of the 200 steps the tip is within 0.5 % of L of the circle's point (the
    benchmark's bound: solids agree with the beam to O(h / L) and their moment-curvature law to
    O((kh)^2), 1.6e-2 of the curvature at the full moment);
  - at the end the ring is closed: the tip is back at the clamp within 0.5 % of L;
  - the run ends at rest (kinetic energy at most 1e-6 of the strain energy);
  - the energy balance stays within 1e-3 of the moment's work (the trapezoidal rule on the
    turning load's work over steps of 1.8 degrees: (dtheta)^2 / 12 = 8e-5);
and the deck on 2 ranks gives the same tip path (1e-7 of L: Newton's tolerance).
usage: elastica_moment.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
failures = []
L, EI, RAMP = 1.0, 2e11 * 0.02 * 0.02 ** 3 / 12, 40.0


def run(label, mesh=None, ranks=1):
    d = chocrun.load_deck(os.path.join(src, "input", "elastica_moment.xml"))
    chocrun.set_param(d, "Analyses/bend/Exodus Interval", 0)
    if mesh:
        chocrun.set_param(d, "Mesh/File", mesh)
    out = os.path.join(work, label)
    chocrun.run(choc, chocrun.write_deck(d, out + ".xml"), out, ranks=ranks)
    s = chocrun.require_completed(chocrun.read_summary(out, "bend"))
    h = chocrun.read_history(out, "bend")
    print(f"{label}: {chocrun.summary_value(s, 'unknowns')} unknowns, "
          f"{chocrun.summary_value(s, 'newton')['iterations']} Newton iterations in {len(h['time']) - 1} steps, "
          f"{chocrun.summary_value(s, 'wall_seconds'):.1f} s")
    return h


def check(label, h):
    t = np.asarray(h["time"])
    worst, at = 0.0, 0.0
    for k in range(1, len(t)):
        kappa = 2 * math.pi * min(t[k] / RAMP, 1.0) / L
        exact = (math.sin(kappa * L) / kappa, (1 - math.cos(kappa * L)) / kappa)
        e = math.hypot(L + h["TIP:DX"][k] - exact[0], h["TIP:DY"][k] - exact[1]) / L
        if e > worst:
            worst, at = e, t[k] / RAMP
    closed = math.hypot(L + h["TIP:DX"][-1], h["TIP:DY"][-1]) / L
    kinetic, strain = h["energy:kinetic"][-1], h["energy:strain"][-1]
    balance = np.max(np.abs(h["energy:balance"])) / strain
    print(f"  tip: largest distance from the circle {worst:.2e} L (at {at:.3f} of the moment); at the end "
          f"{closed:.2e} L from the clamp; kinetic {kinetic / strain:.1e} of the strain energy; "
          f"balance within {balance:.1e} of the moment's work")
    if not worst <= 5e-3:
        failures.append(f"{label}: the tip is {worst:.2e} L from the circle at {at:.3f} of the moment (0.5 %)")
    if not closed <= 5e-3:
        failures.append(f"{label}: the ring is open by {closed:.2e} L (0.5 %)")
    if not kinetic <= 1e-6 * strain:
        failures.append(f"{label}: kinetic energy {kinetic:.2e} J at the end (1e-6 of {strain:.4g} J)")
    if not balance <= 1e-3:
        failures.append(f"{label}: energy balance {balance:.1e} of the work (1e-3)")


h32 = run("hex20_32")
check("hex20_32", h32)
mesh64 = chocrun.gmsh("elastica_beam.geo", os.path.join(work, "hex20_64.msh"), 3, "-order", 2,
                      "-setnumber", "nx", 64, "-setnumber", "hex", 1)
check("hex20_64", run("hex20_64", mesh64))
h2 = run("hex20_32_np2", ranks=2)
for c in ("TIP:DX", "TIP:DY"):
    diff = np.max(np.abs(np.asarray(h2[c]) - np.asarray(h32[c]))) / L
    if not diff <= 1e-7:
        failures.append(f"{c}: 2 ranks differ by {diff:.1e} L (1e-7)")
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("elastica_moment: the beam rolls into a ring under the coupling's pure moment")
