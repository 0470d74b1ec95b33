#!/usr/bin/env python3
"""Issue 73's friction scene: input/block_on_slab.xml (a 0.1 m steel cube dropped flat at 1 m/s on
a meshed 0.2 m slab clamped at its base, node-to-face Lagrange contact on non-matching nodes, 20
steps of 1 us at the implicit defaults) on meshes/block_on_slab.geo (n = 20, m = 40, k = 6:
58,041 unknowns), with Coulomb friction mu = 0.2 and without, at each --masses contact mass
(auto: redistributed with this consistent mass). Reports per run the medians over --repeat runs
of the Newton corrections per step, the time per step, the linear-solve time, the Krylov iterations and
factorisations, the time per step over the frictionless run's (same contact mass), and the
largest difference of corner:DZ from the frictionless auto run's, of its peak. Writes
results/bench/bench_block_on_slab.json.

    bench_block_on_slab.py [--build build] [--repeat 3] [--n 20] [--m 40] [--masses auto normal "velocity update"]"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

TABLE = [["run", "run", ""], ["unknowns", "unknowns", ",d"], ["newton_per_step", "Newton corrections per step", ".2f"],
         ["step_s", "time per step [s]", ".3f"], ["solve_s", "linear solve [s]", ".2f"],
         ["krylov", "Krylov iterations", "d"], ["factorizations", "factorisations", "d"],
         ["vs_frictionless", "time per step / frictionless", ".2f"],
         ["max_difference", "corner:DZ vs the frictionless auto run, of its peak", ".1e"]]


def deck(mesh, mu, mass):
    d = chocrun.load_deck(chocrun.input_path("block_on_slab.xml"))
    chocrun.set_param(d, "Mesh/File", mesh)
    chocrun.set_param(d, "Analyses/drop/Contact/Pairs/floor/Friction Coefficient", mu)
    if mass != "auto":
        chocrun.set_param(d, "Analyses/drop/Contact Mass", mass, create=True)
    return d


def main():
    ap = chocrun.bench_arguments(__doc__, "bench-block-on-slab")
    ap.add_argument("--n", type=int, default=20)
    ap.add_argument("--m", type=int, default=40)
    ap.add_argument("--masses", nargs="+", default=["auto", "normal", "velocity update"])
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    mesh = chocrun.gmsh_mesh("block_on_slab.geo", os.path.join(a.out, f"block_on_slab_{a.n}_{a.m}.msh"), n=a.n, m=a.m)
    rows, reference = [], None
    for mass in a.masses:
        for mu in (0.0, 0.2):
            tag = f"{mass.replace(' ', '_')}_mu{mu:g}"
            path = chocrun.write_deck(deck(mesh, mu, mass), os.path.join(a.out, tag + ".xml"))
            out = os.path.join(a.out, tag)
            rec = chocrun.median_record([chocrun.step_record(choc, path, out, "drop") for _ in range(a.repeat)])
            history = chocrun.read_history(out, "drop")
            reference = reference if reference is not None else history
            rec["max_difference"] = max(chocrun.history_difference(reference, history, ["corner:DZ"]).values())
            rec.update({"run": f"{mass}, mu = {mu:g}", "mass": mass, "mu": mu})
            rows.append(rec)
    for r in rows:
        base = [p for p in rows if p["mass"] == r["mass"] and p["mu"] == 0.0]
        r["vs_frictionless"] = r["step_s"] / base[0]["step_s"] if base and base[0]["step_s"] > 0 else float("nan")
    tables = [{"title": f"A compact block dropped on a meshed slab (medians of {a.repeat} runs)", "columns": TABLE}]
    chocrun.report_bench("bench_block_on_slab", "A compact block dropped on a meshed slab, with and without friction",
                         rows, tables, a)


if __name__ == "__main__":
    main()
