#!/usr/bin/env python3
"""Johnson-Cook damage, reported and not coupled (JohnsonCookDamage.hpp; docs/user-guide/plasticity.md),
on the Johnson-Cook Taylor bar (input/taylor_bar_johnson_cook_axisymmetric.xml, 5 x 51 F-bar QUAD4,
80 us). Four runs: without damage; with a constant failure strain (D1 = 0.5, D2 = D3 = D4 = D5 = 0);
with 4340 steel's fit (Johnson and Cook 1985: D1 = 0.05, D2 = 3.44, D3 = -2.12, D4 = 0.002,
D5 = 0.61, an illustration: 42CrMo4's own fit is not in BENCHMARKS.md) on 1 and 2 ranks.

Checked:
  - not coupled: the histories with either damage equal the run without, byte for byte;
  - a constant failure strain eps_f = D1 gives D = alpha / D1 at every point, so the DAMAGE element
    variable equals EQ_PLASTIC_STRAIN / D1 on every element (both are point averages) to 1e-12 of
    the largest; the log names, once, the element and the time at which a point's D first reached
    1 (alpha reaches 1.8 > D1), and the 4340 fit's run is logged too or not, but once at most;
  - with the fit: 0 <= D <= alpha / D1 on every element (eps_f >= D1 whatever the triaxiality, the
    rate and the temperature), D > 0 exactly where alpha > 0;
  - 2 ranks give the 1-rank DAMAGE field to 1e-8 of its largest value.
usage: johnson_cook_damage.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
failures = []
MAT = "Model/Materials/42CrMo4/"
FIT = {"D1": 0.05, "D2": 3.44, "D3": -2.12, "D4": 0.002, "D5": 0.61}
msh = os.path.join(work, "bar_5.msh")
chocrun.gmsh("taylor_bar_axisymmetric.geo", msh, 2, "-setnumber", "n", 5)


def run(label, damage=None, ranks=1):
    d = chocrun.load_deck(os.path.join(src, "input", "taylor_bar_johnson_cook_axisymmetric.xml"))
    chocrun.set_param(d, "Mesh/File", msh)
    chocrun.set_param(d, "Analyses/impact/Exodus Interval", 1000000)  # the first and the last step
    if damage:
        chocrun.set_param(d, MAT + "Damage", "Johnson-Cook", create=True)
        for k, v in damage.items():
            chocrun.set_param(d, MAT + "Johnson-Cook " + k, v, type="double", create=True)
    out = os.path.join(work, label)
    p = chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, label + ".xml")), out, ranks=ranks)
    chocrun.require_completed(chocrun.read_summary(out, "impact"))
    fields = ("EQ_PLASTIC_STRAIN", "DAMAGE") if damage else ("EQ_PLASTIC_STRAIN",)
    f = chocrun.read_element_fields(os.path.join(out, "impact.exo"), fields)
    lines = re.findall(r"^damage: .*$", p.stdout, re.M)
    with open(chocrun.history_path(out, "impact"), "rb") as h:
        return f, lines, h.read()


def logged_once(label, lines, required):
    print(f"{label}: " + (lines[0] if lines else "no damage line on the log"))
    if len(lines) > 1 or (required and not lines):
        failures.append(f"{label}: {len(lines)} damage lines on the log, expected {'1' if required else 'at most 1'}")
        return
    for line in lines:
        m = re.match(r"damage: Johnson-Cook's D reached (\S+) at t = (\S+) s in element (\d+) of block 'BAR': "
                     r"failure predicted there", line)
        if not (m and float(m.group(1)) >= 1 and 0 < float(m.group(2)) <= 8e-5):
            failures.append(f"{label}: unexpected damage line '{line}'")


_, _, plain = run("none")
const, lines, history = run("constant", {"D1": 0.5})
if history != plain:
    failures.append("a constant failure strain changed the history: damage must not be coupled")
a, D = const["EQ_PLASTIC_STRAIN"], const["DAMAGE"]
err = float(np.max(np.abs(D - a / 0.5)))
print(f"constant eps_f = 0.5: largest alpha {a.max():.4f}, largest D {D.max():.4f}, |D - alpha / D1| <= {err:.2e}")
if not err <= 1e-12 * D.max():
    failures.append(f"constant failure strain: DAMAGE differs from EQ_PLASTIC_STRAIN / D1 by {err:.3e}")
logged_once("constant", lines, required=True)

fit, lines, history = run("fit", FIT)
if history != plain:
    failures.append("4340's damage fit changed the history: damage must not be coupled")
a, D = fit["EQ_PLASTIC_STRAIN"], fit["DAMAGE"]
k = int(np.argmax(D))
print(f"4340 fit: largest D {D.max():.4f} (element {k + 1}, alpha {a[k]:.4f}); D / alpha in "
      f"[{(D[a > 0] / a[a > 0]).min():.4f}, {(D[a > 0] / a[a > 0]).max():.4f}], at most 1 / D1 = {1 / FIT['D1']:.1f}")
if not (np.all(D >= 0) and np.all(D <= a / FIT["D1"] * (1 + 1e-12)) and np.array_equal(D > 0, a > 0)):
    failures.append("4340 fit: D outside [0, alpha / D1], or D > 0 where alpha = 0 (or the reverse)")
logged_once("fit", lines, required=False)

fit2, _, _ = run("fit_np2", FIT, ranks=2)
diff = float(np.max(np.abs(fit2["DAMAGE"] - D)))
print(f"2 ranks against 1: DAMAGE within {diff / D.max():.1e} of its largest value")
if not diff <= 1e-8 * D.max():
    failures.append(f"2 ranks: DAMAGE differs from 1 rank's by {diff:.3e} (largest {D.max():.4f})")
chocrun.finish(failures, "Johnson-Cook damage: OK")
