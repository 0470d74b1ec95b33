#!/usr/bin/env python3
"""The same 3D scene run direct and modal (issue 16): SDNL111 C's HEX8 bars (lateral motion
blocked), 50, 400 and 800 elements per bar, by the direct implicit transient with Lagrange contact
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
    # Only the run compared ('reduced'), not its static-correction variant.
    i = modal.index('    <ParameterList name="reduced_static">')
    j = modal.rindex("  </ParameterList>\n</ParameterList>")
    modal = modal[:i] + modal[j:]
    coarse = os.path.join(a.out, "sdnl111c_modal_50.xml")
    with open(coarse, "w") as f:
        f.write(modal.replace("../meshes/sdnl111_3d.exo", os.path.join(ROOT, "meshes", "sdnl111_3d.exo")))
    fine = os.path.join(a.out, "sdnl111c_modal_400.xml")
    with open(fine, "w") as f:  # the same reduction on the 400-element mesh, Exodus every 3e-5 s as the direct run
        f.write(modal.replace("../meshes/sdnl111_3d.exo", os.path.join(ROOT, "meshes", "sdnl111_3d_400.exo"))
                .replace('<Parameter name="Exodus Interval" type="int" value="10"/>',
                         '<Parameter name="Exodus Interval" type="int" value="30"/>'))
    # 800 elements per bar: the mesh by choc's generator, the direct run at Courant 1 as the
    # 400-element input (half its dt), the modal run as on the other meshes.
    mesh800 = os.path.join(a.out, "sdnl111_3d_800.exo")
    if not os.path.exists(mesh800):
        subprocess.run([choc, "mesh", "--dim", "3", "--axis", "z", "--along1", "800", "--along2", "800",
                        "--across1", "1", "--across2", "1", "--width", "0.02", "--height", "0.02",
                        "--gap", "1e-5", "-o", mesh800], check=True, stdout=subprocess.DEVNULL)
    accurate = open(os.path.join(ROOT, "input", "sdnl111c_accurate.xml")).read()
    direct800 = os.path.join(a.out, "sdnl111c_direct_800.xml")
    with open(direct800, "w") as f:
        f.write(accurate.replace("../meshes/sdnl111_3d_400.exo", mesh800)
                .replace('value="3.008915324260792e-07"', 'value="%r"' % (3.008915324260792e-07 / 2))
                .replace('<Parameter name="Exodus Interval" type="int" value="100"/>',
                         '<Parameter name="Exodus Interval" type="int" value="200"/>'))
    modal800 = os.path.join(a.out, "sdnl111c_modal_800.xml")
    with open(modal800, "w") as f:
        f.write(open(fine).read().replace(os.path.join(ROOT, "meshes", "sdnl111_3d_400.exo"), mesh800))
    cases = [("50 HEX8 per bar", "direct", os.path.join(ROOT, "input", "sdnl111c.xml"), [], "c1_modified"),
             ("50 HEX8 per bar", "modal", coarse, ["modes"], "reduced"),
             ("400 HEX8 per bar", "direct", os.path.join(ROOT, "input", "sdnl111c_accurate.xml"), [], "accurate"),
             ("400 HEX8 per bar", "modal", fine, ["modes"], "reduced"),
             ("800 HEX8 per bar", "direct", direct800, [], "accurate"),
             ("800 HEX8 per bar", "modal", modal800, ["modes"], "reduced")]
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
    print("(medians of %d runs, one rank; Exodus states every 1e-5 s on the 50-element scene, every "
          "3e-5 s on the 400- and 800-element ones)" % a.repeat)


if __name__ == "__main__":
    main()
