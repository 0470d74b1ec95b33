#!/usr/bin/env python3
"""The same 3D scene run direct and modal (issue 16): SDNL111 C's HEX8 bars (lateral motion
blocked), 50 and 400 elements per bar, by the direct implicit transient with Lagrange contact
(input/sdnl111c.xml run c1_modified; input/sdnl111c_accurate.xml) and reduced to 40 modes with
rigid shock links on the 4 contact nodes (input/sdnl111c_modal.xml, also on the 400-element
mesh). Prints, per run, the medians over --repeat runs of the eigen-solve and transient wall
times (from the log's 'done in'), the error of DZ(N1) against d'Alembert, and the speed-up.

    bench_modal_direct.py [--build build] [--repeat 5] [--out results/bench-modal]"""
import argparse
import os
import re
import statistics
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def run(choc, inp, out):
    log = subprocess.run([choc, "run", inp, "-o", out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, check=True).stdout
    times, errors, current = {}, {}, None
    for line in log.splitlines():
        m = re.match(r"analysis '([^']+)'", line)
        if m:
            current = m.group(1)
        m = re.search(r"done in ([0-9.e+-]+) s", line)
        if m and current:
            times[current] = float(m.group(1))
        m = re.search(r"exact solution, N1:DZ\s*: max error \S+ \(([0-9.]+)% of peak", line)
        if m and current:
            errors[current] = float(m.group(1))
    return times, errors


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "bench-modal"))
    a = ap.parse_args()
    choc = os.path.join(a.build, "choc")
    os.makedirs(a.out, exist_ok=True)
    modal = open(os.path.join(ROOT, "input", "sdnl111c_modal.xml")).read()
    fine = os.path.join(a.out, "sdnl111c_modal_400.xml")
    with open(fine, "w") as f:  # the same reduction on the 400-element mesh, Exodus every 3e-5 s as the direct run
        f.write(modal.replace("../meshes/sdnl111_3d.exo", os.path.join(ROOT, "meshes", "sdnl111_3d_400.exo"))
                .replace('<Parameter name="Exodus Interval" type="int" value="10"/>',
                         '<Parameter name="Exodus Interval" type="int" value="30"/>'))
    cases = [("50 HEX8 per bar", "direct", os.path.join(ROOT, "input", "sdnl111c.xml"), [], "c1_modified"),
             ("50 HEX8 per bar", "modal", os.path.join(ROOT, "input", "sdnl111c_modal.xml"), ["modes"], "reduced"),
             ("400 HEX8 per bar", "direct", os.path.join(ROOT, "input", "sdnl111c_accurate.xml"), [], "accurate"),
             ("400 HEX8 per bar", "modal", fine, ["modes"], "reduced")]
    rows = []
    for scene, kind, inp, pre, transient in cases:
        tt, te, err = [], [], None
        for r in range(a.repeat):
            times, errors = run(choc, inp, os.path.join(a.out, "%s_%s" % (kind, scene.split()[0])))
            tt.append(times[transient])
            te.append(sum(times[p] for p in pre))
            err = errors.get(transient)
        rows.append((scene, kind, statistics.median(te), statistics.median(tt), err))
    print("| scene | run | eigen-solve [s] | transient [s] | total [s] | DZ(N1) max error vs d'Alembert | speed-up (transient / total) |")
    print("|---|---|---|---|---|---|---|")
    for i, (scene, kind, te, tt, err) in enumerate(rows):
        d = rows[i - 1] if kind == "modal" else None
        speed = "%.0fx / %.0fx" % (d[3] / tt, (d[2] + d[3]) / (te + tt)) if d else ""
        print("| %s | %s | %.3f | %.3f | %.3f | %.2f %% | %s |" % (scene, kind, te, tt, te + tt, err, speed))
    print("(medians of %d runs, one rank; Exodus states every 1e-5 s on the 50-element scene, every 3e-5 s on the 400-element one)" % a.repeat)


if __name__ == "__main__":
    main()
