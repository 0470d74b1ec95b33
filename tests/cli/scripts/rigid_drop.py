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
  - 2 ranks give the same histories to 1e-8 of their peaks.
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
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("rigid_drop: the rigid block bounces off the slab with the contact's impulse")
