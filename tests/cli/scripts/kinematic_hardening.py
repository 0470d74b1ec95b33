#!/usr/bin/env python3
"""Linear kinematic hardening in a structure (docs/verification/plastic-sphere.md, "Kinematic
hardening"): the thick sphere of input/plastic_sphere_axisymmetric.xml (small strain, HHT, internal
pressure ramped past first yield) with its hardening modulus given as isotropic (H = 20 GPa) and as
kinematic (H_k = 20 GPa). Under a monotone pressure every point of the sphere keeps its deviatoric
stress direction (radial against hoop), a proportional path, on which the two hardening rules are
the same law: the yield surface grows by H alpha, or moves by H_k alpha along the one direction.

Checked:
  - both complete and create no energy (balance at or below 1e-9 of the plastic work);
  - the displacements agree within the mesh's own departure from spherical symmetry (the inner
    equator's radial displacement against the inner pole's axial one, which the exact solution
    makes equal: the discrete sphere's paths are proportional only to that extent);
  - the total energy (strain plus dissipated: the pressure's work) agrees within that asymmetry
    times the plastic work, while the kinematic run stores part of it in the back stress: its
    dissipated work is lower and its strain energy higher by the same amount (to the same bound),
    at least 1 % of the dissipated work.
usage: kinematic_hardening.py CHOC SOURCE_DIR WORK_DIR"""
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
failures = []
runs = {}
for label, H, Hk in (("isotropic", 20e9, 0.0), ("kinematic", 0.0, 20e9)):
    d = chocrun.load_deck(os.path.join(src, "input", "plastic_sphere_axisymmetric.xml"))
    chocrun.set_param(d, "Model/Materials/steel/Hardening Modulus", H)
    chocrun.set_param(d, "Model/Materials/steel/Kinematic Hardening Modulus", Hk, create=True)
    out = os.path.join(work, label)
    chocrun.run(choc, chocrun.write_deck(d, out + ".xml"), out)
    chocrun.require_completed(chocrun.read_summary(out, "pressurize"))
    h = runs[label] = chocrun.read_history(out, "pressurize")
    work_end = h["energy:dissipated"][-1]
    print(f"{label}: plastic work {work_end:.6g} J, balance at most {np.max(h['energy:balance']):.2e} J")
    if not np.max(h["energy:balance"]) <= 1e-9 * work_end:
        failures.append(f"{label}: energy created ({np.max(h['energy:balance']):.2e} J)")

iso, kin = runs["isotropic"], runs["kinematic"]
peak = np.max(np.abs(iso["INNER_EQUATOR:DX"]))
asym = np.max(np.abs(iso["INNER_EQUATOR:DX"] - iso["INNER_POLE:DY"])) / peak
for c in ("INNER_EQUATOR:DX", "INNER_POLE:DY", "OUTER_EQUATOR:DX"):
    diff = np.max(np.abs(iso[c] - kin[c])) / np.max(np.abs(iso[c]))
    print(f"{c}: kinematic against isotropic {diff:.2e} of the peak (the mesh's asymmetry {asym:.2e})")
    if not diff <= asym:
        failures.append(f"{c}: the hardening rules differ by {diff:.2e}, more than the mesh's asymmetry {asym:.2e}")
wp = iso["energy:dissipated"][-1]
total = np.max(np.abs((iso["energy:strain"] + iso["energy:dissipated"]) - (kin["energy:strain"] + kin["energy:dissipated"])))
stored = kin["energy:strain"][-1] - iso["energy:strain"][-1]
less = wp - kin["energy:dissipated"][-1]
print(f"total energy agrees to {total / wp:.1e} of the plastic work; the back stress stores {stored:.4g} J, "
      f"the dissipated work is {less:.4g} J lower")
if not total <= asym * wp:
    failures.append(f"the total energies differ by {total / wp:.1e} of the plastic work")
if not (stored >= 0.01 * wp and abs(stored - less) <= asym * wp):
    failures.append(f"the back stress's energy {stored:.4g} J against the dissipated work's drop {less:.4g} J")
chocrun.finish(failures, "kinematic hardening: OK")
