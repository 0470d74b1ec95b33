#!/usr/bin/env python3
"""Multigrid for elasticity ('Linear Solver/Preconditioner' = Multigrid, src/solvers/
ElasticityMultigrid.hpp) in a stiffness-dominated transient: input/scale-3d.xml's scene (penalty
contact, bar 1 free, bar 2 clamped) on the scale bars at 9,648 unknowns (3 x 3 x 100 HEX8 per
bar) with dt = 1e-4 s, 20 steps (a stiffness-to-mass ratio near 1e5).
Checked, for CG + Multigrid on 1 and 2 ranks against the direct solver (KLU2) on 1:
  - each run completes and its summary names MueLu's smoothed aggregation with 3 components
    per node and 6 rigid-body modes;
  - at most 40 Krylov iterations per Newton solve (the bound the stiffness-dominated scenes
    need; Jacobi takes hundreds here, tests/unit/test_solvers_mpi_multigrid.cpp);
  - the histories equal the direct solver's to 1e-7 of each peak (CG's tolerance is 1e-10) and
    the impacts are the same (count, and the peak force to 1e-7).
usage: multigrid.py CHOC SOURCE_DIR WORK_DIR"""
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from scale_bars import bars_3_100, run_deck  # noqa: E402

choc, src, work, mesh = bars_3_100()
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402


def deck(preconditioner):
    d = chocrun.load_deck(os.path.join(src, "input", "scale-3d.xml"))
    chocrun.set_param(d, "Mesh/File", mesh)
    a = "Analyses/impact"
    chocrun.set_param(d, a + "/Time Step", 1e-4)
    chocrun.set_param(d, a + "/End Time", 2e-3)
    chocrun.set_param(d, a + "/Exodus Interval", 0)
    if preconditioner is None:
        chocrun.set_param(d, a + "/Linear Solver/Method", "Direct")
    else:
        chocrun.set_param(d, a + "/Linear Solver/Preconditioner", preconditioner)
    return chocrun.deck_text(d)


failures = []
run_deck(choc, work, "direct", deck(None))
for name, ranks in (("multigrid", 1), ("multigrid_np2", 2)):
    run_deck(choc, work, name, deck("Multigrid"), ranks)
    s = chocrun.read_summary(os.path.join(work, name), "impact")
    described = chocrun.summary_value(s, "linear_solver")["description"]
    if "MueLu smoothed aggregation (3 components per node, 6 rigid-body modes" not in described:
        failures.append(f"{name}: the summary's linear solver is '{described}'")
    krylov = chocrun.summary_value(s, "krylov_iterations")
    newton = chocrun.summary_value(s, "newton")["iterations"]
    print(f"{name}: {krylov} Krylov iterations in {newton} Newton solves")
    if krylov > 40 * newton:
        failures.append(f"{name}: {krylov / newton:.1f} Krylov iterations per Newton solve (at most 40)")
    direct = chocrun.read_summary(os.path.join(work, "direct"), "impact")
    mine, theirs = chocrun.summary_value(s, "impacts")["interface"], chocrun.summary_value(direct, "impacts")["interface"]
    if mine["number_of_impacts"] != theirs["number_of_impacts"] or \
            abs(mine["largest_peak_force"] - theirs["largest_peak_force"]) > 1e-7 * theirs["largest_peak_force"]:
        failures.append(f"{name}: impacts {mine} differ from the direct solver's {theirs}")
    cmp = subprocess.run([sys.executable, os.path.join(src, "tools", "oracles", "compare_histories.py"),
                          os.path.join(work, "direct", "impact.history.csv"),
                          os.path.join(work, name, "impact.history.csv"), "--rtol-peak", "1e-7"],
                         capture_output=True, text=True)
    print(cmp.stdout.strip())
    if cmp.returncode != 0:
        failures.append(f"{name}: the histories differ from the direct solver's by more than 1e-7 of a peak")
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("multigrid: CG + Multigrid equals the direct solver on 1 and 2 ranks")
