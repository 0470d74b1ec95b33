#!/usr/bin/env python3
"""SDNL111 C (input/sdnl111c.xml: two 3D HEX8 bars, bar 1 at 1 m/s onto bar 2, Lagrange
contact, lateral motion blocked; its first analysis, c1_modified) with both blocks in finite strain (Saint Venant-Kirchhoff,
the same E and nu) against the small-strain deck. The bars' strain is at most
eps = v / c = 1 / 5064 = 2.0e-4 (the impact's wave carries v/2 in each bar, doubled at the
clamped end), so the two kinematics must agree to the order of eps: the displacement of A
(N1:DZ) within 10 eps of its peak. Its velocity jumps at each change of contact status, which
O(eps) shifts in time: its pointwise difference is reported, not bounded. The deck's checks against d'Alembert are printed for
both (the one at 0.8 ms is at 4.96 % of its 5 % in small strain already). The difference is printed (the report of the phase's
issue), with the Newton iterations of both.
usage: finite_small_sdnl111c.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

E, RHO = 2e11, 7800.0
EPS = 1.0 / math.sqrt(E / RHO)
os.makedirs(work, exist_ok=True)
failures = []
runs = {}
for strain in ("small", "finite"):
    d = chocrun.load_deck(os.path.join(src, "input", "sdnl111c.xml"))
    chocrun.keep_analyses(d, ["c1_modified"])  # the deck's first run (modified average acceleration)
    name = "c1_modified"
    chocrun.set_param(d, f"Analyses/{name}/Exodus Interval", 0)
    if strain == "finite":
        chocrun.set_param(d, "Model/Materials/steel/Model", "Saint Venant-Kirchhoff", create=True)
        for block in chocrun.sublists(d, "Model/Blocks"):
            chocrun.set_param(d, f"Model/Blocks/{block}/Strain", "finite", create=True)
    out = os.path.join(work, strain)
    # The deck's check at 0.8 ms holds by 4.96 % against 5 % in small strain (the scheme's
    # dispersion): the O(eps) change of finite strain may cross it (exit 3), so the histories
    # are compared with each other, not with the checks.
    chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, strain + ".xml")), out, ok=(0, 3))
    s = chocrun.require_completed(chocrun.read_summary(out, name), accept=("completed", "check failed"))
    runs[strain] = (chocrun.read_history(out, name), s)
    rows = chocrun.check_rows(s)
    print(f"{strain}: {chocrun.summary_value(s, 'newton')['iterations']} Newton iterations in "
          f"{chocrun.summary_value(s, 'steps')} steps; checks {[r.get('status') for r in rows]}, errors "
          f"{[round(float(r.get('error', 0)), 4) for r in rows]}")
h0, h1 = runs["small"][0], runs["finite"][0]
for c in ("N1:DZ", "N1:VZ"):
    rel = np.max(np.abs(h1[c] - h0[c])) / np.max(np.abs(h0[c]))
    print(f"{c}: finite against small strain {rel:.2e} of its peak (eps = {EPS:.2e}"
          + (f"; at most {10 * EPS:.2e})" if c == "N1:DZ" else "; reported: the velocity jumps at each contact change)"))
    if c == "N1:DZ" and not rel <= 10 * EPS:
        failures.append(f"{c}: finite strain differs from small by {rel:.2e} of its peak (at most 10 eps = {10 * EPS:.2e})")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("SDNL111 C in finite strain: OK")
