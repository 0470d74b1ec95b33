#!/usr/bin/env python3
"""Frame invariance of SDNL111's bars in true 3D at default settings: input/sdnl111c_tet10.xml's
scene (the two bars in TET10, meshes/sdnl111_3d_tet10.msh) with every component free (the
clamped face clamped in all three), Lagrange contact, and the defaults of everything else: the
contact mass (auto), the search (current: the pairs followed in the current configuration) and
the linear solver (auto), 300 steps of 1 us. Run as drawn and turned as a rigid whole by 0.7 rad
about (1, 2, 0.5): the mesh's nodes and bar 1's initial velocity turned.
Checked: the motion of A (N1) seen in the turned frame, R^T u, equals the unturned one to 1e-10 of
its peak and the contact force to 1e-10 of its peak (the same scene: only round-off differs),
with the same Newton iterations and factorisations. (The followed pairs' coefficients were
kept while no component moved by more than 1e-6, a test that depends on the frame: 6e-7 of the
peak apart; they are now compared as vectors.)
usage: bars_turned.py CHOC SOURCE_DIR WORK_DIR"""
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
AXIS, ANGLE = (1.0, 2.0, 0.5), 0.7


def rotation():
    return chocrun.rotation_matrix(ANGLE, AXIS)


def deck(mesh, velocity):
    d = chocrun.load_deck(os.path.join(src, "input", "sdnl111c_tet10.xml"))
    chocrun.keep_analyses(d, ["c1_modified"])
    a = "Analyses/c1_modified"
    chocrun.set_param(d, "Mesh/File", mesh)
    chocrun.remove_param(d, "Model/Active Components")
    chocrun.set_param(d, "Model/Dirichlet/clamped face of bar 2/Components", "DX DY DZ")
    chocrun.set_param(d, a + "/End Time", 3e-4)
    chocrun.set_param(d, a + "/Exodus Interval", 0)
    chocrun.remove_param(d, a + "/Contact Mass")
    chocrun.remove_param(d, a + "/Contact/Pairs/interface/Search")
    chocrun.remove_sublist(d, a + "/Linear Solver")
    chocrun.remove_sublist(d, a + "/Checks")
    chocrun.remove_sublist(d, a + "/Initial Conditions/bar 1 moves towards bar 2")
    for c, v in zip("XYZ", velocity):
        ic = a + f"/Initial Conditions/bar 1 velocity {c}"
        chocrun.set_param(d, ic + "/Node Set", "POU1", create=True)
        chocrun.set_param(d, ic + "/Field", "Velocity", create=True)
        chocrun.set_param(d, ic + "/Components", "D" + c, create=True)
        chocrun.set_param(d, ic + "/Value", float(v), type="double", create=True)
    chocrun.set_param(d, a + "/History", "N1:DX N1:DY N1:DZ")
    return d


R = rotation()
plain_mesh = os.path.join(src, "meshes", "sdnl111_3d_tet10.msh")
turned = os.path.join(work, "turned.msh")
chocrun.turned_mesh(plain_mesh, turned, R)
runs = {}
for name, mesh, v in (("plain", plain_mesh, np.array([0.0, 0.0, -1.0])), ("turned", turned, R @ [0.0, 0.0, -1.0])):
    out = os.path.join(work, name)
    chocrun.run(choc, chocrun.write_deck(deck(mesh, v), os.path.join(work, name + ".xml")), out)
    runs[name] = (chocrun.require_completed(chocrun.read_summary(out, "c1_modified")),
                  chocrun.read_history(out, "c1_modified"))
failures = []
(sa, a), (sb, b) = runs["plain"], runs["turned"]
ua = np.vstack([a["N1:DX"], a["N1:DY"], a["N1:DZ"]])
ub = R.T @ np.vstack([b["N1:DX"], b["N1:DY"], b["N1:DZ"]])
for label, x, y in (("A's motion", ua, ub), ("contact force", a["interface:force"], b["interface:force"])):
    rel = np.max(np.abs(x - y)) / np.max(np.abs(x))
    print(f"{label}: turned against drawn, {rel:.2e} of the peak")
    if not rel <= 1e-10:
        failures.append(f"{label}: {rel:.2e} of the peak apart (at most 1e-10)")
for key in ("newton", "factorizations"):
    va, vb = chocrun.summary_value(sa, key), chocrun.summary_value(sb, key)
    print(f"{key}: {va} and {vb}")
    if va != vb:
        failures.append(f"{key}: {va} as drawn, {vb} turned")
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("bars_turned: the turned bars move as the drawn ones")
