#!/usr/bin/python3
"""Writes the generated verification pages (docs/verification/generated/) from the regression cases.

usage: verification_pages.py [--build BUILD] [--out DIR] [--run [--run-dir DIR]] [--results DIR]
                             [--cases CASE ...] [--require-results] [--no-plots]

For each regression case regression/<case>/ (case.cfg) it writes <out>/<case>.md: what the case
requires (the comment at the top of case.cfg), the hand-written scene page that covers it, where
the reference comes from, the check rows of checks.csv, the whole-history errors against the
closed form, the energy balance of each history, the cost of the run, a plot of the case's
BASELINE_COLUMNS over time (<out>/<case>_<analysis>.png, with the closed form where this script
can compute it), the provenance of the results and a STALE flag when the results predate the
input, its mesh or the last commit touching src/. The extremes (regression/extremes/) get one
summary page, <out>/extremes.md, and <out>/README.md indexes every case.

Where the results come from
  By default, from the last run of the regression suite: `make test` (or, in the build
  directory, `ctest -R '^regression\\.'`) leaves each case's results in
  BUILD/regression/<case>/serial/ (checks.csv, <analysis>.history.csv) and
  BUILD/regression/<case>/serial.log, and each extreme's in BUILD/regression/extremes/<name>/.
  `make docs` does NOT rerun the suite: rerun it first when the pages say STALE or "not run".
  --run runs the inputs itself instead, one after the other on one rank:
  `BUILD/choc run <input> -o <tmpdir>/<case>/serial` for each case and
  regression/extremes/run_case.py for each extreme (a few minutes in all); the results go to
  a temporary directory removed at the end, or to --run-dir when given (kept).

Exit status: 0 when the pages are written; 1 on an error; 2 with --require-results when a
case's results are missing (nothing is written then).
Python 3 with numpy and matplotlib (Debian's /usr/bin/python3); reuses tools/oracles/bar_exact.py and
tools/oracles/friction_oscillator.py for the closed forms.
"""
import argparse
import csv
import json
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools" / "oracles"))
import bar_exact  # noqa: E402  (tools/oracles/bar_exact.py: d'Alembert, the input reader)
import friction_oscillator  # noqa: E402  (tools/oracles/friction_oscillator.py: SDND100's exact motion)

# The hand-written scene page of docs/verification/ covering each case, the scene's heading in
# docs/verification/benchmarks.md (its first words) and the document its rows come from, as the
# scene page and the input's comments say.
CASES = {
    "sdnl111a": ("sdnl111a.md", "SDNL111",
                 "code_aster's SDNL111 document, section 3.3 (DX of A at 2, 4, 6, 8, 10 e-4 s); the "
                 "whole history against d'Alembert's exact solution, tolerances from the input's error estimate"),
    "sdnl111a_rigid": ("sdnl111a.md", "SDNL111",
                       "d'Alembert's exact solution over the whole history, to the one-step release "
                       "estimate of the input (beyond the document)"),
    "sdnl111a_direct": ("sdnl111a.md", "SDNL111",
                        "d'Alembert's exact solution over the whole history, to the input's error estimate (3 %)"),
    "sdnl111b": ("sdnl111b.md", "SDNL111",
                 "code_aster's SDNL111 document, section 4.3 (DX of A at 2 ... 16 e-4 s); the tied "
                 "bars' exact solution (a triangle wave) over the whole history"),
    "sdnl111c_accurate": ("sdnl111c.md", "SDNL111",
                          "code_aster's SDNL111 document, section 5.3 (DZ of N1); d'Alembert's exact "
                          "solution (oedometric wave speed) over the whole history, to 0.1 % of the peak"),
    "sdnl111c_axisymmetric": ("sdnl111c.md", "SDNL111",
                              "code_aster's SDNL111 document, section 5.3 (the 3D rows, DY of N1 here); "
                              "d'Alembert's exact solution over the whole history"),
    "sdnl111c_plane_strain": ("sdnl111c.md", "SDNL111",
                              "code_aster's SDNL111 document, section 5.3 (the 3D rows, DY of N1 here); "
                              "d'Alembert's exact solution over the whole history"),
    "sdnl111c_tet10": ("sdnl111c.md", "SDNL111",
                       "code_aster's SDNL111 document, section 5.3 (DZ of N1); d'Alembert's exact "
                       "solution over the whole history"),
    "sdnl111c_modal": ("sdnl111c.md", "SDNL111",
                       "d'Alembert's exact solution (oedometric wave speed) over the whole history"),
    "sdnl111d_explicit": ("sdnl111d.md", "SDNL111",
                          "code_aster's SDNL111 document, section 6.3 (DZ of N1); d'Alembert's exact "
                          "solution over the whole history (5 %)"),
    "sdnl111_nonmatching": ("sdnl111-nonmatching.md", "SDNL111",
                            "code_aster's SDNL111 document, the rows of model C (section 5.3); "
                            "d'Alembert's exact solution over the whole history (1 % of the peak)"),
    "sdnv100": ("sdnv100.md", "SDNV100",
                "code_aster's SDNV100 deck: its 13 rows with its tolerances, for each contact method"),
    "sdnv100_explicit": ("sdnv100-explicit.md", "SDNV100",
                         "code_aster's SDNV100 deck's rows; d'Alembert's solution for a bar on a rigid "
                         "wall over the whole histories of DZ(N5) and DZ(N100), to 0.5 % of their peaks"),
    "sdnv100_shock_springs": ("sdnv100f.md", "SDNV100",
                              "code_aster's SDNV100 deck (f): the rows the nodal shock-spring model meets, "
                              "with the deck's tolerances"),
    "sdnv104_quad4": ("sdnv104.md", "SDNV104",
                      "the 1-DOF closed form with the ramp (code_aster's deck sdnv104b asks 5 %; 0.5 % here)"),
    "sdnv104_quad8": ("sdnv104.md", "SDNV104",
                      "the 1-DOF closed form with the ramp (code_aster's deck sdnv104e asks 5 %; 0.5 % here)"),
    "sdnd100": ("sdnd100.md", "SDND100",
                "code_aster's SDND100 deck: its 4 rows (the rigid-plastic Coulomb closed form); the exact "
                "elastic-plastic motion of tools/oracles/friction_oscillator.py at the deck's Kt = 4e5 N/m"),
    "sdnd101": ("sdnd101.md", "SDND101",
                "code_aster's SDND101 deck: its 8 rows on the impact statistics, the closed form "
                "(contact frequency sqrt(1.01e6/100), free frequency 10 rad/s)"),
    "sdnl32": ("sdnl32.md", "SDNL32",
               "code_aster's results for SDNL32 run 1 (an external reference, 3 significant digits): "
               "12 rows, the deck's tolerances plus the rounding of the reference"),
    "sliding": ("sliding.md", None,
                "closed form: without friction the block travels v t; the contact carries the load (6,400 N)"),
    "sliding_friction": ("sliding-friction.md", None,
                         "closed form: stopping distance v0^2 m / (2 mu N), travel half way in time, "
                         "friction work mu N d"),
    "copper_bar": ("copper-bar.md", None,
                   "closed form: the initial energy m v0^2 / 2 of the mesh's mass; with the "
                   "non-dissipative scheme the same after the rebound, to 0.1 %"),
}
EXTREMES_PAGE = "extremes.md"

# What the old cross-references of case.cfg comments and notes point to: BRIEF section 1 is the
# SDNL111 problem, BENCHMARKS section N the N-th scene of docs/verification/benchmarks.md.
BENCHMARK_SECTIONS = {1: "SDNV100", 2: "Hertz", 3: "The contact patch test", 4: "SDNV104",
                      5: "SDND100", 6: "SDND101", 7: "SDNL32"}

KIND_MEANING = {
    "analytic": "a value of the document or of a closed form at one time",
    "exact": "the whole history against the exact solution, computed by choc at every step "
             "(src/reference/)",
    "regression": "another code's results (an external reference)",
}

ENERGY_GROWTH_FLAG = 1e-3  # balance above +0.1 % of E0: flagged on the pages and in the index


# ---------------------------------------------------------------- small helpers

def shown(path):
    """A path relative to the repository when inside it, else absolute."""
    path = Path(path)
    return rel(path, ROOT) if str(path).startswith(str(ROOT) + os.sep) else str(path)


def rel(path, start):
    return os.path.relpath(str(path), str(start)).replace(os.sep, "/")


def git(*args):
    try:
        p = subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return None
    return p.stdout.strip() if p.returncode == 0 else None


def stamp(t):
    return time.strftime("%Y-%m-%d %H:%M:%S %Z", time.localtime(t))


def num(x):
    return f"{x:.6g}" if isinstance(x, float) else str(x)


def pct(x):
    return f"{100.0 * x:.3g} %"


def slug(heading):
    """The GitHub anchor of a markdown heading."""
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def machine():
    model = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{len(os.sched_getaffinity(0))} cores (nproc), {model}"


def write_if_changed(path, text):
    path = Path(path)
    if path.is_file() and path.read_text() == text:
        return
    path.write_text(text)


# ---------------------------------------------------------------- the cases and their inputs

def read_case_cfg(path):
    """case.cfg: the comment block at its top and its KEY=VALUE settings."""
    head, values, in_head = [], {}, True
    for line in Path(path).read_text().splitlines():
        s = line.strip()
        if s.startswith("#"):
            if in_head:
                head.append(s[1:].strip())
            continue
        if not s:
            continue
        in_head = False
        m = re.match(r"([A-Z_]+)=(.*)$", s)
        if m:
            words = shlex.split(m.group(2), comments=True)
            values[m.group(1)] = " ".join(words)
    comment = ""
    for h in head:  # a path cut at the end of a line ("meshes/" then "file.geo") stays whole
        comment += ("" if not comment or comment.endswith("/") else " ") + h
    values["COMMENT"] = comment
    return values


class Benchmarks:
    """Headings of docs/verification/benchmarks.md, to link a scene's definition."""

    def __init__(self):
        self.headings = []
        p = ROOT / "docs/verification/benchmarks.md"
        if p.is_file():
            self.headings = [l[3:].strip() for l in p.read_text().splitlines() if l.startswith("## ")]

    def anchor(self, scene):
        for h in self.headings:
            if scene and h.lower().startswith(scene.lower()):
                return slug(h)
        return None


def clean_text(text, out_dir, bench, scene_page=None):
    """A case.cfg comment or a check's note without the project's tracker references: 'issue N'
    is dropped; 'BENCHMARKS section N' and 'BRIEF section 1' become a link to the scene's
    definition; 'the README' (whose tables moved to the scene pages) the scene page."""
    bench_md = rel(ROOT / "docs/verification/benchmarks.md", out_dir)

    def link(scene):
        a = bench.anchor(scene)
        return f"[definition]({bench_md}#{a})" if a else "the benchmark definitions"

    def part(p):
        p = p.strip()
        if re.fullmatch(r"issues? \d+(, \d+)*", p):
            return None
        m = re.fullmatch(r"BENCHMARKS section (\d+)", p)
        if m:
            return link(BENCHMARK_SECTIONS.get(int(m.group(1))))
        if re.fullmatch(r"BRIEF section 1", p):
            return link("SDNL111")
        return p

    def paren(m):
        pieces = re.split(r"([,;]\s*)", m.group(1))  # the separators kept as they are
        parts = [part(x) for x in pieces[0::2]]
        if parts == [x.strip() for x in pieces[0::2]]:
            return m.group(0)
        kept, sep = [], ""
        for i, q in enumerate(parts):
            if q:
                kept.append((sep if kept else "") + q)
            sep = pieces[2 * i + 1] if 2 * i + 1 < len(pieces) else ""
        return "(" + "".join(kept) + ")" if kept else ""

    text = re.sub(r"\(([^()]*)\)", paren, text)
    text = re.sub(r"BENCHMARKS section (\d+)",
                  lambda m: link(BENCHMARK_SECTIONS.get(int(m.group(1)))), text)
    text = re.sub(r"BRIEF section 1", lambda m: link("SDNL111"), text)
    text = re.sub(r",? ?\bissue \d+\b", "", text)
    if scene_page:
        text = re.sub(r"\bthe README\b", f"[the scene page]({scene_page})", text)
    text = re.sub(r"\s+([,:;.)])", r"\1", re.sub(r" {2,}", " ", text))
    return text.strip()


def input_mesh(input_path):
    """The mesh file an input names (Mesh/File, relative to the input), or None."""
    try:
        inp = bar_exact.read_input(input_path)
    except Exception:  # noqa: BLE001  an unreadable input is reported elsewhere (the run fails)
        return None
    f = inp.get("Mesh", {}).get("File")
    return (Path(input_path).parent / f).resolve() if f else None


# ---------------------------------------------------------------- results

def read_checks(path):
    rows = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            for k in ("time", "computed", "reference", "tolerance", "error"):
                try:
                    r[k] = float(r[k])
                except (TypeError, ValueError):
                    r[k] = float("nan")
            rows.append(r)
    return rows


def read_history(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names = rows[0]
    data = np.array([[float(x) for x in r] for r in rows[1:] if r], dtype=float)
    return names, data.reshape(-1, len(names))


def read_cost(results, log):
    """The run's cost: wall_seconds, unknowns, ranks, steps, per_analysis and source (None when
    unknown). From the <analysis>.summary.json files when the run wrote them; otherwise from the
    log, whose format is not a stable interface: that fallback (the lines below the 'if') goes
    once every run writes its summaries."""
    summaries = sorted(Path(results).glob("*.summary.json")) if results else []
    if summaries:
        per = {p.name[:-len(".summary.json")]: json.loads(p.read_text()) for p in summaries}

        def total(key, how=sum):
            v = [s[key] for s in per.values() if isinstance(s.get(key), (int, float))]
            return how(v) if v else None
        return {"wall_seconds": total("wall_seconds"), "unknowns": total("unknowns", max),
                "ranks": total("ranks", max), "steps": total("steps"), "per_analysis": per,
                "source": "<analysis>.summary.json"}
    text = Path(log).read_text(errors="replace") if log and Path(log).is_file() else ""
    wall = re.search(r"results in .*/ \(([0-9.eE+-]+) s\)", text)
    unknowns = re.search(r"(\d+) unknowns", text)
    ranks = re.search(r"on (\d+) rank\(s\)", text)
    return {"wall_seconds": float(wall.group(1)) if wall else None,
            "unknowns": int(unknowns.group(1)) if unknowns else None,
            "ranks": int(ranks.group(1)) if ranks else None, "steps": None, "per_analysis": {},
            "source": "the run log" if text else None}


def results_time(d):
    """When the results were written: the newest mtime of the directory and its files."""
    d = Path(d)
    times = [d.stat().st_mtime] + [p.stat().st_mtime for p in d.iterdir() if p.is_file()]
    return max(times)


class Src:
    """The last commit touching src/, and the commit the pages are generated at."""

    def __init__(self):
        line = git("log", "-1", "--format=%ct %h", "--", "src/")
        self.time, self.commit = (int(line.split()[0]), line.split()[1]) if line else (None, None)
        self.head = git("rev-parse", "--short", "HEAD") or "unknown"
        self.dirty = bool(git("status", "--porcelain", "--", "src/"))


def joined(items):
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def staleness(when, files, src):
    """The reasons the results taken at 'when' are stale, [] when they are not."""
    why = []
    for f in files:
        if f and Path(f).is_file() and Path(f).stat().st_mtime > when:
            why.append(f"`{rel(f, ROOT)}` (modified {stamp(Path(f).stat().st_mtime)})")
    if src.time and src.time > when:
        why.append(f"the last commit touching src/ ({src.commit}, {stamp(src.time)})")
    return why


# ---------------------------------------------------------------- closed forms

def bar_impact_closed_forms(inp, analysis):
    """{column: (function of t, label)} from the analysis' 'Bar Impact Exact Solution' checks."""
    an = inp.get("Analyses", {}).get(analysis, {})
    out = {}
    for name, c in an.get("Checks", {}).items():
        if not (isinstance(c, dict) and c.get("Type") == bar_exact.EXACT_CHECK_TYPE):
            continue
        one = dict(inp, Analyses={analysis: dict(an, Checks={name: c})})
        spec = bar_exact.exact_for_analysis(one, analysis)
        e = spec.exact
        out[spec.ucol] = (e.displacement, "d'Alembert")
        out[spec.vcol] = (e.velocity, "d'Alembert")
        if spec.fcol:
            out[spec.fcol] = (e.force, "d'Alembert")
    return out


def sdnd100_closed_forms(inp, analysis):
    """SDND100's exact elastic-plastic motion (tools/oracles/friction_oscillator.py) along the line
    DX = DY: the deck's m = 1 kg and K = 1e4 N/m, the analysis' stick Kt, mu, N and x0."""
    an = inp.get("Analyses", {}).get(analysis, {})
    links = [l for l in an.get("Shock Links", {}).values()
             if isinstance(l, dict) and "Tangential Stiffness" in l and "Friction Coefficient" in l]
    ics = [c for c in an.get("Initial Conditions", {}).values()
           if isinstance(c, dict) and c.get("Field") == "Displacement"]
    if not links or not ics:
        return {}
    l = links[0]
    normal = l.get("DIST_1", 0.0) * l.get("Normal Stiffness", 0.0)
    x0 = ics[0]["Value"] * math.sqrt(2.0)
    end = an.get("End Time", 0.3)
    seg = friction_oscillator.motion(m=1.0, k=1e4, kt=l["Tangential Stiffness"],
                                     friction=l["Friction Coefficient"] * normal, x0=x0, t_end=end)

    def along(t):
        return np.array([friction_oscillator.position(seg, float(x)) for x in np.atleast_1d(t)]) / math.sqrt(2.0)
    kt = f"{l['Tangential Stiffness']:.3g}".replace("e+0", "e")
    return {"P:DY": (along, f"exact motion, Kt = {kt} N/m")}


def sdnd101_closed_forms(inp, analysis):
    """SDND101's closed form: the deck's oscillator (m = 100 kg, k = 1e4 N/m) leaving x = 0 at v0
    onto the stop of the analysis' 'Normal Stiffness' at zero gap: half a period at
    sqrt((k + ks)/m) in contact, half a period at sqrt(k/m) free, and so on."""
    an = inp.get("Analyses", {}).get(analysis, {})
    links = [l for l in an.get("Shock Links", {}).values() if isinstance(l, dict) and "Normal Stiffness" in l]
    ics = [c for c in an.get("Initial Conditions", {}).values()
           if isinstance(c, dict) and c.get("Field") == "Velocity"]
    if not links or not ics:
        return {}
    m, k, ks, v0 = 100.0, 1e4, links[0]["Normal Stiffness"], ics[0]["Value"]
    wc, w = math.sqrt((k + ks) / m), math.sqrt(k / m)
    tc, tf = math.pi / wc, math.pi / w

    def phase(t):
        s = np.mod(np.asarray(t, dtype=float), tc + tf)
        return s, s < tc

    def x(t):
        s, c = phase(t)
        return np.where(c, v0 / wc * np.sin(wc * s), -v0 / w * np.sin(w * (s - tc)))

    def v(t):
        s, c = phase(t)
        return np.where(c, v0 * np.cos(wc * s), -v0 * np.cos(w * (s - tc)))

    def f(t):
        s, c = phase(t)
        return np.where(c, ks * v0 / wc * np.sin(wc * s), 0.0)
    return {"P:DX": (x, "closed form"), "P:VX": (v, "closed form"), "stop:force": (f, "closed form")}


# case -> the closed forms beyond the inputs' 'Bar Impact Exact Solution' checks
CLOSED_FORMS = {"sdnd100": sdnd100_closed_forms, "sdnd101": sdnd101_closed_forms}


def closed_forms(case, input_path, analysis):
    try:
        inp = bar_exact.read_input(input_path)
        forms = bar_impact_closed_forms(inp, analysis)
        if case in CLOSED_FORMS:
            forms.update(CLOSED_FORMS[case](inp, analysis))
        return forms, None
    except Exception as e:  # noqa: BLE001  an input this script cannot read: plot the history only
        return {}, f"closed form not computed ({e})"


# ---------------------------------------------------------------- one case

def energy_of(names, data):
    """E0 and the extremes of energy:balance; relative to E0, or to the largest E_total when the
    run starts with no energy (a loaded body at rest)."""
    if "energy:total" not in names or "energy:balance" not in names or len(data) == 0:
        return None
    tot = data[:, names.index("energy:total")]
    bal = data[:, names.index("energy:balance")]
    e0 = float(tot[0])
    ref, ref_name = (abs(e0), "E0") if e0 != 0 else (float(np.max(np.abs(tot))), "max E_total")
    lo, hi = float(np.min(bal)), float(np.max(bal))
    return {"e0": e0, "ref": ref, "ref_name": ref_name, "lo": lo, "hi": hi,
            "t_hi": float(data[int(np.argmax(bal)), 0]),
            "lo_rel": lo / ref if ref > 0 else float("nan"), "hi_rel": hi / ref if ref > 0 else float("nan"),
            "flag": ref > 0 and hi > ENERGY_GROWTH_FLAG * ref}


UNITS = [(r"D[XYZ]|DR[XYZ]?", "displacement [m]"), (r"V[XYZ]", "velocity [m/s]"),
         (r"A[XYZ]", "acceleration [m/s²]"), (r".*force", "force [N]"), (r".*work|energy.*", "energy [J]"),
         (r"gap", "gap [m]")]


def unit_of(column):
    comp = column.split(":")[-1]
    if column.startswith("energy:"):
        return "energy [J]"
    for rx, u in UNITS:
        if re.fullmatch(rx, comp):
            return u
    return comp


def plot_history(path, title, names, data, columns, forms, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    groups = {}
    for c in columns:
        groups.setdefault(unit_of(c), []).append(c)
    n = len(groups)
    fig, axes = plt.subplots(n, 1, sharex=True, figsize=(8.0, max(4.5, 1.5 * n)), dpi=100, squeeze=False)
    t = data[:, 0]
    tf = np.linspace(t[0], t[-1], 4000) if len(t) > 1 else t
    for ax, (unit, cols) in zip(axes[:, 0], groups.items()):
        for c in cols:
            ax.plot(t, data[:, names.index(c)], lw=1.2, label=c)
            if c in forms:
                f, label = forms[c]
                ax.plot(tf, f(tf), "--", color="black", lw=0.9, label=f"{c}, {label}")
            pts = [(r["time"], r["reference"]) for r in rows if r["quantity"] == c]
            if pts:
                ax.plot(*zip(*pts), "x", color="red", ms=6, mew=1.5, label=f"{c}, the rows' references")
        ax.set_ylabel(unit, fontsize=8)
        ax.tick_params(labelsize=8)
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7, loc="best")
    axes[-1, 0].set_xlabel("time [s]", fontsize=8)
    axes[0, 0].set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100, metadata={"Software": None})
    plt.close(fig)


class Case:
    def __init__(self, name, cfg_path):
        self.name, self.cfg = name, read_case_cfg(cfg_path)
        self.cfg_path = Path(cfg_path)
        self.input = (ROOT / self.cfg.get("INPUT", "")).resolve()
        self.page, self.scene, self.document = CASES.get(name, (None, None, None))
        self.histories = self.cfg.get("HISTORIES", "").split()
        self.columns = [c for c in self.cfg.get("BASELINE_COLUMNS", "").split(",") if c]
        self.expected_rows = int(self.cfg["CHECKS"]) if self.cfg.get("CHECKS", "").isdigit() else None
        self.results = self.log = None
        self.exit_code = None  # known with --run only
        self.summary = {}

    def locate(self, root):
        self.results, self.log = Path(root) / self.name / "serial", Path(root) / self.name / "serial.log"

    def has_results(self):
        return self.results is not None and (self.results / "checks.csv").is_file()

    def run(self, choc, root):
        out = Path(root) / self.name
        out.mkdir(parents=True, exist_ok=True)

        def once():
            shutil.rmtree(out / "serial", ignore_errors=True)
            with open(out / "serial.log", "w") as log:
                return subprocess.run([str(choc), "run", str(self.input), "-o", str(out / "serial")],
                                      stdout=log, stderr=subprocess.STDOUT, cwd=ROOT).returncode
        self.exit_code = run_with_choc(choc, once)
        self.locate(root)


def wait_for(choc, seconds=120):
    """Another developer may be relinking build/choc: wait for it (up to two minutes)."""
    deadline = time.monotonic() + seconds
    while not os.access(choc, os.X_OK):
        if time.monotonic() > deadline:
            sys.exit(f"verification_pages: no executable {choc} (build it: make build)")
        print(f"verification_pages: {choc} missing, waiting", file=sys.stderr, flush=True)
        time.sleep(10)
    return os.stat(choc).st_mtime


def run_with_choc(choc, once):
    """once() runs choc and returns an exit code; when it fails while build/choc was replaced or
    missing, it runs again once the new build/choc is there."""
    before = wait_for(choc)
    code = once()
    if code != 0 and (not os.access(choc, os.X_OK) or os.stat(choc).st_mtime != before):
        print("verification_pages: build/choc changed during the run: running again", file=sys.stderr)
        wait_for(choc)
        time.sleep(5)  # let the link finish writing it
        code = once()
    return code


def case_page(case, out_dir, src, bench, plots, source_note):
    """Writes <out>/<case>.md (and its PNGs); returns the index's summary of the case."""
    out_dir = Path(out_dir)
    scene_link = rel(ROOT / "docs/verification" / case.page, out_dir) if case.page else None
    scene_title = case.page
    if case.page and (ROOT / "docs/verification" / case.page).is_file():
        first = (ROOT / "docs/verification" / case.page).read_text().splitlines()[0]
        scene_title = first.lstrip("# ").strip()
    L = ["<!-- Generated by tools/docs/verification_pages.py (make docs): edit the script or the case, "
         "not this page. -->", f"# `{case.name}`: generated results", ""]
    statement = clean_text(case.cfg["COMMENT"], out_dir, bench, scene_link)
    L.append(f"**What the case requires.** {statement}")
    L.append("")
    links = [f"case [`regression/{case.name}/case.cfg`]({rel(case.cfg_path, out_dir)})",
             f"input [`{rel(case.input, ROOT)}`]({rel(case.input, out_dir)})"]
    if scene_link:
        links.insert(0, f"scene page [{scene_title}]({scene_link})")
    anchor = bench.anchor(case.scene) if case.scene else None
    if anchor:
        links.append(f"[benchmark definition]({rel(ROOT / 'docs/verification/benchmarks.md', out_dir)}#{anchor})")
    L.append("**See.** " + "; ".join(links) + ".")
    L.append("")
    summary = {"name": case.name, "page": case.page, "status": "not run", "worst": None,
               "stale": [], "energy_flags": [], "rows": 0, "nook": 0}

    if not case.has_results():
        where = shown(case.results) if case.results else "?"
        L += [f"> **NOT RUN**: no results in `{where}/` — run `make test` (or, in the build "
              "directory, `ctest -R '^regression\\.'`), or this script with `--run`.", ""]
        if case.exit_code not in (None, 0):
            L += [f"The run exited with status {case.exit_code}; the end of its log:", "", "```text"]
            L += Path(case.log).read_text(errors="replace").splitlines()[-15:] + ["```", ""]
            summary["status"] = f"run failed (exit {case.exit_code})"
        write_if_changed(out_dir / f"{case.name}.md", "\n".join(L) + "\n")
        summary["written"] = [f"{case.name}.md"]
        return summary

    when = results_time(case.results)
    stale = staleness(when, [case.input, input_mesh(case.input)], src)
    summary["stale"] = stale
    if stale:
        L += ["> **STALE: these results predate " + joined(stale) + ".** Rerun the case "
              "(`make test`, or this script with `--run`).", ""]
    dirty = " (src/ has uncommitted changes)" if src.dirty else ""
    L.append(f"**Provenance.** Results of {stamp(when)} ({source_note(case)}); pages generated at "
             f"commit {src.head}{dirty}; machine: {machine()}.")
    L.append("")

    checks = read_checks(case.results / "checks.csv")
    nook = [r for r in checks if r["status"] != "OK"]
    summary.update(rows=len(checks), nook=len(nook))
    ratios = [(r["error"] / r["tolerance"], r) for r in checks if r["tolerance"] > 0 and math.isfinite(r["error"])]
    if ratios:
        worst = max(ratios, key=lambda x: x[0])
        summary["worst"] = (worst[0], f"{worst[1]['analysis']} {worst[1]['quantity']}")
    count_note = ""
    if case.expected_rows is not None and len(checks) != case.expected_rows:
        count_note = f" — **{len(checks)} rows where the case expects {case.expected_rows}**"
        summary["status"] = f"{len(checks)} of {case.expected_rows} rows"
    elif nook:
        summary["status"] = f"{len(nook)} NOOK"
    else:
        summary["status"] = "all rows OK"
    if case.exit_code not in (None, 0):
        summary["status"] += f", exit {case.exit_code}"
    status = f"{len(checks) - len(nook)} of {len(checks)} rows OK" + (f", **{len(nook)} NOOK**" if nook else "")
    L.append(f"**Status.** {status}{count_note}" + (f"; the run exited with status {case.exit_code}"
                                                       if case.exit_code not in (None, 0) else "") + ".")
    L.append("")

    # The reference.
    L += ["## The reference", ""]
    if case.document:
        L += [f"The rows come from {case.document}.", ""]
    kinds = {}
    for r in checks:
        kinds[r["reference_kind"]] = kinds.get(r["reference_kind"], 0) + 1
    for k, n in kinds.items():
        L.append(f"- `{k}` ({n} row{'s' if n > 1 else ''}): {KIND_MEANING.get(k, 'as the input says')}")
    notes = {}
    for r in checks:
        r["note"] = clean_text(r["note"], out_dir, bench, scene_link) if r["note"] else ""
        if r["note"]:
            notes.setdefault(r["note"], []).append(r)
    if len(notes) <= 4:
        for note, rs in notes.items():
            L.append(f"- note on {len(rs)} row{'s' if len(rs) > 1 else ''}: {note}")
    else:
        L.append(f"- {len(notes)} different notes on {sum(len(x) for x in notes.values())} rows: in the "
                 "rows' table")
    L.append("")

    # The rows.
    with_notes = len(notes) > 4
    L += ["## The rows (`checks.csv`)", "",
          "| analysis | quantity | time [s] | reference | computed | error | tolerance | error / tolerance | status |"
          + (" note |" if with_notes else ""), "|---|---|---|---|---|---|---|---|---|" + ("---|" if with_notes else "")]
    for r in checks:
        show = pct if r["criterion"] == "relative" or "error/peak" in r["quantity"] else num
        ratio = r["error"] / r["tolerance"] if r["tolerance"] > 0 else float("nan")
        st = r["status"] if r["status"] == "OK" else f"**{r['status']}**"
        L.append(f"| {r['analysis']} | {r['quantity']} | {num(r['time'])} | {num(r['reference'])} | "
                 f"{num(r['computed'])} | {show(r['error'])} | {show(r['tolerance'])} | {ratio:.3g} | {st} |"
                 + (f" {r['note']} |" if with_notes else ""))
    L.append("")

    # Histories, closed forms, energy.
    hist_files = {p.name[:-len(".history.csv")]: p for p in sorted(case.results.glob("*.history.csv"))}
    order = [h for h in case.histories if h in hist_files] + [h for h in hist_files if h not in case.histories]
    loaded = {h: read_history(hist_files[h]) for h in order}
    incomplete = sorted(p.name for p in case.results.glob("*.incomplete.*"))

    whole = [r for r in checks if r["quantity"].endswith(("max error/peak", "RMS error/peak"))]
    L += ["## Whole history against the closed form", ""]
    if whole:
        L += ["From `checks.csv` (the error relative to the peak of the exact solution):", "",
              "| analysis | column | max error / peak | at t [s] | tolerance | RMS error / peak | tolerance | status |",
              "|---|---|---|---|---|---|---|---|"]
        pairs = {}
        for r in whole:
            col, what = r["quantity"].rsplit(" ", 1)[0].rsplit(" ", 1)
            pairs.setdefault((r["analysis"], col), {})[what] = r
        for (an, col), d in pairs.items():
            mx, rms = d.get("max"), d.get("RMS")
            st = "OK" if all(x["status"] == "OK" for x in d.values()) else "**NOOK**"
            L.append(f"| {an} | {col} | {pct(mx['computed']) if mx else '—'} | {num(mx['time']) if mx else '—'} | "
                     f"{pct(mx['tolerance']) if mx else '—'} | {pct(rms['computed']) if rms else '—'} | "
                     f"{pct(rms['tolerance']) if rms else '—'} | {st} |")
        L.append("")
    else:
        L += ["No whole-history rows in `checks.csv`.", ""]
    recomputed, form_notes = [], []
    forms_of = {}
    for h in order:
        forms, why = closed_forms(case.name, case.input, h)
        if why:
            form_notes.append(f"{h}: {why}")
        names, data = loaded[h]
        for col, (f, label) in list(forms.items()):
            if col not in names or len(data) == 0:
                continue
            try:
                e = bar_exact.history_error(data[:, 0], data[:, names.index(col)], f(data[:, 0]))
            except ValueError:
                continue
            # The script's closed form must be choc's: where a whole-history row exists, agree.
            row = [r for r in whole if r["analysis"] == h and r["quantity"] == f"{col} max error/peak"]
            if row and abs(row[0]["computed"] - e["max_rel"]) > 1e-6 * max(1.0, abs(row[0]["computed"])) + 1e-9:
                form_notes.append(f"{h}, {col}: the closed form recomputed here gives {pct(e['max_rel'])} "
                                  f"where choc's row gives {pct(row[0]['computed'])}; not plotted")
                del forms[col]
                continue
            recomputed.append((h, col, label, e))
        forms_of[h] = forms
    if recomputed:
        L += ["Recomputed by this script from the histories (the same measure; `tools/oracles/bar_exact.py`, "
              "`tools/oracles/friction_oscillator.py`), also for the columns the checks only report:", "",
              "| analysis | column | closed form | max error / peak | at t [s] | RMS error / peak |",
              "|---|---|---|---|---|---|"]
        for h, col, label, e in recomputed:
            L.append(f"| {h} | {col} | {label} | {pct(e['max_rel'])} | {num(e['time_of_max'])} | {pct(e['rms_rel'])} |")
        L.append("")
    for n in form_notes:
        L += [f"- {n}"]
    if form_notes:
        L.append("")

    L += ["## Energy balance", "",
          "`energy:balance` = E_total(t) + W_dissipated(t) − E_total(0) − W_external(t): negative when "
          "the scheme dissipates, positive when it creates energy (flagged above "
          f"+{100 * ENERGY_GROWTH_FLAG:g} % of E0).", "",
          "| history | E0 [J] | balance min [J] | balance max [J] | min / E0 | max / E0 | |",
          "|---|---|---|---|---|---|---|"]
    for h in order:
        names, data = loaded[h]
        e = energy_of(names, data)
        if e is None:
            L.append(f"| {h} | not recorded | | | | | |")
            continue
        ref = "" if e["ref_name"] == "E0" else f" (E0 = 0: relative to {e['ref_name']} = {e['ref']:.4g} J)"
        flag = f"**growth above +{100 * ENERGY_GROWTH_FLAG:g} %** (at t = {e['t_hi']:.4g} s)" if e["flag"] else ""
        if e["flag"]:
            summary["energy_flags"].append(f"{h} {e['hi_rel']:+.2%}")
        L.append(f"| {h} | {e['e0']:.6g}{ref} | {e['lo']:+.4g} | {e['hi']:+.4g} | {100 * e['lo_rel']:+.3g} % | "
                 f"{100 * e['hi_rel']:+.3g} % | {flag} |")
    L.append("")
    if incomplete:
        L += [f"Incomplete results (the run stopped early): {', '.join(incomplete)}.", ""]

    cost = read_cost(case.results, case.log)
    L += ["## Cost", ""]
    if cost["source"] is None:
        L += ["No log and no summary: the cost is unknown.", ""]
    else:
        parts = []
        if cost["wall_seconds"] is not None:
            parts.append(f"wall time {cost['wall_seconds']:.3g} s")
        if cost["unknowns"] is not None:
            parts.append(f"{cost['unknowns']:,} unknowns")
        if cost["ranks"] is not None:
            parts.append(f"{cost['ranks']} rank{'s' if cost['ranks'] > 1 else ''}")
        if cost["steps"] is not None:
            parts.append(f"{cost['steps']:,} steps")
        L += [f"{', '.join(parts)} (from {cost['source']}).", ""]
        if cost["per_analysis"]:
            L += ["| analysis | status | unknowns | steps | wall time [s] |", "|---|---|---|---|---|"]
            for a, s in cost["per_analysis"].items():
                L.append(f"| {a} | {s.get('status', '')} | {s.get('unknowns', '')} | {s.get('steps', '')} | "
                         f"{s.get('wall_seconds', '')} |")
            L.append("")

    L += ["## Histories", ""]
    for h in case.histories:
        if h not in loaded:
            L += [f"`{h}`: no history file.", ""]
            continue
        names, data = loaded[h]
        cols = [c for c in case.columns if c in names]
        png = f"{case.name}_{h}.png"
        if plots and cols and len(data):
            plot_history(out_dir / png, f"{case.name}: {h}", names, data, cols, forms_of.get(h, {}),
                         [r for r in checks if r["analysis"] == h])
        if cols and (out_dir / png).is_file():
            dashed = [c for c in cols if c in forms_of.get(h, {})]
            cap = f"; dashed: the closed form of {', '.join(dashed)}" if dashed else ""
            if any(r["analysis"] == h and r["quantity"] in cols for r in checks):
                cap += "; crosses: the references of the rows"
            L += [f"`{h}`: {', '.join(cols)}{cap}.", "", f"![{case.name} {h}]({png})", ""]
    write_if_changed(out_dir / f"{case.name}.md", "\n".join(L) + "\n")
    summary["written"] = [f"{case.name}.md"] + [f"{case.name}_{h}.png" for h in case.histories
                                                 if (out_dir / f"{case.name}_{h}.png").is_file()]
    return summary


# ---------------------------------------------------------------- the extremes

def strip_cmake_comment(line):
    quote = False
    for i, ch in enumerate(line):
        if ch == '"':
            quote = not quote
        elif ch == "#" and not quote:
            return line[:i]
    return line


def read_extremes():
    """The extreme(...) calls of regression/extremes/CMakeLists.txt: [(name, run_case.py args)]."""
    text = "\n".join(strip_cmake_comment(l) for l in
                     (ROOT / "regression/extremes/CMakeLists.txt").read_text().splitlines())
    var = {m.group(1): m.group(2) for m in re.finditer(r'^set\((\w+)\s+"([^"]*)"\)', text, re.M)}
    out = []
    for m in re.finditer(r"^extreme\(", text, re.M):
        i, depth, quote = m.end(), 1, False
        while depth:
            ch = text[i]
            if ch == '"':
                quote = not quote
            elif not quote and ch == "(":
                depth += 1
            elif not quote and ch == ")":
                depth -= 1
            i += 1
        body = re.sub(r"\$\{(\w+)\}", lambda v: shlex.quote(var.get(v.group(1), v.group(0))), text[m.end():i - 1])
        args = shlex.split(body)
        out.append((args[0], args[1:]))
    return out


def option(args, name, default=None):
    return args[args.index(name) + 1] if name in args else default


def extreme_figures(name, args, d):
    """What the extreme's results show: its outcome against the expectation and the energy bound
    (recomputed as run_case.py does)."""
    log = d / "run.log"
    res = d / "results"
    expect = option(args, "--expect", "ok")
    f = {"name": name, "expect": expect, "ran": log.is_file(), "histories": [], "verdict": None}
    if not log.is_file():
        return f
    text = log.read_text(errors="replace")
    f["when"] = results_time(d)
    stderr = text.split("\n--- stderr ---\n", 1)[1] if "\n--- stderr ---\n" in text else ""
    f["message"] = " ".join(l for l in stderr.splitlines() if l.strip()).replace(str(d) + os.sep, "")
    tol = float(option(args, "--energy-tol", "0"))
    lf = None
    if "--leapfrog" in args:
        m = re.search(r"critical step (\S+) s .*dt = (\S+) s", text)
        if m:
            s = re.search(r": (\d+) sub-steps per step", text)
            r = float(m.group(2)) / (int(s.group(1)) if s else 1) / float(m.group(1))
            lf = r * r / (1 - r * r) if r < 1 else float("inf")
    f["tol"] = tol + (lf or 0.0) if ("--energy-tol" in args or lf is not None) else None
    f["leapfrog"] = lf
    for h in sorted(res.glob("*.history.csv")) if res.is_dir() else []:
        names, data = read_history(h)
        e = energy_of(names, data)
        if e is None:
            continue
        tot = data[:, names.index("energy:total")]
        e["growth"] = (float(np.max(tot)) - e["e0"]) / e["e0"] if e["e0"] else float("nan")
        e["name"] = h.name[:-len(".history.csv")]
        f["histories"].append(e)
    f["incomplete"] = sorted(p.name for p in res.glob("*.incomplete.*")) if res.is_dir() else []
    logs = [args[i + 1] for i, x in enumerate(args[:-1]) if x == "--log"]
    logged = all(re.search(rx, text, re.M) for rx in logs)
    if expect == "ok":
        bounded = all(f["tol"] is None or e["growth"] <= f["tol"] for e in f["histories"])
        f["outcome"] = "completed" if f["histories"] and not f["incomplete"] else "stopped"
        f["verdict"] = f["outcome"] == "completed" and bounded and logged
    else:
        rx = option(args, "--stderr")
        f["outcome"] = "refused or stopped" if f["message"] else "completed"
        f["verdict"] = bool(f["message"]) and (not rx or re.search(rx, f["message"]) is not None)
    f["cost"] = read_cost(res if res.is_dir() else None, log)
    return f


def extremes_page(out_dir, root, src, ran_verdicts, source):
    out_dir = Path(out_dir)
    scene = rel(ROOT / "docs/verification" / EXTREMES_PAGE, out_dir)
    L = ["<!-- Generated by tools/docs/verification_pages.py (make docs): edit the script or the case, "
         "not this page. -->", "# The extremes: generated results", "",
         "**What the cases require.** Each extreme either completes with every value finite and the total "
         "energy bounded by E0 (1 + the case's tolerance, plus the leapfrog bound of the explicit modal "
         "scheme), or stops with exit 1 or 2 and a one-line message "
         f"([`regression/extremes/CMakeLists.txt`]({rel(ROOT / 'regression/extremes/CMakeLists.txt', out_dir)}), "
         f"run by [`run_case.py`]({rel(ROOT / 'regression/extremes/run_case.py', out_dir)})).", "",
         f"**See.** scene page [Stability at the extremes]({scene}).", ""]
    cases = read_extremes()
    figs = [extreme_figures(n, a, Path(root) / n) for n, a in cases]
    ran = [f for f in figs if f["ran"]]
    stale_all = []
    if ran:
        oldest = min(f["when"] for f in ran)
        stale_all = staleness(oldest, [ROOT / "regression/extremes" / f"{f['name']}.xml" for f in ran], src)
        dirty = " (src/ has uncommitted changes)" if src.dirty else ""
        if stale_all:
            L += ["> **STALE: these results predate " + joined(stale_all) + ".** Rerun them "
                  "(`cd build && ctest -L extremes`, or this script with `--run`).", ""]
        L += [f"**Provenance.** Results of {stamp(oldest)} to {stamp(max(f['when'] for f in ran))} "
              f"({source}); "
              f"pages generated at commit {src.head}{dirty}; machine: {machine()}.", ""]
    L += ["| case | expected | outcome | E0 [J] | max E_total growth / E0 | bound | balance min / max [J] | "
          "balance max / E0 | wall [s] | verdict |", "|---|---|---|---|---|---|---|---|---|---|"]
    n_ok = n_bad = 0
    flagged = []
    for f in figs:
        if not f["ran"]:
            L.append(f"| `{f['name']}` | {f['expect']} | not run | | | | | | | |")
            continue
        verdict = ran_verdicts.get(f["name"], f["verdict"])
        n_ok += bool(verdict)
        n_bad += not verdict
        if f["histories"]:
            e = f["histories"][0]
            e0, growth = f"{e['e0']:.4g}", f"{e['growth']:+.3e}"
            bal = f"{e['lo']:+.3g} / {e['hi']:+.3g}"
            hi = f"{100 * e['hi_rel']:+.3g} %" + (" **above +0.1 %**" if e["flag"] else "")
            if e["flag"]:
                flagged.append(f"{f['name']} {e['hi_rel']:+.2%}")
        else:
            e0 = growth = bal = hi = ""
        bound = "" if f.get("tol") is None else f"{f['tol']:.3e}"
        outcome = f["outcome"] + (f": {f['message']}" if f["message"] and f["expect"] != "ok" else "")
        outcome = outcome.replace("|", "\\|")
        wall = f"{f['cost']['wall_seconds']:.3g}" if f["cost"]["wall_seconds"] is not None else ""
        L.append(f"| `{f['name']}` | {f['expect']} | {outcome} | {e0} | {growth} | {bound} | {bal} | {hi} | {wall} | "
                 f"{'OK' if verdict else '**FAIL**'} |")
    L.append("")
    L += ["The growth is max_t E_total / E0 − 1; the bound the case's `--energy-tol` plus, for the explicit "
          "modal cases, r² / (1 − r²) with r the (sub-)step over the critical step read from the log, as "
          "`run_case.py` computes it. A completed run with no bound (`implicit_k1e16`) must only say in its "
          "log that the energy grows.", ""]
    scaling = ROOT / "regression/extremes/check_scaling.py"
    a, b = Path(root) / "modal_v1e-3/results/run.history.csv", Path(root) / "modal_v1e2/results/run.history.csv"
    if a.is_file() and b.is_file():
        p = subprocess.run([sys.executable, str(scaling), str(a), str(b), "-1e-3", "-1e2", "1e-9"],
                           capture_output=True, text=True)
        L += ["`speed_scaling` (u/v, F/v and E/v² between 1e-3 and 1e2 m/s, to 1e-9 of the peak):", "",
              "```text"] + [l.strip() for l in p.stdout.strip().splitlines()] + ["```", ""]
    write_if_changed(out_dir / "extremes.md", "\n".join(L) + "\n")
    status = "not run" if not ran else (f"all {n_ok} as expected" if not n_bad else f"{n_bad} of {len(ran)} FAIL")
    if ran and len(ran) < len(figs):
        status += f", {len(figs) - len(ran)} not run"
    return {"name": "extremes", "page": EXTREMES_PAGE, "status": status, "worst": None,
            "stale": stale_all, "energy_flags": flagged, "rows": len(ran), "nook": n_bad,
            "written": ["extremes.md"]}


def run_extremes(choc, root):
    """Runs every extreme through run_case.py, one after the other; {name: passed}."""
    verdicts = {}
    for name, args in read_extremes():
        def once():
            return subprocess.run([sys.executable, str(ROOT / "regression/extremes/run_case.py"), str(choc),
                                   str(ROOT / "regression/extremes" / f"{name}.xml"), str(Path(root) / name),
                                   *args], capture_output=True, text=True).returncode
        code = run_with_choc(choc, once)
        verdicts[name] = code == 0
        print(f"  extremes/{name}: {'OK' if code == 0 else 'FAIL'}", flush=True)
    return verdicts


# ---------------------------------------------------------------- the index

def index_page(out_dir, summaries, src, partial):
    L = ["<!-- Generated by tools/docs/verification_pages.py (make docs): edit the script, not this page. -->",
         "# Generated verification results", "",
         "One page per regression case, generated by `make docs` (`tools/docs/verification_pages.py`) from "
         "the results of the last `make test` (`build/regression/<case>/serial/`), or from runs of its own "
         "with `--run`. The hand-written scene pages of [the verification index](../README.md) explain the "
         "scenes and link here.", "",
         f"Generated at commit {src.head}{' (src/ has uncommitted changes)' if src.dirty else ''}; machine: "
         f"{machine()}.", ""]
    if partial:
        L += ["*Partial: only the cases given with `--cases`.*", ""]
    L += ["| case | scene page | status | rows | largest error / tolerance | energy balance above +0.1 % of E0 | "
          "staleness |", "|---|---|---|---|---|---|---|"]
    for s in summaries:
        page = f"[{s['page']}](../{s['page']})" if s["page"] else ""
        worst = f"{s['worst'][0]:.3g} ({s['worst'][1]})" if s["worst"] else ""
        st = s["status"] if s["status"] in ("all rows OK", "not run") or s["status"].startswith("all ") \
            else f"**{s['status']}**"
        stale = "STALE" if s["stale"] else ("" if s["status"] == "not run" else "current")
        energy = "; ".join(f"**{x}**" for x in s["energy_flags"])
        L.append(f"| [{s['name']}]({s['name']}.md) | {page} | {st} | {s['rows']} | {worst} | {energy} | {stale} |")
    L.append("")
    L += ["Status: every row of `checks.csv` OK, the number of NOOK rows, or not run (no results). The "
          "largest error / tolerance is over the case's rows (1 is the limit). Energy: the largest "
          "`energy:balance` relative to E0 in the histories where it exceeds +0.1 %. STALE: the results "
          "predate the input, its mesh or the last commit touching src/.", ""]
    write_if_changed(Path(out_dir) / "README.md", "\n".join(L) + "\n")


# ---------------------------------------------------------------- main

def main():
    doc = __doc__.split("\n\n")
    ap = argparse.ArgumentParser(description="\n\n".join([doc[0]] + doc[2:]),
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build", help="the build directory (choc, regression/): build")
    ap.add_argument("--out", default=str(ROOT / "docs/verification/generated"), help="where the pages go")
    ap.add_argument("--run", action="store_true",
                    help="run each case's input (and each extreme) here, serially on one rank, "
                         "instead of reading the last results of the suite")
    ap.add_argument("--run-dir", help="with --run: keep the results in this directory (default: a "
                                      "temporary directory, removed at the end)")
    ap.add_argument("--results", help="read the results from this directory instead of BUILD/regression "
                                      "(the same layout: <case>/serial/, <case>/serial.log, extremes/<name>/)")
    ap.add_argument("--cases", nargs="+", help="only these cases (and 'extremes')")
    ap.add_argument("--require-results", action="store_true",
                    help="exit 2, writing nothing, when a case's results are missing")
    ap.add_argument("--no-plots", action="store_true", help="keep the existing PNGs")
    a = ap.parse_args()

    t_start = time.monotonic()
    build = Path(a.build).resolve()
    out_dir = Path(a.out).resolve()
    cases = [Case(p.parent.name, p) for p in sorted((ROOT / "regression").glob("*/case.cfg"))]
    want_extremes = True
    if a.cases:
        unknown = set(a.cases) - {c.name for c in cases} - {"extremes"}
        if unknown:
            sys.exit(f"verification_pages: no regression case {', '.join(sorted(unknown))}")
        cases = [c for c in cases if c.name in a.cases]
        want_extremes = "extremes" in a.cases
    for c in cases:
        if c.name not in CASES:
            print(f"verification_pages: warning: case {c.name} has no scene page in the script's CASES "
                  "table", file=sys.stderr)

    tmp = None
    verdicts = {}
    if a.run:
        choc = build / "choc"
        wait_for(choc)
        if a.run_dir:
            root = Path(a.run_dir).resolve()
            root.mkdir(parents=True, exist_ok=True)
        else:
            tmp = tempfile.mkdtemp(prefix="choc-docs-")
            root = Path(tmp)
        try:
            for c in cases:
                t0 = time.monotonic()
                c.run(choc, root)
                print(f"  {c.name}: exit {c.exit_code}, {time.monotonic() - t0:.1f} s", flush=True)
            if want_extremes:
                verdicts = run_extremes(choc, root / "extremes")
        except BaseException:
            if tmp:
                shutil.rmtree(tmp, ignore_errors=True)
            raise

        def source_note(c):
            kept = f" in `{shown(c.results)}/`" if a.run_dir else ""
            return f"run by `verification_pages.py --run`, one rank{kept}"
        ext_source = "run by `verification_pages.py --run` through `run_case.py`, one rank"
    else:
        root = Path(a.results).resolve() if a.results else build / "regression"
        for c in cases:
            c.locate(root)

        def source_note(c):
            return f"`{shown(c.results)}/`"
        ext_source = f"`{shown(root / 'extremes')}/<case>/`"

    try:
        missing = [c for c in cases if not c.has_results()]
        ext_root = root / "extremes"
        if want_extremes:
            missing_ext = [n for n, _ in read_extremes() if not (ext_root / n / "run.log").is_file()]
        else:
            missing_ext = []
        if a.require_results and (missing or missing_ext):
            names = [c.name for c in missing] + [f"extremes/{n}" for n in missing_ext]
            sys.stderr.write(
                f"verification_pages: missing results for {len(names)} case(s): {', '.join(names)}\n"
                f"  (expected {root}/<case>/serial/checks.csv and {ext_root}/<name>/run.log)\n"
                "  run the regression suite first (make test, or in the build directory "
                "ctest -R '^regression\\.'), or pass --run to run the inputs here\n")
            sys.exit(2)
        out_dir.mkdir(parents=True, exist_ok=True)
        src = Src()
        bench = Benchmarks()
        summaries = []
        for c in cases:
            summaries.append(case_page(c, out_dir, src, bench, not a.no_plots, source_note))
        if want_extremes:
            summaries.append(extremes_page(out_dir, ext_root, src, verdicts, ext_source))
        index_page(out_dir, summaries, src, bool(a.cases))
        if not a.cases and not a.no_plots:  # remove the pages and figures of cases that went away
            keep = {"README.md"} | {w for s in summaries for w in s.get("written", [])}
            for p in out_dir.iterdir():
                if p.suffix in (".md", ".png") and p.name not in keep and \
                        (p.suffix == ".png" or "Generated by tools/docs/verification_pages.py" in p.read_text()):
                    p.unlink()
    finally:
        if tmp:
            shutil.rmtree(tmp, ignore_errors=True)

    for s in summaries:
        flags = f"; energy: {', '.join(s['energy_flags'])}" if s["energy_flags"] else ""
        print(f"{s['name']:24s} {s['status']}{'; STALE' if s['stale'] else ''}{flags}")
    print(f"verification_pages: {len(summaries)} pages in {rel(out_dir, Path.cwd())}/ "
          f"({time.monotonic() - t_start:.1f} s)")


if __name__ == "__main__":
    main()
