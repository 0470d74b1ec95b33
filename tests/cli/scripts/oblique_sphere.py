#!/usr/bin/env python3
"""The oblique sphere (input/oblique_sphere.xml): a steel sphere hitting a rigid plane at 5 m/s,
60 degrees from the normal, Coulomb friction mu = 0.1, implicit with Lagrange contact. Sliding
throughout (tan 60 degrees = 1.73 > 7/2 mu (1 + e)), the tangential impulse is mu times the
normal one; each node that sticks for a while (the stick spring's band, 2 mu f_N / k_t) lowers
it by a little. Checked:
  - the run completes with one impact;
  - the impulse of plane:tangential_force over that of plane:force equals mu to 1e-4 (the
    phase's issue's bound);
  - the friction work is positive and at most mu times the normal impulse times the largest
    sliding speed (4.33 m/s, the initial one: friction only slows the contact point);
  - about 3 Newton iterations per step (the phase's issue): at most 3.5 on average and 6 in any
    step, with the status updated after each correction (semi-smooth Newton) and the
    increment test bounding the iterate's error by the corrections' contraction;
  - 'Status Update' = 'converged solve' (a whole Newton solve per status change) gives the same
    histories to 1e-7 of their peaks, in more Newton iterations;
  - GMRES + Jacobi (the pressures condensed out with friction's multiplier columns, on the
    displacements alone) over the first 20 steps gives the direct saddle-point run's histories to
    1e-7 of their peaks.
usage: oblique_sphere.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

MU = 0.1
os.makedirs(work, exist_ok=True)
d = chocrun.load_deck(os.path.join(src, "input", "oblique_sphere.xml"))
chocrun.set_param(d, "Analyses/oblique/Exodus Interval", 0)
out = os.path.join(work, "oblique")
r = chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, "oblique.xml")), out)
s = chocrun.require_completed(chocrun.read_summary(out, "oblique"))
h = chocrun.read_history(out, "oblique")
failures = []
m = re.search(r"impacts of 'plane': (\d+)", r.stdout)
if not m or int(m.group(1)) != 1:
    failures.append(f"impacts of 'plane': {m.group(1) if m else 'none'} (one expected)")
t = h["time"]
normal = np.trapz(h["plane:force"], t)
tangential = np.trapz(h["plane:tangential_force"], t)
ratio = tangential / normal
print(f"normal impulse {normal:.6e} N s, tangential {tangential:.6e} N s: ratio {ratio:.7f} (mu = {MU})")
if not abs(ratio / MU - 1.0) <= 1e-4:
    failures.append(f"tangential over normal impulse {ratio:.7f}, {abs(ratio / MU - 1):.2e} from mu (at most 1e-4)")
work_f = h["plane:friction_work"][-1]
bound = MU * normal * 4.330127018922193
print(f"friction work {work_f:.4e} J (at most mu x normal impulse x 4.33 m/s = {bound:.4e} J)")
if not 0.0 < work_f <= bound:
    failures.append(f"friction work {work_f:.4e} J outside (0, {bound:.4e}]")
steps = chocrun.summary_value(s, "steps")
newton = chocrun.summary_value(s, "newton")
print(f"Newton iterations per step: {newton['iterations'] / steps:.2f} ({newton['iterations']} in {steps} steps, "
      f"at most {newton['max_per_step']})")
if not (newton["iterations"] <= 3.5 * steps and newton["max_per_step"] <= 6):
    failures.append(f"Newton: {newton['iterations'] / steps:.2f} per step, at most {newton['max_per_step']} "
                    "(bounds 3.5 and 6)")


def compare(h_other, label, bound):
    rows = len(h_other["time"])
    for c in ("C:DX", "C:DY", "C:VX", "plane:force", "plane:tangential_force", "plane:friction_work"):
        peak = np.max(np.abs(h[c][:rows]))
        rel = np.max(np.abs(h_other[c] - h[c][:rows])) / peak
        print(f"{label}: {c} differs by {rel:.2e} of its peak over {rows - 1} steps")
        if not rel <= bound:
            failures.append(f"{label}: {c} differs by {rel:.2e} of its peak (at most {bound:g})")


chocrun.set_param(d, "Analyses/oblique/Contact/Status Update", "converged solve", create=True)
out_c = os.path.join(work, "oblique_converged")
chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, "oblique_converged.xml")), out_c)
s_c = chocrun.require_completed(chocrun.read_summary(out_c, "oblique"))
newton_c = chocrun.summary_value(s_c, "newton")["iterations"]
print(f"status after converged solves: {newton_c / steps:.2f} Newton iterations per step")
if not newton_c > newton["iterations"]:
    failures.append(f"status after converged solves: {newton_c} Newton iterations, not more than "
                    f"{newton['iterations']}")
compare(chocrun.read_history(out_c, "oblique"), "status after converged solves", 1e-7)
chocrun.set_param(d, "Analyses/oblique/Contact/Status Update", "each correction")
chocrun.set_param(d, "Analyses/oblique/End Time", 2e-5)
chocrun.set_param(d, "Analyses/oblique/Linear Solver/Method", "GMRES", create=True)
chocrun.set_param(d, "Analyses/oblique/Linear Solver/Preconditioner", "Jacobi", create=True)
out_g = os.path.join(work, "oblique_gmres")
rg = chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, "oblique_gmres.xml")), out_g)
if "condensed out of the Newton system" not in rg.stdout:
    failures.append("GMRES: the log does not say the pressures are condensed")
compare(chocrun.read_history(out_g, "oblique"), "GMRES, condensed", 1e-7)
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("oblique_sphere: the tangential impulse is mu times the normal one")
