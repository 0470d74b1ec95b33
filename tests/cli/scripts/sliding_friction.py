#!/usr/bin/env python3
"""Coulomb friction in a contact pair, on input/sliding_friction.xml (the block of
input/sliding.xml leaving at 10 m/s with mu = 0.01, pressed by 6,400 N; it stops after 0.078 m at
15.6 ms) and input/sliding.xml:

1. The Coulomb law at every node: at every Exodus frame a sliding node (CONTACT_STATUS 2) has a
   tangential traction of mu times its pressure (1e-9: the return onto the cone), a sticking
   node (1) at most that; nodes slide while the block moves (t < 15 ms) and all stick once it
   has stopped (t > 16 ms).
2. The energy: the balance never above +1e-3 of E0 (friction dissipates) and the friction work
   of the run mu N d to 0.5 % (also a regression row); Newton averages <= 2.5 iterations a step.
   Both hold also with the foundation pair in mortar (the input's rows too).
3. The limit mu -> 0: input/sliding.xml with mu = 1e-12 (every friction term computed, the matrix
   graph with every component) gives the frictionless motion and contact force to 1e-8 of their
   peaks; the friction's own effect, mu N t^2 / 2m = 4e-12 m, is far below that.
usage: sliding_friction.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import sys

import netCDF4
import numpy as np

from deck_run import run_deck

choc, src, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
MU = 0.01
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(name, deck_file, edit=lambda s: s):
    return run_deck(choc, src, work, deck_file, name, edit, "sliding_friction")


def history(out, analysis):
    return np.genfromtxt(os.path.join(out, f"{analysis}.history.csv"), delimiter=",", names=True)


# 1 and 2: the friction scene, both analyses; and the Lagrange analysis with a mortar pair.
SLAVE = '<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>'
mortar = lambda s: s.replace(SLAVE, SLAVE + '<Parameter name="Discretization" type="string" value="mortar"/>', 1)
for name, edit, analysis in (("friction", None, "lagrange"), ("friction", None, "penalty"),
                             ("friction_mortar", mortar, "lagrange")):
    if edit is not None or analysis == "lagrange":
        out, log = run(name, "sliding_friction.xml", edit or (lambda s: s))
    label = analysis + (" (mortar)" if edit else "")
    with netCDF4.Dataset(os.path.join(out, f"{analysis}.exo")) as d:
        names = ["".join(c.decode() for c in n if c != b"").strip() for n in d["name_nod_var"][:]]
        get = lambda f: np.asarray(d[f"vals_nod_var{names.index(f) + 1}"][:])
        times = np.asarray(d["time_whole"][:])
        status, p, q = get("CONTACT_STATUS"), get("CONTACT_PRESSURE"), get("CONTACT_TANGENTIAL_TRACTION")
    cone_err, over, sliding, stuck = 0.0, 0.0, [], []
    for k, t in enumerate(times):
        slide, stick = status[k] == 2, status[k] == 1
        if slide.any():
            cone_err = max(cone_err, np.abs(q[k][slide] - MU * p[k][slide]).max() / (MU * p[k][slide]).max())
        if stick.any():
            over = max(over, (q[k][stick] - MU * p[k][stick]).max() / (MU * np.abs(p[k]).max()))
        if 0 < t < 0.015:
            sliding.append(slide.sum() > 0 and stick.sum() == 0)
        if t > 0.016:
            stuck.append(stick.sum() == 28)
    check(cone_err <= 1e-9, f"{label}: sliding nodes' traction = mu p to {cone_err:.1e}")
    check(over <= 1e-9, f"{label}: sticking nodes' traction <= mu p (excess {over:.1e} of mu p)")
    check(all(sliding) and sliding, f"{label}: every contact node slides while the block moves "
          f"({sum(sliding)} of {len(sliding)} frames)")
    check(all(stuck) and stuck, f"{label}: all 28 nodes stick once it has stopped "
          f"({sum(stuck)} of {len(stuck)} frames)")
    h = history(out, analysis)
    growth = h["energybalance"].max() / h["energytotal"][0]
    check(growth <= 1e-3, f"{label}: largest energy balance {growth:+.2e} of E0")
    block = log[log.index(f"analysis '{analysis}'"):]
    m = re.search(r"\(([\d.]+) per step", block)
    check(m and float(m.group(1)) <= 2.5, f"{label}: {m.group(1) if m else '?'} Newton iterations per step")

# 3: mu -> 0 against the frictionless run.
with_mu = lambda s: s.replace('<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>',
                              '<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>\n'
                              '            <Parameter name="Friction Coefficient" type="double" value="1e-12"/>')
out0, _ = run("frictionless", "sliding.xml")
out1, log1 = run("mu_1e-12", "sliding.xml", with_mu)
check("Coulomb friction" in log1, "the mu = 1e-12 run has friction (its log says so)")
h0, h1 = history(out0, "lagrange"), history(out1, "lagrange")
check(h1["slidefriction_work"][-1] > 0, f"mu = 1e-12: friction work {h1['slidefriction_work'][-1]:.2e} J > 0")
for column in ("BLOCK_TOP_CORNERDX", "BLOCK_TOP_CORNERDZ", "slideforce"):
    diff = np.abs(h1[column] - h0[column]).max() / np.abs(h0[column]).max()
    check(diff <= 1e-8, f"mu = 1e-12 against no friction: {column} within {diff:.1e} of its peak")

if failures:
    sys.exit("sliding_friction: " + "; ".join(failures))
print("sliding_friction: all checks hold")
