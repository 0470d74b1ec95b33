#!/usr/bin/env python3
"""The spin of the oblique sphere (input/oblique_sphere.xml: a steel sphere, R = 10 mm, hitting a
rigid plane at 5 m/s, Coulomb friction mu = 0.1, sliding throughout) with finite strain, at 60
and 45 degrees from the normal (docs/verification/oblique-spin.md).

Rigid-body Coulomb impact, sliding throughout: the tangential impulse is mu J_n, applied at the
contact point a distance R below the centre, so the angular momentum about the centre of mass
after the impact is L = -mu J_n R about z (omega R = 2.5 mu (1 + e) v_n for a uniform sphere:
I = 0.4 m R^2, J_n = m (1 + e) v_n). The measured normal impulse J_n (the history's plane:force
integrated) stands for m (1 + e) v_n, and the angular momentum is the history's SPHERE:LZ
(M v about the centre of mass, observers/SetMomentum.hpp), so neither the restitution nor the
mesh's moment of inertia enters the comparison.

The closed form is a rigid body's: it leaves out terms of the order of the sphere's approach
delta / R, the lever arm of the friction force being R - delta(t) (the centre's height above the
plane) and the normal pressure's centre moving off the vertical through the centre (the
tangential traction shifts it on an elastic body). Checked, for 'Strain' = 'finite'
(neo-Hookean, the same E and nu):
  - at 5 m/s, 60 and 45 degrees (delta_max / R = 0.37 % and 0.48 %): the angular momentum after
    the impact departs from -mu J_n R by at most 2 delta_max / R, delta_max the centre of mass's
    largest approach in the run (from SPHERE:PY); and by less than half the small-strain run's
    departure at 60 degrees (which is reported: the small-strain normal force acts on the
    reference positions of points that have moved);
  - at 1 m/s, 60 degrees (delta_max / R = 0.1 %, where the closed form's rigid body holds to that
    order): within 0.2 % of -mu J_n R (the phase's issue's tolerance);
  - L_z is constant after the impact (no external moment): its spread over the last 10 steps
    within 1e-6 of it (small strain's, whose internal forces do not conserve L, is reported).
usage: oblique_spin.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
src = os.path.abspath(src)
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

MU, R, V = 0.1, 0.01, 5.0
os.makedirs(work, exist_ok=True)
failures = []


def run(angle, strain, speed=V, end=None):
    d = chocrun.load_deck(os.path.join(src, "input", "oblique_sphere.xml"))
    a = "Analyses/oblique"
    chocrun.set_param(d, a + "/Exodus Interval", 0)
    chocrun.set_param(d, a + "/History", "C:VX C:VY SPHERE:PX SPHERE:PY SPHERE:LZ")
    if end:
        chocrun.set_param(d, a + "/End Time", end)
    ic = chocrun.sublists(d, a + "/Initial Conditions")
    vx, vy = speed * math.sin(math.radians(angle)), -speed * math.cos(math.radians(angle))
    for name, value in zip(ic, (vx, vy)):  # along x, then down y
        chocrun.set_param(d, f"{a}/Initial Conditions/{name}/Value", value)
    if strain == "finite":
        chocrun.set_param(d, "Model/Blocks/SPHERE/Strain", "finite", create=True)
        chocrun.set_param(d, "Model/Materials/steel/Model", "neo-Hookean", create=True)
    label = f"{strain}_{angle}_v{speed:g}"
    out = os.path.join(work, label)
    r = chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, label + ".xml")), out)
    chocrun.require_completed(chocrun.read_summary(out, "oblique"))
    h = chocrun.read_history(out, "oblique")
    t = h["time"]
    jn, jt = np.trapz(h["plane:force"], t), np.trapz(h["plane:tangential_force"], t)
    last = h["SPHERE:LZ"][-10:]
    lz = float(np.mean(last))
    ref = -MU * jn * R
    spread = float(np.max(last) - np.min(last)) / abs(lz)
    # The centre of mass's height above the plane, from its velocity P_y / m.
    m = h["SPHERE:PY"][0] / vy
    vc = h["SPHERE:PY"] / m
    height = R + np.concatenate([[0.0], np.cumsum(0.5 * (vc[1:] + vc[:-1]) * np.diff(t))])
    approach = (R - float(np.min(height))) / R
    print(f"{label}: {r.wall:.0f} s; J_n = {jn:.6e} N s, J_t / J_n = {jt / jn:.6f}, largest approach "
          f"{100 * approach:.3f} % of R; L_z = {lz:.6e} kg m2/s against -mu J_n R = {ref:.6e}: "
          f"{100 * (lz / ref - 1):+.3f} %; L_z spread after the impact {spread:.1e}")
    if strain == "finite" and not spread <= 1e-6:  # small strain does not conserve L: reported
        failures.append(f"{label}: L_z varies by {spread:.1e} after the impact (at most 1e-6)")
    return lz / ref - 1, approach


small, _ = run(60, "small")
for angle in (60, 45):
    err, approach = run(angle, "finite")
    if not abs(err) <= 2 * approach:
        failures.append(f"finite strain at {angle} degrees: spin {100 * err:+.3f} % from the closed form "
                        f"(at most 2 delta_max / R = {200 * approach:.3f} %)")
    if angle == 60 and not abs(err) < abs(small) / 2:
        failures.append(f"finite strain at 60 degrees: {100 * err:+.3f} %, not below half the small strain's "
                        f"{100 * small:+.3f} %")
err, approach = run(60, "finite", speed=1.0, end=9e-5)
if not abs(err) <= 2e-3:
    failures.append(f"finite strain at 1 m/s: spin {100 * err:+.3f} % from the closed form (at most 0.2 %)")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("oblique sphere's spin: OK")
