#!/usr/bin/env python3
"""Contact multipliers against rigid obstacles condensed out of the Newton system
(src/contact/ContactCondensation.hpp) give the saddle-point system's answer with an iterative
solver on every rank:
  - input/hertz.xml (the axisymmetric sphere on a rigid plane, nodes entering contact at every
    step; its first 100 steps): CG + Jacobi on 1 and 2 ranks against the deck's direct solve of
    the saddle-point system;
  - input/compact_block.xml (a cube's lower face on a rigid plane): CG + Multigrid on 2 ranks
    and GMRES + Jacobi on 1 against the direct solve.
Checked: each log says the pressures are condensed; the histories agree with the direct run's
to 1e-7 of each peak (each Newton iterate is held to 1e-8 of the force reference, each solve
to the solver's tolerance, the direct run's residual tolerance being 1e-8); the impacts are the
same; the sphere's contact gap is closed to 1e-10 of the centre's travel (the constrained part of
each correction is set exactly, not left to the solver's tolerance).
usage: condensed_contact.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import subprocess
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
failures = []


def run(name, deck_file, analysis, method, preconditioner=None, ranks=1, end=None):
    d = chocrun.load_deck(os.path.join(src, "input", deck_file))
    if end:
        chocrun.set_param(d, f"Analyses/{analysis}/End Time", end)
    chocrun.set_param(d, f"Analyses/{analysis}/Exodus Interval", 0, type="int", create=True)
    chocrun.set_param(d, f"Analyses/{analysis}/Linear Solver/Method", method, create=True)
    if preconditioner:
        chocrun.set_param(d, f"Analyses/{analysis}/Linear Solver/Preconditioner", preconditioner, create=True)
    out = os.path.join(work, name)
    r = chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, name + ".xml")), out, ranks=ranks)
    chocrun.require_completed(chocrun.read_summary(out, analysis))
    condensed = "condensed out of the Newton system" in r.stdout
    if method != "Direct" and not condensed:
        failures.append(f"{name}: the log does not say the contact pressures are condensed")
    if method == "Direct" and condensed:
        failures.append(f"{name}: a direct solve condensed the pressures (it solves the saddle point)")
    m = re.search(r"impacts of '(\w+)': (\d+)", r.stdout)
    return chocrun.read_history(out, analysis), (m.group(2) if m else None)


def same(label, ref, other, columns, bound=1e-7):
    for c in columns:
        peak = np.max(np.abs(ref[0][c]))
        rel = np.max(np.abs(other[0][c] - ref[0][c])) / peak if peak > 0 else 0.0
        print(f"{label}: {c} differs by {rel:.2e} of its peak")
        if not rel <= bound:
            failures.append(f"{label}: {c} differs by {rel:.2e} of its peak (at most {bound:g})")
    if other[1] != ref[1]:
        failures.append(f"{label}: {other[1]} impacts against {ref[1]}")


sphere = lambda name, method, prec=None, ranks=1: run(  # noqa: E731
    name, "hertz.xml", "axisymmetric", method, prec, ranks, end=1e-5)
direct = sphere("sphere_direct", "Direct")
for name, ranks in (("sphere_cg", 1), ("sphere_cg_np2", 2)):
    h = sphere(name, "CG", "Jacobi", ranks)
    same(name, direct, h, ["C:DY", "C:VY", "plane:force", "energy:total"])
    travel = np.max(np.abs(h[0]["C:DY"]))
    gap = np.max(np.abs(h[0]["plane:gap"]))
    print(f"{name}: largest |gap| {gap:.2e} m for a travel of {travel:.2e} m")
    if not gap <= 1e-10 * travel:
        failures.append(f"{name}: |gap| reaches {gap:.2e} m, above 1e-10 of the travel {travel:.2e} m")

block = lambda name, method, prec=None, ranks=1: run(name, "compact_block.xml", "drop", method, prec, ranks)  # noqa: E731
direct = block("block_direct", "Direct")
same("block_multigrid_np2", direct, block("block_multigrid_np2", "CG", "Multigrid", 2), ["corner:DZ", "floor:force"])
same("block_gmres", direct, block("block_gmres", "GMRES", "Jacobi"), ["corner:DZ", "floor:force"])
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("condensed_contact: the condensed pressures give the saddle point's histories on 1 and 2 ranks")
