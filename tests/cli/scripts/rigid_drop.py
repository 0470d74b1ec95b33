#!/usr/bin/env python3
"""A rigid block dropped on a deformable slab (input/block_on_slab.xml's scene, the 0.1 m cube
declared rigid, the slab neo-Hookean in finite strain, frictionless penalty contact, central
differences sub-stepped, 20 us): a rigid body next to finite-strain elements, moved by contact.
Checked:
  - the run completes with one impact and creates no energy beyond 1e-3 E0 (penalty contact at
    0.15 of the critical step);
  - the block's momentum change (its history column block:PZ) equals the contact's total impulse
    in the impact statistics to 1e-5 of it: the only force on it is the contact's, both are
    second-order quadratures of it over the sub-steps (h / t_contact = 6.7e-8 / 2e-5, squared 1e-5);
  - the block bounces (its momentum changes sign); its rotation is printed (1.4e-8 rad: the
    node-to-face pairing's ties on the face edges are not symmetric, so the moment is not 0);
  - 2 ranks give the same histories to 1e-8 of their peaks;
and the block dropped tilted, turning at (15, 5, 0) rad/s about its centre, with exactly enforced
contact (Lagrange: forward increments whose pressures move the body, the rigid block the slave
side): a corner strikes first and the block leaves turning the other way; its momentum change
is the contact's impulse (1e-5, as above), its angular momentum about the origin changes by the
integral of x_c x F + M (the resultant and the moment about the centre in its history; the
trapezoidal rule on the steps is the velocity-Verlet kicks' quadrature: 1e-9, round-off), it
creates no energy (the balance ends below 0, never above 1e-3 E0), 2 ranks agree (1e-8), and
the scene turned by 0.9 rad and renumbered gives the same energy and the turned angular velocity
(1e-8: the pressures converge to 1e-12 of the gaps in another sweep order; a lever arm or inertia
in the wrong frame would be off by its whole size).
usage: rigid_drop.py CHOC SOURCE_DIR WORK_DIR"""
import csv
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
failures = []

d = chocrun.load_deck(os.path.join(src, "input", "block_on_slab.xml"))
chocrun.set_param(d, "Mesh/File", os.path.abspath(os.path.join(src, "meshes", "block_on_slab.msh")))
chocrun.set_params(d, {"Model/Blocks/block/Rigid": True, "Model/Blocks/slab/Strain": "finite",
                       "Model/Blocks/slab/Mass": "lumped", "Model/Materials/steel/Model": "neo-Hookean",
                       "Analyses/drop/Scheme": "central differences", "Analyses/drop/Stability Check": "substep"},
                   create=True)
chocrun.set_param(d, "Analyses/drop/Time Step", 2e-7)
chocrun.set_param(d, "Analyses/drop/Contact/Method", "Penalty")
chocrun.set_param(d, "Analyses/drop/Contact/Pairs/floor/Friction Coefficient", 0.0)
deck = chocrun.write_deck(d, os.path.join(work, "rigid_drop.xml"))


def run(ranks):
    out = os.path.join(work, f"np{ranks}")
    chocrun.run(choc, deck, out, ranks=ranks)
    chocrun.require_completed(chocrun.read_summary(out, "drop"))
    with open(os.path.join(out, "drop.impacts.csv")) as f:
        impacts = list(csv.DictReader(f))
    return chocrun.read_history(out, "drop"), impacts


h, impacts = run(1)
if len(impacts) != 1:
    failures.append(f"{len(impacts)} impacts of the block (one expected)")
created = max(h["energy:balance"]) / h["energy:total"][0]
print(f"energy created: {created:.2e} E0")
if not created <= 1e-3:
    failures.append(f"energy created {created:.2e} E0 (at most 1e-3)")
P = np.asarray(h["block:PZ"])
impulse = float(impacts[0]["impulse"]) if impacts else float("nan")
change = P[-1] - P[0]
print(f"block momentum {P[0]:.6f} -> {P[-1]:.6f} N s: change {change:.9f}, contact impulse {impulse:.9f}")
if not abs(change - impulse) <= 1e-5 * impulse:
    failures.append(f"momentum change {change:.9f} N s against the contact impulse {impulse:.9f} (1e-5 of it)")
if not (P[0] < 0 < P[-1]):
    failures.append(f"the block did not bounce: momentum {P[0]} -> {P[-1]} N s")
turn = max(np.max(np.abs(h[f"block:R{c}"])) for c in "XYZ")
print(f"largest rotation {turn:.1e} rad")
h2, _ = run(2)
for c in ("block:Z", "block:VZ", "block:FZ", "corner:DZ", "energy:total"):
    peak = np.max(np.abs(h[c]))
    rel = np.max(np.abs(np.asarray(h[c]) - np.asarray(h2[c]))) / peak
    if not rel <= 1e-8:
        failures.append(f"{c}: 2 ranks differ by {rel:.2e} of the peak (at most 1e-8)")
# Tilted, Lagrange.
with open(deck) as f:
    text = f.read()
falling = """<Parameter name="Field" type="string" value="Velocity" />
          <Parameter name="Components" type="string" value="DZ" />
          <Parameter name="Value" type="double" value="-1" />"""
if falling not in text:
    sys.exit("FAILED: rigid_drop.py: the deck's initial velocity is not the expected text")
text = text.replace(falling, """<Parameter name="Field" type="string" value="Rigid Velocity" />
          <Parameter name="Translation" type="string" value="0 0 -1" />
          <Parameter name="Angular Velocity" type="string" value="15 5 0" />
          <Parameter name="Centre" type="string" value="0.05 0.05 0.05" />""")
text = text.replace('<Parameter name="Method" type="string" value="Penalty" />',
                    '<Parameter name="Method" type="string" value="Lagrange" />')
deck = chocrun.write_text(os.path.join(work, "rigid_drop_tilted.xml"), text)


def run_tilted(ranks):
    out = os.path.join(work, f"tilted_np{ranks}")
    chocrun.run(choc, deck, out, ranks=ranks)
    chocrun.require_completed(chocrun.read_summary(out, "drop"))
    with open(os.path.join(out, "drop.impacts.csv")) as f:
        return chocrun.read_history(out, "drop"), list(csv.DictReader(f))


h, impacts = run_tilted(1)
P = np.asarray(h["block:PZ"])
impulse = sum(float(i["impulse"]) for i in impacts)
print(f"tilted, Lagrange: momentum change {P[-1] - P[0]:.9f} N s, contact impulse {impulse:.9f} N s; "
      f"w {h['block:WX'][0]:.1f} {h['block:WY'][0]:.1f} -> {h['block:WX'][-1]:.2f} {h['block:WY'][-1]:.2f} rad/s")
if not abs(P[-1] - P[0] - impulse) <= 1e-5 * impulse:
    failures.append(f"tilted: momentum change {P[-1] - P[0]:.9f} N s against the impulse {impulse:.9f}")
if not h["block:WX"][-1] < 0 < h["block:WX"][0]:
    failures.append("tilted: the block did not leave turning the other way about x")
col = lambda *names: np.stack([np.asarray(h[n]) for n in names], 1)  # noqa: E731
torque = np.cross(col("block:X", "block:Y", "block:Z"), col("block:FX", "block:FY", "block:FZ")) + \
    col("block:MX", "block:MY", "block:MZ")
L = col("block:LX", "block:LY", "block:LZ")
dL, integral = L[-1] - L[0], np.trapz(torque, h["time"], axis=0)
rel = np.linalg.norm(dL - integral) / np.linalg.norm(dL)
print(f"  angular momentum change {dL} against the moment's integral: {rel:.1e}")
if not rel <= 1e-9:
    failures.append(f"tilted: angular momentum change differs from the moment's integral by {rel:.1e} (1e-9)")
chocrun.check_no_energy_created(h, "tilted", failures)
E0 = h["energy:total"][0]
# The tilted scene turned as a whole and renumbered (BENCHMARKS section 8).
Q = chocrun.rotation_matrix(0.9, (2.0, -1.0, 0.5))
msh = chocrun.renumbered_mesh(os.path.join(src, "meshes", "block_on_slab.msh"), os.path.join(work, "renumbered.msh"))
msh = chocrun.turned_mesh(msh, os.path.join(work, "turned.msh"), Q)
vec = lambda v: " ".join(repr(float(x)) for x in Q @ np.asarray(v))  # noqa: E731
turned = text.replace('value="0 0 -1"', f'value="{vec((0, 0, -1))}"', 1)
turned = turned.replace('value="15 5 0"', f'value="{vec((15, 5, 0))}"', 1)
turned = turned.replace('value="0.05 0.05 0.05"', f'value="{vec((0.05, 0.05, 0.05))}"', 1)
turned = turned.replace(os.path.abspath(os.path.join(src, "meshes", "block_on_slab.msh")), msh)
out = os.path.join(work, "tilted_turned")
chocrun.run(choc, chocrun.write_text(out + ".xml", turned), out)
ht = chocrun.read_history(out, "drop")
energy = np.max(np.abs(np.asarray(ht["energy:total"]) - np.asarray(h["energy:total"]))) / E0
w = Q @ np.array([h[f"block:W{c}"][-1] for c in "XYZ"])
spin = np.linalg.norm(w - np.array([ht[f"block:W{c}"][-1] for c in "XYZ"])) / np.linalg.norm(w)
print(f"  turned by 0.9 rad and renumbered: energy within {energy:.1e} E0, final angular velocity the turned one "
      f"to {spin:.1e}")
if not (energy <= 1e-8 and spin <= 1e-8):
    failures.append(f"tilted, turned and renumbered: energy {energy:.1e} E0, angular velocity {spin:.1e} (1e-8 each)")
h2, _ = run_tilted(2)
chocrun.check_ranks_alike(h, h2, ["block:Z", "block:WX", "block:FZ", "energy:total"], "tilted ", failures)
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("rigid_drop: the rigid block bounces off the slab with the contact's impulse")
