#!/usr/bin/env python3
"""The 'auto' linear solver on the scale scene's bars at 9,648 unknowns (3 x 3 x 100 HEX8 per bar,
tools/build/make-scale-mesh.sh), 20 steps of 1e-6 s (the impact at step 10): the log states CG + Jacobi with the reason
(mass-dominated), and the histories equal those of the same input with 'Method' = 'Direct' to
1e-7 of each peak (CG's tolerance 1e-10 on each solve). 'Newton/Linear Tolerance' = 'fixed'
(every solve to 1e-10) gives the same histories to 1e-7 of each peak with more Krylov iterations
than the default 'adaptive' (each solve only as far as Newton's residual test needs: its
tolerance 1e-8 of the force scale is a relative residual of 1e-9 or more). Then the same at dt =
1e-5 s, where the Newton matrix is stiffness-dominated: 'auto' states Direct.
usage: linear_solver_auto.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from scale_bars import bars_3_100  # noqa: E402

choc, src, work, mesh = bars_3_100()
base = open(os.path.join(src, "input", "scale-3d.xml")).read().replace('"../meshes/scale_3d.exo"', f'"{mesh}"')
base = base.replace('<Parameter name="Exodus Interval" type="int" value="20"/>',
                    '<Parameter name="Exodus Interval" type="int" value="0"/>')
auto = base.replace('<Parameter name="Method" type="string" value="CG"/>', '')
auto = auto.replace('<Parameter name="Preconditioner" type="string" value="Additive Schwarz"/>', '')
direct = base.replace('<Parameter name="Method" type="string" value="CG"/>',
                      '<Parameter name="Method" type="string" value="Direct"/>')
assert mesh in base and 'value="CG"' not in auto and 'value="Direct"' in direct


def run(name, text):
    path = os.path.join(work, name + ".xml")
    with open(path, "w") as f:
        f.write(text)
    p = subprocess.run([choc, "run", path, "-o", os.path.join(work, name)], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"{name}: choc exited {p.returncode}:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    return p.stdout


def krylov(log):
    return int(re.search(r"Krylov iterations: (\d+)", log).group(1))


def compare(name, columns="A:DZ,A:VZ,C:DZ,interface:force,energy:total"):
    cmp = subprocess.run([sys.executable, os.path.join(src, "tools", "oracles", "compare_histories.py"),
                          os.path.join(work, "direct", "impact.history.csv"),
                          os.path.join(work, name, "impact.history.csv"),
                          "--rtol-peak", "1e-7", "--columns", columns], capture_output=True, text=True)
    print(cmp.stdout)
    return cmp.returncode == 0


failures = []
log = run("auto", auto)
line = re.search(r"linear solver (.*)", log).group(1)
print("auto:", line)
if not re.match(r"Belos CG \+ Jacobi \('auto': 9,648 unknowns, symmetric, mass-dominated: stiffness/mass [0-9.]+ <= 100\)", line):
    failures.append("auto at dt = 1e-6 s did not state CG + Jacobi, mass-dominated: " + line)
run("direct", direct)
if not compare("auto"):
    failures.append("auto (CG + Jacobi) and Direct differ by more than 1e-7 of a peak")
fixed = auto.replace('<ParameterList name="Linear Solver">',
                     '<ParameterList name="Newton"><Parameter name="Linear Tolerance" type="string" '
                     'value="fixed"/></ParameterList><ParameterList name="Linear Solver">')
assert 'value="fixed"' in fixed
fixedLog = run("fixed", fixed)
print(f"Krylov iterations: adaptive {krylov(log)}, fixed {krylov(fixedLog)}")
if not compare("fixed"):
    failures.append("CG + Jacobi with 'Linear Tolerance' = 'fixed' and Direct differ by more than 1e-7 of a peak")
if not krylov(log) < krylov(fixedLog):
    failures.append(f"the adaptive linear tolerance took {krylov(log)} Krylov iterations, fixed {krylov(fixedLog)}")
stiff = auto.replace('<Parameter name="Time Step" type="double" value="1e-6"/>',
                     '<Parameter name="Time Step" type="double" value="1e-5"/>')
assert 'value="1e-5"' in stiff
line = re.search(r"linear solver (.*)", run("stiff", stiff)).group(1)
print("auto, dt = 1e-5 s:", line)
# The direct package: MUMPS where the build has it (above 5,000 unknowns), KLU2 otherwise.
if not re.match(r"(Amesos2 KLU2|MUMPS) \('auto': 9,648 unknowns, symmetric, stiffness-dominated: stiffness/mass [0-9.]+ > 100, at most 100,000 unknowns", line):
    failures.append("auto at dt = 1e-5 s did not state Direct, stiffness-dominated: " + line)
if failures:
    sys.exit("linear_solver_auto: " + "; ".join(failures))
print("linear_solver_auto: OK")
