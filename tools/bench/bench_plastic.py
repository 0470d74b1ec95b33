#!/usr/bin/env python3
"""The cost of explicit plasticity per element-cycle (`make bench-plastic`): the 3D Taylor bar
(input/taylor_bar_3d.xml: copper, J2 with linear hardening, finite strain, the quarter with symmetry
planes, 227 m/s onto a rigid wall, central differences) for its first --end-time (10 us by default:
the plastic front runs through the impact end), on meshes/taylor_bar_3d.geo with --n elements across
the radius:
  - HEX8 F-bar (the input's formulation: locking-free),
  - HEX8 one-point (one material update per element, hourglass stiffness at the default coefficient),
  - HEX8 standard (locks in plastic flow; the cost of F-bar's mean dilatation beside it),
  - TET10 standard (the same grid cut into tetrahedra, tets = 1, -order 2),
on 1 and 2 ranks; and the anchor's scene: HEX8 one-point on the finer quarter (--anchor-n, 8 by
default: 10,368 elements) at the default interval of the critical step's estimate (100 steps), the
run docs/performance/plasticity.md compares with the issue's anchor (0.33 us per element-cycle for
an explicit code's one-point hexahedron; the target 1.5 times that). Per run: the element-cycles
(elements x sub-steps), the internal force's time per element-cycle (the assembly timer of the
slowest rank times the ranks: the CPU per element and sub-step) and the whole analysis' per
element-cycle likewise. Medians of --repeat runs.
Writes results/bench/bench_plastic.json.

    bench_plastic.py [--build build] [--repeat 3] [--n 4] [--anchor-n 8] [--end-time 1e-5] [--ranks 1 2]"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

TABLE = [["element", "element", ""], ["ranks", "ranks", "d"], ["elements", "elements", ",d"],
         ["unknowns", "unknowns", ",d"], ["substeps", "sub-steps", ",d"],
         ["force_us", "internal force per element-cycle [us]", ".3f"],
         ["cycle_us", "whole step per element-cycle [us]", ".3f"], ["speedup", "1 rank / this", ".2f"],
         ["wall_s", "wall [s]", ".2f"]]
# (label, tets, order, formulation, the anchor's scene: --anchor-n and the default estimate interval)
SCENES = [("HEX8 F-bar", 0, 1, "F-bar", False), ("HEX8 one-point", 0, 1, "one-point", False),
          ("HEX8 standard", 0, 1, "standard", False), ("TET10 standard", 1, 2, "standard", False),
          ("HEX8 one-point, estimate every 100", 0, 1, "one-point", True)]


def recorder(elements):
    """The per-run figures of chocrun.rank_sweep for a mesh of `elements` elements."""
    def record(choc, deck, out, analysis, ranks):
        r = chocrun.run(choc, deck, out, ranks=ranks)
        s = chocrun.require_completed(chocrun.read_summary(out, analysis))
        cycles = elements * chocrun.substeps(s)
        value = lambda key: chocrun.summary_value(s, key)  # noqa: E731
        return {"unknowns": value("unknowns"), "substeps": chocrun.substeps(s),
                "step_s": value("timers/analysis/max") / value("steps"),
                "force_us": 1e6 * ranks * value("timers/assembly/max") / cycles,
                "cycle_us": 1e6 * ranks * value("timers/analysis/max") / cycles,
                "wall_s": r.wall, "choc_commit": value("choc/commit")}
    return record


def main():
    ap = chocrun.bench_arguments(__doc__, "bench-plastic")
    ap.add_argument("--n", type=int, default=4)
    ap.add_argument("--anchor-n", type=int, default=8)
    ap.add_argument("--end-time", type=float, default=1e-5)
    ap.add_argument("--ranks", nargs="+", type=int, default=[1, 2])
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    a.out = os.path.abspath(a.out)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for label, tets, order, formulation, anchor in SCENES:
        n = a.anchor_n if anchor else a.n
        msh = chocrun.gmsh("taylor_bar_3d.geo", os.path.join(a.out, f"bar_tets{tets}_n{n}.msh"), 3, "-order", order,
                           "-setnumber", "n", n, "-setnumber", "tets", tets)
        elements = chocrun.count_gmsh_elements(msh, 3)
        d = chocrun.load_deck(chocrun.input_path("taylor_bar_3d.xml"))
        chocrun.set_param(d, "Mesh/File", msh)
        chocrun.set_param(d, "Model/Blocks/BAR/Formulation", formulation)
        chocrun.set_param(d, "Analyses/impact/End Time", a.end_time)
        chocrun.set_param(d, "Analyses/impact/Time Step", 4e-8 * 4 / n)
        chocrun.set_param(d, "Analyses/impact/Exodus Interval", 1000000)
        if anchor:
            chocrun.remove_param(d, "Analyses/impact/Critical Step Interval")  # the default, 100
        tag = label.replace(" ", "_").replace("-", "").replace(",", "")
        deck = chocrun.write_deck(d, os.path.join(a.out, tag + ".xml"))
        sweep = chocrun.rank_sweep(choc, deck, os.path.join(a.out, tag), "impact", a.ranks, a.repeat,
                                   recorder(elements))
        for _, _, rec in sweep:
            rec.update({"element": label + (f", n = {n}" if anchor else ""), "elements": elements})
            rows.append(rec)
    tables = [{"title": f"Explicit J2 per element-cycle, the 3D Taylor bar's first {a.end_time * 1e6:g} us "
                        f"(medians of {a.repeat} runs)", "columns": TABLE}]
    chocrun.report_bench("bench_plastic", "The cost of explicit plasticity", rows, tables, a)


if __name__ == "__main__":
    main()
