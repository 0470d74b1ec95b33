#!/usr/bin/python3
"""The contact mass's trade (make study-contact-mass; issue 73): every implicit contact
treatment of 'Contact Mass' on the scenes where it matters, each against its reference,
with its cost.

Treatments: redistributed ('auto' with a consistent mass), normal, velocity update ('auto' with a lumped one)
(projected in the scene's own mass's norm, lumped or consistent) and standard. Scenes and references:
  - taylor3d: input/taylor_bar_3d_implicit.xml (HHT -0.3 at 0.1 us, J2, lumped) against
    input/taylor_bar_3d.xml (central differences on the same mesh): face radius and length;
  - taylor3d_consistent: taylor3d with the implicit input's block mass consistent
    ('Model/Blocks/BAR/Mass'): redistributed, velocity update (projected in the consistent mass's
    norm) and standard, against the same central differences;
  - taylor_axi: input/taylor_bar_axisymmetric_implicit.xml against
    input/taylor_bar_axisymmetric.xml: the same;
  - copper: input/copper_bar.xml with Lagrange contact and the lumped mass (average acceleration
    at 0.2 us) against central differences at 20 ns on the same mesh: rebound velocity (the
    bar's momentum over its mass at 80 us) and contact time (from t = 0, where the face touches
    the wall, to the middle of the step after the last with a force: contact_span);
  - bar03: examples/03-bar-on-wall (average acceleration, consistent mass) against d'Alembert:
    the top face's largest error over the history (the input's exact-solution row);
  - sdnv100: input/sdnv100.xml's 'lagrange' analysis against its deck's rows (the largest
    relative error of its checks);
  - sdnl111e2: input/sdnl111e.xml's 'e2_alpha01' (HHT alpha = -0.1) with its deck's rows;
  - hertz, hertz2: input/hertz.xml (a steel sphere on a rigid plane, axisymmetric) and
    input/hertz_two_spheres.xml (two meshed spheres head on: each moves as the one on the plane)
    against Hertz (tools/oracles/hertz.py): the restitution (rebound velocity from the impulse
    over the impact velocity; 1 for Hertz's elastic impact) and the contact duration;
  - bracket: input/bracket_drop.xml (TET10, h = 3.7 mm, lumped, mu = 0.2) as
    tools/bench/bench_bracket.py's implicit reference at 0.2 us, against the same run with the
    standard mass (central differences are within 0.15 % of it): the motion as a share of each
    peak and the friction work (bench_bracket.compare);
  - copper_dt: the copper scene at 0.4, 0.2, 0.1 and 0.05 us against central differences at
    10 ns: the rebound's and the contact time's convergence in dt (normal and velocity update);
  - copper_h: the copper scene's velocity update on meshes/copper_bar.geo at (nc, m, nz) =
    (1, 1, 12), (2, 2, 24), (4, 4, 48) (h halved each time; the section an 8 nc-gon, so the rebound
    is the momentum over each mesh's own mass), average acceleration at 0.4, 0.2, 0.1 us, each
    against central differences on its own mesh at 40, 20, 10 ns: the rebound and the contact time
    per mesh, and their observed orders in h (of the differences, and of each sequence by
    Richardson); d'Alembert (nu = 0, so only indicative) in the reference;
  - release: input/copper_bar.xml as it is (average acceleration, consistent mass) with Penalty
    and Lagrange contact at 0.1 to 2 us: the largest energy balance (the release term, the energy
    an opening constraint returns; docs/verification/copper-bar.md);
  - oblique, block: input/oblique_sphere.xml (mu = 0.1) and input/compact_block.xml: impacts,
    energy and cost only (their references are in their own tests).
For every run: impacts (closings of the pair), the largest energy balance over E0 (energy
created), Newton corrections per step, wall seconds, exit code.

usage: tools/study/contact_mass_study.py [--build build] [--out results/contact-mass]
       [--scenes taylor3d,copper,...] [--treatments normal,...]
Writes OUT/contact_mass.csv and OUT/README.md (the tables of docs/verification/contact-mass.md).
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

TREATMENTS = ["redistributed", "normal", "velocity update", "standard"]
R0, L0 = 3.2e-3, 32.4e-3          # the Taylor bars (meshes/taylor_bar*.geo)
COPPER_MASS = 9.0704e-3           # the copper bar's mass [kg] (docs/verification/copper-bar.md)
COPPER_BASE = {"Analyses/impact/Exodus Interval": 0, "Analyses/impact/Contact/Method": "Lagrange",
               "Analyses/impact/History": "centre:DZ centre:VZ top:DZ top:VZ bar:PZ", "Model/Blocks/bar/Mass": "lumped"}
# copper_h's meshes (meshes/copper_bar.geo's nc, m, nz: h halved each time), each with its implicit
# step and its central-differences step; the bar (rho, E, R, L, impact velocity) for its mass and d'Alembert.
COPPER_LEVELS = ((1, 1, 12, 4e-7, 4e-8), (2, 2, 24, 2e-7, 2e-8), (4, 4, 48, 1e-7, 1e-8))
COPPER_RHO, COPPER_E, COPPER_V0 = 8930.0, 1.17e11, 227.0


def deck(path, analysis, values, drop_checks=False):
    d = chocrun.load_deck(path)
    chocrun.keep_analyses(d, [analysis])
    chocrun.set_params(d, values, create=True)
    if drop_checks and chocrun.has(d, f"Analyses/{analysis}/Checks"):
        chocrun.remove_sublist(d, f"Analyses/{analysis}/Checks")
    return d


def run(build, work, tag, d, analysis, cwd=None):
    """Runs the deck (any exit code); returns (summary or None, history or None, the Run)."""
    out = os.path.join(work, tag)
    path = chocrun.write_deck(d, os.path.join(work, tag + ".xml"))
    r = chocrun.run(chocrun.choc_path(build), path, out, ok=None, cwd=cwd)
    try:
        return chocrun.read_summary(out, analysis), chocrun.read_history(out, analysis), r
    except (OSError, ValueError, KeyError):
        return None, None, r


def common(summary, history, r):
    """The figures every row has (the wall time of the whole process, from chocrun.run)."""
    row = {"exit": r.returncode, "wall_s": r.wall}
    if not summary:
        return row
    steps = max(1, summary.get("steps", 0))
    row["newton_per_step"] = summary.get("newton", {}).get("iterations", 0) / steps
    row["impacts"] = sum(v.get("number_of_impacts", 0) for v in summary.get("impacts", {}).values())
    if history and "energy:balance" in history:
        e0 = float(history["energy:total"][0])
        row["energy_created_E0"] = max(float(b) for b in history["energy:balance"]) / e0
    return row


def treatment_run(build, work, tag, path, analysis, t, cwd=None, values=None):
    """The input at `path` with 'Contact Mass' = t, no Exodus output and `values` (parameter paths),
    run into WORK/<tag>_<t>: (its row's common figures, summary, history, output directory)."""
    d = deck(path, analysis, dict({f"Analyses/{analysis}/Exodus Interval": 0, f"Analyses/{analysis}/Contact Mass": t},
                                  **(values or {})))
    out_tag = f"{tag}_{t.replace(' ', '_')}"
    s, h, proc = run(build, work, out_tag, d, analysis, cwd=cwd)
    return dict(common(s, h, proc), scene=tag, treatment=t), s, h, os.path.join(work, out_tag)


def taylor(build, work, implicit, explicit, tag, treatments, values=None):
    """The implicit input (with `values`) per treatment against the explicit one's shape."""
    _, ref_h, _ = run(build, work, tag + "_reference", deck(chocrun.input_path(explicit), "impact",
                                                                 {"Analyses/impact/Exodus Interval": 0}), "impact")
    ref = shape(ref_h)
    rows = []
    for t in treatments:
        row, _, h, _ = treatment_run(build, work, tag, chocrun.input_path(implicit), "impact", t, values=values)
        if h:
            r, length = shape(h)
            row["error_1"] = f"radius {(r / ref[0] - 1) * 100:+.2f} %"
            row["error_2"] = f"length {(length / ref[1] - 1) * 100:+.2f} %"
        rows.append(row)
    return rows, f"central differences: radius {ref[0] * 1e3:.4f} mm, length {ref[1] * 1e3:.4f} mm"


def shape(h):
    return R0 + float(h["EDGE:DX"][-1]), L0 + float(h["REAR:DY"][-1]) - float(h["CENTRE:DY"][-1])


def contact_span(h, column, start=None):
    """Contact time: the force falls to 0 within the step after its last non-zero sample, its end
    placed at the middle of that step; it rises from 0 at `start` when the scene knows it (the
    copper bar touches the wall at t = 0 by construction: an implicit run's first force is a
    step later, central differences' at t = 0), else at the middle of the step before the first
    non-zero sample (the sampling's error is then at most half a step at each end)."""
    t = [float(x) for x in h["time"]]
    on = [k for k, x in enumerate(h[column]) if abs(float(x)) > 0]
    if not on:
        return 0.0
    first, last = on[0], on[-1]
    if start is None:
        start = t[first] - 0.5 * (t[first] - t[first - 1]) if first > 0 else t[first]
    end = t[last] + 0.5 * (t[last + 1] - t[last]) if last + 1 < len(t) else t[last]
    return end - start


def copper(build, work, treatments, steps=None):
    """The copper bar against central differences (at 20 ns, or 10 ns when `steps` lists the
    implicit steps of a convergence series)."""
    base = COPPER_BASE
    path = chocrun.input_path("copper_bar.xml")
    cd_dt = 1e-8 if steps else 2e-8
    ref_d = deck(path, "impact", dict(base, **{"Analyses/impact/Scheme": "central differences",
                                               "Analyses/impact/Time Step": cd_dt}), drop_checks=True)
    _, ref_h, _ = run(build, work, f"copper_reference_{cd_dt:g}", ref_d, "impact")
    v_ref, span_ref = float(ref_h["bar:PZ"][-1]) / COPPER_MASS, contact_span(ref_h, "plane:force", start=0.0)
    rows = []
    runs = [(t, dt) for t in treatments for dt in steps] if steps else [(t, None) for t in treatments]
    for t, dt in runs:
        values = dict(base, **{"Analyses/impact/Contact Mass": t})
        if dt:
            values["Analyses/impact/Time Step"] = dt
        tag = f"copper_{t.replace(' ', '_')}" + (f"_{dt:g}" if dt else "")
        s, h, proc = run(build, work, tag, deck(path, "impact", values, drop_checks=True), "impact")
        row = dict(common(s, h, proc), scene="copper_dt" if dt else "copper",
                   treatment=t + (f", dt = {dt * 1e6:g} us" if dt else ""))
        if h:
            v = float(h["bar:PZ"][-1]) / COPPER_MASS
            row["error_1"] = f"rebound {(v / v_ref - 1) * 100:+.2f} %"
            row["error_2"] = f"contact time {(contact_span(h, 'plane:force', start=0.0) / span_ref - 1) * 100:+.2f} %"
        rows.append(row)
    return rows, (f"central differences at {cd_dt * 1e9:g} ns: rebound {v_ref:.2f} m/s, "
                  f"contact time {span_ref * 1e6:.2f} us")


def copper_mass(h, nc):
    """The mesh's mass [kg]: the run's initial momentum over -v0 (its first history row), else the
    8 nc-gon's section, (4 nc / pi) sin(pi / (4 nc)) of pi R^2, times rho L. (Not the summary's
    initial energy: central differences count it after the contact has stopped the impact face.)"""
    if h and len(h["bar:PZ"]):
        return -float(h["bar:PZ"][0]) / COPPER_V0
    return COPPER_RHO * L0 * 4 * nc * R0 ** 2 * math.sin(math.pi / (4 * nc))


def copper_h_run(build, work, tag, mesh, nc, values):
    """The copper scene (COPPER_BASE and `values`) on `mesh`: its row (the common figures, the
    unknowns and the mass), the rebound (the momentum over the mesh's own mass) and the contact time."""
    d = deck(chocrun.input_path("copper_bar.xml"), "impact", dict(COPPER_BASE, **values), drop_checks=True)
    chocrun.set_param(d, "Mesh/File", mesh)
    s, h, proc = run(build, work, tag, d, "impact")
    row = dict(common(s, h, proc), scene="copper_h", unknowns=(s or {}).get("unknowns"), mass=copper_mass(h, nc))
    if not h:
        return row, None, None
    return row, float(h["bar:PZ"][-1]) / row["mass"], contact_span(h, "plane:force", start=0.0)


def copper_h_level(build, work, level, treatments):
    """One mesh of copper_h: its central-differences reference and each treatment's run, as rows,
    and {'reference' or the treatment: (rebound, contact time)}."""
    nc, m, nz, dt, cd_dt = level
    mesh = chocrun.gmsh("copper_bar.geo", os.path.abspath(os.path.join(work, f"copper_bar_{nc}_{m}_{nz}.msh")), 3,
                        "-setnumber", "nc", nc, "-setnumber", "m", m, "-setnumber", "nz", nz)
    label = f"nc = {nc}, m = {m}, nz = {nz} (h = {L0 / nz * 1e3:g} mm)"
    row, v_ref, span_ref = copper_h_run(build, work, f"copper_h_{nc}_{m}_{nz}_reference", mesh, nc, {
        "Analyses/impact/Scheme": "central differences", "Analyses/impact/Time Step": cd_dt})
    label += f", {row['unknowns']} unknowns, mass {row['mass'] * 1e3:.4f} g"
    row["treatment"] = f"central differences at {cd_dt * 1e9:g} ns (the reference), {label}"
    if v_ref is not None:
        row["error_1"], row["error_2"] = f"rebound {v_ref:.2f} m/s", f"contact time {span_ref * 1e6:.3f} us"
    rows, out = [row], {"reference": (v_ref, span_ref)}
    for t in treatments:
        row, v, span = copper_h_run(build, work, f"copper_h_{nc}_{m}_{nz}_{t.replace(' ', '_')}", mesh, nc, {
            "Analyses/impact/Contact Mass": t, "Analyses/impact/Time Step": dt})
        row["treatment"] = f"{t}, dt = {dt * 1e6:g} us, {label}"
        if v is not None and v_ref is not None:
            row["error_1"] = f"rebound {v:.2f} m/s ({(v / v_ref - 1) * 100:+.2f} %)"
            row["error_2"] = f"contact time {span * 1e6:.3f} us ({(span / span_ref - 1) * 100:+.2f} %)"
        out[t] = (v, span)
        rows.append(row)
    return rows, out


def richardson(x):
    """The observed order of three values on meshes of h, h / 2, h / 4: log2((x1 - x2) / (x2 - x3)),
    as text ('-' when a value is missing; 'not monotone' when the increments change sign)."""
    if len(x) != 3 or None in x:
        return "-"
    a, b = x[0] - x[1], x[1] - x[2]
    if a * b <= 0:
        return f"not monotone (increments {a:+.3g}, {b:+.3g})"
    return f"p = {math.log2(a / b):.2f}"


def difference_orders(x, ref):
    """The relative differences x / ref - 1 per mesh and log2 of the ratio of successive ones."""
    d = [None if a is None or b is None else a / b - 1 for a, b in zip(x, ref)]
    text = ", ".join("-" if e is None else f"{e * 100:+.3f} %" for e in d)
    p = [f"{math.log2(abs(d0 / d1)):.2f}" if d0 and d1 else "-" for d0, d1 in zip(d, d[1:])]
    return f"differences {text}: p = {', '.join(p)}"


def copper_h_orders(results, t):
    """The row of the observed orders in h of treatment t (None: of the central differences)."""
    key = t or "reference"
    seq = [[r.get(key, (None, None))[k] for r in results] for k in (0, 1)]
    ref = [[r["reference"][k] for r in results] for k in (0, 1)]
    row = {"scene": "copper_h", "treatment": f"observed order in h: {t or 'central differences'}"}
    for k, name in ((0, "rebound"), (1, "contact time")):
        row[f"error_{k + 1}"] = f"{name}: Richardson {richardson(seq[k])}" + (
            f"; {difference_orders(seq[k], ref[k])}" if t else "")
    return row


def copper_h(build, work, treatments):
    """copper_h: the rows of every mesh of COPPER_LEVELS, then the observed orders' rows; the
    reference text with d'Alembert's bar against the finest mesh."""
    rows, results = [], []
    for level in COPPER_LEVELS:
        r, res = copper_h_level(build, work, level, treatments)
        rows += r
        results.append(res)
    rows += [copper_h_orders(results, t) for t in [None] + treatments]
    span = 2 * L0 / math.sqrt(COPPER_E / COPPER_RHO)
    name = {"reference": "central differences"}
    fine = ", ".join(f"{name.get(k, k)}: {v:.2f} m/s ({(v / COPPER_V0 - 1) * 100:+.2f} %), "
                     f"{s * 1e6:.3f} us ({(s / span - 1) * 100:+.2f} %)"
                     for k, (v, s) in results[-1].items() if v is not None)
    return rows, (f"central differences on each mesh at {', '.join(f'{lv[4] * 1e9:g}' for lv in COPPER_LEVELS)} ns; "
                  f"d'Alembert (nu = 0, here 0.35: indicative): rebound {COPPER_V0:g} m/s, contact time 2 L / c = "
                  f"{span * 1e6:.3f} us; the finest mesh against it: {fine}")


def worst_check(summary, kind=None):
    """The check row (of reference kind `kind`, or any) with the largest error over its tolerance:
    (quantity, error, tolerance, status), and the number of rows that failed."""
    worst, failed = None, 0
    rows = (summary or {}).get("checks", {}).get("rows", {})
    for c in rows.values():
        if kind and c.get("reference_kind") != kind:
            continue
        e, tol = c.get("error"), c.get("tolerance")
        failed += c.get("status") != "OK"
        if not isinstance(e, (int, float)) or not tol:
            continue
        if worst is None or abs(e) / tol > abs(worst[1]) / worst[2]:
            worst = (c.get("quantity", "?"), e, tol, c.get("status", "?"))
    return worst, failed


def deck_rows(build, work, tag, path, analysis, treatments, kind=None, cwd=None):
    rows = []
    for t in treatments:
        row, s, _, _ = treatment_run(build, work, tag, path, analysis, t, cwd=cwd)
        w, failed = worst_check(s, kind)
        if w:
            row["error_1"] = f"{w[0]}: {w[1]:.3g} ({abs(w[1]) / w[2]:.2f} of its tolerance)"
            row["error_2"] = f"{failed} rows failed"
        rows.append(row)
    return rows


SCENES = ["taylor3d", "taylor_axi", "copper", "bar03", "sdnv100", "sdnl111e2", "hertz", "hertz2", "bracket", "oblique",
          "block", "release", "copper_dt", "copper_h", "taylor3d_consistent"]
CONVERGENCE_STEPS = (4e-7, 2e-7, 1e-7, 5e-8)
RELEASE_STEPS = (1e-7, 2e-7, 5e-7, 1e-6, 2e-6)
# The scenes compared with their inputs' own rows (or only counted): input, analysis.
DECK_SCENES = {"sdnv100": ("sdnv100.xml", "lagrange"), "sdnl111e2": ("sdnl111e.xml", "e2_alpha01"),
               "oblique": ("oblique_sphere.xml", "oblique"), "block": ("compact_block.xml", "drop")}
HERTZ_SCENES = {"hertz": "hertz.xml", "hertz2": "hertz_two_spheres.xml"}


def release(build, work, treatments):
    rows = []
    for method in ("Penalty", "Lagrange"):
        for t in treatments:
            if t == "standard":
                continue  # it chatters: docs/verification/copper-bar.md
            row = {"scene": "release", "treatment": f"{method}, {t}"}
            for k, dt in enumerate(RELEASE_STEPS):
                d = deck(chocrun.input_path("copper_bar.xml"), "impact",
                         {"Analyses/impact/Exodus Interval": 0, "Analyses/impact/Contact/Method": method,
                          "Analyses/impact/Contact Mass": t, "Analyses/impact/Time Step": dt}, drop_checks=True)
                _, h, proc = run(build, work, f"release_{method}_{t.replace(' ', '_')}_{dt:g}", d, "impact")
                e0 = float(h["energy:total"][0]) if h else 0.0
                row[f"dt{k}"] = (f"{max(float(b) for b in h['energy:balance']) / e0 * 100:+.3f} %" if h and e0
                                 else f"- (exit {proc.returncode})")
            rows.append(row)
    return rows


def bracket(build, work, treatments):
    chocrun.add_tool_path("bench")
    import bench_bracket  # noqa: E402  (tools/bench/bench_bracket.py)
    _, ref, _ = run(build, work, "bracket_reference", bench_bracket.deck(None, "reference", 2e-7, "standard"), "drop")
    rows = []
    for t in treatments:
        s, h, proc = run(build, work, f"bracket_{t.replace(' ', '_')}", bench_bracket.deck(None, "reference", 2e-7, t), "drop")
        row = dict(common(s, h, proc), scene="bracket", treatment=t)
        if h and ref:
            motion, friction, _ = bench_bracket.compare(ref, h)
            row["error_1"] = f"motion {motion:.2e} of the peaks"
            row["error_2"] = f"friction work {friction:.2e}"
        rows.append(row)
    return rows, "the same run with the standard mass"


def hertz_scene(build, work, tag, name, treatments):
    chocrun.add_tool_path("oracles")
    import hertz as oracle  # noqa: E402  (tools/oracles/hertz.py)
    ref = oracle.hertz()
    rows = []
    for t in treatments:
        row, _, h, out = treatment_run(build, work, tag, chocrun.input_path(name), "axisymmetric", t)
        if h:
            m = oracle.measure(chocrun.history_path(out, "axisymmetric"), ref)
            row["error_1"] = f"restitution {m['rebound velocity'][0] / ref['v']:.4f}"
            row["error_2"] = f"duration {(m['contact duration'][0] / ref['tc'] - 1) * 100:+.2f} %"
        rows.append(row)
    return rows, f"Hertz: restitution 1, duration {ref['tc'] * 1e6:.2f} us"


def bar_scenes(build, work, scenes, treatments):
    """The Taylor bars' and the copper bar's scenes: rows and {scene: reference}."""
    rows, refs = [], {}
    if "taylor3d" in scenes:
        r, refs["taylor3d"] = taylor(build, work, "taylor_bar_3d_implicit.xml", "taylor_bar_3d.xml", "taylor3d", treatments)
        rows += r
    if "taylor3d_consistent" in scenes:
        r, refs["taylor3d_consistent"] = taylor(
            build, work, "taylor_bar_3d_implicit.xml", "taylor_bar_3d.xml", "taylor3d_consistent",
            [t for t in treatments if t != "normal"], values={"Model/Blocks/BAR/Mass": "consistent"})
        rows += r
    if "taylor_axi" in scenes:
        r, refs["taylor_axi"] = taylor(build, work, "taylor_bar_axisymmetric_implicit.xml", "taylor_bar_axisymmetric.xml",
                                       "taylor_axi", treatments)
        rows += r
    if "copper" in scenes:
        r, refs["copper"] = copper(build, work, treatments)
        rows += r
    if "copper_dt" in scenes:
        r, refs["copper_dt"] = copper(build, work, [t for t in treatments if t in ("normal", "velocity update")],
                                      CONVERGENCE_STEPS)
        rows += r
    if "copper_h" in scenes:
        r, refs["copper_h"] = copper_h(build, work, [t for t in treatments if t == "velocity update"])
        rows += r
    return rows, refs


def study(build, work, scenes, treatments):
    rows, refs = bar_scenes(build, work, scenes, treatments)
    if "bar03" in scenes:
        ex = os.path.join(chocrun.TOP, "examples", "03-bar-on-wall")
        rows += deck_rows(build, work, "bar03", os.path.join(ex, "input.xml"), "drop", treatments, kind="exact", cwd=ex)
        refs["bar03"] = "d'Alembert (the input's exact-solution rows)"
    if "release" in scenes:
        rows += release(build, work, treatments)
        refs["release"] = "none: energy created by the opening constraints, at dt = " + ", ".join(
            f"{dt * 1e6:g} us" for dt in RELEASE_STEPS)
    if "bracket" in scenes:
        r, refs["bracket"] = bracket(build, work, treatments)
        rows += r
    for tag, name in HERTZ_SCENES.items():
        if tag in scenes:
            r, refs[tag] = hertz_scene(build, work, tag, name, treatments)
            rows += r
    for tag, (name, analysis) in DECK_SCENES.items():
        if tag in scenes:
            rows += deck_rows(build, work, tag, chocrun.input_path(name), analysis, treatments)
            refs[tag] = f"the rows of input/{name}"
    return rows, refs


FIELDS = ["scene", "treatment", "error_1", "error_2", "impacts", "energy_created_E0", "newton_per_step", "wall_s", "exit"]


def fmt(v):
    if v is None or v == "":
        return "-"
    if isinstance(v, float):
        return f"{v:.3g}"
    return str(v)


def write(out, rows, refs):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "contact_mass.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, FIELDS, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    lines = ["# The contact mass's trade (tools/study/contact_mass_study.py)", ""]
    for scene in dict.fromkeys(r["scene"] for r in rows):
        if scene == "release":
            lines += [f"## release: {refs['release']}", "", "| method, treatment | " +
                      " | ".join(f"{dt * 1e6:g} us" for dt in RELEASE_STEPS) + " |",
                      "|---|" + "---|" * len(RELEASE_STEPS)]
            lines += ["| " + r["treatment"] + " | " + " | ".join(r[f"dt{k}"] for k in range(len(RELEASE_STEPS))) + " |"
                      for r in rows if r["scene"] == "release"]
            lines.append("")
            continue
        lines += [f"## {scene}: reference {refs.get(scene, '')}", "",
                  "| treatment | error | | impacts | energy created / E0 | Newton / step | wall [s] | exit |",
                  "|---|---|---|---|---|---|---|---|"]
        for r in rows:
            if r["scene"] == scene:
                lines.append("| " + " | ".join(fmt(r.get(k)) for k in FIELDS[1:]) + " |")
        lines.append("")
    text = "\n".join(lines)
    with open(os.path.join(out, "README.md"), "w") as f:
        f.write(text)
    print(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/contact-mass")
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--treatments", default=",".join(TREATMENTS))
    a = ap.parse_args()
    scenes = [s for s in a.scenes.split(",") if s]
    unknown = [s for s in scenes if s not in SCENES]
    if unknown:
        sys.exit(f"contact_mass_study: --scenes: unknown {', '.join(unknown)} (valid: {', '.join(SCENES)})")
    treatments = [t for t in a.treatments.split(",") if t]
    work = os.path.join(a.out, "runs")
    os.makedirs(work, exist_ok=True)
    rows, refs = study(a.build, work, scenes, treatments)
    write(a.out, rows, refs)


if __name__ == "__main__":
    main()
