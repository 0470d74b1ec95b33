#!/usr/bin/env python3
"""Implicit Lagrange contact on a yielding contact zone (docs/user-guide/plasticity.md): the
elastic-plastic sphere of input/plastic_impact_axisymmetric.xml (J2, no hardening) at 10 times its
yield velocity, on TRI6 of 0.1 mm at the contact, for its first 10 us (5.5 % of its kinetic energy
already dissipated plastically), by average acceleration (dt = 0.2 us, Lagrange contact, the
inputs' defaults: 'Status Update' and 'Line Search' auto, so converged solves and a line search;
'Newton/Maximum Iterations' 30 and 8 step cuts allowed) against central differences on the same
mesh (forward-increment Lagrange, the test cli.plastic_impact's scheme):
  - the implicit run completes (before the line search it stopped at its second or third step);
  - at 10 us its contact force, plastic work and the centre's displacement are the explicit run's
    within 1 % (both schemes are second order: at dt = 0.2 us their error on a 43 us contact is of
    order (pi dt / 43 us)^2 / 12 = 2e-5; the 1 % leaves room for the two ways the contact is
    enforced, at t_n+1 by multipliers against by forward increments);
  - energy:balance at or below 1e-3 E0 (no energy created);
  - its first 4 us (20 steps, past first yield) on 2 ranks and on the mesh with its nodes
    renumbered give the 1-rank histories to 1e-6 of their peaks (Newton stops each step within
    1e-8 of the step's motion, with another sum order or path on each; 20 steps of it);
  - at the default 'Maximum Iterations' (10) and no step cuts the implicit run stops with exit 2
    (a numerical failure), its message naming 'Newton/Maximum Iterations', and no complete result;
  - the default scheme (modified average acceleration, alpha = -0.1, whose damping of the highest
    frequencies calms the yielding contact) at the default Newton settings completes the same
    10 us, its force, plastic work and motion within the same 1 % of central differences.
usage: plastic_impact_implicit.py CHOC SOURCE_DIR WORK_DIR"""
import os
import sys

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

END = 1e-5
os.makedirs(work, exist_ok=True)
msh = os.path.join(work, "sphere_h0.1mm.msh")
chocrun.gmsh("hertz_axisymmetric.geo", msh, 2, "-order", 2, "-setnumber", "h", 1e-4)


def deck(tag, params, remove=()):
    d = chocrun.load_deck(chocrun.input_path("plastic_impact_axisymmetric.xml"))
    chocrun.set_params(d, dict({"Mesh/File": msh, "Analyses/impact/End Time": END}, **params), create=True)
    for p in remove:
        chocrun.remove_param(d, p)
    return chocrun.write_deck(d, os.path.join(work, tag + ".xml"))


explicit = deck("explicit", {})
implicit_params = {"Analyses/impact/Scheme": "average acceleration", "Analyses/impact/Time Step": 2e-7,
                   "Analyses/impact/Newton/Maximum Iterations": 30, "Analyses/impact/Step Control/Maximum Step Cuts": 8}
implicit = deck("implicit", implicit_params, remove=("Analyses/impact/Stability Check",))
runs = {}
for tag, path in (("explicit", explicit), ("implicit", implicit)):
    out = os.path.join(work, tag)
    print(f"{tag}: {chocrun.run(choc, path, out).wall:.1f} s")
    runs[tag] = (chocrun.read_summary(out, "impact"), chocrun.read_history(out, "impact"))

failures = []
summary, hist = runs["implicit"]
chocrun.require_completed(summary)
print(f"implicit: {summary['steps']} steps, {summary['newton']['iterations']} Newton corrections, "
      f"{summary['failed_attempts']} failed attempts")
e0 = float(hist["energy:total"][0])
balance = float(max(hist["energy:balance"])) / e0
print(f"implicit: energy:balance at most {balance:.2e} E0 (at most 1e-3)")
if not balance <= 1e-3:
    failures.append(f"implicit: energy:balance reaches {balance:.2e} E0")
ex = runs["explicit"][1]


def against_explicit(h, label):
    """The contact force, plastic work and centre's motion at END within 1 % of the explicit run's."""
    out = []
    for col in ("plane:force", "energy:plastic", "C:DY"):
        a, b = float(h[col][-1]), float(ex[col][-1])
        rel = abs(a - b) / abs(b)
        print(f"{label} at {END:g} s, {col}: {a:.6g} against explicit {b:.6g}: {rel:.1e} apart (at most 1e-2)")
        if not (abs(b) > 0 and rel <= 1e-2):
            out.append(f"{label}, {col} at {END:g} s: {a:.6g} against explicit {b:.6g}")
    return out


failures += against_explicit(hist, "implicit")
# The same run over its first 4 us on 2 ranks and on the renumbered mesh, against the 1-rank rows.
renumbered = chocrun.renumbered_mesh(msh, os.path.join(work, "sphere_renumbered.msh"))
short = {"Analyses/impact/End Time": 4e-6}
short_deck = deck("implicit_4us", dict(implicit_params, **short), remove=("Analyses/impact/Stability Check",))
chocrun.run(choc, short_deck, os.path.join(work, "np2"), ranks=2)
chocrun.run(choc, deck("renumbered_4us", dict(implicit_params, **short, **{"Mesh/File": renumbered}),
                       remove=("Analyses/impact/Stability Check",)), os.path.join(work, "renumbered"))
rows = len(chocrun.read_history(os.path.join(work, "np2"), "impact")["time"])
first = {k: v[:rows] for k, v in hist.items()}
columns = ("C:DY", "C:VY", "plane:force", "energy:plastic")
failures += chocrun.ranks_agree(first, chocrun.read_history(os.path.join(work, "np2"), "impact"), columns, 1e-6)
failures += chocrun.ranks_agree(first, chocrun.read_history(os.path.join(work, "renumbered"), "impact"), columns,
                                1e-6, label="renumbered against the mesh's numbering")

defaults = deck("defaults", {"Analyses/impact/Scheme": "average acceleration", "Analyses/impact/Time Step": 2e-7},
                remove=("Analyses/impact/Stability Check",))
stopped = chocrun.run(choc, defaults, os.path.join(work, "defaults"), ok=(2,))
message = stopped.stdout + stopped.stderr
print(f"defaults: exit {stopped.returncode}; names 'Newton/Maximum Iterations': {'Newton/Maximum Iterations' in message}")
if "'Newton/Maximum Iterations'" not in message:
    failures.append("defaults: the failure does not name 'Newton/Maximum Iterations'")
if os.path.exists(os.path.join(work, "defaults", "impact.history.csv")):
    failures.append("defaults: a complete history written by a failed run")
# The default scheme (modified average acceleration, alpha = -0.1: it damps the highest
# frequencies) at the default Newton settings (10 iterations, no step cuts) completes the same
# 10 us, within the same 1 % of central differences.
damped = deck("default_scheme", {"Analyses/impact/Time Step": 2e-7}, remove=("Analyses/impact/Stability Check",
                                                                            "Analyses/impact/Scheme"))
run = chocrun.run(choc, damped, os.path.join(work, "default_scheme"))
summary = chocrun.read_summary(os.path.join(work, "default_scheme"), "impact")
chocrun.require_completed(summary)
hd = chocrun.read_history(os.path.join(work, "default_scheme"), "impact")
print(f"default scheme: {run.wall:.1f} s, {summary['newton']['iterations']} Newton corrections in "
      f"{summary['steps']} steps, {summary['failed_attempts']} failed attempts")
failures += against_explicit(hd, "default scheme")
chocrun.finish(failures, "plastic_impact_implicit: every check holds")
