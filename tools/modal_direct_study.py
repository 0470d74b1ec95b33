#!/usr/bin/env python3
"""SDNL32 modal or direct (issue 16): the same scene (run 1 without damping) by the modal
transient on 4 to 31 modes (central differences, dt = 1e-5 s, sub-stepped when the basis asks
for it) and by the direct implicit transient on all 31 unknowns (average acceleration, the stop
a penalty contact of the tip node on a plane), each against the direct run at dt = 2.5e-7 s:
the largest error of DY(N11) over 20 ms relative to its peak, and the cost (medians of
--repeat runs of the analyses' wall times).

    modal_direct_study.py [--build build] [--out results/modal-direct] [--repeat 3]"""
import argparse
import os
import re
import statistics
import subprocess

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def modal_input(m):
    s = open(os.path.join(ROOT, "input", "sdnl32.xml")).read()
    s = s.replace("../meshes/", os.path.join(ROOT, "meshes") + "/")
    start = s.index('    <ParameterList name="run1_exact_tip">')
    s = s[:start] + "  </ParameterList>\n</ParameterList>\n"  # modes and run1 only
    s = re.sub(r"      <ParameterList name=\"Checks\">.*?\n      </ParameterList>\n", "", s, flags=re.S)
    s = s.replace('<Parameter name="Number of Modes" type="int" value="10"/>',
                  '<Parameter name="Number of Modes" type="int" value="%d"/>' % m)
    s = s.replace('<Parameter name="Modal Damping" type="double" value="0.01"/>',
                  '<Parameter name="Modal Damping" type="double" value="0"/>\n'
                  '      <Parameter name="Stability Check" type="string" value="substep"/>')
    return s


def direct_input(dt):
    s = open(os.path.join(ROOT, "input", "sdnl32_direct.xml")).read()
    s = s.replace("../meshes/", os.path.join(ROOT, "meshes") + "/")
    return s.replace('<Parameter name="Time Step" type="double" value="1e-6"/>',
                     '<Parameter name="Time Step" type="double" value="%r"/>' % dt)


def run(choc, text, out):
    os.makedirs(out, exist_ok=True)
    path = out + ".xml"
    with open(path, "w") as f:
        f.write(text)
    log = subprocess.run([choc, "run", path, "-o", out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, check=True).stdout
    return sum(float(x) for x in re.findall(r"done in ([0-9.e+-]+) s", log))


def tip(out, name):
    with open(os.path.join(out, name + ".history.csv")) as f:
        cols = f.readline().strip().split(",")
        d = np.loadtxt(f, delimiter=",", ndmin=2)
    return d[:, 0], d[:, cols.index("N11:DY")]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "modal-direct"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--check", action="store_true",
                    help="test: the modal run on all 31 modes equals the direct run at dt = 1e-6 s to "
                         "1e-5 of the peak (their time-discretisation errors, 1.7e-6 and 7e-7, with a "
                         "margin of 4), and 10 modes do not (truncation 2.6e-4)")
    a = ap.parse_args()
    choc = os.path.join(a.build, "choc")
    os.makedirs(a.out, exist_ok=True)
    if a.check:
        run(choc, direct_input(1e-6), os.path.join(a.out, "direct"))
        td, yd = tip(os.path.join(a.out, "direct"), "direct")
        peak = np.max(np.abs(yd))
        errors = {}
        for m in (31, 10):
            run(choc, modal_input(m), os.path.join(a.out, "modal%d" % m))
            t, y = tip(os.path.join(a.out, "modal%d" % m), "run1")
            errors[m] = np.max(np.abs(y - np.interp(t, td, yd))) / peak
            print("modal %d modes against direct: %.3e of the peak" % (m, errors[m]))
        ok = errors[31] <= 1e-5 and errors[10] > 1e-4
        print("OK" if ok else "FAIL: 31 modes must agree to 1e-5, 10 modes must not (truncation)")
        raise SystemExit(0 if ok else 1)
    ref_dir = os.path.join(a.out, "direct_reference")
    run(choc, direct_input(2.5e-7), ref_dir)
    tr, yr = tip(ref_dir, "direct")
    peak = np.max(np.abs(yr))
    rows = []
    cases = [("modal", m, modal_input(m), "run1") for m in (4, 6, 10, 16, 31)]
    cases += [("direct", dt, direct_input(dt), "direct") for dt in (1e-5, 4e-6, 2e-6, 1e-6)]
    for kind, p, text, name in cases:
        out = os.path.join(a.out, "%s_%g" % (kind, p))
        cost = statistics.median(run(choc, text, out) for _ in range(a.repeat))
        t, y = tip(out, name)
        err = np.max(np.abs(y - np.interp(t, tr, yr))) / peak
        rows.append((kind, p, cost, err))
    lines = ["| run | modes / dt | wall time [s] (modal: eigen-solve + transient) | max error of DY(N11) / peak |",
             "|---|---|---|---|"]
    for kind, p, cost, err in rows:
        lines.append("| %s | %s | %.3f | %.2e |" % (kind, ("%d modes" % p) if kind == "modal" else ("dt = %g s" % p),
                                                     cost, err))
    lines.append("(reference: the direct run at dt = 2.5e-7 s; medians of %d runs, one rank)" % a.repeat)
    table = "\n".join(lines)
    print(table)
    with open(os.path.join(a.out, "README.md"), "w") as f:
        f.write("# SDNL32, modal or direct\n\n" + table + "\n")


if __name__ == "__main__":
    main()
