#!/usr/bin/env python3
"""Contact between meshed bodies is as cheap as against an obstacle: input/hertz_two_spheres.xml
(two steel spheres of 10 mm at 5 m/s each, head on, node to face between the two meshes) against
input/hertz.xml (one sphere at 5 m/s on a rigid plane), both 100 steps of 0.1 us (the first
fifth of the impact; Lagrange contact, average acceleration, the direct solver).
By symmetry the plane between the spheres stays still, so each sphere moves as the sphere on the
rigid plane. Checked:
  - C:DY (the upper sphere's centre) equals the one-sphere run's to 1e-5 of its peak: the
    spheres start 1 nm apart (meshes/hertz_two_spheres.geo), which delays the contact by 1e-10 s,
    5e-10 m of the centre's travel, 1e-5 of the 5e-5 m peak;
  - the lower sphere moves as the mirror image of the upper one (C2:DY = -C:DY, the same bound);
  - the two-sphere run factors at most 1.5 times as often as the obstacle run, plus 2 (the
    slave nodes over the edges between two master faces kept their face: before, they changed
    face at almost every step, 98 factorisations against 25) and takes at most 1.5 times its
    Newton iterations.
usage: two_spheres.py CHOC SOURCE_DIR WORK_DIR"""
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)


def run(name, deck_file):
    d = chocrun.load_deck(os.path.join(src, "input", deck_file))
    chocrun.set_param(d, "Analyses/axisymmetric/End Time", 1e-5)
    chocrun.set_param(d, "Analyses/axisymmetric/Exodus Interval", 0)
    out = os.path.join(work, name)
    chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, name + ".xml")), out)
    s = chocrun.require_completed(chocrun.read_summary(out, "axisymmetric"))
    return s, chocrun.read_history(out, "axisymmetric")


one, h1 = run("one_sphere", "hertz.xml")
two, h2 = run("two_spheres", "hertz_two_spheres.xml")
failures = []
peak = np.max(np.abs(h1["C:DY"]))
for label, diff in (("C:DY against the sphere on the plane", h2["C:DY"] - h1["C:DY"]),
                    ("C2:DY + C:DY (mirror image)", h2["C2:DY"] + h2["C:DY"])):
    rel = np.max(np.abs(diff)) / peak
    print(f"{label}: {rel:.2e} of the peak {peak:.3e} m")
    if not rel <= 1e-5:
        failures.append(f"{label}: {rel:.2e} of the peak (at most 1e-5)")
f1, f2 = chocrun.summary_value(one, "factorizations"), chocrun.summary_value(two, "factorizations")
n1, n2 = chocrun.summary_value(one, "newton")["iterations"], chocrun.summary_value(two, "newton")["iterations"]
print(f"factorisations: {f2} (two spheres) against {f1} (obstacle); Newton iterations {n2} against {n1}")
if f2 > 1.5 * f1 + 2:
    failures.append(f"{f2} factorisations against the obstacle run's {f1} (at most 1.5 x + 2)")
if n2 > 1.5 * n1:
    failures.append(f"{n2} Newton iterations against the obstacle run's {n1} (at most 1.5 x)")
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("two_spheres: meshed bodies in contact cost what a sphere on an obstacle costs")
