#!/usr/bin/env python3
"""The contact velocity update on a consistent mass (ContactStrategy::correctVelocity projecting in
M's norm): example 03 (a steel bar of 40 HEX8 layers on a rigid plane, average acceleration, its
blocks' consistent mass) with 'Contact Mass' = velocity update.
Checked:
  - one impact (no chatter);
  - no energy created beyond the scheme's release term: energy:balance at most 1e-3 E0 (the
    redistributed mass's own run reaches 1e-3 E0 at its opening; the lumped projection on this
    consistent mass created 1.9e-2 E0);
  - the kinetic energy the update takes (energy:dissipated at the end, average acceleration
    dissipating nothing else) is positive and at most 5 % of E0: the projection is the smallest
    correction in M's norm, so it takes no more than zeroing the velocity of the two lowest node
    planes would, whose share of M is at most two layers of 40.
usage: velocity_update_consistent.py CHOC SOURCE_DIR WORK_DIR"""
import os
import sys

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
example = os.path.join(src, "examples", "03-bar-on-wall")
d = chocrun.load_deck(os.path.join(example, "input.xml"))
chocrun.set_params(d, {"Analyses/drop/Contact Mass": "velocity update", "Analyses/drop/Exodus Interval": 0})
chocrun.remove_sublist(d, "Analyses/drop/Checks")
out = os.path.join(work, "run")
chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, "bar.xml")), out)
summary = chocrun.require_completed(chocrun.read_summary(out, "drop"))
h = chocrun.read_history(out, "drop")
e0 = float(h["energy:total"][0])
created = max(float(b) for b in h["energy:balance"]) / e0
taken = float(h["energy:dissipated"][-1]) / e0
impacts = sum(v["number_of_impacts"] for v in summary["impacts"].values())
print(f"impacts {impacts}, energy:balance at most {created:.2e} E0, taken by the update {taken:.4f} E0, "
      f"final kinetic energy {float(h['energy:kinetic'][-1]) / e0:.4f} E0")
failures = []
if impacts != 1:
    failures.append(f"{impacts} impacts (one)")
if not created <= 1e-3:
    failures.append(f"energy created: {created:.2e} E0 (at most 1e-3)")
if not 0 < taken <= 0.05:
    failures.append(f"the update took {taken:.4f} E0 (between 0 and 0.05)")
chocrun.finish(failures, "the velocity update on a consistent mass: one impact, no energy created")
