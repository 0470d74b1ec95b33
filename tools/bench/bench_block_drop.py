#!/usr/bin/env python3
"""A compact 3D body with Lagrange and penalty contact: input/compact_block.xml (a 0.1 m steel
cube dropped flat on a rigid plane at 1 m/s, its lower face in contact from the first step, 10
steps of 1 us) on n x n x n HEX8 (meshes/compact_block.geo), with
  - Lagrange contact and 'auto': the pressures condensed out of the Newton system (every pair
    against an obstacle), CG + Jacobi at this step (src/contact/ContactCondensation.hpp);
  - Penalty contact (penalty stiffness 1e11 N/m per node) with 'auto' (CG + Jacobi), the
    reference the issue compares Lagrange with;
  - Lagrange contact with Method = Direct, Direct Package = MUMPS (the saddle-point system,
    factored on every rank), at the sizes of --direct-sizes only (its fill on a compact graph);
on 1 and 2 ranks. Reports per size, run and rank count the medians over --repeat runs of the time
per step, the analysis and linear-solve times, the Krylov iterations, the factorisations, the
largest process's memory and that memory per unknown, the time per step over the penalty run's
(same size and ranks), and the largest difference of corner:DZ from the first run's, of its
peak. Writes results/bench/bench_block_drop.json.

    bench_block_drop.py [--build build] [--repeat 3] [--sizes 20 30 45] [--direct-sizes 20] [--ranks 1 2]"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

TABLE = [["n", "n", "d"], ["unknowns", "unknowns", ",d"], ["run", "run", ""], ["ranks", "ranks", "d"],
         ["step_s", "time per step [s]", ".3f"], ["solve_s", "linear solve [s]", ".2f"],
         ["krylov", "Krylov iterations", "d"], ["factorizations", "factorisations", "d"],
         ["peak_rss_mib", "peak memory [MiB]", ".0f"], ["kib_per_unknown", "memory per unknown [KiB]", ".1f"],
         ["vs_penalty", "time per step / penalty's", ".2f"],
         ["max_difference", "corner:DZ vs the first run, of its peak", ".1e"]]
RUNS = {"Lagrange, auto": ("Lagrange", "auto", None), "Penalty, auto": ("Penalty", "auto", None),
        "Lagrange, MUMPS": ("Lagrange", "Direct", "MUMPS")}


def deck(mesh, method, solver, package):
    d = chocrun.load_deck(chocrun.input_path("compact_block.xml"))
    an = "Analyses/drop"
    chocrun.set_param(d, "Mesh/File", mesh)
    chocrun.set_param(d, f"{an}/Contact/Method", method)
    if method == "Penalty":
        chocrun.set_param(d, f"{an}/Contact/Penalty Stiffness", 1e11, type="double", create=True)
    chocrun.set_param(d, f"{an}/Linear Solver/Method", solver, create=True)
    if package:
        chocrun.set_param(d, f"{an}/Linear Solver/Direct Package", package, create=True)
    return d


def main():
    ap = chocrun.bench_arguments(__doc__, "bench-block-drop")
    ap.add_argument("--sizes", nargs="+", type=int, default=[20, 30, 45])
    ap.add_argument("--direct-sizes", nargs="+", type=int, default=[20])
    ap.add_argument("--ranks", nargs="+", type=int, default=[1, 2])
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for n in a.sizes:
        mesh = chocrun.gmsh_mesh("compact_block.geo", os.path.join(a.out, f"block_{n}.msh"), n=n)
        reference = None
        for label, (method, solver, package) in RUNS.items():
            if package and n not in a.direct_sizes:
                continue
            path = chocrun.write_deck(deck(mesh, method, solver, package),
                                      os.path.join(a.out, f"block_{n}_{method}_{package or solver}.xml"))
            for ranks in a.ranks:
                out = os.path.join(a.out, f"block_{n}_{method}_{package or solver}_np{ranks}")
                rec = chocrun.median_record([chocrun.step_record(choc, path, out, "drop", ranks)
                                             for _ in range(a.repeat)])
                history = chocrun.read_history(out, "drop")
                reference = reference if reference is not None else history
                rec["max_difference"] = max(chocrun.history_difference(reference, history, ["corner:DZ"]).values())
                rec.update({"n": n, "run": label, "ranks": ranks})
                rows.append(rec)
    for r in rows:
        penalty = [p for p in rows if p["run"] == "Penalty, auto" and p["n"] == r["n"] and p["ranks"] == r["ranks"]]
        r["vs_penalty"] = r["step_s"] / penalty[0]["step_s"] if penalty and penalty[0]["step_s"] > 0 else float("nan")
    tables = [{"title": f"A compact block on a rigid plane (medians of {a.repeat} runs)", "columns": TABLE}]
    chocrun.report_bench("bench_block_drop", "A compact block dropped on a rigid plane", rows, tables, a)


if __name__ == "__main__":
    main()
