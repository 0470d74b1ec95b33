#!/usr/bin/env python3
"""SDNV100 by explicit central differences (issue 14, README "SDNV100 at 0.5 % of the peak"):
input/sdnv100_explicit.xml on meshes of n HEX8 along (meshes/sdnv100_bar.geo, one across), dt
the largest step below COURANT x h / c that puts the contact instant 2e-5 s on a step (so the
separation, 1e-4 s, is one too), and prints per mesh the whole-history max error and RMS of
DZ(N5), DZ(N100), VZ(N100) and VZ(N5) against d'Alembert (% of each peak, from choc's log),
the energy balance and the wall time (median of --repeat runs of the whole process).
    sdnv100_explicit_study.py [--build build] [--out results/sdnv100_explicit]
                              [--sizes 40 320 640 1000] [--courant 0.99] [--repeat 3]"""
import argparse
import math
import os
import re
import statistics
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
C = 5000.0  # sqrt(E / rho), nu = 0


def deck(mesh, dt):
    s = open(os.path.join(ROOT, "input", "sdnv100_explicit.xml")).read()
    s = s.replace('value="../meshes/sdnv100_bar_1000.msh"', f'value="{mesh}"')
    s, n = re.subn(r'(<Parameter name="Time Step" type="double" value=")[^"]*"', rf'\g<1>{dt!r}"', s)
    assert n == 1 and mesh in s
    return s


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/sdnv100_explicit")
    ap.add_argument("--sizes", type=int, nargs="+", default=[40, 320, 640, 1000])
    ap.add_argument("--courant", type=float, default=0.99)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    choc = os.path.abspath(os.path.join(a.build, "choc"))
    os.makedirs(a.out, exist_ok=True)
    print("| HEX8 along | Courant | N5:DZ | N100:DZ | N100:VZ | N5:VZ | energy balance (J) | run (median) |")
    print("|---|---|---|---|---|---|---|---|")
    for n in a.sizes:
        mesh = os.path.abspath(os.path.join(a.out, f"bar_{n}.msh"))
        subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "n", str(n),
                        os.path.join(ROOT, "meshes", "sdnv100_bar.geo"), "-o", mesh],
                       check=True, stdout=subprocess.DEVNULL)
        h = 0.2 / n
        steps = math.ceil(2e-5 / (a.courant * h / C))
        dt = 2e-5 / steps
        path = os.path.join(a.out, f"n{n}.xml")
        with open(path, "w") as f:
            f.write(deck(mesh, dt))
        walls = []
        for _ in range(a.repeat):
            t0 = time.perf_counter()
            p = subprocess.run([choc, "run", path, "-o", os.path.join(a.out, f"n{n}")],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            walls.append(time.perf_counter() - t0)
            if p.returncode not in (0, 3):  # 3: some check NOOK (a coarse mesh misses 0.5 %)
                raise SystemExit(f"n = {n}: choc exited {p.returncode}:\n{p.stdout[-2000:]}")
        err = {m.group(1): (m.group(2), m.group(3)) for m in re.finditer(
            r"exact solution, (\S+)\s*: max error \S+ \(([\d.]+)% of peak.*?RMS ([\d.]+)% of peak", p.stdout)}
        bal = re.search(r"balance in \[(\S+), (\S+)\] J", p.stdout)
        cells = [" / ".join(f"{float(x):.3g}" for x in err[c]) for c in ("N5:DZ", "N100:DZ", "N100:VZ", "N5:VZ")]
        print(f"| {n} | {dt * C / h:.3f} | " + " | ".join(cells) +
              f" | [{float(bal.group(1)):.3g}, {float(bal.group(2)):.2g}] | {statistics.median(walls):.2f} s |",
              flush=True)


if __name__ == "__main__":
    main()
