#!/usr/bin/env python3
"""Contact status changes on a kept factorisation ('Linear Solver/Update Budget',
src/solvers/DirectSolver.cpp): the scale scene's bars (tools/build/make-scale-mesh.sh) with
Lagrange contact and Method = Direct (KLU2), 100 steps of 1e-6 s (two impacts of the bars,
contact nodes opening and closing), at growing sizes, with 'Update Budget' = 0 (refactor at
every change of status, as before), the default budget with 'Update Form' = GMRES, and the
defaults (the capacitance form first). Reports per size and run the medians
over --repeat runs of (from each run's summary) the analysis and linear-solve times, the
factorisations, the matrices solved on a kept factorisation, the GMRES iterations, and the
largest difference of the histories (A:DZ, A:VZ, C:DZ, the contact force, the total energy)
between the two, of each peak. Writes results/bench/bench_kept_factorization.json.

    bench_kept_factorization.py [--build build] [--repeat 3] [--sizes 3x100 5x200 7x300] [--json PATH]"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

COLUMNS = ["A:DZ", "A:VZ", "C:DZ", "interface:force", "energy:total"]
TABLE = [["unknowns", "unknowns", ",d"], ["budget", "Update Budget", ""], ["form", "Update Form", ""], ["analysis_s", "analysis [s]", ".2f"],
         ["solve_s", "linear solve [s]", ".2f"], ["factorizations", "factorisations", "d"],
         ["kept_factorizations", "solved on a kept one", "d"], ["krylov_iterations", "GMRES iterations", "d"],
         ["max_difference", "histories: max difference of a peak", ".1e"]]


def scene_deck(mesh, budget, form=None):
    """The scene as a deck tree: input/scale-3d.xml on `mesh`, Lagrange contact, Direct, 1e-4 s,
    no Exodus output, the energy balance warned about only, 'Update Budget' = budget and
    'Update Form' = form (None: the defaults)."""
    d = chocrun.load_deck(chocrun.input_path("scale-3d.xml"))
    an = "Analyses/" + chocrun.only_analysis(d)
    chocrun.set_param(d, "Mesh/File", mesh)
    chocrun.set_param(d, f"{an}/Exodus Interval", 0)
    chocrun.set_param(d, f"{an}/Contact/Method", "Lagrange")
    chocrun.remove_param(d, f"{an}/Contact/Penalty Stiffness")
    chocrun.set_param(d, f"{an}/Linear Solver/Method", "Direct")
    chocrun.remove_param(d, f"{an}/Linear Solver/Preconditioner")
    chocrun.set_param(d, f"{an}/End Time", 1e-4)
    # The input's standard contact mass under Lagrange contact chatters (+5.8 % of E0 at 9,648
    # unknowns): that is what makes the statuses change here, the solver's workload, not a result.
    chocrun.set_param(d, f"{an}/Energy Balance Check", "warn", create=True)
    if budget is not None:
        chocrun.set_param(d, f"{an}/Linear Solver/Update Budget", int(budget), create=True)
    if form is not None:
        chocrun.set_param(d, f"{an}/Linear Solver/Update Form", form, create=True)
    return d


def scene(mesh, budget):
    """scene_deck's text (tests/cli/scripts/kept_factorization.py runs the same scene)."""
    return chocrun.deck_text(scene_deck(mesh, budget))


def measure(choc, path, out, analysis):
    chocrun.run(choc, path, out)
    s = chocrun.require_completed(chocrun.read_summary(out, analysis))
    v = lambda key: chocrun.summary_value(s, key)  # noqa: E731
    return {"unknowns": v("unknowns"), "analysis_s": v("timers/analysis/max"), "solve_s": v("timers/linear_solve/max"),
            "factorizations": v("factorizations"), "kept_factorizations": v("kept_factorizations"),
            "krylov_iterations": v("krylov_iterations"), "impacts": v("impacts/interface/number_of_impacts"),
            "choc_commit": v("choc/commit")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(chocrun.TOP, "build"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sizes", nargs="+", default=["3x100", "5x200", "7x300"])
    ap.add_argument("--out", default=os.path.join(chocrun.TOP, "results", "bench-kept-factorization"))
    ap.add_argument("--json", default=None, help="the figures' file (default results/bench/<bench>.json)")
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for size in a.sizes:
        across, along = size.split("x")
        mesh = chocrun.make_scale_mesh(choc, across, along, os.path.join(a.out, f"bars_{across}_{along}.exo"))
        results = {}
        for label, budget, form in (("0", 0, None), ("gmres", None, "GMRES"), ("auto", None, None)):
            deck = scene_deck(mesh, budget, form)
            analysis = chocrun.only_analysis(deck)
            path = chocrun.write_deck(deck, os.path.join(a.out, f"kept_{size}_{label}.xml"))
            out = os.path.join(a.out, f"kept_{size}_{label}")
            rec = chocrun.median_record([measure(choc, path, out, analysis) for _ in range(a.repeat)])
            rec["budget"] = "0 (refactor)" if label == "0" else "auto"
            rec["form"] = "" if label == "0" else (form or "capacitance")
            results[label] = (rec, chocrun.read_history(out, analysis))
        ref = results["0"][1]
        for label in ("0", "gmres", "auto"):
            rec, h = results[label]
            if label != "0":
                rec["max_difference"] = max(chocrun.history_difference(ref, h, COLUMNS).values())
            rec["size"] = size
            rows.append(rec)
    tables = [{"title": f"Refactoring against a kept factorisation (medians of {a.repeat} runs, one rank)",
               "columns": TABLE}]
    chocrun.print_tables(rows, tables)
    chocrun.write_bench_json("bench_kept_factorization", "Contact status changes on a kept factorisation",
                             rows, tables, vars(a), a.json, choc_commit=rows[0]["choc_commit"] if rows else None)


if __name__ == "__main__":
    main()
