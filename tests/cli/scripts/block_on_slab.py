#!/usr/bin/env python3
"""The compact block dropped flat on a meshed slab (input/block_on_slab.xml: 1 m/s, Lagrange node
to face, Coulomb mu = 0.2, the consistent mass, 'Contact Mass' = auto: the contact surfaces
massless), its first 10 steps. The contact layer's nodes have no inertia, so each step's stick
and slip are found statically; Newton starts them from their last two increments extrapolated
('Newton/Massless Start' = 'extrapolated', the default) rather than from the Newmark predictor.
Checked:
  - both starts complete with one impact and create no energy beyond 1e-4 E0 (issue 73);
  - they reach the same solution: the corner's motion and the contact forces within 1e-7 of
    their peaks (Newton's tolerances are 1e-8 of the residual's reference and of the step's
    increment), the friction work within 1e-6 (the sum of F_t times the slip increments, which
    are far smaller than the step's increment that the increment test measures); the gap is
    round-off around 0 in contact and is not compared;
  - the extrapolated start takes fewer Newton corrections than the predictor's (the
    predictor's tangential slip of a massless node comes from its Newmark velocity, which only
    closes the scheme's relations).
usage: block_on_slab.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
failures = []


def run(start):
    d = chocrun.load_deck(os.path.join(src, "input", "block_on_slab.xml"))
    chocrun.set_param(d, "Analyses/drop/End Time", 1e-5)
    chocrun.set_param(d, "Analyses/drop/Exodus Interval", 0, create=True)
    chocrun.set_param(d, "Analyses/drop/Newton/Massless Start", start, create=True)
    tag = start.replace(" ", "_")
    out = os.path.join(work, tag)
    r = chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, tag + ".xml")), out)
    s = chocrun.require_completed(chocrun.read_summary(out, "drop"))
    h = chocrun.read_history(out, "drop")
    m = re.search(r"impacts of 'floor': (\d+)", r.stdout)
    if not m or int(m.group(1)) != 1:
        failures.append(f"{start}: impacts of 'floor': {m.group(1) if m else 'none'} (one expected)")
    created = max(h["energy:balance"]) / h["energy:total"][0]
    newton = chocrun.summary_value(s, "newton")["iterations"]
    print(f"{start}: {newton} Newton corrections in {chocrun.summary_value(s, 'steps')} steps, "
          f"largest balance {created:.2e} E0")
    if not created <= 1e-4:
        failures.append(f"{start}: energy created {created:.2e} E0 (at most 1e-4)")
    return h, newton


h, newton = run("extrapolated")
h_p, newton_p = run("predictor")
for c, bound in (("corner:DZ", 1e-7), ("corner:VZ", 1e-7), ("floor:force", 1e-7), ("floor:tangential_force", 1e-7),
                 ("floor:friction_work", 1e-6)):
    peak = np.max(np.abs(h_p[c]))
    rel = np.max(np.abs(h[c] - h_p[c])) / peak
    print(f"{c}: the starts differ by {rel:.2e} of its peak")
    if not rel <= bound:
        failures.append(f"{c}: the starts differ by {rel:.2e} of its peak (at most {bound:g})")
if not newton < newton_p:
    failures.append(f"the extrapolated start took {newton} Newton corrections, not fewer than the "
                    f"predictor's {newton_p}")
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("block_on_slab: the same solution in fewer Newton corrections")
