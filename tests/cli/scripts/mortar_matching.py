#!/usr/bin/env python3
"""Mortar on matching meshes is node to face: with the master covering each slave
edge exactly, the dual functions' integrals give M_jm = D_j delta_jm, so each slave node is
constrained against its own master node, as node to face does. input/sdnl111c_axisymmetric.xml
on QUAD4 (meshes/sdnl111_2d.geo at order 1: LINE2 contact edges, rings weighted by 2 pi r), run
with node to face and with 'Discretization' = mortar: every history column (N1's motion, the
energies, the contact force and gap) equal to 1e-9 of its peak (the energy balance: of the
total energy's peak; the same equations, only round-off differs), and the same Newton
iterations.
usage: mortar_matching.py CHOC SOURCE_DIR WORK_DIR"""
import glob
import os
import re
import subprocess
import sys

import numpy as np

from deck_run import run_deck

choc, src, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
mesh = os.path.join(work, "quad4.msh")
subprocess.run(["gmsh", "-2", "-order", "1", "-format", "msh41", os.path.join(src, "meshes", "sdnl111_2d.geo"),
                "-o", mesh], check=True, stdout=subprocess.DEVNULL)
SLAVE = '<Parameter name="Slave Side Set" type="string" value="CNT_POU2"/>'
failures = []
logs = {}
for name in ("node_to_face", "mortar"):
    def edit(s, name=name):
        s = s.replace(f"{src}/meshes/sdnl111_2d_quad8.msh", mesh)
        return s.replace(SLAVE, SLAVE + '<Parameter name="Discretization" type="string" value="mortar"/>') \
            if name == "mortar" else s
    _, logs[name] = run_deck(choc, src, work, "sdnl111c_axisymmetric.xml", name, edit, "mortar_matching")
    deck = open(os.path.join(work, name + ".xml")).read()
    if mesh not in deck or (name == "mortar") != ('name="Discretization"' in deck):
        failures.append(f"{name}: the deck is not the one meant")
histories = sorted(glob.glob(os.path.join(work, "node_to_face", "*.history.csv")))
if not histories:
    failures.append("no history written")
for path in histories:
    a = np.genfromtxt(path, delimiter=",", names=True)
    b = np.genfromtxt(path.replace("node_to_face", "mortar"), delimiter=",", names=True)
    for column in a.dtype.names[1:]:
        # The balance is a difference of energies: its round-off is that of the total energy.
        peak = np.abs(a["energytotal" if column == "energybalance" else column]).max()
        diff = np.abs(a[column] - b[column]).max() / peak if peak > 0 else np.abs(b[column]).max()
        print(f"{os.path.basename(path)} {column}: mortar against node to face {diff:.1e} of the peak")
        if not diff <= 1e-9:
            failures.append(f"{os.path.basename(path)} {column} differs by {diff:.1e} of its peak")
newton = {k: re.findall(r"(\d+) Newton iterations", v) for k, v in logs.items()}
if newton["mortar"] != newton["node_to_face"] or not newton["mortar"]:
    failures.append(f"Newton iterations {newton['mortar']} against {newton['node_to_face']}")
if failures:
    sys.exit("mortar_matching: " + "; ".join(failures))
print("mortar_matching: mortar equals node to face on matching meshes")
