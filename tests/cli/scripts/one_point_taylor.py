#!/usr/bin/env python3
"""The one-point HEX8 with hourglass stiffness on the 3D Taylor bar (docs/verification/taylor-bar.md,
"One point"): the copper quarter of input/taylor_bar_3d.xml with 'Formulation' = 'one-point' at the
default 'Hourglass Coefficient', central differences.

Checked:
  - on the 0.8 mm O-grid (n = 4) the run completes, creates no energy (balance at or below 1e-6 E0),
    reports its hourglass energy (energy:hourglass), which stays below 10 % of the internal energy
    (strain energy plus plastic work) at every output (the usual bound on an hourglass-controlled
    run: above it the control, not the material, carries the load) and ends with at least 97 % of
    E0 as plastic work;
  - its final impact-face radius and length agree with the axisymmetric bar of the same element size
    (QUAD4 F-bar, 0.8 mm) within that bar's own mesh error estimate |x(1.6 mm) - x(0.8 mm)|;
  - 2 ranks, and the mesh with its node tags reversed, give the 1-rank histories of the 1.6 mm
    quarter (n = 2) to 1e-8 of their peaks;
  - the whole 1.6 mm bar turned as a rigid whole with its wall and its velocity moves as the bar drawn
    along y, seen in the turned frame, to 1e-8 of the peak displacement over the first 20 us: the
    mean gradient and the hourglass vectors are frame invariant.
usage: one_point_taylor.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

R0, L0 = 3.2e-3, 32.4e-3
POINTS = ("EDGE", "REAR", "CENTRE")
os.makedirs(work, exist_ok=True)
failures = []
runs = {}  # label: (the run, its summary)


def shape(h):
    return (R0 + h["EDGE:DX"][-1]) * 1e3, (L0 + h["REAR:DY"][-1] - h["CENTRE:DY"][-1]) * 1e3


def finish_run(d, label, ranks=1):
    out = os.path.join(work, label)
    r = chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, label + ".xml")), out, ranks=ranks)
    runs[label] = (r, chocrun.require_completed(chocrun.read_summary(out, "impact")))
    return chocrun.read_history(out, "impact")


def substeps_in_log(text, steps, initial, dt):
    """The sub-steps a run took by its log: `initial` per step until each line "t = T s: the
    deformed mesh's stable step is ...: N sub-step(s) per step", N from the step starting at T."""
    total, before, per, largest = 0, 0, initial, initial
    for m in re.finditer(r"t = ([0-9.e+-]+) s: the deformed mesh's stable step is [0-9.e+-]+ s: (\d+) sub-step", text):
        k = round(float(m.group(1)) / dt)
        total += per * (k - before)
        before, per = k, int(m.group(2))
        largest = max(largest, per)
    return total + per * (steps - before), largest


def quarter(n, ranks=1, full=0, R=None, end=None, renumbered=False):
    d = chocrun.taylor_bar_3d_deck(work, n=n, full=full, R=R, end=end, points=POINTS)
    chocrun.set_param(d, "Model/Blocks/BAR/Formulation", "one-point")
    chocrun.set_param(d, "Analyses/impact/Time Step", 4e-8 * 4 / n)
    if renumbered:  # the node tags reversed (each element's nodes in its own order still)
        msh = chocrun.find(d, "Mesh/File", None).get("value")
        chocrun.set_param(d, "Mesh/File", chocrun.renumbered_mesh(msh, msh[:-4] + "_renumbered.msh"))
    label = f"one_point_n{n}_full{full}_np{ranks}" + ("_turned" if R is not None else "") + \
        ("_renumbered" if renumbered else "")
    return finish_run(d, label, ranks)


def axisymmetric(n):
    msh = chocrun.gmsh("taylor_bar_axisymmetric.geo", os.path.join(work, f"axi_{n}.msh"), 2, "-setnumber", "n", n)
    d = chocrun.load_deck(os.path.join(src, "input", "taylor_bar_axisymmetric.xml"))
    chocrun.set_param(d, "Mesh/File", msh)
    chocrun.set_param(d, "Analyses/impact/Exodus Interval", 0)
    return shape(finish_run(d, f"axi_{n}"))


# The 0.8 mm quarter: energy, hourglass energy, and its shape against the axisymmetric bar.
h = quarter(4)
e0 = h["energy:total"][1]
bal, hg = np.asarray(h["energy:balance"]), np.asarray(h["energy:hourglass"])
internal = np.asarray(h["energy:strain"]) + np.asarray(h["energy:plastic"])
ratio = float(np.max(hg[1:] / np.maximum(internal[1:], 1e-300)))
print(f"0.8 mm quarter: plastic work {h['energy:dissipated'][-1] / e0:.4f} E0, balance in "
      f"[{bal.min() / e0:.2e}, {bal.max() / e0:.2e}] E0, hourglass energy at most {ratio:.3f} of the internal energy "
      f"(at the end {hg[-1] / e0:.2e} E0)")
if not bal.max() <= 1e-6 * e0:
    failures.append(f"energy created: balance up to {bal.max() / e0:.2e} E0")
if not ratio <= 0.10:
    failures.append(f"hourglass energy reaches {ratio:.3f} of the internal energy (at most 0.10)")
if not h["energy:dissipated"][-1] >= 0.97 * e0:
    failures.append(f"plastic work {h['energy:dissipated'][-1] / e0:.4f} E0, below 0.97")
r1, l1 = shape(h)
run4, s4 = runs["one_point_n4_full0_np1"]
logged, largest = substeps_in_log(run4.stdout + run4.stderr, s4["steps"], s4["substeps_per_step"], s4["time_step"])
print(f"sub-steps: {s4['substeps_taken']} in the summary (at most {s4['substeps_largest']} per step), {logged} by the "
      f"log (at most {largest}), {s4['steps']} steps")
if not (s4["substeps_taken"] == logged and s4["substeps_largest"] == largest and logged > s4["steps"]):
    failures.append(f"sub-steps: summary {s4['substeps_taken']} (largest {s4['substeps_largest']}), log {logged} "
                    f"(largest {largest}), steps {s4['steps']}")
(ra, la), (ra4, la4) = axisymmetric(2), axisymmetric(4)
for what, v1, va, va4 in (("radius", r1, ra, ra4), ("length", l1, la, la4)):
    est = abs(va - va4)
    print(f"{what}: one-point quarter {v1:.4f} mm, axisymmetric F-bar {va4:.4f} mm (mesh error estimate {est:.4f} mm)")
    if not abs(v1 - va4) <= est:
        failures.append(f"{what}: one-point {v1:.4f} mm and axisymmetric {va4:.4f} mm differ by more than {est:.4f} mm")

# Ranks and frame on the 1.6 mm bar.
h2 = quarter(2)
failures += chocrun.ranks_agree(h2, quarter(2, ranks=2), ("EDGE:DX", "REAR:DY", "energy:hourglass"))
failures += chocrun.ranks_agree(h2, quarter(2, renumbered=True), ("EDGE:DX", "REAR:DY", "energy:hourglass"),
                               label="node tags reversed against the mesh as meshed")
R = chocrun.rotation_matrix(0.7, (0.3, -0.5, 0.81))
ha, hb = quarter(2, full=1, end=2e-5), quarter(2, full=1, end=2e-5, R=R)
ua = np.stack([np.stack([ha[f"{p}:{c}"] for c in ("DX", "DY", "DZ")], axis=1) for p in POINTS])
ub = np.stack([np.stack([hb[f"{p}:{c}"] for c in ("DX", "DY", "DZ")], axis=1) for p in POINTS])
diff = float(np.max(np.abs(np.einsum("ji,ptj->pti", R, ub) - ua))) / float(np.max(np.abs(ua)))
print(f"turned as a whole: R^T u against u, {diff:.1e} of the peak displacement (at most 1e-8)")
if not diff <= 1e-8:
    failures.append(f"frame invariance: the turned bar's motion differs by {diff:.1e} of the peak")
chocrun.finish(failures, "one-point Taylor bar: OK")
