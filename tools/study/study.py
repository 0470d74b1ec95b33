#!/usr/bin/python3
"""The speed-accuracy study (make study).

For each modelisation, sweeps the knobs that set cost and accuracy (time step, elements along
the bars, number of modes, shock/penalty stiffness, scheme and alpha, linear solver), one at a
time around the reference settings plus a few combined "accurate" configurations, and records
for each run the error against the exact solution over the whole history (max and RMS of u_A
relative to the peak, the worst document row, the contact force) and the cost (wall and CPU
seconds, peak memory, steps, unknowns, Newton and linear iterations when the run has them):
each run's <analysis>.summary.json (the exact-solution checks made to report their rows), the
contact force's error recomputed from the history (tools/oracles/bar_exact.py: choc reports no
row for it), the process's CPU time and peak memory from wait4.

usage: tools/study/study.py [--build build] [--out results/study] [--cases A,B,...] [--quick]
Writes OUT/study.csv, OUT/pareto_<case>.png and prints a summary; tools/study/study_report.py
turns the CSV into OUT/README.md.
"""
import argparse
import copy
import math
import csv
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402
from chocrun import get_param, set_param  # noqa: E402

chocrun.add_tool_path("oracles")
import bar_exact  # noqa: E402

TOP = chocrun.TOP

COLUMNS = ["case", "parameter", "value", "max_error_rel_peak", "rms_error_rel_peak",
           "worst_document_row_rel", "force_max_error_rel_peak", "wall_s", "cpu_s",
           "peak_mem_mb", "steps", "dofs", "newton_iterations", "linear_iterations", "status"]
# The keys a sweep may add to the reference decks (absent from some of them); any other key of
# a sweep must exist, or the edit is an error naming it.
MAY_CREATE = {"Exodus Interval", "Progress Interval", "Stability Check", "Normal Law", "Analyses/modes/Method"}


# ---------------------------------------------------------------- decks
def analyses(root):
    return chocrun.sublist(root, "Analyses")


def keep_only(root, names):
    chocrun.keep_analyses(root, names)


def analysis_type(root, name):
    return get_param(root, f"Analyses/{name}/Type")


# ---------------------------------------------------------------- running
def run_choc(build, xml_root, workdir, tag):
    """Runs choc on xml_root (any exit code); returns (the Run, deck path, output dir)."""
    path = chocrun.write_deck(xml_root, os.path.join(workdir, tag + ".xml"))
    out = os.path.join(workdir, tag)
    r = chocrun.run(chocrun.choc_path(build), path, out, ok=None, log=os.path.join(workdir, tag + ".log"))
    return r, path, out


def force_error(deck_path, out, analysis):
    """The contact force's max error against the exact solution, of its peak, recomputed from the
    history (choc reports no row for it); "" when the check names no force column."""
    specs = [sp for sp in bar_exact.exact_specs_for_analysis(bar_exact.read_input(deck_path), analysis) if sp.fcol]
    if not specs:
        return ""
    h = chocrun.read_history(out, analysis)
    sp = specs[0]
    return bar_exact.history_error(h["time"], h[sp.fcol], sp.exact.force(h["time"]))["max_rel"]


def relative_rows(root, analysis):
    """The (quantity, time) of the analysis's document rows judged relative to their reference
    (Criterion 'relative', the default), read before force_exact_rows makes them report-only."""
    base = f"Analyses/{analysis}/Checks"
    rows = set()
    for n in chocrun.sublists(root, base) if chocrun.has(root, base) else []:
        p = f"{base}/{n}"
        if get_param(root, f"{p}/Type", "") != chocrun.EXACT_CHECK and \
                get_param(root, f"{p}/Criterion", "relative") == "relative":
            rows.add((get_param(root, f"{p}/Quantity"), float(get_param(root, f"{p}/Time"))))
    return rows


def parse_results(s, deck_path, out, analysis, relative=()):
    """The study's figures of one run from its summary s (and the history for the force);
    relative: relative_rows() of the deck."""
    r = {"max_error_rel_peak": "", "rms_error_rel_peak": "", "worst_document_row_rel": "",
         "force_max_error_rel_peak": "", "steps": "", "dofs": "", "newton_iterations": "",
         "linear_iterations": ""}
    r["dofs"] = chocrun.summary_value(s, "unknowns")
    r["steps"] = s.get("steps", "")
    r["newton_iterations"] = s.get("newton", {}).get("iterations", "")
    r["linear_iterations"] = s.get("krylov_iterations", "")
    errors = chocrun.exact_errors(s)
    if errors:
        first = next(iter(errors.values()))
        r["max_error_rel_peak"] = first.get("max", "")
        r["rms_error_rel_peak"] = first.get("rms", "")
    # The document's relative rows, relative to their reference (force_exact_rows made every
    # row report-only and absolute, so the error is recomputed here).
    worst = 0.0
    for row in chocrun.check_rows(s):
        if (row["quantity"], row["time"]) in relative and row.get("reference"):
            worst = max(worst, abs(row["computed"] - row["reference"]) / abs(row["reference"]))
    r["worst_document_row_rel"] = worst
    if s.get("status") in ("completed", "check failed"):
        r["force_max_error_rel_peak"] = force_error(deck_path, out, analysis)
    return r


# ---------------------------------------------------------------- the cases
def mesh_for(build, workdir, dim, along, gap_shift=None, gap=1e-5):
    """Generates (once) a bar-impact mesh with `along` elements per bar."""
    workdir = os.path.abspath(workdir)  # choc resolves a relative mesh path beside the input
    os.makedirs(os.path.join(workdir, "meshes"), exist_ok=True)
    name = f"bars_{dim}d_{along}{'_b' if gap_shift else ''}_gap{gap:g}.exo"
    path = os.path.join(workdir, "meshes", name)
    if not os.path.exists(path):
        cmd = [os.path.join(build, "choc"), "mesh", "--dim", str(dim), "--along1", str(along),
               "--along2", str(along), "--gap", str(gap), "--axis", "x" if dim == 1 else "z",
               "-o", path]
        if gap_shift:
            cmd[-2:-2] = ["--shift-a", str(gap_shift)]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return path


def base_input(name):
    # The mesh path is made absolute for the runs written elsewhere.
    return chocrun.load_deck(chocrun.input_path(name))


def force_exact_rows(root, analysis):
    """Makes the run report its exact-solution errors as rows (report-only tolerance) and
    not fail on the document's rows (a study records, it does not judge). Returns whether the
    analysis has a 'Bar Impact Exact Solution' check."""
    exact = chocrun.report_exact_errors(root, analysis)
    base = f"Analyses/{analysis}/Checks"
    for n in chocrun.sublists(root, base) if chocrun.has(root, base) else []:
        if f"{base}/{n}" not in exact:
            set_param(root, f"{base}/{n}/Tolerance", 1e9, "double", create=True)
            set_param(root, f"{base}/{n}/Criterion", "absolute", "string", create=True)
    return bool(exact)


def modal_case(letter, input_name, analysis, quick):
    """Sweeps of a modal transient case (A or B)."""
    base = base_input(input_name)
    keep_only(base, ["modes", analysis])
    set_param(base, f"Analyses/{analysis}/Exodus Interval", 0, "int", create=True)
    set_param(base, f"Analyses/{analysis}/Progress Interval", 0.0, "double", create=True)
    set_param(base, f"Analyses/{analysis}/Stability Check", "substep", "string", create=True)
    a = f"Analyses/{analysis}"
    shift = -1.1e-5 if letter == "B" else None
    sweeps = []
    dts = [2e-6, 1e-6, 5e-7, 2.5e-7] if quick else [2e-6, 1e-6, 5e-7, 2.5e-7, 1.25e-7]
    sweeps += [("dt", v, [(f"{a}/Time Step", v, "double")]) for v in dts]
    # The lowest modes: fewer than 23 modes nearest 20 kHz would leave out the rigid-body mode
    # (0 Hz is farther from the shift than every mode below 28 kHz) and the bar would not move.
    sweeps += [("modes", v, [("Analyses/modes/Number of Modes", v, "int"),
                             ("Analyses/modes/Which", "Lowest", "string")])
               for v in ([10, 20, 40, 80] if quick else [10, 20, 40, 60, 80, 95])]
    sweeps += [("shock_stiffness", v, [(f"{a}/Shock Links/shock/Normal Stiffness", v, "double")])
               for v in [5e8, 5e9, 5e10, 5e11]]
    sweeps += [("scheme", v, [(f"{a}/Scheme", v, "string")])
               for v in ["symplectic Euler", "central differences", "adaptive"]]
    alongs = [25, 50, 100] if quick else [25, 50, 100, 200, 400]
    sweeps += [("elements_along", n, [("MESH", (1, n, shift), None),
                                      ("Analyses/modes/Number of Modes", int(0.8 * n), "int"),
                                      ("Analyses/modes/Which", "Lowest", "string")])
               for n in alongs]
    # Combined configurations aiming at 0.1% of peak: lumped mass with central differences at
    # the bar's Courant limit dt = h/c (the 1D "magic" step, exact for the lumped chain), a
    # rigid link enforced by a forward-increment Lagrange multiplier (A and C then move as one
    # interior node, as in the continuous bar), and the complete modal basis (dense
    # eigen-solve: the lumped chain needs its highest modes to carry a sharp front), no damping.
    c = (2e11 / 7800) ** 0.5
    end0 = get_param(base, f"{a}/End Time")
    for n in ([100, 200, 400] if quick else [100, 200, 400, 800]):
        dt = (1.0 / n) / c
        steps = int(math.ceil(end0 / dt))
        sweeps.append(("accurate", f"lumped,{n}el,rigid,CD,Courant 1", [
            # B: A and C coincide (gap 0) so that the tied link has no free play, as in the
            # exact solution of the tied bars.
            ("MESH", (1, n, None, 0.0) if letter == "B" else (1, n, shift), None),
            ("LUMPED", None, None),
            ("Analyses/modes/Number of Modes", 2 * n + 1 - 1, "int"),  # 2(n+1) nodes, D fixed
            ("Analyses/modes/Which", "Lowest", "string"),
            ("Analyses/modes/Method", "dense", "string"),
            (f"{a}/Time Step", dt, "double"),
            (f"{a}/End Time", steps * dt, "double"),
            (f"{a}/Scheme", "central differences", "string"),
            (f"{a}/Shock Links/shock/Normal Law", "rigid", "string"),
            (f"{a}/Modal Damping", 0.0, "double"),
        ] + ([  # B: no free play (the exact solution has none): r = 0 at all times
            (f"{a}/Shock Links/shock/DIST_1", 0.0, "double"),
            (f"{a}/Shock Links/shock/DIST_2", 0.0, "double")] if letter == "B" else [])))
    return base, analysis, sweeps


def implicit_cases(input_name, letter, quick):
    """One case per Transient analysis of a 3D input (C1, C2, D, E1, E2)."""
    root = base_input(input_name)
    names = [n for n in chocrun.analyses(root) if analysis_type(root, n) == "Transient"]
    out = []
    for i, name in enumerate(names):
        case = letter + (str(i + 1) if len(names) > 1 else "")
        base = copy.deepcopy(root)
        keep_only(base, [name])
        a = f"Analyses/{name}"
        set_param(base, f"{a}/Exodus Interval", 0, "int", create=True)
        sweeps = []
        sweeps += [("dt", v, [(f"{a}/Time Step", v, "double")])
                   for v in ([2e-6, 1e-6, 5e-7] if quick else [4e-6, 2e-6, 1e-6, 5e-7, 2.5e-7])]
        sweeps += [("elements_along", n, [("MESH", (3, n, None), None)])
                   for n in ([25, 50, 100] if quick else [25, 50, 100, 200])]
        sweeps += [("alpha", v, [(f"{a}/Alpha", v, "double")]) for v in [0.0, -0.1, -0.2, -1.0 / 3.0]]
        method = get_param(base, f"{a}/Contact/Method", None)
        if method == "Penalty":
            key = next((k for k in ["Penalty Stiffness", "Stiffness"]
                        if get_param(base, f"{a}/Contact/{k}", None) is not None), "Penalty Stiffness")
            sweeps += [("penalty_stiffness", v, [(f"{a}/Contact/{key}", v, "double")])
                       for v in [1e8, 1e9, 1e10, 1e11, 1e12]]
        sweeps += [("linear_solver", v, [(f"{a}/Linear Solver/Method", v, "string")])
                   for v in ["Direct", "CG", "GMRES"]]
        if letter == "C" and i == 0:
            # Beyond the reference: Lagrange contact with massless contact nodes, average
            # acceleration, consistent mass at Courant 1/sqrt(2) (phase errors of mass and
            # trapezoidal rule cancel to fourth order), no damping.
            cp = math.sqrt(2e11 * 0.7 / (7800 * 1.3 * 0.4))
            end0 = get_param(base, f"{a}/End Time")
            for n in ([50, 100, 200] if quick else [50, 100, 200, 400]):
                dt = (1.0 / n) / (math.sqrt(2) * cp)
                steps = int(math.ceil(end0 / dt))
                sweeps.append(("accurate", f"redistributed,{n}el,avg accel,Courant 0.707", [
                    ("MESH", (3, n, None), None),
                    (f"{a}/Scheme", "average acceleration", "string"),
                    (f"{a}/Contact Mass", "redistributed", "string"),
                    (f"{a}/Time Step", dt, "double"),
                    (f"{a}/End Time", steps * dt, "double"),
                    (f"{a}/Rayleigh Damping/Stiffness Coefficient", 0.0, "double"),
                    (f"{a}/Rayleigh Damping/Mass Coefficient", 0.0, "double")]))
        out.append((case, base, name, sweeps))
    return out


def apply(build, workdir, base, changes):
    root = copy.deepcopy(base)
    for path, value, typ in changes:
        if path == "MESH":
            dim, along, shift = value[:3]
            gap = value[3] if len(value) > 3 else 1e-5
            set_param(root, "Mesh/File", mesh_for(build, workdir, dim, along, shift, gap))
        elif path == "LUMPED":
            for blk in chocrun.sublists(root, "Model/Blocks"):
                set_param(root, f"Model/Blocks/{blk}/Mass", "lumped", "string", create=True)
        else:
            create = path in MAY_CREATE or path.rsplit("/", 1)[-1] in MAY_CREATE
            set_param(root, path, value, typ, create=create)
    return root


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(TOP, "build"))
    ap.add_argument("--out", default=os.path.join(TOP, "results", "study"))
    ap.add_argument("--cases", default="A,B,C,D,E")
    ap.add_argument("--quick", action="store_true", help="fewer points (for a smoke test)")
    ap.add_argument("--append", action="store_true", help="add rows to an existing study.csv")
    a = ap.parse_args()
    wanted = set(a.cases.split(","))
    os.makedirs(a.out, exist_ok=True)
    work = os.path.join(a.out, "runs")
    plan = []
    if "A" in wanted:
        b, an, sw = modal_case("A", "sdnl111a.xml", "plans_z", a.quick)
        plan.append(("A", b, an, sw))
    if "B" in wanted:
        b, an, sw = modal_case("B", "sdnl111b.xml", "cerc_int", a.quick)
        plan.append(("B", b, an, sw))
    for letter in "CDE":
        if letter in wanted and os.path.exists(os.path.join(TOP, "input", f"sdnl111{letter.lower()}.xml")):
            plan += implicit_cases(f"sdnl111{letter.lower()}.xml", letter, a.quick)
    rows = []
    for case, base, analysis, sweeps in plan:
        relative = relative_rows(base, analysis)
        if not force_exact_rows(base, analysis):
            print(f"study: case {case} has no exact-solution comparison; skipped", file=sys.stderr)
            continue
        for parameter, value, changes in sweeps:
            root = apply(a.build, work, base, changes)
            tag = re.sub(r"[^A-Za-z0-9_.-]+", "_", f"{case}_{parameter}_{value}")
            r, path, out = run_choc(a.build, root, work, tag)
            rc = r.returncode
            summary = (chocrun.read_summary(out, analysis)
                       if os.path.exists(chocrun.summary_path(out, analysis)) else None)
            res = parse_results(summary, path, out, analysis, relative) if summary else {}
            status = {0: "ok", 1: "input error", 2: "numerical failure", 3: "checks failed"}.get(rc, f"exit {rc}")
            if rc != 0:
                # The summary's reason; an input error stops choc before any analysis (no
                # summary): its one-line message on stderr, shown as it is.
                reason = summary.get("reason", "") if summary else \
                    next((l for l in reversed(r.stderr.splitlines()) if l.strip()), "")
                status += ": " + reason.strip()[:120]
            row = {"case": case, "parameter": parameter, "value": value, "wall_s": round(r.wall, 4),
                   "cpu_s": round(r.cpu, 4), "peak_mem_mb": round(r.maxrss_mib, 1), "status": status, **res}
            rows.append(row)
            fmt = lambda x: f"{x:10.3e}" if isinstance(x, float) else f"{'-':>10s}"
            print(f"{case:3s} {parameter:18s} {str(value):36s} max {fmt(res.get('max_error_rel_peak'))} "
                  f"rms {fmt(res.get('rms_error_rel_peak'))} wall {r.wall:7.3f} s  {status[:40]}", flush=True)
    path = os.path.join(a.out, "study.csv")
    append = a.append and os.path.exists(path)
    with open(path, "a" if append else "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        if not append:
            w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in COLUMNS})
    print(f"study: {len(rows)} runs -> {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
