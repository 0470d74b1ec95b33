#!/usr/bin/env python3
"""Coulomb friction in explicit central differences (forward increments, src/contact/
CoulombFriction::increment): the compact block (meshes/compact_block.geo, 4 x 4 x 4 HEX8, a 0.1 m
steel cube of 7.8 kg) resting on a rigid plane, sliding along x at v0 = 1 m/s, pressed by a
pressure on its upper face ramped to 3.9e5 Pa (N = 3,900 N) over T = 1 ms, mu = 0.2. Its
deceleration a(t) = A min(t / T, 1), A = mu N / m = 100 m/s2, stops it at t_s = T + v(T) / A =
10.5 ms after x_s = v0 T - A T^2 / 6 + v(T)^2 / (2 A) = 5.4958 mm, v(T) = v0 - A T / 2.
Checked, by central differences (Lagrange contact, forward increments):
  - the upper corner's final x within 1 % of x_s (the block's elastic shear under the friction
    force moves it by 1e-7 m), and over the last millisecond it moves by less than 1e-3 of x_s
    (it sticks once stopped; its elastic vibration is 1e-7 m);
  - the friction work within 1 % of the initial kinetic energy less the strain energy the
    pressure leaves (the block at rest);
  - the energy balance at or below +0.1 % of the initial kinetic energy at every row;
  - the same run by the implicit scheme (average acceleration, the implicit friction law) moves
    the corner and dissipates the same work within 1 %;
  - on 2 ranks, the explicit histories equal the 1-rank ones to 1e-8 of their peaks.
(Restart bit for bit: restart.explicit_friction.)
usage: explicit_friction.py CHOC SOURCE_DIR WORK_DIR"""
import os
import subprocess
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
mesh = os.path.join(work, "block_4.msh")
subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "n", "4",
                os.path.join(src, "meshes", "compact_block.geo"), "-o", mesh], check=True, stdout=subprocess.DEVNULL)
V0, MU, P, T, MASS = 1.0, 0.2, 3.9e5, 1e-3, 7.8
A = MU * P * 0.01 / MASS
VT = V0 - A * T / 2
X_STOP = V0 * T - A * T * T / 6 + VT * VT / (2 * A)
END = 0.012
AN = "Analyses/slide"


def deck(explicit):
    """tests/restart/inputs/block_friction_explicit.xml (the scene above on 10 x 10 x 10 HEX8) on
    the 4 x 4 x 4 mesh, to END."""
    d = chocrun.load_deck(os.path.join(src, "tests", "restart", "inputs", "block_friction_explicit.xml"))
    chocrun.set_param(d, "Mesh/File", mesh)
    chocrun.set_param(d, f"{AN}/End Time", END)
    chocrun.set_param(d, f"{AN}/Exodus Interval", 0)
    for key, value in (("Contact/Pairs/floor/Friction Coefficient", MU), ("Pressures/weight/Value", P),
                       ("Pressures/weight/Ramp Time", T), ("Initial Conditions/sliding along x/Value", V0)):
        chocrun.set_param(d, f"{AN}/{key}", value)
    if not explicit:
        chocrun.set_param(d, f"{AN}/Scheme", "modified average acceleration")
    return d


def run(name, explicit, ranks=1, args=()):
    path = chocrun.write_deck(deck(explicit), os.path.join(work, name + ".xml"))
    out = os.path.join(work, name)
    chocrun.run(choc, path, out, ranks=ranks, args=args)
    chocrun.require_completed(chocrun.read_summary(out, "slide"))
    return chocrun.read_history(out, "slide")


failures = []


def within(label, value, expected, rel):
    err = abs(value - expected) / abs(expected)
    print(f"{label}: {value:.6g} against {expected:.6g} ({err:.2e})")
    if not err <= rel:
        failures.append(f"{label}: {value:.6g} against {expected:.6g}, {err:.2e} apart (at most {rel:g})")


ex = run("explicit", True)
e0 = 0.5 * MASS * V0 * V0
within("explicit: final corner:DX against x_s", ex["corner:DX"][-1], X_STOP, 1e-2)
# Stopped, it sticks: over the last millisecond the corner vibrates elastically (the stop excites
# the block's modes) but does not creep, by less than 1e-3 of the distance slid.
late = ex["time"] >= END - 1e-3
creep = np.ptp(ex["corner:DX"][late])
print(f"explicit: the corner moves by {creep:.2e} m over the last millisecond")
if not creep <= 1e-3 * X_STOP:
    failures.append(f"explicit: the block still moves by {creep:.2e} m over the last millisecond after it stopped")
work_ex = ex["floor:friction_work"][-1]
within("explicit: friction work against the kinetic energy less the strain energy left",
       work_ex, e0 - ex["energy:strain"][-1], 1e-2)
balance = np.max(ex["energy:balance"])
print(f"explicit: largest energy balance {balance:.3e} J ({balance / e0:.2e} of E0)")
if not balance <= 1e-3 * e0:
    failures.append(f"explicit: the energy balance reaches {balance:.3e} J, above +0.1 % of E0 = {e0:.3g} J")
im = run("implicit", False)
within("implicit against explicit: final corner:DX", ex["corner:DX"][-1], im["corner:DX"][-1], 1e-2)
within("implicit against explicit: friction work", work_ex, im["floor:friction_work"][-1], 1e-2)
np2 = run("explicit_np2", True, ranks=2)
for c in ("corner:DX", "corner:VX", "floor:tangential_force", "floor:friction_work", "energy:kinetic"):
    peak = np.max(np.abs(ex[c]))
    rel = np.max(np.abs(np2[c] - ex[c])) / peak if peak > 0 else 0.0
    if not rel <= 1e-8:
        failures.append(f"2 ranks: {c} differs by {rel:.2e} of its peak (at most 1e-8)")
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("explicit_friction: forward-increment friction stops the block where Coulomb's law does")
