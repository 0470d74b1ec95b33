#!/usr/bin/env python3
"""Reads, partitions and assembles a large TET10 mesh made by gmsh on 2 MPI ranks, reporting
the time and every rank's peak memory of each phase. Not a test: `make bench-mesh`.

usage: tools/bench/bench_large_mesh.py [--build DIR] [--n 20] [--ranks 2] [--json PATH]
n elements across meshes/cantilever_block.geo in TET10: n = 20 gives about 1.05 million
unknowns. `choc check` of a one-step transient sets it up: mesh read, element geometry check,
Zoltan2 partition, stiffness and mass assembly. Writes results/bench/bench_large_mesh.json.

The one tool that still reads choc's log: the per-phase set-up timings and memory (mesh read,
element geometry check, partition and DOF map, stiffness and mass assembly) are printed by
`choc check` and written to no file (<analysis>.summary.json is written by analyses that run,
and holds no set-up phase); the lines are matched strictly and a missing phase is an error.
"""
import argparse
import os
import re
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

chocrun.add_tool_path("study")
from modal_convergence import block_deck, mesh_block  # noqa: E402

TRANSIENT = """<ParameterList name="transient">
    <Parameter name="Type" type="string" value="Transient"/>
    <Parameter name="Time Step" type="double" value="1e-6"/>
    <Parameter name="End Time" type="double" value="1e-6"/>
    <ParameterList name="Linear Solver"><Parameter name="Method" type="string" value="CG"/></ParameterList>
  </ParameterList>"""
# The set-up phases `choc check` prints (src/app: "  <phase> (<detail>): <s> s; peak memory per
# rank [MiB]: <m> ..."): the log is read for these lines only (see the module's docstring).
PHASES = ("mesh read", "element geometry check", "partition and DOF map", "stiffness assembly", "mass assembly")
PHASE_LINE = re.compile(r"^  (?P<phase>[a-zA-Z ]+?)(?: \((?P<detail>[^)]*)\))?: (?P<s>[0-9.eE+-]+) s; "
                        r"peak memory per rank \[MiB\]: (?P<mib>[0-9. ]+)$")
COLUMNS = [["phase", "phase", ""], ["detail", "", ""], ["seconds", "time [s]", ".2f"],
           ["mib_per_rank", "peak memory per rank after it [MiB]", "list:.0f"]]


def phases(log):
    """The set-up phases of `choc check`'s log: [{phase, detail, seconds, mib_per_rank}]."""
    found = []
    for line in log.splitlines():
        m = PHASE_LINE.match(line)
        if m and m.group("phase") in PHASES:
            found.append({"phase": m.group("phase"), "detail": m.group("detail") or "",
                          "seconds": float(m.group("s")), "mib_per_rank": [float(x) for x in m.group("mib").split()]})
    missing = [p for p in PHASES if p not in {f["phase"] for f in found}]
    if missing:
        sys.exit(f"bench_large_mesh: choc check printed no line for {', '.join(missing)} (has its log changed? "
                 f"see PHASE_LINE)")
    return found


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(chocrun.TOP, "build"))
    ap.add_argument("--n", type=int, default=20)
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--json", default=None, help="the figures' file (default results/bench/<bench>.json)")
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    work = os.path.join(chocrun.TOP, "results", "bench_large_mesh")
    os.makedirs(work, exist_ok=True)
    start = time.time()
    mesh = mesh_block(work, a.n, False)
    print(f"gmsh mesh {mesh} ({os.path.getsize(mesh) / 1e6:.0f} MB) ready in {time.time() - start:.1f} s")
    deck = os.path.join(work, "deck.xml")
    with open(deck, "w") as f:
        f.write(block_deck(f"TET10, n = {a.n}", mesh, 0.3, TRANSIENT))
    r = chocrun.run(choc, deck, None, ranks=a.ranks, command="check")
    rows = phases(r.stdout)
    for row in rows:
        row["ranks"] = a.ranks
    tables = [{"title": f"TET10 block, n = {a.n}, {a.ranks} ranks: `choc check` set-up phases", "columns": COLUMNS,
               "note": f"whole `choc check` process: {r.wall:.1f} s wall"}]
    chocrun.print_tables(rows, tables)
    chocrun.write_bench_json("bench_large_mesh", "A large gmsh mesh read, partitioned and assembled", rows, tables,
                             dict(vars(a), mesh_mb=round(os.path.getsize(mesh) / 1e6, 1), check_wall_s=r.wall),
                             a.json)


if __name__ == "__main__":
    main()
