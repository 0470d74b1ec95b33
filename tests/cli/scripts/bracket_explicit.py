#!/usr/bin/env python3
"""The bracket drop by central differences (input/bracket_drop.xml with the lumped mass and the
explicit scheme: forward-increment pressures and Coulomb friction, mu = 0.2; 19,434 unknowns,
300 us in 19 sub-steps per step). Checked:
  - one impact; the friction work positive and below the initial kinetic energy E0;
  - the energy balance at or below +0.1 % of E0 at every row (the phase's issue's bound);
  - on 2 ranks, the same histories to 1e-8 of their peaks.
(Against the implicit run at a small step, motion and friction work: tools/bench/bench_bracket.py.)
usage: bracket_explicit.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
d = chocrun.load_deck(os.path.join(src, "input", "bracket_drop.xml"))
chocrun.set_param(d, "Analyses/drop/Exodus Interval", 0)
chocrun.set_param(d, "Model/Blocks/BRACKET/Mass", "lumped", create=True)
chocrun.set_param(d, "Analyses/drop/Scheme", "central differences", create=True)
chocrun.set_param(d, "Analyses/drop/Stability Check", "substep", create=True)
path = chocrun.write_deck(d, os.path.join(work, "explicit.xml"))
failures = []
runs = {}
for ranks in (1, 2):
    out = os.path.join(work, f"explicit_np{ranks}")
    r = chocrun.run(choc, path, out, ranks=ranks)
    chocrun.require_completed(chocrun.read_summary(out, "drop"))
    runs[ranks] = chocrun.read_history(out, "drop")
    m = re.search(r"impacts of 'floor': (\d+)", r.stdout)
    if not m or int(m.group(1)) != 1:
        failures.append(f"{ranks} rank(s): impacts of 'floor': {m.group(1) if m else 'none'} (one expected)")
h = runs[1]
e0 = h["energy:kinetic"][0]
balance = np.max(h["energy:balance"])
work_f = h["floor:friction_work"][-1]
print(f"E0 {e0:.6g} J; largest balance {balance:.3e} J ({balance / e0:.2e} of E0); friction work {work_f:.4g} J")
if not balance <= 1e-3 * e0:
    failures.append(f"the energy balance reaches {balance / e0:.2e} of E0 (at most +1e-3)")
if not 0.0 < work_f < e0:
    failures.append(f"friction work {work_f:.4g} J outside (0, E0 = {e0:.4g} J)")
for c in ("TIP:DX", "TIP:DZ", "CORNER:DZ", "floor:force", "floor:tangential_force", "floor:friction_work"):
    peak = np.max(np.abs(h[c]))
    rel = np.max(np.abs(runs[2][c] - h[c])) / peak
    if not rel <= 1e-8:
        failures.append(f"2 ranks: {c} differs by {rel:.2e} of its peak (at most 1e-8)")
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("bracket_explicit: the explicit drop with friction keeps its energy balance on 1 and 2 ranks")
