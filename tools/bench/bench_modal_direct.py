#!/usr/bin/env python3
"""The same 3D scene run direct and modal: SDNL111 C's HEX8 bars (lateral motion
blocked), 50, 400 and 800 elements per bar, by the direct implicit transient with Lagrange contact
(input/sdnl111c.xml run c1_modified; input/sdnl111c_accurate.xml) and reduced to 40 modes with
rigid shock links on the 4 contact nodes (input/sdnl111c_modal.xml, also on the 400-element
mesh). Reports, per run, the medians over --repeat runs of the eigen-solve and transient times
(each analysis's wall_seconds in its summary), the error of DZ(N1) against d'Alembert over the
whole history (the summary's check row) and the speed-up. Writes
results/bench/bench_modal_direct.json.

    bench_modal_direct.py [--build build] [--repeat 5] [--out results/bench-modal] [--sizes 50 400 800]
                          [--json PATH]"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

COLUMNS = [["scene", "scene", ""], ["run", "run", ""], ["eigen_s", "eigen-solve [s]", ".3f"],
           ["transient_s", "transient [s]", ".3f"], ["total_s", "total [s]", ".3f"],
           ["error_pct", "DZ(N1) max error vs d'Alembert [%]", ".2f"],
           ["speedup", "speed-up (transient / total)", ""]]


def modal_deck(mesh, exodus_interval=None):
    """input/sdnl111c_modal.xml's 'modes' and 'reduced' (not its static-correction variant)."""
    d = chocrun.load_deck(chocrun.input_path("sdnl111c_modal.xml"))
    chocrun.keep_analyses(d, ["modes", "reduced"])
    if mesh:
        chocrun.set_param(d, "Mesh/File", mesh)
    if exodus_interval:
        chocrun.set_param(d, "Analyses/reduced/Exodus Interval", exodus_interval)
    chocrun.report_exact_errors(d, "reduced")
    return d


def direct_deck(name, analysis, mesh=None, dt_factor=1.0, exodus_interval=None):
    d = chocrun.load_deck(chocrun.input_path(name))
    chocrun.keep_analyses(d, [analysis])
    an = f"Analyses/{analysis}"
    if mesh:
        chocrun.set_param(d, "Mesh/File", mesh)
    if dt_factor != 1.0:
        chocrun.set_param(d, f"{an}/Time Step", chocrun.get_param(d, f"{an}/Time Step") * dt_factor)
    if exodus_interval:
        chocrun.set_param(d, f"{an}/Exodus Interval", exodus_interval)
    chocrun.report_exact_errors(d, analysis)
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(chocrun.TOP, "build"))
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--sizes", type=int, nargs="+", default=[50, 400, 800], choices=[50, 400, 800])
    ap.add_argument("--out", default=os.path.join(chocrun.TOP, "results", "bench-modal"))
    ap.add_argument("--json", default=None, help="the figures' file (default results/bench/<bench>.json)")
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    mesh400 = os.path.join(chocrun.TOP, "meshes", "sdnl111_3d_400.exo")
    cases = []
    if 50 in a.sizes:
        cases += [("50 HEX8 per bar", "direct", direct_deck("sdnl111c.xml", "c1_modified"), "c1_modified"),
                  ("50 HEX8 per bar", "modal", modal_deck(None), "reduced")]
    if 400 in a.sizes:  # the same reduction on the 400-element mesh, Exodus every 3e-5 s as the direct run
        cases += [("400 HEX8 per bar", "direct", direct_deck("sdnl111c_accurate.xml", "accurate"), "accurate"),
                  ("400 HEX8 per bar", "modal", modal_deck(mesh400, 30), "reduced")]
    if 800 in a.sizes:
        # 800 elements per bar: the mesh by choc's generator, the direct run at Courant 1 as the
        # 400-element input (half its dt), the modal run as on the other meshes.
        mesh800 = os.path.join(a.out, "sdnl111_3d_800.exo")
        if not os.path.exists(mesh800):
            chocrun.mesh(choc, mesh800, "--dim", 3, "--axis", "z", "--along1", 800, "--along2", 800,
                         "--across1", 1, "--across2", 1, "--width", 0.02, "--height", 0.02, "--gap", 1e-5)
        cases += [("800 HEX8 per bar", "direct",
                   direct_deck("sdnl111c_accurate.xml", "accurate", mesh800, 0.5, 200), "accurate"),
                  ("800 HEX8 per bar", "modal", modal_deck(mesh800, 30), "reduced")]
    rows = []
    for scene, kind, deck, transient in cases:
        tag = "%s_%s" % (kind, scene.split()[0])
        path = chocrun.write_deck(deck, os.path.join(a.out, tag + ".xml"))
        recs = []
        for _ in range(a.repeat):
            out = os.path.join(a.out, tag)
            chocrun.run(choc, path, out)
            s = chocrun.read_summaries(out, chocrun.analyses(deck))
            tt = chocrun.summary_value(chocrun.require_completed(s[transient]), "wall_seconds")
            te = sum(chocrun.summary_value(x, "wall_seconds") for n, x in s.items() if n != transient)
            recs.append({"scene": scene, "run": kind, "eigen_s": te, "transient_s": tt, "total_s": te + tt,
                         "error_pct": 100 * chocrun.exact_error(s[transient], "N1:DZ"),
                         "unknowns": chocrun.summary_value(s[transient], "unknowns"),
                         "choc_commit": chocrun.summary_value(s[transient], "choc/commit")})
        rows.append(chocrun.median_record(recs))
    for i, r in enumerate(rows):
        d = rows[i - 1] if r["run"] == "modal" and i > 0 and rows[i - 1]["scene"] == r["scene"] else None
        if d:
            r["speedup_transient"] = d["transient_s"] / r["transient_s"]
            r["speedup_total"] = d["total_s"] / r["total_s"]
            r["speedup"] = "%.0fx / %.0fx" % (r["speedup_transient"], r["speedup_total"])
    tables = [{"title": f"direct against modal (medians of {a.repeat} runs, one rank)", "columns": COLUMNS,
               "note": "Exodus states every 1e-5 s on the 50-element scene, every 3e-5 s on the 400- and "
                       "800-element ones"}]
    chocrun.print_tables(rows, tables)
    chocrun.write_bench_json("bench_modal_direct", "The same 3D scene direct and modal", rows, tables, vars(a),
                             a.json, choc_commit=rows[0]["choc_commit"] if rows else None)


if __name__ == "__main__":
    main()
