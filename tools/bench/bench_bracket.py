#!/usr/bin/env python3
"""The bracket drop (input/bracket_drop.xml): a steel L-bracket (meshes/bracket.geo, TET10) falling at
3 m/s onto a tilted rigid plane, Coulomb friction mu = 0.2, Lagrange contact, 300 steps of 1 us,
  - implicit, 'auto' (the friction's saddle point: MUMPS on every rank, or GMRES + Jacobi with
    the pressures condensed when mass-dominated);
  - explicit central differences (lumped mass; forward-increment pressures and friction);
on 1 and 2 ranks, medians of --repeat runs of the time per step; and once, on one rank, the
implicit run with the lumped mass at a step of --reference-step (the reference of motion), with
each run's own contact mass: the implicit runs' default (the contact-surface nodes' mass
redistributed onto their elements' other nodes) and the explicit runs' (the standard lumped mass:
central differences need every diagonal entry positive). Reported: the largest difference of
TIP:DX, TIP:DZ and CORNER:DZ from that reference, of each peak, the friction work's relative
difference at the end, the largest energy balance over E0; for the explicit runs also the motion
against the redistributed reference (the two mass models' own difference, which shrinks with h).
Writes results/bench/bench_bracket.json.

    bench_bracket.py [--build build] [--repeat 3] [--sizes 3.7e-3] [--ranks 1 2] [--reference-step 1e-7]
(--sizes 1.5e-3: about 200,000 unknowns.)"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402
import numpy as np  # noqa: E402

TABLE = [["h_mm", "h [mm]", ".2f"], ["unknowns", "unknowns", ",d"], ["run", "run", ""], ["ranks", "ranks", "d"],
         ["step_s", "time per step [s]", ".4f"], ["speedup", "1 rank / this", ".2f"],
         ["newton_per_step", "Newton per step", ".2f"], ["peak_rss_mib", "peak memory [MiB]", ".0f"],
         ["motion", "motion vs reference, of the peak", ".1e"], ["work", "friction work vs reference", ".1e"],
         ["balance", "largest balance / E0", ".1e"], ["contact_mass", "contact mass", ""]]
MOTION = ["TIP:DX", "TIP:DZ", "CORNER:DZ"]
AN = "Analyses/drop"


def deck(mesh, run, dt=None, contact_mass=None):
    """input/bracket_drop.xml as `run` (implicit, explicit or reference) on `mesh` (None: the
    deck's own), with `contact_mass` when given."""
    d = chocrun.load_deck(chocrun.input_path("bracket_drop.xml"))
    if contact_mass:
        chocrun.set_param(d, f"{AN}/Contact Mass", contact_mass, create=True)
    if mesh:
        chocrun.set_param(d, "Mesh/File", mesh)
    chocrun.set_param(d, f"{AN}/Exodus Interval", 0)
    if run in ("explicit", "reference"):
        chocrun.set_param(d, "Model/Blocks/BRACKET/Mass", "lumped", create=True)
    if run == "explicit":
        chocrun.set_param(d, f"{AN}/Scheme", "central differences", create=True)
        chocrun.set_param(d, f"{AN}/Stability Check", "substep", create=True)
    if run == "reference":
        chocrun.set_param(d, f"{AN}/Time Step", dt)
    return d


def compare(ref, h):
    """The reference interpolated at h's times (its step divides h's)."""
    at = lambda c: np.interp(h["time"], ref["time"], ref[c])  # noqa: E731
    motion = max(np.max(np.abs(h[c] - at(c))) / np.max(np.abs(ref[c])) for c in MOTION)
    work = abs(h["floor:friction_work"][-1] / ref["floor:friction_work"][-1] - 1.0)
    e0 = h["energy:kinetic"][0]
    return motion, work, float(np.max(h["energy:balance"]) / e0)


def main():
    ap = chocrun.bench_arguments(__doc__, "bench-bracket")
    ap.add_argument("--sizes", nargs="+", type=float, default=[3.7e-3])
    ap.add_argument("--ranks", nargs="+", type=int, default=[1, 2])
    ap.add_argument("--reference-step", type=float, default=1e-7)
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for hsize in a.sizes:
        mesh = chocrun.gmsh_mesh("bracket.geo", os.path.join(a.out, f"bracket_{hsize:g}.msh"), order=2, h=hsize)
        references = {}
        for mass in ("redistributed", "standard"):
            ref_out = os.path.join(a.out, f"bracket_{hsize:g}_reference_{mass}")
            ref_path = chocrun.write_deck(deck(mesh, "reference", a.reference_step, mass), ref_out + ".xml")
            chocrun.run(choc, ref_path, ref_out)
            references[mass] = chocrun.read_history(ref_out, "drop")
        for run, mass in (("implicit", "redistributed"), ("explicit", "standard")):
            path = chocrun.write_deck(deck(mesh, run), os.path.join(a.out, f"bracket_{hsize:g}_{run}.xml"))
            prefix = os.path.join(a.out, f"bracket_{hsize:g}_{run}")
            for _, out, rec in chocrun.rank_sweep(choc, path, prefix, "drop", a.ranks, a.repeat):
                h = chocrun.read_history(out, "drop")
                rec["motion"], rec["work"], rec["balance"] = compare(references[mass], h)
                if mass != "redistributed":
                    rec["motion_redistributed"], rec["work_redistributed"], _ = compare(references["redistributed"], h)
                rec.update({"h_mm": 1e3 * hsize, "run": run, "contact_mass": mass})
                rows.append(rec)
    tables = [{"title": f"The bracket drop (medians of {a.repeat} runs; reference: implicit, lumped mass, "
                        f"dt = {a.reference_step:g} s, the run's contact mass)", "columns": TABLE}]
    chocrun.report_bench("bench_bracket", "The bracket drop, implicit and explicit", rows, tables, a)


if __name__ == "__main__":
    main()
