#!/usr/bin/env python3
"""Stiffness-dominated implicit steps on the preconditioners of CG: input/scale-3d.xml's scene
(SDNL111's two bars in 3D, penalty contact, bar 2 clamped) on 7 x 7 x 400 HEX8 per bar (153,792
unknowns, tools/build/make-scale-mesh.sh), 5 steps at each --dt (1e-4 s: a stiffness-to-mass
ratio theta of 119,000; 3e-5 s: 10,600; 1e-5 s: 1,190) with CG and
  - Multigrid (MueLu smoothed aggregation for elasticity, src/solvers/ElasticityMultigrid.hpp),
  - Additive Schwarz (one subdomain per rank, ILU(0)),
  - Jacobi (skipped at theta 119,000, where it exceeds 1,000 iterations per solve),
on 1 and 2 ranks, the rank counts alternating within each repeat. Reports the medians over
--repeat runs of the linear-solve time, the Krylov iterations per Newton solve, the hierarchies
or preconditioners built, the analysis time and the peak memory per unknown, and the largest
difference of A:DZ from the Multigrid run on one rank, of its peak. Writes
results/bench/bench_multigrid.json.

    bench_multigrid.py [--build build] [--repeat 3] [--dt 1e-4 3e-5] [--ranks 1 2]
                       [--preconditioners Multigrid "Additive Schwarz" Jacobi] [--mesh 7 400]"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

TABLE = [["dt", "dt [s]", ".0e"], ["preconditioner", "preconditioner", ""], ["ranks", "ranks", "d"],
         ["solve_s", "linear solve [s]", ".1f"], ["per_solve", "Krylov per Newton solve", ".1f"],
         ["builds", "preconditioners built", "d"], ["analysis_s", "analysis [s]", ".1f"],
         ["bytes_per_unknown", "peak memory per unknown [B]", ".0f"],
         ["max_difference", "A:DZ vs Multigrid on 1 rank, of its peak", ".1e"]]


def deck(mesh, dt, preconditioner):
    d = chocrun.load_deck(chocrun.input_path("scale-3d.xml"))
    an = "Analyses/impact"
    chocrun.set_param(d, "Mesh/File", mesh)
    chocrun.set_param(d, f"{an}/Time Step", dt)
    chocrun.set_param(d, f"{an}/End Time", 5 * dt)
    chocrun.set_param(d, f"{an}/Exodus Interval", 0)
    chocrun.set_param(d, f"{an}/Linear Solver/Preconditioner", preconditioner)
    return d


def measure(choc, path, out, ranks):
    chocrun.run(choc, path, out, ranks=ranks)
    s = chocrun.require_completed(chocrun.read_summary(out, "impact"))
    v = lambda key: chocrun.summary_value(s, key)  # noqa: E731
    newton = max(1, v("newton")["iterations"])
    return {"unknowns": v("unknowns"), "solve_s": v("timers/linear_solve/max"),
            "per_solve": v("krylov_iterations") / newton, "builds": v("factorizations"),
            "analysis_s": v("timers/analysis/max"), "bytes_per_unknown": chocrun.bytes_per_unknown(s),
            "choc_commit": v("choc/commit")}


def main():
    ap = chocrun.bench_arguments(__doc__, "bench-multigrid")
    ap.add_argument("--dt", nargs="+", type=float, default=[1e-4, 3e-5])
    ap.add_argument("--ranks", nargs="+", type=int, default=[1, 2])
    ap.add_argument("--preconditioners", nargs="+", default=["Multigrid", "Additive Schwarz", "Jacobi"])
    ap.add_argument("--mesh", nargs=2, type=int, default=[7, 400], metavar=("ACROSS", "ALONG"))
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    mesh = os.path.join(a.out, f"bars_{a.mesh[0]}_{a.mesh[1]}.exo")
    chocrun.make_scale_mesh(choc, a.mesh[0], a.mesh[1], mesh)
    rows = []
    for dt in a.dt:
        reference = None
        for prec in a.preconditioners:
            if prec == "Jacobi" and dt >= 1e-4:
                continue  # over 1,000 iterations per solve (docs/performance/linear-solver-auto.md)
            tag = f"dt{dt:g}_{prec.replace(' ', '_')}"
            path = chocrun.write_deck(deck(mesh, dt, prec), os.path.join(a.out, tag + ".xml"))
            runs = {r: [] for r in a.ranks}
            for _ in range(a.repeat):
                for ranks in a.ranks:  # alternating: both rank counts see the same machine load
                    runs[ranks].append(measure(choc, path, os.path.join(a.out, f"{tag}_np{ranks}"), ranks))
            for ranks in a.ranks:
                rec = chocrun.median_record(runs[ranks])
                history = chocrun.read_history(os.path.join(a.out, f"{tag}_np{ranks}"), "impact")
                reference = reference if reference is not None else history
                rec["max_difference"] = max(chocrun.history_difference(reference, history, ["A:DZ"]).values())
                rec.update({"dt": dt, "preconditioner": prec, "ranks": ranks})
                rows.append(rec)
    tables = [{"title": f"CG preconditioners on stiffness-dominated steps, {rows[0]['unknowns']:,} unknowns "
                        f"(medians of {a.repeat} runs)" if rows else "", "columns": TABLE}]
    chocrun.report_bench("bench_multigrid", "Multigrid against Schwarz and Jacobi on stiffness-dominated steps",
                         rows, tables, a)


if __name__ == "__main__":
    main()
