#!/usr/bin/env python3
"""Scale benchmark (`make bench`): input/scale-3d.xml on 1 and 2 MPI ranks.

usage: tools/bench/bench_scale.py [--build DIR] [--sizes] [--end-time T] [--repeat N]
                                  [--solver input|auto] [--mesh ACROSS ALONG] [--json PATH]
                                  [--contact lagrange [--friction MU]]

Generates meshes/scale_3d.exo (tools/build/make-scale-mesh.sh) when missing, runs the input with
np = 1 and np = 2 (mpirun --allow-run-as-root --oversubscribe --bind-to none), and reports, per
run, from each run's impact.summary.json: the unknowns, the wall time of the process (mesh
reading, assembly, set-up, steps) and the analysis time, the time per step split into assembly,
linear solve, contact and output (each the slowest rank's timer), Krylov iterations per step,
the peak resident memory of every rank and per unknown, the speed-up and the parallel
efficiency, each rank's CPU time, and the load average before the run (other processes on the
machine distort the figures: read them next to it).
--sizes also runs smaller meshes (same scene, 20 steps) for the growth of time per step and
memory with the unknowns. --repeat N runs np = 1 and np = 2 in turn N times and reports the
median of each figure over the N runs and the median of the N pairs' speed-ups (the host's load
weighs on both runs of a pair). --solver auto drops the input's 'Method' and 'Preconditioner'
(CG + Additive Schwarz), so that the default linear solver 'auto' chooses (CG + Jacobi here,
mass-dominated) with the default adaptive linear tolerance, and compares its np = 1 histories
with one run of the input as written. --mesh ACROSS ALONG runs the scene on another mesh (made
in the work directory; e.g. --mesh 3 40 for a smoke test).
--contact lagrange runs the scene with Lagrange contact (no penalty stiffness; with --friction MU
a Coulomb coefficient on the pair) beside the input's penalty contact with the same linear
solver, np = 1 and 2 for each, and reports Lagrange's time per step over penalty's per np (the
issue's bounds: 1.5 without friction, 2.5 with) and the largest difference of their histories.
Writes the figures to results/bench/bench_scale.json (bench_scale_auto.json with --solver auto),
from which tools/docs/performance_pages.py makes docs/performance/generated/.
"""
import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

COLUMNS = [["series", "run", ""], ["np", "np", "d"], ["unknowns", "unknowns", ",d"], ["wall_s", "wall [s]", ".2f"],
           ["analysis_s", "analysis [s]", ".2f"], ["steps", "steps", "d"], ["ms_per_step", "ms/step", ",.1f"],
           ["assembly_ms", "assembly", ",.1f"], ["solve_ms", "solve", ",.1f"], ["contact_ms", "contact", ".1f"],
           ["output_ms", "output", ".1f"], ["krylov_per_step", "Krylov/step", ".1f"],
           ["mib_per_rank", "MiB per rank", "list:.0f"], ["bytes_per_unknown", "B/unknown (all ranks)", ",.0f"],
           ["speedup", "speed-up", ".2f"], ["efficiency", "eff.", ".2f"], ["load", "load", ".1f"],
           ["cpu_s_per_rank", "CPU s per rank", "list:.1f"]]
NOTE = ("ms/step = analysis time / steps; assembly, solve, contact, output per step from the slowest "
        "rank's timers; speed-up and efficiency on the analysis time (median over back-to-back pairs "
        "of runs); wall includes start-up, mesh reading and matrix assembly; load = 1-min load "
        "average before the run; CPU = each rank's process time; medians over the repeats")


def measure(choc, xml, np_, outdir, series):
    """One run's figures, from its summary."""
    r = chocrun.run(choc, xml, outdir, ranks=np_)
    s = chocrun.require_completed(chocrun.read_summary(outdir, ANALYSIS))
    v = lambda key: chocrun.summary_value(s, key)  # noqa: E731
    steps = max(v("steps"), 1)
    newton = v("newton/iterations")
    krylov = v("krylov_iterations")
    rec = {"series": series, "np": v("ranks"), "unknowns": v("unknowns"), "wall_s": r.wall, "load": r.load,
           "analysis_s": v("timers/analysis/max"), "steps": v("steps"), "newton": newton,
           "krylov_per_step": krylov / steps, "krylov_per_newton": krylov / max(newton, 1),
           "mib_per_rank": chocrun.peak_mib_per_rank(s), "bytes_per_unknown": chocrun.bytes_per_unknown(s),
           "cpu_s_per_rank": v("cpu_seconds_per_rank"), "linear_solver": v("linear_solver/description"),
           "factorizations": v("factorizations"),
           "choc_commit": v("choc/commit")}
    for key, timer in (("assembly_ms", "assembly"), ("solve_ms", "linear_solve"), ("contact_ms", "contact"),
                       ("output_ms", "output")):
        rec[key] = 1e3 * v(f"timers/{timer}/max") / steps
    rec["ms_per_step"] = 1e3 * rec["analysis_s"] / steps
    return rec


def median_runs(choc, xml, repeat, tmp, prefix, series):
    """Runs xml on np = 1 and np = 2 in turn `repeat` times (the host's load then weighs on both
    runs of a pair); returns each np's median figures, the np = 2 one with the median speed-up
    of the pairs and the largest difference of its histories from np = 1's."""
    runs = {1: [], 2: []}
    for _ in range(repeat):
        for np_ in (1, 2):
            runs[np_].append(measure(choc, xml, np_, os.path.join(tmp, f"{prefix}{np_}"), series))
    rows = [chocrun.median_record(runs[np_]) for np_ in (1, 2)]
    pairs = sorted(r1["analysis_s"] / r2["analysis_s"] for r1, r2 in zip(runs[1], runs[2]))
    rows[1]["speedup"] = chocrun.median(pairs)
    rows[1]["efficiency"] = rows[1]["speedup"] / 2
    rows[1]["speedup_pairs"] = pairs
    diff = compare(os.path.join(tmp, f"{prefix}1"), os.path.join(tmp, f"{prefix}2"))
    rows[1]["histories_vs_np1"] = diff
    print(f"{series}, {rows[0]['unknowns']:,} unknowns: np = 2 histories against np = 1, max |diff| / peak: "
          + ", ".join(f"{c} {d:.1e}" for c, d in diff.items()))
    return rows


def compare(reference_dir, other_dir):
    """{column: max |other - reference| / peak} of the two runs' histories."""
    return chocrun.history_difference(chocrun.read_history(reference_dir, ANALYSIS),
                                      chocrun.read_history(other_dir, ANALYSIS))


ANALYSIS = "impact"


def main():
    global ANALYSIS
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(chocrun.TOP, "build"))
    ap.add_argument("--sizes", action="store_true")
    ap.add_argument("--end-time", type=float, default=None)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--solver", choices=("input", "auto"), default="input")
    ap.add_argument("--mesh", type=int, nargs=2, metavar=("ACROSS", "ALONG"),
                    help="run on ACROSS x ACROSS x ALONG HEX8 per bar instead of meshes/scale_3d.exo")
    ap.add_argument("--json", default=None, help="the figures' file (default results/bench/<bench>.json)")
    ap.add_argument("--contact", choices=("input", "lagrange"), default="input")
    ap.add_argument("--friction", type=float, default=0.0)
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    tmp = tempfile.mkdtemp(prefix="choc-bench-")
    if a.mesh:
        mesh = chocrun.make_scale_mesh(choc, a.mesh[0], a.mesh[1], os.path.join(tmp, "scale_%d_%d.exo" % tuple(a.mesh)))
    else:
        mesh = chocrun.make_scale_mesh(choc)
    m = chocrun.machine()
    print(f"machine: {m['nproc']} cores, {m['cpu_model']}")
    deck = chocrun.load_deck(chocrun.input_path("scale-3d.xml"))
    ANALYSIS = chocrun.only_analysis(deck)
    an = f"Analyses/{ANALYSIS}"
    chocrun.set_param(deck, "Mesh/File", mesh)
    if a.end_time:
        chocrun.set_param(deck, f"{an}/End Time", a.end_time)
    as_written = chocrun.write_deck(deck, os.path.join(tmp, "scale-3d.xml"))
    series = "input/scale-3d.xml" + (" (own mesh)" if a.mesh else "")
    src = as_written
    if a.solver == "auto":
        chocrun.remove_param(deck, f"{an}/Linear Solver/Method")
        chocrun.remove_param(deck, f"{an}/Linear Solver/Preconditioner")
        src = chocrun.write_deck(deck, os.path.join(tmp, "scale-3d-auto.xml"))
        series += ", linear solver 'auto'"
    if a.contact == "lagrange":
        return lagrange_against_penalty(choc, deck, an, src, series, a, tmp)
    runs = median_runs(choc, src, a.repeat, tmp, "np", series)
    print("linear solver:", runs[0]["linear_solver"])
    if a.solver == "auto":
        ref = measure(choc, as_written, 1, os.path.join(tmp, "as_written"), "as written (one run)")
        ref["repeat"] = 1
        runs.append(ref)
        diff = compare(os.path.join(tmp, "as_written"), os.path.join(tmp, "np1"))
        runs[0]["histories_vs_as_written"] = diff
        print("'auto' against the input as written, np = 1, max |diff| / peak: "
              + ", ".join(f"{c} {d:.1e}" for c, d in diff.items()))
    tables = [{"title": series + (f" (medians of {a.repeat} runs per np)" if a.repeat > 1 else ""),
               "columns": COLUMNS, "where": {"series": series}, "note": NOTE}]
    if a.solver == "auto":
        tables.append({"title": "input/scale-3d.xml as written (one run)", "columns": COLUMNS,
                       "where": {"series": "as written (one run)"}})
    if a.sizes:
        base = chocrun.load_deck(chocrun.input_path("scale-3d.xml"))
        for across, along in ((3, 250), (5, 300), (7, 400)):
            mesh_s = chocrun.make_scale_mesh(choc, across, along, os.path.join(tmp, f"m{across}_{along}.exo"))
            d = chocrun.parse_deck(chocrun.deck_text(base))
            chocrun.set_param(d, "Mesh/File", mesh_s)
            chocrun.set_param(d, f"{an}/End Time", 2e-5)
            x = chocrun.write_deck(d, os.path.join(tmp, f"m{across}_{along}.xml"))
            runs += median_runs(choc, x, a.repeat, tmp, f"s{across}_", "sizes")
        tables.append({"title": "sizes (20 steps, contact from step 10)" +
                       (f" (medians of {a.repeat} runs per np)" if a.repeat > 1 else ""),
                       "columns": COLUMNS, "where": {"series": "sizes"}, "note": NOTE})
    chocrun.print_tables(runs, tables)
    name = "bench_scale" + ("_auto" if a.solver == "auto" else "")
    chocrun.write_bench_json(name, "Scale: the implicit scale scene on 1 and 2 ranks" +
                             (", linear solver 'auto'" if a.solver == "auto" else ""),
                             runs, tables, vars(a), a.json, choc_commit=runs[0]["choc_commit"])
    print(f"\nruns in {tmp}")


LAGRANGE_COLUMNS = COLUMNS[:7] + [["solve_ms", "solve", ",.1f"], ["krylov_per_step", "Krylov/step", ".1f"],
                                  ["newton", "Newton", "d"], ["factorizations", "set-ups", "d"],
                                  ["vs_penalty", "time/step over penalty's", ".2f"], ["speedup", "speed-up", ".2f"],
                                  ["mib_per_rank", "MiB per rank", "list:.0f"], ["load", "load", ".1f"]]


def lagrange_against_penalty(choc, deck, an, penalty_xml, series, a, tmp):
    """The scene with Lagrange contact (and friction) beside the penalty deck, the same solver."""
    chocrun.set_param(deck, f"{an}/Contact/Method", "Lagrange")
    chocrun.remove_param(deck, f"{an}/Contact/Penalty Stiffness")
    label = "Lagrange"
    if a.friction > 0:
        pair = chocrun.sublists(deck, f"{an}/Contact/Pairs")[0]
        chocrun.set_param(deck, f"{an}/Contact/Pairs/{pair}/Friction Coefficient", a.friction, create=True)
        label += f", mu = {a.friction:g}"
    lagrange_xml = chocrun.write_deck(deck, os.path.join(tmp, "scale-3d-lagrange.xml"))
    penalty = median_runs(choc, penalty_xml, a.repeat, tmp, "pen", series + ", penalty")
    lagrange = median_runs(choc, lagrange_xml, a.repeat, tmp, "lag", series + ", " + label)
    for p, l in zip(penalty, lagrange):
        l["vs_penalty"] = l["ms_per_step"] / p["ms_per_step"]
    diff = compare(os.path.join(tmp, "pen1"), os.path.join(tmp, "lag1"))
    lagrange[0]["histories_vs_penalty"] = diff
    print("Lagrange against penalty, np = 1, max |diff| / peak: " + ", ".join(f"{c} {d:.1e}" for c, d in diff.items()))
    print("linear solver (Lagrange):", lagrange[0]["linear_solver"])
    runs = penalty + lagrange
    title = f"{series}: {label} contact against penalty" + (f" (medians of {a.repeat} runs per np)" if a.repeat > 1 else "")
    tables = [{"title": title, "columns": LAGRANGE_COLUMNS, "note": NOTE}]
    chocrun.print_tables(runs, tables)
    name = "bench_scale_lagrange" + ("_auto" if a.solver == "auto" else "") + ("_friction" if a.friction > 0 else "")
    chocrun.write_bench_json(name, "Scale: the implicit scale scene with " + label + " contact against penalty",
                             runs, tables, vars(a), a.json, choc_commit=runs[0]["choc_commit"])
    print(f"\nruns in {tmp}")


if __name__ == "__main__":
    main()
