#!/usr/bin/env python3
"""The direct solver's packages on a contact scene: KLU2 (the system gathered on rank 0) against
MUMPS (factored on every rank, src/solvers/MumpsBackend.cpp), on 1 and 2 ranks. The scene is
tools/bench/bench_kept_factorization.py's: the scale scene's bars (tools/build/make-scale-mesh.sh)
with Lagrange contact and Method = Direct, 100 steps of 1e-6 s, statuses opening and closing,
the default Update Budget. Reports per size, package and rank count the medians over --repeat
runs of the analysis and linear-solve times, the factorisations, the peak memory, and the
largest difference of the histories from KLU2's on one rank, of each peak. Writes
results/bench/bench_direct_packages.json.

    bench_direct_packages.py [--build build] [--repeat 3] [--sizes 3x100 5x200] [--ranks 1 2]"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402
from bench_kept_factorization import COLUMNS, scene_deck  # noqa: E402

TABLE = [["size", "bars", ""], ["unknowns", "unknowns", ",d"], ["package", "package", ""], ["ranks", "ranks", "d"],
         ["analysis_s", "analysis [s]", ".2f"], ["solve_s", "linear solve [s]", ".2f"],
         ["factorizations", "factorisations", "d"], ["peak_rss_mib", "peak memory [MiB]", ".0f"],
         ["max_difference", "histories: max difference of a peak", ".1e"]]


def measure(choc, path, out, analysis, ranks):
    r = chocrun.run(choc, path, out, ranks=ranks)
    s = chocrun.require_completed(chocrun.read_summary(out, analysis))
    v = lambda key: chocrun.summary_value(s, key)  # noqa: E731
    return {"unknowns": v("unknowns"), "analysis_s": v("timers/analysis/max"), "solve_s": v("timers/linear_solve/max"),
            "factorizations": v("factorizations"), "peak_rss_mib": r.maxrss_mib,
            "choc_commit": v("choc/commit")}


def main():
    ap = chocrun.bench_arguments(__doc__, "bench-direct-packages")
    ap.add_argument("--sizes", nargs="+", default=["3x100", "5x200"])
    ap.add_argument("--ranks", nargs="+", type=int, default=[1, 2])
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for size in a.sizes:
        across, along = size.split("x")
        mesh = chocrun.make_scale_mesh(choc, across, along, os.path.join(a.out, f"bars_{across}_{along}.exo"))
        reference = None
        for package in ("KLU2", "MUMPS"):
            deck = scene_deck(mesh, None)
            analysis = chocrun.only_analysis(deck)
            chocrun.set_param(deck, f"Analyses/{analysis}/Linear Solver/Direct Package", package, create=True)
            path = chocrun.write_deck(deck, os.path.join(a.out, f"direct_{size}_{package}.xml"))
            for ranks in a.ranks:
                out = os.path.join(a.out, f"direct_{size}_{package}_np{ranks}")
                rec = chocrun.median_record([measure(choc, path, out, analysis, ranks) for _ in range(a.repeat)])
                history = chocrun.read_history(out, analysis)
                if reference is None:
                    reference = history
                rec["max_difference"] = max(chocrun.history_difference(reference, history, COLUMNS).values())
                rec.update({"size": size, "package": package, "ranks": ranks})
                rows.append(rec)
    tables = [{"title": f"KLU2 on rank 0 against MUMPS on every rank (medians of {a.repeat} runs)", "columns": TABLE}]
    chocrun.report_bench("bench_direct_packages", "Direct packages on a contact scene", rows, tables, a)


if __name__ == "__main__":
    main()
