#!/usr/bin/env python3
"""Reads, partitions and assembles a large TET10 mesh made by gmsh on 2 MPI ranks, printing
the time and every rank's peak memory of each phase (issue 13). Not a test: `make bench-mesh`.

usage: tools/bench_large_mesh.py [--build DIR] [--n 20] [--ranks 2]
n elements across meshes/cantilever_block.geo in TET10: n = 20 gives about 1.05 million
unknowns. `choc check` of a one-step transient sets it up: mesh read, element geometry check,
Zoltan2 partition, stiffness and mass assembly.
"""
import argparse
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from modal_convergence import TOP, block_deck, mesh_block  # noqa: E402

TRANSIENT = """<ParameterList name="transient">
    <Parameter name="Type" type="string" value="Transient"/>
    <Parameter name="Time Step" type="double" value="1e-6"/>
    <Parameter name="End Time" type="double" value="1e-6"/>
    <ParameterList name="Linear Solver"><Parameter name="Method" type="string" value="CG"/></ParameterList>
  </ParameterList>"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(TOP, "build"))
    ap.add_argument("--n", type=int, default=20)
    ap.add_argument("--ranks", type=int, default=2)
    a = ap.parse_args()
    work = os.path.join(TOP, "results", "bench_large_mesh")
    os.makedirs(work, exist_ok=True)
    start = time.time()
    mesh = mesh_block(work, a.n, False)
    print(f"gmsh mesh {mesh} ({os.path.getsize(mesh) / 1e6:.0f} MB) ready in {time.time() - start:.1f} s")
    deck = os.path.join(work, "deck.xml")
    with open(deck, "w") as f:
        f.write(block_deck(f"TET10, n = {a.n}", mesh, 0.3, TRANSIENT))
    run = subprocess.run(["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
                          "-np", str(a.ranks), os.path.join(a.build, "choc"), "check", deck],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"bench_large_mesh: choc check failed ({run.returncode}): {run.stderr.strip()}")
    for line in run.stdout.splitlines():
        if re.match(r"^  (mesh read|element geometry|partition|stiffness|mass)|^partition:|.*is valid", line):
            print(line)


if __name__ == "__main__":
    main()
