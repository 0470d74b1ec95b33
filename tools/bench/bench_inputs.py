#!/usr/bin/env python3
"""Wall time of each input (`make bench-inputs`; not a test): the whole process, start-up
included, best and median of N runs, and per analysis (from the last run's summaries) its
time, steps and time per step. Writes results/bench/bench_inputs.json.

usage: tools/bench/bench_inputs.py [--build DIR] [--repeat N] [--json PATH] [input ...]
       (default inputs: input/sdnl111?.xml)
"""
import argparse
import glob
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

COLUMNS = [["input", "input", ""], ["best_s", "best [s]", ".3f"], ["median_s", "median [s]", ".3f"],
           ["analyses", "per analysis (last run): time, steps, time per step", ""]]


def per_analysis(summaries):
    cells = []
    for name, s in summaries.items():
        t = chocrun.summary_value(s, "wall_seconds")
        steps = s.get("substeps_taken") or s.get("steps")
        cells.append(f"{name} {t:.3f} s" + (f", {steps} steps, {1e6 * t / steps:.0f} us/step" if steps else ""))
    return "; ".join(cells)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(chocrun.TOP, "build"))
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--json", default=None, help="the figures' file (default results/bench/<bench>.json)")
    ap.add_argument("inputs", nargs="*")
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    inputs = a.inputs or sorted(glob.glob(os.path.join(chocrun.TOP, "input", "sdnl111?.xml")))
    work = tempfile.mkdtemp(prefix="choc-bench-inputs-")
    rows = []
    for path in inputs:
        name = os.path.splitext(os.path.basename(path))[0]
        out = os.path.join(work, name)
        walls = []
        for _ in range(a.repeat):
            shutil.rmtree(out, ignore_errors=True)
            walls.append(chocrun.run(choc, os.path.abspath(path), out, ok=None).wall)
        names = chocrun.analyses(chocrun.load_deck(path, absolute_mesh=False))
        summaries = chocrun.read_summaries(out, names)
        rows.append({"input": name, "best_s": min(walls), "median_s": chocrun.median(walls), "repeat": a.repeat,
                     "walls_s": sorted(walls), "analyses": per_analysis(summaries),
                     "analysis_s": {n: chocrun.summary_value(s, "wall_seconds") for n, s in summaries.items()},
                     "status": {n: chocrun.summary_value(s, "status") for n, s in summaries.items()},
                     "choc_commit": chocrun.summary_value(next(iter(summaries.values())), "choc/commit")})
        print(f"{name:14s} {rows[-1]['best_s']:10.3f} {rows[-1]['median_s']:10.3f}   {rows[-1]['analyses']}",
              flush=True)
    tables = [{"title": f"each input, whole process (best and median of {a.repeat} runs, one rank)",
               "columns": COLUMNS}]
    chocrun.write_bench_json("bench_inputs", "Wall time of each input", rows, tables, vars(a), a.json,
                             choc_commit=rows[0]["choc_commit"] if rows else None)
    m = chocrun.machine()
    print(f"machine: {m['nproc']} cores, {m['cpu_model']}")
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
