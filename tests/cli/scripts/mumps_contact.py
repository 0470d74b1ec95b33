#!/usr/bin/env python3
"""MUMPS ('Linear Solver/Direct Package' = MUMPS, src/solvers/MumpsBackend.cpp) solves the
contact systems that KLU2 solves on rank 0, on every rank:
  - the scale scene's bars at 9,648 unknowns with Lagrange contact, 100 steps of 1e-6 s (the
    saddle-point system, statuses opening and closing; tools/bench/bench_kept_factorization.py's
    scene): MUMPS on 1 and 2 ranks against KLU2 on 1;
  - input/sliding_friction.xml's Lagrange run (Coulomb friction: a tangent that is not
    symmetric): MUMPS against KLU2;
  - input/compact_block.xml (a compact 3D body, the lower face of a cube on a rigid plane):
    MUMPS on 1 and 2 ranks against KLU2.
Checked: each run completes, its log names MUMPS, the histories agree with KLU2's to 1e-7 of
each peak (each solve is held to the direct solver's residual tolerance, 1e-8, and Newton's to
1e-8; for friction, the columns that are not round-off of the summation order) and the impacts
are the same.
usage: mumps_contact.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from scale_bars import bars_3_100, run_deck  # noqa: E402

choc, src, work, mesh = bars_3_100()
sys.path.insert(0, os.path.join(src, "tools", "bench"))
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402
from bench_kept_factorization import scene_deck  # noqa: E402


def with_package(deck, analysis, package):
    chocrun.set_param(deck, f"Analyses/{analysis}/Linear Solver/Method", "Direct", create=True)
    chocrun.set_param(deck, f"Analyses/{analysis}/Linear Solver/Direct Package", package, create=True)
    return chocrun.deck_text(deck)


def run(name, text, ranks=1):
    return run_deck(choc, work, name, text, ranks)


def same(a, b, history, columns):
    cmp = subprocess.run([sys.executable, os.path.join(src, "tools", "oracles", "compare_histories.py"),
                          os.path.join(work, a, history), os.path.join(work, b, history),
                          "--rtol-peak", "1e-7", "--columns", columns], capture_output=True, text=True)
    print(cmp.stdout.strip())
    return cmp.returncode == 0


def impacts(log, pair):
    m = re.search(r"impacts of '%s': (\d+)" % pair, log)
    return int(m.group(1)) if m else None


failures = []
bars = lambda package: with_package(scene_deck(mesh, None), "impact", package)  # noqa: E731
logs = {"klu2": run("klu2", bars("KLU2")), "mumps": run("mumps", bars("MUMPS")),
        "mumps_np2": run("mumps_np2", bars("MUMPS"), ranks=2)}
for name in ("mumps", "mumps_np2"):
    if "linear solver MUMPS" not in logs[name]:
        failures.append(f"{name}: the log does not name MUMPS as the linear solver")
    if impacts(logs[name], "interface") != impacts(logs["klu2"], "interface"):
        failures.append(f"{name}: {impacts(logs[name], 'interface')} impacts against KLU2's "
                        f"{impacts(logs['klu2'], 'interface')}")
    if not same("klu2", name, "impact.history.csv", "A:DZ,A:VZ,C:DZ,interface:force,energy:total"):
        failures.append(f"{name}: the histories differ from KLU2's by more than 1e-7 of a peak")

def friction(package):
    deck = chocrun.load_deck(os.path.join(src, "input", "sliding_friction.xml"))
    chocrun.keep_analyses(deck, ["lagrange"])
    return with_package(deck, "lagrange", package)


analysis = "lagrange"
run("friction_klu2", friction("KLU2"))
log = run("friction_mumps", friction("MUMPS"))
if "linear solver MUMPS" not in log:
    failures.append("friction: the log does not name MUMPS")
# The columns regression/sliding_friction compares across rank counts (its RANK_COLUMNS): the
# strain energy of the translated block, the balance built from it and the gap (zero in
# contact) are round-off of the summation order; so is the stick force once the block rests,
# k_t times a relative motion whose round-off is eps |u| (1e10 N/m x 2e-16 x 5 m ~ 1e-5 N).
if not same("friction_klu2", "friction_mumps", analysis + ".history.csv",
            "BLOCK_TOP_CORNER:DX,BLOCK_TOP_CORNER:VX,slide:force,slide:friction_work,energy:kinetic"):
    failures.append("friction: the histories differ from KLU2's by more than 1e-7 of a peak")
def block(package):
    deck = chocrun.load_deck(os.path.join(src, "input", "compact_block.xml"))
    return with_package(deck, "drop", package)


run("block_klu2", block("KLU2"))
for name, ranks in (("block_mumps", 1), ("block_mumps_np2", 2)):
    run(name, block("MUMPS"), ranks)
    if not same("block_klu2", name, "drop.history.csv", "corner:DZ,corner:VZ,floor:force,energy:total"):
        failures.append(f"{name}: the compact block's histories differ from KLU2's by more than 1e-7 of a peak")
if failures:
    sys.exit("mumps_contact: " + "; ".join(failures))
print("mumps_contact: OK")
