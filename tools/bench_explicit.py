#!/usr/bin/env python3
"""Explicit benchmark (`make bench-explicit`, issue 17): input/scale-3d.xml's scene (300,300
unknowns) by explicit central differences on 1 and 2 MPI ranks.

usage: tools/bench_explicit.py [--build DIR] [--end-time T] [--repeat N] [--contact penalty lagrange]
                               [--ranks 1 2] [--mesh ACROSS ALONG]

The variant: lumped mass, 'Scheme' = 'central differences' with sub-steps, the mass part of
the Rayleigh damping only (a stiffness-proportional term would cut the critical step), penalty
8e8 N/m per slave node (twice the axial stiffness a node's share of an element carries,
E a^2 / 81 / h = 4e8 N/m: stiffer penalties make the contact nodes bounce with the lumped
mass), no Exodus output; or (--contact lagrange) forward-increment Lagrange multipliers, which
add no stiffness, so the mesh alone sets the critical step. Prints per contact method and run the medians over --repeat runs of: the analysis time,
the time per simulated microsecond and per (sub-)step and per unknown, the sub-steps, the peak
resident memory per rank and per unknown, and the np = 2 speed-up (the ranks' runs alternate;
the median over the repeats of each pair's ratio of analysis times). --mesh ACROSS ALONG runs the
scene on another mesh (tools/make-scale-mesh.sh: ACROSS x ACROSS x ALONG HEX8 per bar, made in
the work directory); e.g. --mesh 18 560 is 1,215,270 unknowns. --ranks chooses the rank counts.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MPI = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none"]


def variant(end_time, contact="penalty", mesh=None):
    s = open(os.path.join(TOP, "input", "scale-3d.xml")).read()
    s = s.replace("../meshes/", os.path.join(TOP, "meshes") + "/")
    if mesh:
        s = s.replace(os.path.join(TOP, "meshes", "scale_3d.exo"), mesh)
        assert mesh in s
    s = s.replace('<Parameter name="Material" type="string" value="steel"/>',
                  '<Parameter name="Material" type="string" value="steel"/>\n'
                  '        <Parameter name="Mass" type="string" value="lumped"/>')
    s = re.sub(r'<Parameter name="Scheme" type="string" value="[^"]*"/>\s*'
               r'<Parameter name="Alpha" type="double" value="[^"]*"/>',
               '<Parameter name="Scheme" type="string" value="central differences"/>\n'
               '      <Parameter name="Stability Check" type="string" value="substep"/>', s)
    s = s.replace('<Parameter name="Stiffness Coefficient" type="double" value="1e-7"/>',
                  '<Parameter name="Stiffness Coefficient" type="double" value="0"/>')
    if contact == "penalty":
        s = s.replace('<Parameter name="Penalty Stiffness" type="double" value="1e10"/>',
                      '<Parameter name="Penalty Stiffness" type="double" value="8e8"/>')
    else:
        s = s.replace('<Parameter name="Method" type="string" value="Penalty"/>',
                      '<Parameter name="Method" type="string" value="Lagrange"/>')
        assert 'value="Lagrange"' in s
    s = re.sub(r'<Parameter name="End Time" type="double" value="[^"]*"/>',
               '<Parameter name="End Time" type="double" value="%r"/>' % end_time, s)
    s = s.replace('<Parameter name="Exodus Interval" type="int" value="20"/>',
                  '<Parameter name="Exodus Interval" type="int" value="0"/>')
    assert "central differences" in s and 'value="lumped"' in s
    return s


def run(choc, xml, np_, out):
    cmd = ([] if np_ == 1 else MPI + ["-np", str(np_)]) + [choc, "run", xml, "-o", out]
    p = subprocess.run(cmd, capture_output=True, text=True)
    log = p.stdout + p.stderr
    if p.returncode != 0:
        sys.exit("bench_explicit: np = %d failed (exit %d):\n%s" % (np_, p.returncode, log[-3000:]))
    analysis = float(re.search(r"done in ([0-9.e+-]+) s", log).group(1))
    steps, sub = map(int, re.search(r"(\d+) steps of (\d+) sub-step", log).groups())
    unknowns = int(re.search(r"(\d+) unknowns( \(\+ \d+ contact pressures\))?;", log).group(1))
    mem = re.search(r"peak resident per rank \[MiB\]: ([^;]+);.*?(\d+) bytes per unknown", log)
    return analysis, steps * sub, unknowns, mem.group(1).strip(), int(mem.group(2))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(TOP, "build"))
    ap.add_argument("--end-time", type=float, default=5e-6)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--contact", nargs="+", choices=["penalty", "lagrange"], default=["penalty", "lagrange"])
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--mesh", type=int, nargs=2, metavar=("ACROSS", "ALONG"))
    a = ap.parse_args()
    choc = os.path.join(a.build, "choc")
    if not os.path.exists(os.path.join(TOP, "meshes", "scale_3d.exo")):
        subprocess.run([os.path.join(TOP, "tools", "make-scale-mesh.sh")], check=True)
    work = tempfile.mkdtemp(prefix="choc-bench-explicit-")
    mesh = None
    if a.mesh:
        mesh = os.path.join(work, "scale_%d_%d.exo" % tuple(a.mesh))
        subprocess.run([os.path.join(TOP, "tools", "make-scale-mesh.sh"), choc, str(a.mesh[0]), str(a.mesh[1]), mesh],
                       check=True, stdout=subprocess.DEVNULL)
    print("| contact | np | unknowns | analysis [s] | per simulated us [s] | sub-steps | per sub-step [ms] | per sub-step and unknown [ns] | peak memory per rank [MiB] | bytes per unknown |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    speedups = []
    for contact in a.contact:
        xml = os.path.join(work, "explicit_%s.xml" % contact)
        with open(xml, "w") as f:
            f.write(variant(a.end_time, contact, mesh))
        # The ranks' runs alternate (np = 1, np = 2, np = 1, ...): the host's load, which moves
        # these figures by a quarter, then weighs on both sides of each speed-up alike.
        runs = {np_: [] for np_ in a.ranks}
        for k in range(a.repeat):
            for np_ in a.ranks:
                runs[np_].append(run(choc, xml, np_, os.path.join(work, "%s_np%d_%d" % (contact, np_, k))))
        for np_ in a.ranks:
            t = statistics.median(r[0] for r in runs[np_])
            _, sub, n, mem, bpu = runs[np_][-1]
            print("| %s | %d | %d | %.2f | %.3f | %d | %.1f | %.1f | %s | %d |"
                  % (contact, np_, n, t, t / (a.end_time * 1e6), sub, 1e3 * t / sub,
                     1e9 * t / sub / n, mem, bpu), flush=True)
        if 1 in runs and 2 in runs:
            ratios = [r1[0] / r2[0] for r1, r2 in zip(runs[1], runs[2])]
            speedups.append("%s %.2f" % (contact, statistics.median(ratios)))
    if speedups:
        print("\nnp = 2 speed-up: %s (median over %d back-to-back pairs of np = 1 and np = 2 runs of the "
              "ratio of their analysis times; mesh reading and assembly excluded)"
              % (", ".join(speedups), a.repeat))

if __name__ == "__main__":
    main()
