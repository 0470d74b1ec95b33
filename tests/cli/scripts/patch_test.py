#!/usr/bin/env python3
"""The contact patch test (docs/verification/patch-test.md): input/patch_test.xml, two blocks
pressed by p = 1e7 Pa through a flat interface, lateral motion blocked: the exact state is a
uniform stress, a contact pressure p at every point of the interface.

- Matching faces (meshes/patch_test.geo with tet = 0: HEX8 3 x 3 on HEX8 3 x 3): node-to-face
  contact passes the patch test: every slave node's pressure is p to 1e-8 (round-off; this
  also checks the harness: load, supports, settling, pressure output).
- Non-matching faces (the committed mesh: HEX8 3 x 3 on TET4 4 x 4 triangles; and a generated
  one, HEX8 3 x 3 on 7 x 7), either face as the slave:
  - mortar ('Discretization' = mortar, dual multipliers) passes it: every slave node's dual
    pressure is p to 1e-8;
  - node to face does not pass it in general; its error, the spread (max - min) / p of the
    slave nodes' pressures, is reported, not checked.
  Every run must be static at the end (|VZ| < 1e-6 m/s) and carry the load through the contact
  (the input's check, 1e-6).
usage: patch_test.py CHOC SOURCE_DIR WORK_DIR"""
import os
import subprocess
import sys

import netCDF4
import numpy as np

choc, src, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
P = 1e7
failures = []


def run(name, mesh, swap=False, mortar=False):
    s = open(os.path.join(src, "input", "patch_test.xml")).read()
    s = s.replace('value="../meshes/patch_test.msh"', f'value="{mesh}"')
    if mortar:
        s = s.replace('<Parameter name="Slave Side Set" type="string" value="LOWER_TOP"/>',
                      '<Parameter name="Slave Side Set" type="string" value="LOWER_TOP"/>\n'
                      '<Parameter name="Discretization" type="string" value="mortar"/>')
        assert "mortar" in s
    if swap:
        s = s.replace('value="UPPER_BOTTOM"/>', 'value="@"/>').replace('value="LOWER_TOP"/>',
                                                                      'value="UPPER_BOTTOM"/>')
        s = s.replace('value="@"/>', 'value="LOWER_TOP"/>')
    path = os.path.join(work, name + ".xml")
    open(path, "w").write(s)
    out = os.path.join(work, name)
    r = subprocess.run([choc, "run", path, "-o", out], capture_output=True, text=True)
    if r.returncode != 0:  # exit 1 also when the input's force check fails
        failures.append(f"{name}: choc exited {r.returncode}: {r.stderr.strip()}")
        return None
    d = netCDF4.Dataset(os.path.join(out, "lagrange.exo"))
    names = ["".join(c.decode() for c in n if c != b"").strip() for n in d["name_nod_var"][:]]
    get = lambda f: np.asarray(d[f"vals_nod_var{names.index(f) + 1}"][-1])
    p, vz = get("CONTACT_PRESSURE"), get("VEL_Z")
    slave = p != 0
    spread = (p[slave].max() - p[slave].min()) / P
    print(f"{name}: {slave.sum()} slave nodes, pressure from {p[slave].min():.6g} to "
          f"{p[slave].max():.6g} Pa (p = {P:g}): spread {spread:.3e} of p; largest |VZ| {np.abs(vz).max():.1e} m/s")
    if not np.abs(vz).max() < 1e-6:
        failures.append(f"{name}: not static at the end")
    return spread


matching = os.path.join(work, "matching.msh")
subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "tet", "0",
                os.path.join(src, "meshes", "patch_test.geo"), "-o", matching],
               check=True, stdout=subprocess.DEVNULL)
spread = run("matching", matching)
if spread is not None and not spread <= 1e-8:
    failures.append(f"matching faces: pressure spread {spread:.3e} of p (1e-8 asked)")
committed = os.path.join(src, "meshes", "patch_test.msh")
fine = os.path.join(work, "fine.msh")
subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "k", "7",
                os.path.join(src, "meshes", "patch_test.geo"), "-o", fine],
               check=True, stdout=subprocess.DEVNULL)
for label, mesh in (("", committed), ("7x7_", fine)):
    run(f"nonmatching_{label}triangles_slave", mesh)
    run(f"nonmatching_{label}quadrilaterals_slave", mesh, swap=True)
    for swap, slave in ((False, "triangles"), (True, "quadrilaterals")):
        spread = run(f"mortar_{label}{slave}_slave", mesh, swap=swap, mortar=True)
        if spread is not None and not spread <= 1e-8:
            failures.append(f"mortar, {label}{slave} slave: pressure spread {spread:.3e} of p (1e-8 asked)")
if failures:
    sys.exit("patch_test: " + "; ".join(failures))
