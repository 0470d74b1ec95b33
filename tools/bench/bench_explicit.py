#!/usr/bin/env python3
"""Explicit benchmark (`make bench-explicit`): input/scale-3d.xml's scene (300,300
unknowns) by explicit central differences on 1 and 2 MPI ranks.

usage: tools/bench/bench_explicit.py [--build DIR] [--end-time T] [--repeat N] [--contact penalty lagrange]
                                     [--ranks 1 2] [--mesh ACROSS ALONG] [--json PATH]

The variant: lumped mass, 'Scheme' = 'central differences' with sub-steps, the mass part of
the Rayleigh damping only (a stiffness-proportional term would cut the critical step), penalty
8e8 N/m per slave node (twice the axial stiffness a node's share of an element carries,
E a^2 / 81 / h = 4e8 N/m: stiffer penalties make the contact nodes bounce with the lumped
mass), no Exodus output; or (--contact lagrange) forward-increment Lagrange multipliers, which
add no stiffness, so the mesh alone sets the critical step. Reports per contact method and run
the medians over --repeat runs of (from each run's summary): the analysis time, the time per
simulated microsecond and per (sub-)step and per unknown, the sub-steps, the peak resident
memory per rank and per unknown, and the np = 2 speed-up (the ranks' runs alternate; the median
over the repeats of each pair's ratio of analysis times). --mesh ACROSS ALONG runs the scene on
another mesh (tools/build/make-scale-mesh.sh: ACROSS x ACROSS x ALONG HEX8 per bar, made in the
work directory); e.g. --mesh 18 560 is 1,215,270 unknowns. --ranks chooses the rank counts.
Writes results/bench/bench_explicit.json (bench_explicit_<ACROSS>x<ALONG>.json with --mesh).
"""
import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

COLUMNS = [["contact", "contact", ""], ["np", "np", "d"], ["unknowns", "unknowns", ",d"],
           ["analysis_s", "analysis [s]", ".2f"], ["per_us_s", "per simulated us [s]", ".3f"],
           ["substeps", "sub-steps", ",d"], ["per_substep_ms", "per sub-step [ms]", ".1f"],
           ["per_substep_unknown_ns", "per sub-step and unknown [ns]", ".1f"],
           ["mib_per_rank", "peak memory per rank [MiB]", "list:.0f"], ["bytes_per_unknown", "bytes per unknown", ",.0f"],
           ["speedup", "np = 2 speed-up", ".2f"]]


def variant(end_time, contact="penalty", mesh=None):
    """The explicit variant of input/scale-3d.xml (a deck tree) and its analysis's name."""
    d = chocrun.load_deck(chocrun.input_path("scale-3d.xml"))
    name = chocrun.only_analysis(d)
    an = f"Analyses/{name}"
    if mesh:
        chocrun.set_param(d, "Mesh/File", mesh)
    for block in chocrun.sublists(d, "Model/Blocks"):
        chocrun.set_param(d, f"Model/Blocks/{block}/Mass", "lumped", create=True)
    chocrun.set_param(d, f"{an}/Scheme", "central differences")
    chocrun.remove_param(d, f"{an}/Alpha")
    chocrun.set_param(d, f"{an}/Stability Check", "substep", create=True)
    chocrun.set_param(d, f"{an}/Rayleigh Damping/Stiffness Coefficient", 0.0)
    if contact == "penalty":
        chocrun.set_param(d, f"{an}/Contact/Penalty Stiffness", 8e8)
    else:
        chocrun.set_param(d, f"{an}/Contact/Method", "Lagrange")
        chocrun.remove_param(d, f"{an}/Contact/Penalty Stiffness")
    chocrun.set_param(d, f"{an}/End Time", float(end_time))
    chocrun.set_param(d, f"{an}/Exodus Interval", 0)
    return d, name


def measure(choc, xml, analysis, np_, out, contact, end_time):
    chocrun.run(choc, xml, out, ranks=np_)
    s = chocrun.require_completed(chocrun.read_summary(out, analysis))
    t = chocrun.summary_value(s, "wall_seconds")
    sub = chocrun.substeps(s)
    n = chocrun.summary_value(s, "unknowns")
    return {"contact": contact, "np": np_, "unknowns": n, "analysis_s": t, "per_us_s": t / (end_time * 1e6),
            "substeps": sub, "per_substep_ms": 1e3 * t / sub, "per_substep_unknown_ns": 1e9 * t / sub / n,
            "critical_step": chocrun.summary_value(s, "critical_step"),
            "substeps_per_step": chocrun.summary_value(s, "substeps_per_step"),
            "mib_per_rank": chocrun.peak_mib_per_rank(s), "bytes_per_unknown": chocrun.bytes_per_unknown(s),
            "choc_commit": chocrun.summary_value(s, "choc/commit")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(chocrun.TOP, "build"))
    ap.add_argument("--end-time", type=float, default=5e-6)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--contact", nargs="+", choices=["penalty", "lagrange"], default=["penalty", "lagrange"])
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--mesh", type=int, nargs=2, metavar=("ACROSS", "ALONG"))
    ap.add_argument("--json", default=None, help="the figures' file (default results/bench/<bench>.json)")
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    work = tempfile.mkdtemp(prefix="choc-bench-explicit-")
    if a.mesh:
        mesh = chocrun.make_scale_mesh(choc, a.mesh[0], a.mesh[1], os.path.join(work, "scale_%d_%d.exo" % tuple(a.mesh)))
    else:
        mesh = chocrun.make_scale_mesh(choc)
    rows = []
    for contact in a.contact:
        deck, analysis = variant(a.end_time, contact, mesh)
        xml = chocrun.write_deck(deck, os.path.join(work, "explicit_%s.xml" % contact))
        # The ranks' runs alternate (np = 1, np = 2, np = 1, ...): the host's load, which moves
        # these figures by a quarter, then weighs on both sides of each speed-up alike.
        runs = {np_: [] for np_ in a.ranks}
        for k in range(a.repeat):
            for np_ in a.ranks:
                runs[np_].append(measure(choc, xml, analysis, np_, os.path.join(work, "%s_np%d_%d" % (contact, np_, k)),
                                         contact, a.end_time))
        mine = {np_: chocrun.median_record(runs[np_]) for np_ in a.ranks}
        if 1 in runs and 2 in runs:
            ratios = [r1["analysis_s"] / r2["analysis_s"] for r1, r2 in zip(runs[1], runs[2])]
            mine[2]["speedup"] = chocrun.median(ratios)
            mine[2]["speedup_pairs"] = sorted(ratios)
        rows += [mine[np_] for np_ in a.ranks]
    scene = "input/scale-3d.xml's scene" + (" on %d x %d x %d HEX8 per bar" % (a.mesh[0], a.mesh[0], a.mesh[1])
                                            if a.mesh else "")
    tables = [{"title": f"central differences, {scene}, {a.end_time:g} s simulated (medians of {a.repeat} runs)",
               "columns": COLUMNS,
               "note": "np = 2 speed-up: median over back-to-back pairs of np = 1 and np = 2 runs of the ratio "
                       "of their analysis times; mesh reading and assembly excluded"}]
    chocrun.print_tables(rows, tables)
    name = "bench_explicit" + ("_%dx%d" % tuple(a.mesh) if a.mesh else "")
    chocrun.write_bench_json(name, f"Explicit central differences: {scene}", rows, tables, vars(a), a.json,
                             choc_commit=rows[0]["choc_commit"] if rows else None)


if __name__ == "__main__":
    main()
