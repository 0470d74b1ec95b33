#!/usr/bin/env python3
"""The oblique sphere (input/oblique_sphere.xml): a steel sphere hitting a rigid plane at 5 m/s,
60 degrees from the normal, Coulomb friction mu = 0.1, Lagrange contact, 60 steps of 1 us,
implicit ('auto': MUMPS on every rank for friction's saddle point). For each mesh (meshes/
oblique_sphere.geo's h near the contact and H beyond) and each 'Contact/Status Update' (the
status after each Newton correction, the default, or after converged solves), on 1 and 2 ranks:
the medians of --repeat runs of the time per step, with the Newton iterations per step,
factorisations and the tangential over the normal impulse (mu to 1e-4 is the phase's bound).
Writes results/bench/bench_oblique_sphere.json.

    bench_oblique_sphere.py [--build build] [--repeat 3] [--meshes 3.5e-4,3e-3 2e-4,2.5e-3] [--ranks 1 2]
(the defaults: 5,995 and 17,117 unknowns.)"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402
import numpy as np  # noqa: E402

TABLE = [["unknowns", "unknowns", ",d"], ["status", "Status Update", ""], ["ranks", "ranks", "d"],
         ["step_s", "time per step [s]", ".3f"], ["speedup", "1 rank / this", ".2f"],
         ["newton_per_step", "Newton per step", ".2f"], ["factorizations", "factorisations", "d"],
         ["krylov", "GMRES iterations on kept factorisations", "d"], ["peak_rss_mib", "peak memory [MiB]", ".0f"],
         ["ratio_error", "|impulse ratio / mu - 1|", ".1e"]]
AN = "Analyses/oblique"
MU = 0.1


def deck(mesh, status):
    d = chocrun.load_deck(chocrun.input_path("oblique_sphere.xml"))
    chocrun.set_param(d, "Mesh/File", mesh)
    chocrun.set_param(d, f"{AN}/Exodus Interval", 0)
    chocrun.set_param(d, f"{AN}/Contact/Status Update", status, create=True)
    return d


def impulse_ratio_error(out):
    h = chocrun.read_history(out, "oblique")
    ratio = np.trapz(h["plane:tangential_force"], h["time"]) / np.trapz(h["plane:force"], h["time"])
    return abs(ratio / MU - 1.0)


def main():
    ap = chocrun.bench_arguments(__doc__, "bench-oblique-sphere")
    ap.add_argument("--meshes", nargs="+", default=["3.5e-4,3e-3", "2e-4,2.5e-3"],
                    help="h,H pairs of meshes/oblique_sphere.geo [m]")
    ap.add_argument("--ranks", nargs="+", type=int, default=[1, 2])
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for pair in a.meshes:
        h, big = (float(x) for x in pair.split(","))
        mesh = chocrun.gmsh_mesh("oblique_sphere.geo", os.path.join(a.out, f"oblique_{h:g}.msh"), order=2, h=h, H=big)
        for status in ("each correction", "converged solve"):
            tag = status.split()[0]
            path = chocrun.write_deck(deck(mesh, status), os.path.join(a.out, f"oblique_{h:g}_{tag}.xml"))
            prefix = os.path.join(a.out, f"oblique_{h:g}_{tag}")
            for _, out, rec in chocrun.rank_sweep(choc, path, prefix, "oblique", a.ranks, a.repeat):
                rec.update({"status": status, "ratio_error": impulse_ratio_error(out)})
                rows.append(rec)
    tables = [{"title": f"The oblique sphere, 60 steps (medians of {a.repeat} runs)", "columns": TABLE}]
    chocrun.report_bench("bench_oblique_sphere", "The oblique sphere: frictional Newton", rows, tables, a)


if __name__ == "__main__":
    main()
