#!/usr/bin/env python3
"""Writes the SDNL111 report: RESULTS_DIR/report.md and plots in RESULTS_DIR/plots/.

usage: make_report.py RESULTS_DIR [--inputs DIR] [--input FILE.xml] [--output DIR]

RESULTS_DIR is either the suite's results directory (one sub-directory per input, as written
by tools/build/run-suite.sh: RESULTS_DIR/<input>/ for every input/sdnl111?.xml), or one run's
directory (it holds checks.csv or histories directly; --input names its input, otherwise
<inputs>/<dir name>.xml). The report holds:
  - every row of every checks.csv, with the total count of checks and of NOOK rows;
  - per transient run with a 'Bar Impact Exact Solution' check: the max and RMS error of u_A relative
    to the peak of the exact solution, computed here from the history with tools/oracles/bar_exact.py
    (independent of the C++ computation, which is read back from checks.csv, or from the run
    log <run dir>.log at its printed precision, and compared);
  - one figure per transient run: u_A, v_A and the contact force against the exact solution,
    and the error of u_A over time.
Exit 0 when the report was written and nothing below went wrong; 1 when a results directory
has no checks.csv, an input has no results directory, a history is unreadable, or the Python
and C++ errors against the exact solution disagree (more than 1e-6 relative); 2 on bad usage.
"""
import os
import sys

try:
    import numpy as np  # noqa: F401
    import matplotlib  # noqa: F401
except ImportError:  # e.g. a pyenv python3 first on PATH: use Debian's, which has them
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    raise

import argparse
import csv
import glob
import math
import re
import time as _time

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "oracles"))
import bar_exact  # noqa: E402

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
AGREEMENT_RTOL = 1e-6
CHOC_OUTPUTS = ("checks.csv", "*.history.csv", "*.history.incomplete.csv", "*.exo")


class History:
    def __init__(self, path):
        self.path = path
        self.analysis = os.path.basename(path).split(".history")[0]
        self.incomplete = path.endswith(".history.incomplete.csv")
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
        if not rows or not rows[0] or rows[0][0] != "time":
            raise ValueError("first column is not 'time'")
        self.names = rows[0]
        if len(rows) < 2:
            raise ValueError("no data row")
        for i, r in enumerate(rows[1:], start=2):
            if len(r) != len(self.names):
                raise ValueError(f"line {i}: {len(r)} fields, {len(self.names)} expected")
        try:
            data = np.array(rows[1:], dtype=float)
        except ValueError as e:
            raise ValueError(f"not a number: {e}") from None
        self.t = data[:, 0]
        self.cols = {n: data[:, i] for i, n in enumerate(self.names)}
        if not np.all(np.isfinite(self.t)) or np.any(np.diff(self.t) <= 0):
            raise ValueError("times are not finite and increasing")

    def nonfinite(self):
        return [n for n, v in self.cols.items() if not np.all(np.isfinite(v))]


class Run:
    """One input's results directory."""

    def __init__(self, name, rdir, xml):
        self.name, self.dir, self.xml = name, rdir, xml
        self.inp, self.input_error = None, None
        self.checks, self.histories, self.modes = [], [], []
        self.log = {}  # analysis -> {column: dict of printed strings}


def fmt(v, digits=6):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return str(v)
    return f"{v:.{digits}g}"


def fmt_error(value, criterion):
    try:
        x = float(value)
    except ValueError:
        return value
    return f"{100 * x:.3g}%" if criterion == "relative" else f"{x:.3g}"


def read_checks(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    need = ["analysis", "quantity", "time", "computed", "reference", "reference_kind",
            "criterion", "tolerance", "error", "status", "note"]
    if rows and any(k not in rows[0] for k in need):
        raise ValueError("missing columns " + ", ".join(k for k in need if k not in rows[0]))
    return rows


LOG_ANALYSIS = re.compile(r"^analysis '([^']+)'")
LOG_EXACT = re.compile(r"exact solution, (\S+?)\s*: max error (\S+) \((\S+)% of peak (\S+) "
                       r"at t = (\S+) s\), RMS (\S+)% of peak")


def read_log(path):
    out, current = {}, None
    with open(path, errors="replace") as f:
        for line in f:
            m = LOG_ANALYSIS.match(line)
            if m:
                current = m.group(1)
                continue
            m = LOG_EXACT.search(line)
            if m and current:
                out.setdefault(current, {})[m.group(1)] = {
                    "max": m.group(2), "max_rel": m.group(3), "peak": m.group(4),
                    "time_of_max": m.group(5), "rms_rel": m.group(6)}
    return out


def half_unit(text):
    """Half a unit of the last printed digit of a number printed as text."""
    mant, _, exp = text.lower().partition("e")
    decimals = len(mant.split(".")[1]) if "." in mant else 0
    return 0.5 * 10.0 ** (-decimals + (int(exp) if exp else 0))


def discover(results, inputs_dir, single_input, problems):
    runs = []
    if any(glob.glob(os.path.join(results, p)) for p in CHOC_OUTPUTS):
        name = os.path.splitext(os.path.basename(single_input))[0] if single_input \
            else os.path.basename(os.path.normpath(results))
        xml = single_input or os.path.join(inputs_dir, name + ".xml")
        runs.append(Run(name, results, xml))
    else:
        names = {os.path.splitext(os.path.basename(p))[0]
                 for p in glob.glob(os.path.join(inputs_dir, "sdnl111?.xml"))}
        for d in glob.glob(os.path.join(results, "*")):
            if os.path.isdir(d) and any(glob.glob(os.path.join(d, p)) for p in CHOC_OUTPUTS):
                names.add(os.path.basename(d))
        for name in sorted(names):
            runs.append(Run(name, os.path.join(results, name),
                            os.path.join(inputs_dir, name + ".xml")))
    for run in runs:
        if not os.path.isdir(run.dir):
            problems.append((True, f"{run.name}: no results directory {run.dir} (not run?)"))
            continue
        if os.path.exists(run.xml):
            try:
                run.inp = bar_exact.read_input(run.xml)
            except Exception as e:  # noqa: BLE001
                run.input_error = f"cannot read {run.xml}: {e}"
        else:
            run.input_error = f"no input file {run.xml}"
        if run.input_error:
            problems.append((False, f"{run.name}: {run.input_error}; no exact solution"))
        cpath = os.path.join(run.dir, "checks.csv")
        if not os.path.exists(cpath):
            problems.append((True, f"{run.name}: no checks.csv in {run.dir} (the run did not finish?)"))
        else:
            try:
                run.checks = read_checks(cpath)
            except Exception as e:  # noqa: BLE001
                problems.append((True, f"{run.name}: unreadable {cpath}: {e}"))
        for hp in sorted(glob.glob(os.path.join(run.dir, "*.history.csv")) +
                         glob.glob(os.path.join(run.dir, "*.history.incomplete.csv"))):
            try:
                h = History(hp)
            except Exception as e:  # noqa: BLE001
                problems.append((True, f"{run.name}: unreadable history {hp}: {e}"))
                continue
            if h.incomplete:
                problems.append((False, f"{run.name}/{h.analysis}: incomplete run, history stops "
                                        f"at t = {h.t[-1]:.6g} s"))
            bad = h.nonfinite()
            if bad:
                problems.append((False, f"{run.name}/{h.analysis}: non-finite values in {', '.join(bad)}"))
            run.histories.append(h)
        order = list((run.inp or {}).get("Analyses", {}))
        run.histories.sort(key=lambda h: (order.index(h.analysis) if h.analysis in order
                                          else len(order), h.analysis))
        for mp in sorted(glob.glob(os.path.join(run.dir, "*.modes.csv"))):
            try:
                with open(mp, newline="") as f:
                    rows = list(csv.DictReader(f))
                run.modes.append((os.path.basename(mp)[:-len(".modes.csv")], rows))
            except Exception as e:  # noqa: BLE001
                problems.append((False, f"{run.name}: unreadable {mp}: {e}"))
        lp = os.path.normpath(run.dir) + ".log"
        if os.path.exists(lp):
            run.log = read_log(lp)
    return runs


def find_column(h, wanted, suffix):
    if wanted and wanted in h.cols:
        return wanted
    for n in h.names:
        if n.endswith(suffix):
            return n
    return None


def analyse(run, h, problems):
    """Errors against the exact solution for one history; None when there is none."""
    if run.inp is None:
        return None
    try:
        spec = bar_exact.exact_for_analysis(run.inp, h.analysis)
    except ValueError as e:
        problems.append((False, f"{run.name}/{h.analysis}: no exact solution: {e}"))
        return None
    if spec is None:
        return None
    res = {"spec": spec, "errors": {}, "cpp": {}, "agree": []}
    ex = spec.exact
    series = {"u": (spec.ucol, ex.displacement), "v": (spec.vcol, ex.velocity),
              "f": (find_column(h, spec.fcol, ":force"), ex.force)}
    res["columns"] = {k: c for k, (c, _) in series.items()}
    if spec.ucol not in h.cols:
        problems.append((False, f"{run.name}/{h.analysis}: the history has no column {spec.ucol}"))
        return None
    res["force_abs"] = False
    for key, (col, fn) in series.items():
        if col is None or col not in h.cols:
            continue
        ref = fn(h.t)
        if key == "f" and ex.bilateral and np.nanmin(h.cols[col]) >= 0:
            # a bilateral (circular) link reports the magnitude of its force along the relative
            # position: compare with |exact force| rather than show a false disagreement
            ref = np.abs(ref)
            res["force_abs"] = True
        res.setdefault("ref", {})[key] = ref
        try:
            res["errors"][key] = bar_exact.history_error(h.t, h.cols[col], ref)
        except ValueError:
            pass
    # The C++ values: full precision from checks.csv, else the log at its printed precision.
    ue = res["errors"].get("u")
    full = {r["quantity"][len(spec.ucol) + 1:]: float(r["computed"]) for r in run.checks
            if r["analysis"] == h.analysis and r["quantity"] in
            (spec.ucol + " max error/peak", spec.ucol + " RMS error/peak")}
    for what, key in (("max error/peak", "max_rel"), ("RMS error/peak", "rms_rel")):
        if what in full and ue:
            cpp, py = full[what], ue[key]
            rel = abs(py - cpp) / max(abs(cpp), 1e-300)
            res["cpp"][key] = cpp
            res["agree"].append((f"u {what}", rel <= AGREEMENT_RTOL, f"rel. diff {rel:.1e}"))
    printed = run.log.get(h.analysis, {})
    for key in ("u", "v", "f"):
        col, err = res["columns"].get(key), res["errors"].get(key)
        if not col or col not in printed or not err:
            continue
        p = printed[col]
        for field, scale in (("max", 1.0), ("max_rel", 100.0), ("rms_rel", 100.0)):
            if key == "u" and field != "max" and field in res["cpp"]:
                continue  # already compared at full precision
            val = scale * err[field]
            ok = abs(val - float(p[field])) <= half_unit(p[field]) * (1 + 1e-9) + 1e-300
            res["agree"].append((f"{col} {field} (log, {p[field]})", ok, f"python {val:.6g}"))
            if key == "u" and field != "max":
                res["cpp"].setdefault(field, float(p[field]) / 100.0)
    for what, ok, detail in res["agree"]:
        if not ok:
            problems.append((True, f"{run.name}/{h.analysis}: Python and C++ errors against the "
                                   f"exact solution disagree: {what}: {detail}"))
    return res


def plot(run, h, res, path):
    ms = 1e3 * h.t
    fig, axes = plt.subplots(2, 2, figsize=(13, 8.5), sharex=True)
    (au, av), (af, ae) = axes
    spec = res["spec"] if res else None
    cols = res["columns"] if res else {
        "u": next((n for n in h.names if re.search(r":D[XYZ]$", n)), None),
        "v": next((n for n in h.names if re.search(r":V[XYZ]$", n)), None),
        "f": find_column(h, None, ":force")}
    ref = res.get("ref", {}) if res else {}

    def panel(ax, key, scale, ylabel, what):
        col = cols.get(key)
        if key in ref:
            label = "exact (d'Alembert)"
            if key == "f" and res.get("force_abs"):
                label = "|exact force| (the link reports a magnitude)"
            ax.plot(ms, scale * ref[key], color="0.55", lw=4.5, alpha=0.55, solid_capstyle="butt",
                    label=label, zorder=1)
        if col and col in h.cols:
            ax.plot(ms, scale * h.cols[col], color="C0", lw=1.2, label=f"choc {col}", zorder=2)
        else:
            ax.text(0.5, 0.5, f"no {what} column in the history", transform=ax.transAxes,
                    ha="center", va="center", color="0.4")
        ax.set_ylabel(ylabel)
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=8)

    panel(au, "u", 1e6, "displacement of A, u_A [µm]", "displacement")
    # the declared checks of this displacement (document tables) on top
    ucol = cols.get("u")
    pts = [r for r in run.checks if r["analysis"] == h.analysis and r["quantity"] == ucol]
    if pts:
        au.plot([1e3 * float(r["time"]) for r in pts], [1e6 * float(r["reference"]) for r in pts],
                "o", mfc="none", mec="C3", ms=8, mew=1.5, zorder=3,
                label="declared checks (reference)")
        au.legend(loc="best", fontsize=8)
    panel(av, "v", 1.0, "velocity of A, v_A [m/s]", "velocity")
    panel(af, "f", 1e-3, "contact force (compression > 0) [kN]", "contact force")
    af.set_xlabel("time [ms]")
    ae.set_xlabel("time [ms]")
    if res and "u" in res["errors"]:
        e = res["errors"]["u"]
        d = np.abs(h.cols[ucol] - ref["u"]) / e["peak"]
        ae.semilogy(ms, np.where(d > 0, d, np.nan), color="C1", lw=1.0,
                    label=f"|u_A - u_exact| / peak (peak {1e6 * e['peak']:.1f} µm)")
        ae.axhline(e["rms_rel"], color="C2", ls="--", lw=1.2, label=f"RMS {100 * e['rms_rel']:.3g}%")
        ae.plot([1e3 * e["time_of_max"]], [e["max_rel"]], "v", color="C3",
                label=f"max {100 * e['max_rel']:.3g}% at {1e3 * e['time_of_max']:.4g} ms")
        tol = spec.params.get("Max Error Tolerance", 0.0)
        if tol > 0:
            ae.axhline(tol, color="C3", ls=":", lw=1.2, label=f"max error tolerance {100 * tol:.3g}%")
        # at most ~6 decades below the largest error (log ticks are costly, round-off is noise)
        ae.set_ylim(max(e["max_rel"] * 1e-6, float(np.nanmin(np.where(d > 0, d, np.nan)))),
                    max(e["max_rel"], tol) * 2.0)
        ae.set_ylabel("error of u_A / peak of exact u_A [-]")
        ae.yaxis.set_major_locator(matplotlib.ticker.LogLocator(numticks=8))
        ae.yaxis.set_minor_locator(matplotlib.ticker.NullLocator())  # cheaper, and enough
        ae.grid(True, alpha=0.3)
        ae.legend(loc="lower right", fontsize=8)
    else:
        ae.text(0.5, 0.5, "no exact solution declared for this run", transform=ae.transAxes,
                ha="center", va="center", color="0.4")
        ae.set_yticks([])
    title = f"{run.name} / {h.analysis}"
    mine = [r for r in run.checks if r["analysis"] == h.analysis]
    if mine:
        nook = sum(1 for r in mine if r["status"] != "OK")
        title += f"  —  {len(mine)} checks, {nook} NOOK"
    if h.incomplete:
        title += f"  —  INCOMPLETE: run stopped at t = {h.t[-1]:.4g} s"
    sub = ""
    if spec:
        ex = spec.exact
        sub = (f"exact: {'bilateral' if ex.bilateral else 'unilateral'} contact, c = {ex.c:.1f} m/s "
               f"({spec.wave_speed}), L = {ex.length:g} m, v0 = {ex.v0:g} m/s, t0 = {ex.t0:g} s, "
               f"Z|v0|/2 = {ex.force_magnitude():.0f} N")
    fig.suptitle(title + ("\n" + sub if sub else ""), fontsize=11)
    fig.subplots_adjust(left=0.07, right=0.98, bottom=0.07, top=0.9, hspace=0.08, wspace=0.2)
    fig.savefig(path, dpi=90)
    plt.close(fig)


_JOBS = []


def _plot_job(i):
    run, h, res, png = _JOBS[i]
    try:
        plot(run, h, res, png)
        return None
    except Exception as e:  # noqa: BLE001
        return f"{type(e).__name__}: {e}"


def md_escape(s):
    return str(s).replace("|", "\\|")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results")
    ap.add_argument("--inputs", default=os.path.join(TOP, "input"),
                    help="directory of the input files (default: the repository's input/)")
    ap.add_argument("--input", help="input file of RESULTS_DIR when it is one run's directory")
    ap.add_argument("--output", help="where report.md and plots/ go (default RESULTS_DIR)")
    a = ap.parse_args()
    if not os.path.isdir(a.results):
        print(f"make_report: {a.results} is not a directory", file=sys.stderr)
        return 2
    start = _time.time()
    out = a.output or a.results
    plots = os.path.join(out, "plots")
    os.makedirs(plots, exist_ok=True)
    problems = []
    runs = discover(a.results, a.inputs, a.input, problems)

    global _JOBS
    exact_rows, figures = [], []
    for run in runs:
        for h in run.histories:
            res = analyse(run, h, problems)
            png = os.path.join(plots, f"{run.name}_{h.analysis}.png")
            exact_rows.append((run, h, res))
            _JOBS.append((run, h, res, png))
    outcome = [_plot_job(i) for i in range(len(_JOBS))]
    for (run, h, res, png), err in zip(_JOBS, outcome):
        if err:
            problems.append((True, f"{run.name}/{h.analysis}: plot failed: {err}"))
        else:
            figures.append((run, h, os.path.relpath(png, out)))

    nchecks = sum(len(r.checks) for r in runs)
    nnook = sum(1 for r in runs for c in r.checks if c["status"] != "OK")
    L = ["# SDNL111 report", "",
         f"Results: `{os.path.abspath(a.results)}`; generated {_time.strftime('%Y-%m-%d %H:%M:%S')}.", "",
         f"**{nchecks} checks, {nnook} NOOK** over {len(runs)} input(s): " +
         ", ".join(f"{r.name} ({len(r.checks)} checks, "
                   f"{sum(1 for c in r.checks if c['status'] != 'OK')} NOOK)" if r.checks
                   else f"{r.name} (no checks.csv)" for r in runs) + ".", ""]
    if problems:
        L += ["## Problems", ""]
        L += [f"- {'**ERROR**' if fatal else 'note'}: {md_escape(msg)}" for fatal, msg in problems]
        L.append("")
    L += ["## Checks", "",
          "Relative errors and tolerances in %, absolute ones in the quantity's unit (m for "
          "displacements). Kind: analytic = the document's table, exact = d'Alembert solution.", "",
          "| input | analysis | quantity | time [s] | computed | reference | kind | error | tolerance | status | note |",
          "|---|---|---|---|---|---|---|---|---|---|---|"]
    for run in runs:
        for c in run.checks:
            status = c["status"] if c["status"] == "OK" else f"**{c['status']}**"
            L.append("| " + " | ".join(md_escape(x) for x in (
                run.name, c["analysis"], c["quantity"], fmt(float(c["time"])),
                fmt(float(c["computed"])), fmt(float(c["reference"])), c["reference_kind"],
                fmt_error(c["error"], c["criterion"]), fmt_error(c["tolerance"], c["criterion"]),
                status, c["note"])) + " |")
    L += ["", "## Displacement of A against the exact solution", "",
          "Computed here from each history with the Python closed form (tools/oracles/bar_exact.py), "
          "independently of choc's C++ (src/reference/BarImpactExact.cpp); peak = max |u_exact| "
          f"over the history's times. 'C++' is choc's own value (checks.csv at full precision, "
          f"else the run log at its printed precision); they must agree to {AGREEMENT_RTOL:g} "
          "relative (or to the printed digits).", "",
          "| input | analysis | column | c [m/s] | t0 [s] | peak [m] | max error / peak | at t [s] "
          "| RMS error / peak | C++ max / RMS | v_A RMS / v0 | force RMS / (Z v0 / 2) | Python vs C++ |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for run, h, res in exact_rows:
        name = h.analysis + (" (incomplete)" if h.incomplete else "")
        if not res or "u" not in res["errors"]:
            why = "no exact solution declared" if not res else \
                "exact u_A is 0 at every sample (history too short)"
            L.append(f"| {run.name} | {name} | — | | | | {why} | | | | | | |")
            continue
        ex, e = res["spec"].exact, res["errors"]["u"]
        cpp = res["cpp"]
        cpps = " / ".join(f"{100 * cpp[k]:.4g}%" if k in cpp else "—" for k in ("max_rel", "rms_rel"))
        ev, ef = res["errors"].get("v"), res["errors"].get("f")
        vrms = f"{100 * ev['rms'] / abs(ex.v0):.3g}%" if ev else "—"
        frms = f"{100 * ef['rms'] / ex.force_magnitude():.3g}% ({res['columns']['f']}" + \
            (", vs abs(exact))" if res["force_abs"] else ")") if ef else "—"
        if res["agree"]:
            bad = [w for w, ok, _ in res["agree"] if not ok]
            full = [float(d.split()[-1]) for w, ok, d in res["agree"] if d.startswith("rel. diff")]
            worst = f", max rel. diff {max(full):.1e} at full precision" if full else ""
            agree = ("**DISAGREE**: " + "; ".join(bad)) if bad else \
                f"agree ({len(res['agree'])} values{worst})"
        else:
            agree = "no C++ value found"
        L.append("| " + " | ".join(md_escape(x) for x in (
            run.name, name, res["columns"]["u"], f"{ex.c:.2f}", f"{ex.t0:g}", f"{e['peak']:.5g}",
            f"{100 * e['max_rel']:.4g}%", f"{e['time_of_max']:.6g}", f"{100 * e['rms_rel']:.4g}%",
            cpps, vrms, frms, agree)) + " |")
    modal = [(run, m, rows) for run in runs for m, rows in run.modes]
    if modal:
        L += ["", "## Modal bases", "", "| input | analysis | modes | frequencies [Hz] | max residual |",
              "|---|---|---|---|---|"]
        for run, m, rows in modal:
            try:
                f = [float(r["frequency_hz"]) for r in rows]
                res_ = max(float(r.get("residual", "nan")) for r in rows)
                L.append(f"| {run.name} | {m} | {len(rows)} | {min(f):.6g} to {max(f):.6g} | {res_:.2e} |")
            except (KeyError, ValueError):
                L.append(f"| {run.name} | {m} | {len(rows)} | unreadable | |")
    impacts = [(run, f) for run in runs for f in sorted(glob.glob(os.path.join(run.dir, "*.impacts.csv")))]
    if impacts:
        L += ["", "## Impact statistics", "",
              "Per link or contact pair (`<analysis>.impacts.csv`): the number of impacts, the "
              "largest and mean peak force, the total impulse, and the first impact's start, peak "
              "instant and duration.", "",
              "| input | analysis | link / pair | impacts | largest peak force [N] | mean peak force [N] "
              "| total impulse [N s] | first impact: start, peak at, duration [s] |",
              "|---|---|---|---|---|---|---|---|"]
        for run, f in impacts:
            with open(f) as h:
                rows = list(csv.DictReader(h))
            for link in sorted({r["link"] for r in rows}):
                mine = [r for r in rows if r["link"] == link]
                peaks = [float(r["peak_force"]) for r in mine]
                first = mine[0]
                L.append("| " + " | ".join(md_escape(x) for x in (
                    run.name, os.path.basename(f)[:-len(".impacts.csv")], link, str(len(mine)),
                    f"{max(peaks):.6g}", f"{sum(peaks) / len(peaks):.6g}",
                    f"{sum(float(r['impulse']) for r in mine):.6g}",
                    f"{float(first['start_time']):.6g}, {float(first['peak_time']):.6g}, "
                    f"{float(first['duration']):.6g}")) + " |")
    L += ["", "## Plots", "",
          "Per run: u_A, v_A and the contact force (thin blue: choc; wide grey underneath: the "
          "exact solution; red circles: the declared checks' reference values), and the error of "
          "u_A relative to the peak (log scale).", ""]
    for run, h, rel in figures:
        L += [f"### {run.name} / {h.analysis}", "", f"![{run.name} {h.analysis}]({rel})", ""]
    L += ["## ParaView", "",
          "Renderings of the transient Exodus results (warped by the displacement x 1000, "
          "coloured by the axial displacement and the contact pressure) are written to "
          "`paraview/` by `xvfb-run -a pvbatch tools/report/paraview_views.py` (run by `make run` after "
          "this report when ParaView is installed).", ""]
    with open(os.path.join(out, "report.md"), "w") as f:
        f.write("\n".join(L) + "\n")
    fatal = [m for ok, m in problems if ok]
    print(f"make_report: {os.path.join(out, 'report.md')}: {nchecks} checks, {nnook} NOOK; "
          f"{len(figures)} plot(s) in {plots} ({_time.time() - start:.1f} s)")
    for m in fatal:
        print(f"make_report: error: {m}", file=sys.stderr)
    return 1 if fatal else 0


if __name__ == "__main__":
    sys.exit(main())
