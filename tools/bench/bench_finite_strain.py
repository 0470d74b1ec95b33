#!/usr/bin/env python3
"""The cost of finite strain (`make bench-finite`): the same scene with 'Strain' = 'small' (an
assembled stiffness: one sparse product per step) and 'finite' (the internal force element by
element: F, the neo-Hookean stress, f_e, at every quadrature point), on 1 and 2 ranks.

  - explicit: a free body spun about its axis (Initial Conditions 'Rigid Velocity', omega = 100
    rad/s), central differences with the lumped mass, 'Stability Check' = 'substep', --steps
    steps; per mesh: the time per step and per element and step, and the finite over small ratio;
  - implicit: the same body by average acceleration (10 us steps): the time per step, the
    Newton iterations, and the assembly (internal force and tangent) and linear solve per
    Newton iteration.
Meshes: meshes/compact_block.geo (HEX8, --cube n per side: 20 gives 27,783 unknowns) and
meshes/oblique_sphere.geo (TET10, the default 5,995 unknowns). Medians of --repeat runs.
Writes results/bench/bench_finite_strain.json.

    bench_finite_strain.py [--build build] [--repeat 3] [--cube 20] [--steps 100] [--ranks 1 2]"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

TABLE = [["mesh", "mesh", ""], ["scheme", "scheme", ""], ["strain", "Strain", ""], ["ranks", "ranks", "d"],
         ["unknowns", "unknowns", ",d"], ["elements", "elements", ",d"], ["step_s", "time per step [s]", ".4f"],
         ["per_element_us", "per element and step [us]", ".3f"], ["ratio", "finite / small", ".2f"],
         ["speedup", "1 rank / this", ".2f"], ["newton_per_step", "Newton per step", ".2f"],
         ["assembly_per_newton_s", "assembly per Newton [s]", ".4f"], ["solve_per_newton_s", "solve per Newton [s]", ".4f"]]


def deck(mesh, block, centre, strain, scheme, steps, dt):
    law = "neo-Hookean" if strain == "finite" else "linear elastic"
    return chocrun.spin_deck(mesh, block, (0, 0, 100), centre, scheme, dt, steps * dt, strain, law,
                             extra='\n    <Parameter name="Stability Check" type="string" value="substep"/>')


def main():
    ap = chocrun.bench_arguments(__doc__, "bench-finite-strain")
    ap.add_argument("--cube", type=int, default=20)
    ap.add_argument("--steps", type=int, default=100)
    ap.add_argument("--ranks", nargs="+", type=int, default=[1, 2])
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    meshes = [("HEX8 cube", chocrun.gmsh_mesh("compact_block.geo", os.path.join(a.out, "cube.msh"), order=1, n=a.cube),
               "block", (0.05, 0.05, 0.05)),
              ("TET10 sphere", chocrun.gmsh_mesh("oblique_sphere.geo", os.path.join(a.out, "sphere.msh"), order=2),
               "SPHERE", (0, 0.01, 0))]
    rows = []
    for label, mesh, block, centre in meshes:
        elements = chocrun.count_gmsh_elements(mesh, 3)
        for scheme, dt, steps in (("central differences", 1e-7, a.steps), ("average acceleration", 1e-5, 20)):
            small = {}
            for strain in ("small", "finite"):
                tag = f"{label.split()[0]}_{scheme.split()[0]}_{strain}"
                path = os.path.join(a.out, tag + ".xml")
                with open(path, "w") as f:
                    f.write(deck(mesh, block, centre, strain, scheme, steps, dt))
                for n, out, rec in chocrun.rank_sweep(choc, path, os.path.join(a.out, tag), "spin", a.ranks, a.repeat):
                    s = chocrun.read_summary(out, "spin")
                    newton = max(1, rec["newton_per_step"] * chocrun.summary_value(s, "steps"))
                    rec.update({"mesh": label, "scheme": scheme, "strain": strain, "elements": elements,
                                "per_element_us": 1e6 * rec["step_s"] / elements,
                                "assembly_per_newton_s": chocrun.summary_value(s, "timers/assembly/max", 0.0) / newton,
                                "solve_per_newton_s": rec["solve_s"] / newton})
                    if strain == "small":
                        small[n] = rec["step_s"]
                    rec["ratio"] = rec["step_s"] / small[n] if n in small else 1.0
                    rows.append(rec)
    tables = [{"title": f"Small against finite strain (medians of {a.repeat} runs)", "columns": TABLE}]
    chocrun.report_bench("bench_finite_strain", "The cost of finite strain", rows, tables, a)


if __name__ == "__main__":
    main()
