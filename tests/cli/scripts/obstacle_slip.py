#!/usr/bin/env python3
"""A rigid plane sliding under SDNV100's bar: the wall of input/sdnv100.xml given a
tangential velocity of 1 m/s along x. The bar cannot move along x (only DZ is free), so every
contact node slips by exactly v t relative to the wall (CONTACT_SLIP = 1.4e-4 m at 1.4e-4 s,
and 0 off the contact face), and the normal contact is unchanged: the deck's 39 rows still
pass (exit 0). usage: obstacle_slip.py CHOC SOURCE_DIR WORK_DIR"""
import os
import subprocess
import sys

import netCDF4
import numpy as np

choc, src, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
deck = open(os.path.join(src, "input", "sdnv100.xml")).read()
deck = deck.replace('value="../meshes/', f'value="{src}/meshes/')
normal = '<Parameter name="Normal" type="string" value="0 0 1"/>'
assert deck.count(normal) == 3
deck = deck.replace(normal, normal + '<Parameter name="Velocity" type="string" value="1 0 0"/>')
path = os.path.join(work, "sliding_wall.xml")
open(path, "w").write(deck)
run = subprocess.run([choc, "run", path, "-o", os.path.join(work, "out")], capture_output=True, text=True)
if run.returncode != 0:
    sys.exit(f"obstacle_slip: choc exited {run.returncode}: {run.stderr.strip()}")
failures = []
for name in ("a_penalty", "c_continuous", "lagrange"):
    d = netCDF4.Dataset(os.path.join(work, "out", f"{name}.exo"))
    names = ["".join(c.decode() for c in n if c != b"").strip() for n in d["name_nod_var"][:]]
    slip = np.asarray(d[f"vals_nod_var{names.index('CONTACT_SLIP') + 1}"][-1])
    t = float(d["time_whole"][-1])
    face = np.abs(np.asarray(d["coordz"][:])) < 1e-12
    err = np.abs(slip[face] - t).max() / t
    print(f"{name}: slip of the {face.sum()} contact nodes at t = {t:g} s: {slip[face]} "
          f"(relative error {err:.1e}); off the face: {np.abs(slip[~face]).max()}")
    if not (face.sum() == 4 and err <= 1e-12 and np.abs(slip[~face]).max() == 0.0):
        failures.append(name)
if failures:
    sys.exit("obstacle_slip: wrong CONTACT_SLIP in " + ", ".join(failures))
