#!/usr/bin/env python3
"""A tumbling free body (BENCHMARKS.md section 14): a free steel cube (meshes/compact_block.geo,
side a = 0.1 m, 2 x 2 x 2 HEX8, neo-Hookean with E = 200 GPa, nu = 0.3) given a rigid spin of
omega = 1000 rad/s about the vertical axis through its centre (Initial Conditions 'Rigid
Velocity'), no contact, no damping, turning ten times (T = 20 pi / omega = 62.8 ms), by central
differences (lumped mass, dt = 5 us) and by average acceleration (omega dt = 0.02).

Exact: the body turns rigidly but for the centrifugal stretch, whose strain is of the order of
eps = rho omega^2 a^2 / E = 3.9e-4 (twice that at most, oscillating about the steady stretch
from a rigid start). Checked, with the tolerances that follows from eps:
  - the corner (0, 0, a) stays at its distance r0 = a / sqrt(2) from the spin axis to 2 eps;
  - its angle about the axis follows omega t to 4 eps of the angle turned Theta (the angular
    momentum I omega is constant, and I grows with the stretch by at most 4 eps) plus twice the
    schemes' phase error, Theta (omega dt)^2 / 12 (second-order schemes on a rotation);
  - the energy balance stays at or below +1e-4 E0 (no scheme creates energy) and above
    -2 (omega dt)^2 E0: average acceleration and central differences damp nothing, but their
    energy errs by O((omega dt)^2) on a rotation (measured: (omega dt)^2 E0 for both);
  - numbering invariance: the explicit run on the mesh with its nodes numbered backwards gives
    the same corner motion to 1e-9 a;
  - frame invariance: the explicit run with the cube, its spin axis and centre turned as a whole
    (R: 0.7 rad about (0.3, -0.5, 0.81)) gives R times the corner's motion to 1e-9 a;
  - HHT and generalized-alpha (their defaults) create no energy either: balance at most
    +1e-4 E0, its dissipation reported;
  - 2 ranks give 1 rank's histories: the corner's displacements to 1e-9 a, the kinetic energy to
    1e-9 of its value (Newton's tolerance, 1e-10 of the forces, for the implicit run);
  - central differences (velocity Verlet, with the integer-step velocities it writes) conserve
    the linear momentum and the angular momentum about the centre of mass exactly for forces
    derived from a frame-invariant energy: both to 1e-8 of m r0 omega and I omega (from the
    Exodus file's positions and velocities and the lumped masses, m_e / 8 per node of each
    cube element); average acceleration's angular momentum is reported; the history's own
    block:LZ (choc's M v about the centre of mass) equals that Exodus-based value to 1e-12;
  - the explicit run's Exodus file holds the Cauchy stress and the strain-energy density of each
    element (element variables SIGMA_XX ... STRAIN_ENERGY_DENSITY): the density times the
    element volume, summed, is the history's strain energy at the same time (to 1e-9 of it:
    the same integral, averaged and multiplied back), and 2 ranks write 1 rank's values to 1e-9
    of the largest;
  - 'Strain' = 'small' (linear elastic) on the same deck fails the first check by orders of
    magnitude: a small-strain body given a spin moves each point along its initial velocity
    (r = r0 sqrt(1 + (omega t)^2)); that is why large rotations need 'Strain' = 'finite'. choc
    says so itself: the run stops (exit 2) past a rotation of 0.5 rad (here at the check of step
    100, a quarter of the way), naming the element and the rotation (the small-strain domain,
    docs/user-guide/errors.md).
usage: tumbling_block.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import sys

import netCDF4
import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

A, RHO, E, OMEGA = 0.1, 7800.0, 2e11, 1000.0
EPS = RHO * OMEGA ** 2 * A ** 2 / E
TURNS = 10
END = TURNS * 2 * math.pi / OMEGA
os.makedirs(work, exist_ok=True)
mesh = chocrun.gmsh_mesh("compact_block.geo", os.path.join(work, "cube.msh"), order=1, n=2)


def rotation(angle=0.7, axis=(0.3, -0.5, 0.81)):
    return chocrun.rotation_matrix(angle, axis)


def deck(scheme, dt, strain="finite", law="neo-Hookean", end=END, exodus=0, R=None):
    R = np.eye(3) if R is None else R
    omega, centre = R @ np.array([0, 0, OMEGA]), R @ np.array([A / 2, A / 2, A / 2])
    msh = mesh if R is None or np.allclose(R, np.eye(3)) else chocrun.turned_mesh(mesh, os.path.join(work, "cube_turned.msh"), R)
    return chocrun.spin_deck(msh, "block", omega, centre, scheme, dt, end, strain, law, E=E, rho=RHO,
                             history="corner:DX corner:DY corner:DZ block:PX block:PY block:LZ", exodus=exodus)


def write(name, text):
    return chocrun.write_text(os.path.join(work, name + ".xml"), text)


failures = []


def corner_motion(h):
    """The corner's distance from the spin axis over r0, and its angle turned (unwrapped)."""
    x = 0.0 + h["corner:DX"] - A / 2
    y = 0.0 + h["corner:DY"] - A / 2
    r0 = A / math.sqrt(2)
    angle = np.unwrap(np.arctan2(y, x)) - math.atan2(-A / 2, -A / 2)
    return np.hypot(x, y) / r0, angle


def check(label, h, dt):
    ratio, angle = corner_motion(h)
    stretch = np.max(np.abs(ratio - 1))
    phase = np.max(np.abs(angle - OMEGA * h["time"]))
    theta = OMEGA * END
    phase_tol = 4 * EPS * theta + 2 * theta * (OMEGA * dt) ** 2 / 12
    energy_tol = 2 * (OMEGA * dt) ** 2
    e0 = h["energy:total"][0]
    bal = h["energy:balance"]
    print(f"{label}: corner radius within {stretch:.2e} of r0 (at most {2 * EPS:.2e}); angle within "
          f"{phase:.2e} rad of omega t (at most {phase_tol:.2e}); balance in [{bal.min() / e0:.2e}, "
          f"{bal.max() / e0:.2e}] E0; {angle[-1] / (2 * math.pi):.3f} turns")
    if not stretch <= 2 * EPS:
        failures.append(f"{label}: the corner's radius moved by {stretch:.2e} of r0 (at most {2 * EPS:.2e})")
    if not phase <= phase_tol:
        failures.append(f"{label}: the corner's angle is {phase:.2e} rad from omega t (at most {phase_tol:.2e})")
    if not (bal.max() <= 1e-4 * e0 and bal.min() >= -energy_tol * e0):
        failures.append(f"{label}: energy balance in [{bal.min() / e0:.2e}, {bal.max() / e0:.2e}] E0 "
                        f"(within [-{energy_tol:.1e}, 1e-4] E0)")
    if not angle[-1] >= (TURNS - 0.1) * 2 * math.pi:
        failures.append(f"{label}: turned {angle[-1] / (2 * math.pi):.3f} times, not {TURNS}")


def element_fields(out):
    """The Exodus element variables of the one block: names, times, values[name][step][element]."""
    with netCDF4.Dataset(os.path.join(out, "spin.exo")) as d:
        names = [str(n) for n in netCDF4.chartostring(d.variables["name_elem_var"][:])]
        times = np.array(d.variables["time_whole"][:])
        values = {n: np.array(d.variables[f"vals_elem_var{k + 1}eb1"][:]) for k, n in enumerate(names)}
    return names, times, values


def momenta(out):
    """Linear and angular momentum (about the centre of mass, z) at each Exodus time, from the
    positions, velocities and lumped masses (HEX8 cubes: m_e / 8 per node)."""
    with netCDF4.Dataset(os.path.join(out, "spin.exo")) as d:
        names = [str(n) for n in netCDF4.chartostring(d.variables["name_nod_var"][:])]
        var = lambda n: np.array(d.variables[f"vals_nod_var{names.index(n) + 1}"][:])  # noqa: E731
        X, Y = np.array(d.variables["coordx"][:]), np.array(d.variables["coordy"][:])
        times = np.array(d.variables["time_whole"][:])
        conn = np.array(d.variables["connect1"][:]) - 1
        ux, uy, vx, vy = var("DISP_X"), var("DISP_Y"), var("VEL_X"), var("VEL_Y")
    m = np.zeros(X.size)
    for element in conn:
        m[element] += RHO * (A / 2) ** 3 / 8
    x, y = X + ux, Y + uy
    M = m.sum()
    px, py = (vx * m).sum(axis=1), (vy * m).sum(axis=1)
    cx, cy = (x * m).sum(axis=1) / M, (y * m).sum(axis=1) / M
    L = (m * ((x - cx[:, None]) * vy - (y - cy[:, None]) * vx)).sum(axis=1)
    return np.hypot(px, py), L, M, times


def check_momenta(label, out, tolerance, h):
    p, L, M, times = momenta(out)
    # The history's block:LZ (M v about the centre of mass, computed by choc) at the same times:
    # the same sums over the lumped masses, to round-off (1e-12 of I omega).
    rows = [int(np.argmin(np.abs(h["time"] - t))) for t in times]
    dLh = np.max(np.abs(h["block:LZ"][rows] - L)) / abs(L[0])
    print(f"{label}: the history's block:LZ equals the Exodus file's angular momentum to {dLh:.1e} of I omega")
    if not dLh <= 1e-12:
        failures.append(f"{label}: history block:LZ differs from the Exodus angular momentum by {dLh:.1e}")
    scale_p = M * OMEGA * A / math.sqrt(2)
    dp, dL = np.max(p) / scale_p, np.max(np.abs(L - L[0])) / abs(L[0])
    print(f"{label}: linear momentum within {dp:.1e} of m r0 omega, angular momentum within {dL:.1e} of its start"
          + (f" (at most {tolerance:g})" if tolerance else " (reported)"))
    if tolerance and not (dp <= tolerance and dL <= tolerance):
        failures.append(f"{label}: momentum {dp:.1e}, angular momentum {dL:.1e} (at most {tolerance:g})")


def check_element_fields(out, out2, h):
    names, times, values = element_fields(out)
    expected = ["SIGMA_XX", "SIGMA_YY", "SIGMA_ZZ", "SIGMA_XY", "SIGMA_YZ", "SIGMA_ZX", "STRAIN_ENERGY_DENSITY"]
    if names != expected:
        failures.append(f"element variables {names}, expected {expected}")
        return
    volume = (A / 2) ** 3  # 2 x 2 x 2 equal cubes
    worst = 0.0
    for k, t in enumerate(times):
        row = int(np.argmin(np.abs(h["time"] - t)))
        strain = h["energy:strain"][row]
        total = np.sum(values["STRAIN_ENERGY_DENSITY"][k]) * volume
        worst = max(worst, abs(total - strain) / max(np.max(h["energy:strain"]), 1e-300))
    print(f"Exodus: sum of the elements' energy density x volume = the history's strain energy to {worst:.1e}")
    if not worst <= 1e-9:
        failures.append(f"Exodus strain-energy density integrates to the strain energy only to {worst:.1e}")
    _, _, values2 = element_fields(out2)
    for n in expected:
        diff = np.max(np.abs(values2[n] - values[n])) / max(np.max(np.abs(values[n])), 1e-300)
        if not diff <= 1e-9:
            failures.append(f"Exodus {n}: 2 ranks differ from 1 by {diff:.1e} of its largest value")


runs = {"explicit": ("central differences", 5e-6), "implicit": ("average acceleration", 0.02 / OMEGA)}
for label, (scheme, dt) in runs.items():
    out = os.path.join(work, label)
    chocrun.run(choc, write(label, deck(scheme, dt, exodus=1000 if label == "explicit" else 250)), out)
    h = chocrun.read_history(out, "spin")
    check(label, h, dt)
    out2 = out + "_np2"
    chocrun.run(choc, os.path.join(work, label + ".xml"), out2, ranks=2)
    h2 = chocrun.read_history(out2, "spin")
    worst = 0.0
    for c in ("corner:DX", "corner:DY", "corner:DZ", "energy:kinetic", "block:LZ"):
        scale = np.max(np.abs(h[c])) if c.startswith(("energy", "block")) else A
        rel = np.max(np.abs(h2[c] - h[c])) / scale
        worst = max(worst, rel)
        if not rel <= 1e-9:
            failures.append(f"{label}: 2 ranks: {c} differs by {rel:.1e} of its scale (at most 1e-9)")
    print(f"{label}: 2 ranks equal 1 rank's histories to {worst:.1e}")
    check_momenta(label, out, 1e-8 if label == "explicit" else None, h)
    if label == "explicit":
        check_element_fields(out, out2, h)

# Frame invariance: the explicit run turned as a whole.
R = rotation()
out = os.path.join(work, "turned")
chocrun.run(choc, write("turned", deck("central differences", 5e-6, R=R)), out)
ht, h = chocrun.read_history(out, "spin"), chocrun.read_history(os.path.join(work, "explicit"), "spin")
u = np.vstack([h[f"corner:D{c}"] for c in "XYZ"])
ut = R.T @ np.vstack([ht[f"corner:D{c}"] for c in "XYZ"])
frame = np.max(np.abs(ut - u)) / A
print(f"turned by 0.7 rad: R^T times the corner's motion equals the unturned one to {frame:.1e} a")
if not frame <= 1e-9:
    failures.append(f"frame invariance: the turned run's corner motion differs by {frame:.1e} a (at most 1e-9)")

# Numbering invariance: the explicit run with the nodes numbered backwards.
renumbered = chocrun.renumbered_mesh(mesh, os.path.join(work, "cube_renumbered.msh"))
text = deck("central differences", 5e-6).replace(f'value="{mesh}"', f'value="{renumbered}"')
out = os.path.join(work, "renumbered")
chocrun.run(choc, write("renumbered", text), out)
hr = chocrun.read_history(out, "spin")
numbering = max(np.max(np.abs(hr[f"corner:D{c}"] - h[f"corner:D{c}"])) for c in "XYZ") / A
print(f"nodes numbered backwards: the corner's motion equals the original's to {numbering:.1e} a")
if not numbering <= 1e-9:
    failures.append(f"numbering invariance: the corner's motion differs by {numbering:.1e} a (at most 1e-9)")

# The dissipative presets: their energy balance is reported (negative by design) and must not
# show energy created (at most +1e-4 E0).
for scheme in ("HHT", "generalized-alpha"):
    label = scheme.replace(" ", "_")
    out = os.path.join(work, label)
    chocrun.run(choc, write(label, deck(scheme, 0.02 / OMEGA)), out)
    h = chocrun.read_history(out, "spin")
    e0, bal = h["energy:total"][0], h["energy:balance"]
    print(f"{scheme}: energy balance in [{bal.min() / e0:.2e}, {bal.max() / e0:.2e}] E0 over ten turns")
    if not bal.max() <= 1e-4 * e0:
        failures.append(f"{scheme}: energy balance reaches {bal.max() / e0:.2e} E0 (created)")

# Small strain: a quarter turn is enough to show it.
out = os.path.join(work, "small")
small = chocrun.run(choc, write("small", deck("central differences", 5e-6, "small", "linear elastic", END / 40)), out,
                    ok=(2,))
if not ("a rotation of" in small.stderr and "past the small-strain limit (0.5)" in small.stderr):
    failures.append("small strain: no stop past 0.5 rad:\n" + small.stdout[-2000:] + small.stderr)
ratio, _ = corner_motion(chocrun.read_history(os.path.join(out, "spin.history.incomplete.csv")))
print(f"small strain after a quarter turn: the corner is at {ratio[-1]:.3f} r0 (exact: 1 + O(eps))")
if not ratio[-1] > 1 + 100 * EPS:
    failures.append(f"small strain kept the corner at {ratio[-1]} r0: the test cannot tell the kinematics apart")

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("tumbling block: OK")
