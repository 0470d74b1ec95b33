#!/usr/bin/env python3
"""A rigid steel box spinning near its intermediate axis (input/rigid_spin.xml; BENCHMARKS section
17), explicit central differences with the block declared rigid, through the whole run: the
initial 'Rigid Velocity' taken by the body, its nodes placed by it, its energy in the history.
Exact: the kinetic energy and |L| are constant, the box keeps its shape, and it flips about its
intermediate axis with the period T = 4 K(k) / nu (Landau and Lifshitz, section 37).
Checked, from the history of four nodes (the corner and the ends of its three edges there):
  - the edges keep their lengths and right angles to 1e-12 of the box's size (round-off of the
    placement by R, summed over the steps);
  - the kinetic energy stays within 1e-4 of E0 = 1/2 w . J w (the splitting's O((h w)^2) error
    at h w = 0.01 is 1e-4 at most; the energy balance is the same number);
  - the body-frame angular velocity from the nodes' velocities starts at the input's (1e-12),
    its component about the intermediate axis changes sign with the period T within 1e-3 (the
    splitting's O((h w)^2) period error, measured 2e-6 at h w = 0.0125 on the unit test's body);
  - the body's own history columns (box:X ... box:MZ) agree: its centre stays at the box's
    middle (to 1e-12 m: the round-off of the momentum the 135 nodes' velocities sum to, eps |w| c
    135, over the 6 s) and its force and moment are 0 (a free body, exactly), |L| is constant to round-off
    (1e-13), box:kinetic is energy:kinetic, and box:WX..WZ is the angular velocity the nodes'
    velocities give (1e-10 of |w|);
  - the same run on 2 ranks gives the same histories to 1e-9 of their peaks (the forces summed
    in another order);
  - the scene turned as a whole (mesh, angular velocity and centre by one rotation) and its
    nodes renumbered gives the same kinetic energy (1e-9 of E0) and the turned angular velocity
    and centre (1e-9 of |w| and of the box's size): BENCHMARKS section 8;
  - what rigid blocks cannot do yet is refused (exit 1, one line naming the block's 'Rigid'):
    an implicit scheme, an initial displacement of its nodes, a node fixed by a Dirichlet
    condition.
usage: rigid_spin.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
failures = []
A, B, C, RHO = 0.1, 0.2, 0.4, 7800.0
M = RHO * A * B * C
J = np.array([M * (B * B + C * C) / 12, M * (A * A + C * C) / 12, M * (A * A + B * B) / 12])  # about x, y, z edges
W0 = np.array([0.3, 10.0, 0.2])


def closed_form_period():
    """T = 4 K(k) / nu with the moments ascending (I1 < I2 < I3): z, y, x here."""
    I1, I2, I3 = J[2], J[1], J[0]
    w = np.array([W0[2], W0[1], W0[0]])
    E = 0.5 * (I1 * w[0] ** 2 + I2 * w[1] ** 2 + I3 * w[2] ** 2)
    L2 = (I1 * w[0]) ** 2 + (I2 * w[1]) ** 2 + (I3 * w[2]) ** 2
    if L2 < 2 * E * I2:  # the other side of the separatrix: the formulas with I1 and I3 exchanged
        I1, I3 = I3, I1
    nu = math.sqrt((I3 - I2) * (L2 - 2 * E * I1) / (I1 * I2 * I3))
    k2 = (I2 - I1) * (2 * E * I3 - L2) / ((I3 - I2) * (L2 - 2 * E * I1))
    a, b = 1.0, math.sqrt(1 - k2)
    while abs(a - b) > 1e-16 * a:
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    return 4 * (math.pi / (2 * a)) / nu, E


def run(ranks):
    out = os.path.join(work, f"np{ranks}")
    chocrun.run(choc, os.path.join(src, "input", "rigid_spin.xml"), out, ranks=ranks)
    chocrun.require_completed(chocrun.read_summary(out, "spin"))
    return chocrun.read_history(out, "spin")


def nodes(h, name, X):
    x = np.stack([X[0] + h[f"{name}:DX"], X[1] + h[f"{name}:DY"], X[2] + h[f"{name}:DZ"]], axis=1)
    v = np.stack([h[f"{name}:VX"], h[f"{name}:VY"], h[f"{name}:VZ"]], axis=1)
    return x, v


h = run(1)
T, E0 = closed_form_period()
x0, v0 = nodes(h, "corner", (0, 0, 0))
edges = []
for name, X, length in (("xedge", (A, 0, 0), A), ("yedge", (0, B, 0), B), ("zedge", (0, 0, C), C)):
    x, v = nodes(h, name, X)
    edges.append((x - x0, v - v0, length))
rigidity = 0.0
for d, _, length in edges:
    rigidity = max(rigidity, np.max(np.abs(np.linalg.norm(d, axis=1) - length)))
for i in range(3):
    for j in range(i + 1, 3):
        rigidity = max(rigidity, np.max(np.abs(np.sum(edges[i][0] * edges[j][0], axis=1))) / C)
print(f"edges' lengths and right angles kept to {rigidity:.2e} m")
if not rigidity <= 1e-12 * C * 10:
    failures.append(f"the box deformed by {rigidity:.2e} m (at most 1e-11)")

energy = np.asarray(h["energy:kinetic"])
drift = np.max(np.abs(energy - E0)) / E0
print(f"kinetic energy: E0 = {E0:.6f} J (closed form), history {energy[0]:.6f} J, largest change {drift:.2e} E0")
if not drift <= 1e-4:
    failures.append(f"the kinetic energy moved by {drift:.2e} E0 (at most 1e-4)")

# the angular velocity from the edges' relative velocities: v_i = w x d_i, in the body frame
# (the edges' unit vectors) w_b = (w . e_x, w . e_y, w . e_z) = ((d_y . v_z) ... ) via least squares
wb, ws = [], []
for n in range(len(energy)):
    rows, rhs = [], []
    for d, v, _ in edges:
        dn = d[n]
        rows.extend([[0, dn[2], -dn[1]], [-dn[2], 0, dn[0]], [dn[1], -dn[0], 0]])  # -[d]x w = v
        rhs.extend(v[n])
    w = np.linalg.lstsq(np.array(rows), np.array(rhs), rcond=None)[0]
    frame = np.array([e[0][n] / e[2] for e in edges])
    wb.append(frame @ w)
    ws.append(w)
wb, ws = np.array(wb), np.array(ws)

# the body's own columns
col = lambda name: np.asarray(h[f"box:{name}"])  # noqa: E731
centre = np.stack([col("X"), col("Y"), col("Z")], axis=1)
moved = np.max(np.abs(centre - np.array([A / 2, B / 2, C / 2])))
loads = max(np.max(np.abs(col(k))) for k in ("FX", "FY", "FZ", "MX", "MY", "MZ"))
L = np.linalg.norm(np.stack([col("LX"), col("LY"), col("LZ")], axis=1), axis=1)
spin = np.stack([col("WX"), col("WY"), col("WZ")], axis=1)
print(f"box columns: centre moved {moved:.1e} m, force and moment {loads:.1e}, |L| within "
      f"{np.max(np.abs(L - L[0])) / L[0]:.1e}, w against the nodes' {np.max(np.abs(spin - ws)) / np.linalg.norm(W0):.1e}")
if not moved <= 1e-12 or loads != 0.0:
    failures.append(f"the free body's centre moved by {moved:.2e} m or felt {loads:.2e} N (N m)")
if not np.max(np.abs(L - L[0])) <= 1e-13 * L[0]:
    failures.append(f"|L| changed by {np.max(np.abs(L - L[0])) / L[0]:.2e} of itself (at most 1e-13)")
if not np.max(np.abs(col("kinetic") - energy)) <= 1e-13 * E0:
    failures.append("box:kinetic differs from energy:kinetic")
if not np.max(np.abs(spin - ws)) <= 1e-10 * np.linalg.norm(W0):
    failures.append(f"box:W differs from the nodes' angular velocity by {np.max(np.abs(spin - ws)):.2e} rad/s")
start = np.max(np.abs(wb[0] - W0)) / np.linalg.norm(W0)
print(f"body-frame angular velocity at t = 0: {wb[0]} (input {W0}), difference {start:.1e}")
if not start <= 1e-12:
    failures.append(f"the body started at {wb[0]} rad/s, not the input's {W0}")
t = np.asarray(h["time"])
crossings = [t[n - 1] + (t[n] - t[n - 1]) * wb[n - 1, 1] / (wb[n - 1, 1] - wb[n, 1])
             for n in range(1, len(t)) if (wb[n - 1, 1] > 0) != (wb[n, 1] > 0)]
if len(crossings) < 3:
    failures.append(f"{len(crossings)} sign changes of the intermediate axis' spin (3 expected in 6 s)")
else:
    period = crossings[2] - crossings[0]
    error = (period - T) / T
    print(f"flip period: {period:.6f} s against the closed form {T:.6f} s ({error:+.2e})")
    if not abs(error) <= 1e-3:
        failures.append(f"flip period {period:.6f} s, {error:+.2e} from the closed form {T:.6f} s (at most 1e-3)")

h2 = run(2)
for c in [k for k in h if k.startswith(("corner", "zedge", "energy:kinetic", "box:L", "box:W"))]:
    peak = max(np.max(np.abs(h[c])), 1e-300)
    rel = np.max(np.abs(np.asarray(h[c]) - np.asarray(h2[c]))) / peak
    if not rel <= 1e-9:
        failures.append(f"{c}: 2 ranks differ by {rel:.2e} of the peak (at most 1e-9)")

Q = chocrun.rotation_matrix(0.7, (1.0, -2.0, 0.5))
msh = chocrun.renumbered_mesh(os.path.join(src, "meshes", "rigid_box.msh"), os.path.join(work, "renumbered.msh"))
msh = chocrun.turned_mesh(msh, os.path.join(work, "turned.msh"), Q)
dt = chocrun.load_deck(os.path.join(src, "input", "rigid_spin.xml"))
chocrun.set_param(dt, "Mesh/File", os.path.abspath(msh))
chocrun.set_param(dt, "Analyses/spin/Initial Conditions/spinning/Angular Velocity", " ".join(repr(x) for x in Q @ W0))
chocrun.set_param(dt, "Analyses/spin/Initial Conditions/spinning/Centre",
                  " ".join(repr(x) for x in Q @ np.array([A / 2, B / 2, C / 2])))
chocrun.set_param(dt, "Analyses/spin/History", "corner:DX")
out_t = os.path.join(work, "turned")
chocrun.run(choc, chocrun.write_deck(dt, os.path.join(work, "turned.xml")), out_t)
ht = chocrun.read_history(out_t, "spin")
e_t = np.max(np.abs(np.asarray(ht["box:kinetic"]) - np.asarray(h["box:kinetic"]))) / E0
w_t = np.stack([ht["box:WX"], ht["box:WY"], ht["box:WZ"]], axis=1)
x_t = np.stack([ht["box:X"], ht["box:Y"], ht["box:Z"]], axis=1)
w_diff = np.max(np.abs(w_t - spin @ Q.T)) / np.linalg.norm(W0)
x_diff = np.max(np.abs(x_t - centre @ Q.T)) / C
print(f"turned and renumbered: kinetic energy within {e_t:.1e} E0, w within {w_diff:.1e} of |w|, centre within {x_diff:.1e} of c")
if not (e_t <= 1e-9 and w_diff <= 1e-9 and x_diff <= 1e-9):
    failures.append(f"the turned, renumbered scene differs: energy {e_t:.2e} E0, w {w_diff:.2e}, centre {x_diff:.2e}")


def refused(name, change, words):
    d = chocrun.load_deck(os.path.join(src, "input", "rigid_spin.xml"))
    change(d)
    deck = chocrun.write_deck(d, os.path.join(work, name + ".xml"))
    r = chocrun.run(choc, deck, os.path.join(work, name), ok=None)
    lines = [ln for ln in r.stderr.strip().splitlines() if ln.strip()]
    text = " ".join(lines)
    if r.returncode != 1 or "Model/Blocks/box/Rigid" not in text or not all(w in text for w in words):
        failures.append(f"{name}: exit {r.returncode}, {text[:300]!r} (exit 1 naming Model/Blocks/box/Rigid and {words})")
    else:
        print(f"{name}: refused: {lines[-1][:160]}")


refused("implicit", lambda d: chocrun.set_param(d, "Analyses/spin/Scheme", "HHT"), ["implicit"])
refused("displaced", lambda d: chocrun.set_params(
    d, {"Analyses/spin/Initial Conditions/moved/Node Set": "corner",
        "Analyses/spin/Initial Conditions/moved/Field": "Displacement",
        "Analyses/spin/Initial Conditions/moved/Components": "DX",
        "Analyses/spin/Initial Conditions/moved/Value": 1e-3}, create=True), ["initial displacement"])
refused("fixed_node", lambda d: chocrun.set_params(
    d, {"Model/Dirichlet/held/Node Set": "corner", "Model/Dirichlet/held/Components": "DX"}, create=True), ["fixed"])
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("rigid_spin: a rigid body spins and flips as Euler's equations say")
