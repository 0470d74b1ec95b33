#!/usr/bin/env python3
"""Scale benchmark (`make bench`): input/scale-3d.xml on 1 and 2 MPI ranks.

usage: tools/bench_scale.py [--build DIR] [--sizes] [--end-time T] [--repeat N] [--solver input|auto]

Generates meshes/scale_3d.exo (tools/make-scale-mesh.sh) when missing, runs the input with
np = 1 and np = 2 (mpirun --allow-run-as-root --oversubscribe), and prints, per run: the
unknowns, the wall time (whole run: mesh reading, assembly, set-up, steps) and the analysis
time, the time per step split into assembly, linear solve, contact and output (rank 0's
stacked timer), Krylov iterations per step, the peak resident memory of every rank and per
unknown, the speed-up and the parallel efficiency, and the load average before the run
(other processes on the machine distort the figures: read them next to it).
--sizes also runs smaller meshes (same scene, 20 steps) for the growth of time per step and
memory with the unknowns. --repeat N runs np = 1 and np = 2 in
turn N times and reports each np's median run (whose analysis time is the median; N odd) and
the median of the N pairs' speed-ups (the host's load weighs on both runs of a pair). --solver auto
drops the input's 'Method' and 'Preconditioner' (CG + Additive Schwarz), so that the default
linear solver 'auto' chooses (CG + Jacobi here, mass-dominated) with the default adaptive
linear tolerance, and compares its np = 1 histories with one run of the input as written.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# --bind-to none: Open MPI pins rank r to core r for np <= 2; on a machine shared with other
# jobs a pinned rank waits for its core while the other core idles (measured: 2 pinned ranks
# slower than 1, 2 unpinned ranks 1.65 times faster, 65k unknowns, load average 3-4).
MPI = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none"]


def load():
    return open("/proc/loadavg").read().split()[0]


def run(choc, xml, np_, outdir):
    cmd = ([] if np_ == 1 else MPI + ["-np", str(np_)]) + [choc, "run", xml, "-o", outdir]
    la = load()
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.monotonic() - t0
    if p.returncode != 0:
        sys.exit(f"bench_scale: {' '.join(cmd)} failed ({p.returncode}):\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    log = p.stdout
    r = {"np": np_, "wall": wall, "load": la}
    r["unknowns"] = int(re.search(r"(\d+) unknowns on", log).group(1))
    m = re.search(r"time: ([\d.]+) s = assembly ([\d.]+) \+ linear solve ([\d.]+) \+ contact ([\d.]+) \+ output ([\d.]+)", log)
    r["analysis"], r["assembly"], r["solve"], r["contact"], r["output"] = map(float, m.groups())
    r["steps"] = int(re.search(r"(\d+) steps, (\d+) Newton", log).group(1))
    r["newton"] = int(re.search(r"(\d+) steps, (\d+) Newton", log).group(2))
    m = re.search(r"Krylov iterations: (\d+) \(([\d.]+) per step, ([\d.]+) per Newton", log)
    r["krylov_step"], r["krylov_solve"] = (float(m.group(2)), float(m.group(3))) if m else (0, 0)
    m = re.search(r"memory: peak resident per rank \[MiB\]: ([\d. ]+); all ranks ([\d.]+) MiB, (\d+) bytes per unknown", log)
    r["mem"] = [float(x) for x in m.group(1).split()]
    r["bytes_per_unknown"] = int(m.group(3))
    r["cpu"] = [float(x) for x in re.search(r"cpu time per rank \[s\]: ([\d. ]+)", log).group(1).split()]
    r["log"] = log
    return r


def table(rows, title):
    print(f"\n{title}")
    print(f"{'np':>3} {'unknowns':>9} {'wall s':>8} {'analysis s':>10} {'steps':>5} "
          f"{'ms/step':>8} {'assembly':>8} {'solve':>8} {'contact':>8} {'output':>8} "
          f"{'Krylov/step':>11} {'MiB per rank':>16} {'B/unknown':>9} {'speed-up':>8} {'eff.':>5} {'load':>5} {'cpu s per rank':>15}")
    base = {}
    for r in rows:
        s = max(r["steps"], 1)
        key = r["unknowns"]
        if r["np"] == 1:
            base[key] = r
        b = base.get(key)
        sp = b["analysis"] / r["analysis"] if b else float("nan")
        print(f"{r['np']:>3} {r['unknowns']:>9} {r['wall']:>8.2f} {r['analysis']:>10.2f} {r['steps']:>5} "
              f"{1e3 * r['analysis'] / s:>8.1f} {1e3 * r['assembly'] / s:>8.1f} {1e3 * r['solve'] / s:>8.1f} "
              f"{1e3 * r['contact'] / s:>8.1f} {1e3 * r['output'] / s:>8.1f} {r['krylov_step']:>11.1f} "
              f"{' '.join('%.0f' % m for m in r['mem']):>16} {r['bytes_per_unknown']:>9} "
              f"{sp:>8.2f} {sp / r['np']:>5.2f} {r['load']:>5} {' '.join('%.1f' % c for c in r['cpu']):>15}")
    print("(ms/step = analysis time / steps; assembly, solve, contact, output per step from rank 0's "
          "timer; speed-up and efficiency on the analysis time; wall includes start-up, mesh reading "
          "and matrix assembly; load = 1-min load average before the run; cpu = user + system time of "
          "each rank's process)")


def compare(tmp, reference, other, title):
    """Prints the largest difference of every history column of run `other` from `reference`
    (directories under tmp), per column's peak (tools/compare_histories.py)."""
    cmp = subprocess.run([sys.executable, os.path.join(TOP, "tools", "compare_histories.py"),
                          os.path.join(tmp, reference, "impact.history.csv"),
                          os.path.join(tmp, other, "impact.history.csv"), "--rtol-peak", "1e-6"],
                         capture_output=True, text=True)
    print(f"{title} (max |diff| / peak):")
    print(cmp.stdout.rstrip())


def median_runs(choc, xml, repeat, tmp, prefix):
    """Runs xml on np = 1 and np = 2 in turn `repeat` times (the host's load then weighs on both
    runs of a pair); returns each np's median run (by analysis time) and the pairs' speed-ups."""
    runs = {1: [], 2: []}
    for _ in range(repeat):
        for np_ in (1, 2):
            runs[np_].append(run(choc, xml, np_, os.path.join(tmp, f"{prefix}{np_}")))
    rows = [sorted(runs[np_], key=lambda r: r["analysis"])[len(runs[np_]) // 2] for np_ in (1, 2)]
    return rows, sorted(r1["analysis"] / r2["analysis"] for r1, r2 in zip(runs[1], runs[2]))


def print_pairs(pairs, what):
    if len(pairs) > 1:
        print(f"{what}: np = 2 speed-up, median over {len(pairs)} back-to-back pairs of runs: "
              f"{pairs[len(pairs) // 2]:.2f} (pairs: {', '.join('%.2f' % p for p in pairs)})")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(TOP, "build"))
    ap.add_argument("--sizes", action="store_true")
    ap.add_argument("--end-time", default="")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--solver", choices=("input", "auto"), default="input")
    a = ap.parse_args()
    choc = os.path.join(os.path.abspath(a.build), "choc")
    subprocess.run([os.path.join(TOP, "tools", "make-scale-mesh.sh"), choc], check=True)
    xml = os.path.join(TOP, "input", "scale-3d.xml")
    tmp = tempfile.mkdtemp(prefix="choc-bench-")
    print(f"machine: {os.cpu_count()} cores, {open('/proc/cpuinfo').read().split('model name')[1].split(':')[1].splitlines()[0].strip()}")
    src = xml
    title = "input/scale-3d.xml"
    if a.end_time or a.solver == "auto":
        src = os.path.join(tmp, "scale-3d.xml")
        txt = open(xml).read().replace("../meshes/scale_3d.exo", os.path.join(TOP, "meshes", "scale_3d.exo"))
        if a.end_time:
            txt = re.sub(r'(name="End Time" type="double" value=")[^"]*', r"\g<1>" + a.end_time, txt)
        open(src, "w").write(txt)
        if a.solver == "auto":
            asWritten = src
            src = os.path.join(tmp, "scale-3d-auto.xml")
            auto = txt.replace('<Parameter name="Method" type="string" value="CG"/>', "")
            auto = auto.replace('<Parameter name="Preconditioner" type="string" value="Additive Schwarz"/>', "")
            assert 'value="CG"' not in auto and "Additive Schwarz\"" not in auto
            open(src, "w").write(auto)
            title = "input/scale-3d.xml with the linear solver 'auto'"
    rows, pairs = median_runs(choc, src, a.repeat, tmp, "np")
    table(rows, title + (f" (median run of {a.repeat} per np)" if a.repeat > 1 else ""))
    print_pairs(pairs, "input/scale-3d.xml")
    print("linear solver:", re.search(r"linear solver (.*)", rows[0]["log"]).group(1))
    compare(tmp, "np1", "np2", "np = 2 vs np = 1 histories")
    if a.solver == "auto":
        ref = run(choc, asWritten, 1, os.path.join(tmp, "as_written"))
        table([ref], "input/scale-3d.xml as written (one run)")
        compare(tmp, "as_written", "np1", "'auto' vs the input as written, np = 1")
    if a.sizes:
        srows = []
        for across, along in ((3, 250), (5, 300), (7, 400)):
            mesh = os.path.join(tmp, f"m{across}_{along}.exo")
            subprocess.run([os.path.join(TOP, "tools", "make-scale-mesh.sh"), choc, str(across), str(along), mesh],
                           check=True, capture_output=True)
            txt = open(xml).read().replace("../meshes/scale_3d.exo", mesh)
            txt = re.sub(r'(name="End Time" type="double" value=")[^"]*', r"\g<1>2e-5", txt)
            x = os.path.join(tmp, f"m{across}_{along}.xml")
            open(x, "w").write(txt)
            r, p = median_runs(choc, x, a.repeat, tmp, f"s{across}_")
            srows += r
            print_pairs(p, f"{r[0]['unknowns']:,} unknowns")
        table(srows + rows, "sizes (20 steps, contact from step 10; the last two rows: input/scale-3d.xml)"
              + (f" (median run of {a.repeat} per np)" if a.repeat > 1 else ""))
    print(f"\nlogs and results in {tmp}")


if __name__ == "__main__":
    main()
