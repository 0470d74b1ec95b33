#!/usr/bin/env python3
"""The direct solver keeps its factorisation through changes of contact status ('Linear
Solver/Update Budget', src/solvers/DirectSolver.cpp): the scale scene's bars at 9,648 unknowns
(3 x 3 x 100 HEX8 per bar, tools/build/make-scale-mesh.sh) with Lagrange contact and Method = Direct,
100 steps of 1e-6 s (5 impacts, contact nodes opening and closing). With 'Update Budget' = 0
every change of status refactors; with the default (auto) the changed matrices are solved on
the kept factorisation (its capacitance form, or GMRES preconditioned by it). Checked: the histories agree to 1e-7 of each
peak (each solve is held to the direct solver's residual tolerance, 1e-8), the same impacts,
at most half the factorisations, and the log names the kept ones; on 2 ranks (the system
gathered to rank 0) the same histories.
usage: kept_factorization.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from scale_bars import bars_3_100, run_deck  # noqa: E402

choc, src, work, mesh = bars_3_100()
sys.path.insert(0, os.path.join(src, "tools", "bench"))
from bench_kept_factorization import scene  # noqa: E402  (the benchmark's scene, same edits)

base = scene(mesh, None)  # the default budget (auto)
refactor = scene(mesh, 0)
assert 'Update Budget' in refactor and 'Update Budget' not in base


def run(name, text, ranks=1):
    return run_deck(choc, work, name, text, ranks)


def figures(log):
    f = int(re.search(r"(\d+) factorisations", log).group(1))
    kept = re.search(r"\((\d+) changes of contact status solved on the factorisation kept", log)
    impacts = int(re.search(r"impacts of 'interface': (\d+)", log).group(1))
    return f, int(kept.group(1)) if kept else 0, impacts


def same(a, b):
    cmp = subprocess.run([sys.executable, os.path.join(src, "tools", "oracles", "compare_histories.py"),
                          os.path.join(work, a, "impact.history.csv"), os.path.join(work, b, "impact.history.csv"),
                          "--rtol-peak", "1e-7", "--columns", "A:DZ,A:VZ,C:DZ,interface:force,energy:total"],
                         capture_output=True, text=True)
    print(cmp.stdout)
    return cmp.returncode == 0


failures = []
r = figures(run("refactor", refactor))
k = figures(run("kept", base))
print(f"refactor: {r[0]} factorisations, {r[2]} impacts; kept: {k[0]} factorisations, "
      f"{k[1]} matrices solved on a kept one, {k[2]} impacts")
if r[1] != 0:
    failures.append("'Update Budget' = 0 still kept a factorisation")
if not (k[1] > 0 and 2 * k[0] <= r[0]):
    failures.append(f"the default budget kept {k[1]} factorisations and made {k[0]} against {r[0]}")
if k[2] != r[2]:
    failures.append(f"{k[2]} impacts against {r[2]}")
if not same("refactor", "kept"):
    failures.append("the histories with the kept factorisation differ from refactoring by more than 1e-7 of a peak")
k2 = figures(run("kept_np2", base, ranks=2))
print(f"2 ranks: {k2[0]} factorisations, {k2[1]} kept")
if k2[1] == 0:
    failures.append("on 2 ranks no factorisation was kept")
if not same("kept", "kept_np2"):
    failures.append("2 ranks differ from 1 by more than 1e-7 of a peak")
if failures:
    sys.exit("kept_factorization: " + "; ".join(failures))
print("kept_factorization: OK")
