#!/usr/bin/env python3
"""Many active contact constraints between meshed bodies: input/stacked_plates.xml (the upper steel
plate pressed onto the lower at 1 m/s, every slave node of the non-matching interface active from
the first step, 5 steps of 1 us, CG + Jacobi with the pressures projected out) on
meshes/stacked_plates.geo with n = --sizes ((n + 1)^2 active constraints), G = C^T C factored
  - dense: Cholesky of the m x m matrix on every rank (m^2 doubles, m^3 / 3 operations per
    factorisation, m^2 per solve; the path below 300 active constraints),
  - sparse: KLU2 on each rank alone (solvers/ReplicatedSparseLU.hpp; the path from 300),
forced by the test hook CHOC_TEST_SPARSE_GRAM_FROM, dense only up to --dense-max. Reports per
size, path and rank count the medians over --repeat runs (the paths alternating) of the time per
step, the linear-solve and contact times, the Krylov iterations, the peak memory, and the
largest difference of interface:force from the dense run's, of its peak. Writes
results/bench/bench_projected_gram.json.

    bench_projected_gram.py [--build build] [--repeat 3] [--sizes 20 30 50 70 100] [--dense-max 70] [--ranks 1]"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

TABLE = [["n", "n", "d"], ["active", "active constraints", ",d"], ["unknowns", "unknowns", ",d"],
         ["path", "G factored", ""], ["ranks", "ranks", "d"], ["step_s", "time per step [s]", ".3f"],
         ["solve_s", "linear solve [s]", ".2f"], ["contact_s", "contact [s]", ".2f"],
         ["krylov", "Krylov iterations", "d"], ["peak_rss_mib", "peak memory [MiB]", ".0f"],
         ["max_difference", "interface:force vs dense, of its peak", ".1e"]]
PATHS = {"dense": "1000000000", "sparse": "1"}


def record(choc, path, out, ranks, hook):
    rec = chocrun.step_record(choc, path, out, "press", ranks, env={"CHOC_TEST_SPARSE_GRAM_FROM": hook})
    s = chocrun.read_summary(out, "press")
    rec["contact_s"] = chocrun.summary_value(s, "timers/contact/max", 0.0)
    return rec


def main():
    ap = chocrun.bench_arguments(__doc__, "bench-projected-gram")
    ap.add_argument("--sizes", nargs="+", type=int, default=[20, 30, 50, 70, 100])
    ap.add_argument("--dense-max", type=int, default=70)
    ap.add_argument("--ranks", nargs="+", type=int, default=[1])
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for n in a.sizes:
        mesh = chocrun.gmsh_mesh("stacked_plates.geo", os.path.join(a.out, f"plates_{n}.msh"), n=n)
        d = chocrun.load_deck(chocrun.input_path("stacked_plates.xml"))
        chocrun.set_param(d, "Mesh/File", mesh)
        path = chocrun.write_deck(d, os.path.join(a.out, f"plates_{n}.xml"))
        paths = [p for p in PATHS if p == "sparse" or n <= a.dense_max]
        for ranks in a.ranks:
            runs = {p: [] for p in paths}
            for _ in range(a.repeat):  # the paths alternating
                for p in paths:
                    runs[p].append(record(choc, path, os.path.join(a.out, f"plates_{n}_{p}_np{ranks}"), ranks, PATHS[p]))
            reference = chocrun.read_history(os.path.join(a.out, f"plates_{n}_{paths[0]}_np{ranks}"), "press")
            for p in paths:
                rec = chocrun.median_record(runs[p])
                history = chocrun.read_history(os.path.join(a.out, f"plates_{n}_{p}_np{ranks}"), "press")
                rec["max_difference"] = max(chocrun.history_difference(reference, history, ["interface:force"]).values())
                rec.update({"n": n, "active": (n + 1) ** 2, "path": p, "ranks": ranks})
                rows.append(rec)
    tables = [{"title": f"Stacked plates, the Gram matrix dense or sparse (medians of {a.repeat} runs)", "columns": TABLE}]
    chocrun.report_bench("bench_projected_gram", "Many active contact constraints: G dense or sparse", rows, tables, a)


if __name__ == "__main__":
    main()
