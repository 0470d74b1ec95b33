#!/usr/bin/env python3
"""Explicit against implicit, error against cost (part of `make study`).

Four scenes with a closed form, each run by both schemes on a series of meshes. For the bars
the time step is tied to the mesh (Courant number about 1, where both schemes are most accurate
for a bar's wave) and the error is over the whole history:
  - SDNV100 (docs/verification/sdnv100.md): input/sdnv100_explicit.xml (central differences, lumped
    mass, forward-increment Lagrange contact) and input/sdnv100.xml's analysis 'lagrange'
    (Newmark beta = 0.28, gamma = 0.55 as the deck, consistent mass with the massless contact
    face; and 'implicit, trapezoidal': beta = 1/4, gamma = 1/2, no numerical damping), n HEX8
    along (meshes/sdnv100_bar.geo), dt = 2e-5 / ceil(2e-5 / (C h / c)) so that
    the contact instant falls on a step; error: DZ(N5), the contact face.
  - SDNL111 D's scene (two 3D bars, lateral motion blocked): input/sdnl111d_explicit.xml and
    input/sdnl111d.xml (HHT alpha = -0.1 as the deck; 'implicit, trapezoidal': alpha = 0), both
    with Lagrange contact instead of their penalties (whose stiffness was chosen for 50
    elements), the implicit one at the default contact mass, n HEX8 along each bar (`choc mesh
    --dim 3`), dt = C h / c
    (c the oedometric speed, 5,875 m/s; C = 1 implicit, 0.95 explicit, below its critical step
    h / c); error: DZ(N1), bar 1's contact face.
  - SDNL111 C's scene: the same with C's Rayleigh damping (1e-7 K + 1e-3 M) in both schemes,
    the implicit run input/sdnl111c.xml's first analysis (alpha = -0.1) at the default contact
    mass; the exact solution is the undamped one, as in C's regression case.
  - Hertz's impact, axisymmetric (input/hertz.xml: average acceleration, dt 0.1 to 0.4 us;
    central differences on the lumped TRI6 mass with forward-increment Lagrange contact, 0.1 us
    steps cut into sub-steps), TRI6 of 0.2 to 0.025 mm near the first point of contact
    (meshes/hertz_axisymmetric.geo); error: the largest of the peak force's, the contact
    duration's and the largest approach's differences from Hertz (tools/oracles/hertz.py). Hertz's
    half-space theory is itself about 3.7 % from the finite sphere (README, section "Contact"),
    so each run is also compared with the finest one, the discretisation's share.
Cost: the whole process's wall time (start-up, mesh, assembly included), median of --repeat
runs. Prints one table per scene and, per scene and scheme, the cheapest run within 1 % and
0.1 % of the peak (for Hertz also within 1 % of the finest run), and writes OUT/study.csv.
The errors, steps and sub-steps come from each analysis's <analysis>.summary.json (its exact-
solution checks made to report their rows), the decks are edited through tools/lib/chocrun.py.
    explicit_implicit_study.py [--build build] [--out results/explicit_implicit] [--repeat 2]
"""
import argparse
import copy
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

chocrun.add_tool_path("oracles")
import hertz  # noqa: E402

ROOT = chocrun.TOP


def deck(name, keep=None):
    """input/NAME as a deck tree (mesh path absolute), with only the analysis `keep` if given."""
    d = chocrun.load_deck(chocrun.input_path(name))
    if keep:
        chocrun.keep_analyses(d, [keep])
    return d


def edited(d, **params):
    """A copy of the one-analysis deck d with the analysis's parameters set (keyword: the
    parameter's name with '_' for ' ', e.g. Time_Step=1e-6)."""
    d = copy.deepcopy(d)
    an = "Analyses/" + chocrun.only_analysis(d)
    for key, value in params.items():
        chocrun.set_param(d, f"{an}/{key.replace('_', ' ')}", value)
    return d


def run(choc, xml, outdir, repeat, analysis):
    """Runs xml `repeat` times; returns its whole-history errors {column: % of the peak}, the median
    wall time of the process, the (sub-)steps taken and the sub-step (None without sub-steps), all
    from the analysis's summary."""
    walls = []
    for _ in range(repeat):
        # 3: a check NOOK (coarse meshes miss the rows)
        walls.append(chocrun.run(choc, xml, outdir, ok=(chocrun.EXIT_OK, chocrun.EXIT_CHECK_FAILED)).wall)
    s = chocrun.require_completed(chocrun.read_summary(outdir, analysis), ("completed", "check failed"))
    err = {c: 100 * e["max"] for c, e in chocrun.exact_errors(s).items() if "max" in e}
    # Explicit runs may cut each step into sub-steps (at 0.9 of the critical step).
    per = s.get("substeps_per_step")
    substep = chocrun.summary_value(s, "time_step") / per if per else None
    return err, chocrun.median(walls), chocrun.substeps(s), substep


def run_on(choc, out, tag, d, mesh, dt, repeat):
    """Runs the one-analysis deck `d` on `mesh` with step dt and no Exodus output as OUT/TAG.xml
    into OUT/TAG, its exact-solution errors reported as rows; returns run()'s errors, wall time,
    steps and sub-step."""
    d = edited(d, Time_Step=float(dt), Exodus_Interval=0)
    chocrun.set_param(d, "Mesh/File", mesh)
    analysis = chocrun.only_analysis(d)
    chocrun.report_exact_errors(d, analysis)
    xml = chocrun.write_deck(d, os.path.join(out, tag + ".xml"))
    return run(choc, xml, os.path.join(out, tag), repeat, analysis)


def measure(choc, out, scene, scheme, n, d, mesh, dt, h, c, quantities, repeat):
    """Runs the deck `d` on `mesh` with step dt (no Exodus output) and returns its row:
    the max errors of `quantities` (the first is the row's error), the sub-step actually taken
    and the Courant number c dt / h."""
    tag = f"{scene.replace(' ', '').lower()}_{scheme.replace(', ', '_')}_{n}"
    err, wall, steps, substep = run_on(choc, out, tag, d, mesh, dt, repeat)
    dt = substep or dt
    print(f"  {scene} {scheme} n = {n}: {err[quantities[0]]:.3g} % in {wall:.2f} s", flush=True)
    return {"scene": scene, "scheme": scheme, "along": n, "dt": dt, "courant": dt * c / h, "steps": steps,
            "error": err[quantities[0]], "error_other": err[quantities[1]] if len(quantities) > 1 else "",
            "wall": wall}


def sdnv100(choc, out, repeat):
    C = 5000.0
    rows = []
    explicit = deck("sdnv100_explicit.xml")
    implicit = deck("sdnv100.xml", "lagrange")
    trapezoidal = edited(implicit, Beta=0.25, Gamma=0.5)
    plans = [("explicit", n, 0.988) for n in (40, 80, 160, 320, 640, 1000)] + \
            [(scheme, n, 1.0) for scheme in ("implicit", "implicit, trapezoidal") for n in (20, 40, 80, 160, 320, 640)]
    for scheme, n, courant in plans:
        mesh = os.path.join(out, f"sdnv100_bar_{n}.msh")
        if not os.path.exists(mesh):
            chocrun.gmsh("sdnv100_bar.geo", mesh, 3, "-setnumber", "n", n)
        h = 0.2 / n
        dt = 2e-5 / math.ceil(2e-5 / (courant * h / C) - 1e-9)
        d = {"explicit": explicit, "implicit": implicit, "implicit, trapezoidal": trapezoidal}[scheme]
        rows.append(measure(choc, out, "SDNV100", scheme, n, d, mesh, dt, h, C, ("N5:DZ", "N100:DZ"), repeat))
    return rows


def bars(choc, out, repeat, scene, explicit, implicit):
    """SDNL111's two 3D bars (lateral motion blocked) by `explicit` and `implicit` (decks,
    Lagrange contact), the implicit one also with alpha = 0 (trapezoidal), on n HEX8 along each
    bar; error: DZ(N1), bar 1's contact face, against d'Alembert."""
    E, nu, rho = 2e11, 0.3, 7800.0
    C = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho)  # lateral motion blocked
    rows = []
    trapezoidal = edited(implicit, Alpha=0.0)
    for scheme, d in (("explicit", explicit), ("implicit", implicit), ("implicit, trapezoidal", trapezoidal)):
        for n in (50, 100, 200, 400, 800) + ((1600,) if scheme == "explicit" else ()):
            mesh = os.path.join(out, f"sdnl111_3d_{n}.exo")
            if not os.path.exists(mesh):
                chocrun.mesh(choc, mesh, "--dim", 3, "--axis", "z", "--along1", n, "--along2", n,
                             "--width", 0.02, "--height", 0.02, "--gap", 1e-5)
            h = 1.0 / n
            # Central differences' critical step is h / c here (the element bound, exact on a
            # regular bar): 0.95 of it, which the stability check accepts without sub-steps
            # (with C's stiffness-proportional damping the fine meshes' steps are cut).
            dt = (0.95 if scheme == "explicit" else 1.0) * h / C
            rows.append(measure(choc, out, scene, scheme, n, d, mesh, dt, h, C, ("N1:DZ",), repeat))
    return rows


def lagrange(d):
    """The one-analysis deck d with Lagrange contact instead of its penalty (whose stiffness was
    chosen for 50 elements)."""
    an = "Analyses/" + chocrun.only_analysis(d)
    if chocrun.get_param(d, f"{an}/Contact/Method") != "Penalty":
        raise SystemExit(f"explicit_implicit_study: {an} has no penalty contact to replace")
    chocrun.set_param(d, f"{an}/Contact/Method", "Lagrange")
    chocrun.remove_param(d, f"{an}/Contact/Penalty Stiffness")
    return d


def default_contact_mass(d):
    """Lagrange contact at the default contact mass (the surfaces' mass redistributed)."""
    an = "Analyses/" + chocrun.only_analysis(d)
    if chocrun.get_param(d, f"{an}/Contact Mass") != "standard":
        raise SystemExit(f"explicit_implicit_study: {an}/Contact Mass is not 'standard'")
    chocrun.remove_param(d, f"{an}/Contact Mass")
    return d


def sdnl111d(choc, out, repeat):
    return bars(choc, out, repeat, "SDNL111 D", lagrange(deck("sdnl111d_explicit.xml")),
                default_contact_mass(lagrange(deck("sdnl111d.xml"))))


def sdnl111c(choc, out, repeat):
    """C: D's scene with C's Rayleigh damping (1e-7 K + 1e-3 M) in both schemes; the implicit
    run is input/sdnl111c.xml's first analysis (modified average acceleration, alpha = -0.1)."""
    implicit = default_contact_mass(deck("sdnl111c.xml", "c1_modified"))
    explicit = lagrange(deck("sdnl111d_explicit.xml"))
    chocrun.copy_sublist(implicit, "Analyses/c1_modified/Rayleigh Damping",
                         explicit, "Analyses/" + chocrun.only_analysis(explicit))
    return bars(choc, out, repeat, "SDNL111 C", explicit, implicit)


HERTZ_QUANTITIES = ("peak force", "contact duration", "largest approach")


def hertz_run(choc, out, scheme, size, dt, d, repeat):
    """input/hertz.xml's sphere (axisymmetric TRI6, Lagrange contact) meshed with elements of
    `size` near the first point of contact, steps of dt; error: the largest of the peak force's,
    the contact duration's and the largest approach's differences from Hertz."""
    mesh = os.path.join(out, f"hertz_h{size * 1e3:g}mm.msh")
    if not os.path.exists(mesh):
        chocrun.gmsh("hertz_axisymmetric.geo", mesh, 2, "-order", 2, "-setnumber", "h", repr(size))
    tag = f"hertz_{scheme.replace(', ', '_')}_h{size * 1e3:g}mm_dt{dt * 1e9:g}ns"
    _, wall, steps, substep = run_on(choc, out, tag, d, mesh, dt, repeat)
    m = hertz.measure(os.path.join(out, tag, "axisymmetric.history.csv"), hertz.hertz())
    diffs = {q: 100 * (m[q][0] / m[q][1] - 1) for q in HERTZ_QUANTITIES}
    worst = max(diffs.values(), key=abs)
    print(f"  Hertz {scheme} h = {size * 1e3:g} mm, dt = {dt:g} s: {worst:+.3g} % in {wall:.2f} s", flush=True)
    return {"scene": "Hertz", "scheme": scheme, "along": f"{size * 1e3:g} mm", "dt": substep or dt, "courant": "",
            "steps": steps, "error": abs(worst), "error_other": " / ".join(f"{diffs[q]:+.2f}" for q in HERTZ_QUANTITIES),
            "wall": wall, "values": {q: m[q][0] for q in HERTZ_QUANTITIES}}


def hertz_scene(choc, out, repeat):
    """Hertz's impact (axisymmetric): central differences on the lumped TRI6 mass (forward-
    increment Lagrange contact, the 0.1 us step cut into sub-steps below the critical step)
    against the input's average acceleration (massless contact arc) at steps of 0.1 to 0.4 us,
    on meshes of 0.2 to 0.025 mm near the first point of contact (the input's: 0.05 mm)."""
    implicit = deck("hertz.xml")
    an = "Analyses/" + chocrun.only_analysis(implicit)
    if chocrun.get_param(implicit, f"{an}/Scheme") != "average acceleration":
        raise SystemExit("explicit_implicit_study: input/hertz.xml's scheme is no longer average acceleration")
    explicit = edited(implicit, Scheme="central differences")
    chocrun.set_param(explicit, f"{an}/Stability Check", "substep", create=True)
    for block in chocrun.sublists(explicit, "Model/Blocks"):
        chocrun.set_param(explicit, f"Model/Blocks/{block}/Mass", "lumped", create=True)
    rows = [hertz_run(choc, out, "explicit", size, 1e-7, explicit, repeat) for size in (2e-4, 1e-4, 5e-5, 2.5e-5)]
    rows += [hertz_run(choc, out, "implicit", size, dt, implicit, repeat)
             for size, dt in ((2e-4, 1e-7), (1e-4, 1e-7), (5e-5, 4e-7), (5e-5, 2e-7), (5e-5, 1e-7))]
    # The discretisation's share: each run against the finest one (explicit, 0.025 mm), whose
    # own distance from Hertz is the finite sphere's (README, section "Contact").
    finest = rows[3]["values"]
    for r in rows:
        r["from_finest"] = 100 * max(abs(r["values"][q] / finest[q] - 1) for q in HERTZ_QUANTITIES)
    return rows


def cheapest(rows, key, target):
    ok = [r for r in rows if r[key] <= target]
    best = min(ok, key=lambda r: r["wall"]) if ok else None
    return f"<= {target:g} %: " + (f"{best['along']} (dt {best['dt']:.3g} s), {best[key]:.3g} %, {best['wall']:.2f} s"
                                   if best else "not reached")


def report(rows):
    for scene, what in (("SDNV100", "DZ(N5)"), ("SDNL111 D", "DZ(N1)"), ("SDNL111 C", "DZ(N1)"),
                        ("Hertz", "the peak force, contact duration and largest approach (the largest)")):
        mine = [r for r in rows if r["scene"] == scene]
        hertz_scene = scene == "Hertz"
        print(f"\n{scene}: max error of {what}" + (" against Hertz" if hertz_scene else " over the whole history")
              + ", % of " + ("Hertz's values" if hertz_scene else "its peak") + ", against the run's wall time")
        if hertz_scene:
            print("| scheme | TRI6 near O | dt [s] | steps | force / duration / approach [%] | max error | "
                  "from the finest run | wall [s] |")
            print("|---|---|---|---|---|---|---|---|")
        else:
            print("| scheme | HEX8 along | dt [s] | Courant | steps | max error | wall [s] |")
            print("|---|---|---|---|---|---|---|")
        for r in mine:
            if hertz_scene:
                print(f"| {r['scheme']} | {r['along']} | {r['dt']:.3g} | {r['steps']} | {r['error_other']} | "
                      f"{r['error']:.3g} % | {r['from_finest']:.3g} % | {r['wall']:.2f} |")
            else:
                print(f"| {r['scheme']} | {r['along']} | {r['dt']:.3g} | {r['courant']:.3f} | {r['steps']} | "
                      f"{r['error']:.3g} % | {r['wall']:.2f} |")
        for scheme in ("explicit", "implicit", "implicit, trapezoidal"):
            theirs = [r for r in mine if r["scheme"] == scheme]
            if not theirs:
                continue
            cells = [cheapest(theirs, "error", target) for target in (1.0, 0.1)]
            if hertz_scene:  # Hertz's own floor (the finite sphere) hides the discretisation's error
                cells.append("within " + cheapest(theirs, "from_finest", 1.0) + " of the finest run")
            print(f"cheapest {scheme}: " + "; ".join(cells))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/explicit_implicit")
    ap.add_argument("--repeat", type=int, default=2)
    a = ap.parse_args()
    choc = os.path.abspath(os.path.join(a.build, "choc"))
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    rows = sdnv100(choc, out, a.repeat) + sdnl111d(choc, out, a.repeat) + sdnl111c(choc, out, a.repeat) + \
        hertz_scene(choc, out, a.repeat)
    fields = ["scene", "scheme", "along", "dt", "courant", "steps", "error", "error_other", "from_finest", "wall"]
    with open(os.path.join(out, "study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    report(rows)
    print(f"\n{os.path.join(out, 'study.csv')}")


if __name__ == "__main__":
    main()
