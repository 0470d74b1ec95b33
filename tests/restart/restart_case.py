#!/usr/bin/env python3
"""Restart tests: a run stopped and continued from its checkpoint must equal the
uninterrupted run, bit for bit on the same ranks and to solver tolerance on others.

  restart_case.py stops   CHOC INPUT OUT --analysis A --steps N... [--contact-column COL --contact-steps N...]
                          [--log-once PATTERN]
  restart_case.py ranks   CHOC INPUT OUT --analysis A --steps N --np-first P --np-restart Q --tolerance T
  restart_case.py kill    CHOC INPUT OUT --seeds S... [--kills K]
  restart_case.py fault   CHOC INPUT OUT --file-size BYTES
  restart_case.py refuse  CHOC INPUT OUT --analysis A --steps N

stops: the reference run, then for each N a run stopped at the end of nominal step N of
  analysis A (CHOC_TEST_SIGNAL_AT_STEP) and continued with --restart; histories and Exodus files
  must be identical to the reference's (tools/oracles/compare_results.py). With --contact-column, the
  reference history must show contact (COL != 0) at each of --contact-steps. With --log-once, a line
  matching PATTERN is logged once by the reference and once by the stopped and continued runs together.
ranks: stopped on P ranks, continued on Q ranks; equal to the 1-rank reference to T of peak.
  (With --checkpoint-steps or --checkpoint-seconds, every mode runs a copy of INPUT with checkpoints.)
kill: SIGKILL at random moments (seeded), then --restart from the last checkpoint (or from the
  start when none was written yet), K kills per seed; the final results equal the reference.
fault: the run under a file-size limit (RLIMIT_FSIZE) must end with exit 2 and one stderr line
  naming the file, leave readable incomplete results and a checkpoint, and that checkpoint
  continued without the limit must give the reference results.
refuse: a checkpoint from another input, another mesh, truncated, corrupted, past the end time,
  or without its results files: exit 1, one stderr line saying why, no result file written."""
import argparse
import glob
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
COMPARE = os.path.join(HERE, "..", "..", "tools", "oracles", "compare_results.py")
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none"]


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(cmd, env=None, limit=None, expect=None, log=None):
    def preexec():
        if limit is not None:
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    e = dict(os.environ)
    e.pop("CHOC_TEST_SIGNAL_AT_STEP", None)
    e.update(env or {})
    p = subprocess.run(cmd, env=e, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                       preexec_fn=preexec)
    if log:
        with open(log, "w") as f:
            f.write(p.stdout)
    if expect is not None and p.returncode != expect:
        fail("%s: exit %d, expected %d\nstderr: %s\nstdout tail:\n%s" % (
            " ".join(cmd), p.returncode, expect, p.stderr, "\n".join(p.stdout.splitlines()[-15:])))
    return p


def choc(a, out, extra=(), np_=1):
    cmd = [a.choc, "run", a.input, "-o", out] + list(extra)
    return (MPIRUN + ["-np", str(np_)] + cmd) if np_ > 1 else cmd


IGNORE = []  # --ignore: passed to compare_results.py with --tolerance
VECTOR_PEAKS = []  # ["--vector-peaks"] when given: passed with --tolerance


def compare(ref, out, tolerance=None):
    cmd = [sys.executable, COMPARE, ref, out] + (["--tolerance", str(tolerance)] if tolerance else [])
    if tolerance:
        cmd += VECTOR_PEAKS + (["--ignore"] + IGNORE if IGNORE else [])
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(p.stdout.strip())
    if p.returncode != 0:
        fail("results of %s differ from the reference %s" % (out, ref))


def reference(a):
    ref = os.path.join(a.out, "reference")
    shutil.rmtree(ref, ignore_errors=True)
    t0 = time.time()
    run(choc(a, ref), expect=0, log=ref + ".log")
    return ref, time.time() - t0


def checkpoint_of(out, analysis):
    return os.path.join(out, analysis + ".checkpoint")


def stop_and_restart(a, ref, n, np_first=1, np_restart=1):
    out = os.path.join(a.out, "stop%d_np%d_%d" % (n, np_first, np_restart))
    shutil.rmtree(out, ignore_errors=True)
    p = run(choc(a, out, np_=np_first), env={"CHOC_TEST_SIGNAL_AT_STEP": "%s:%d" % (a.analysis, n)},
            expect=143, log=out + ".first.log")
    if "--restart" not in p.stderr:
        fail("the interruption message does not say how to continue: " + p.stderr)
    ck = checkpoint_of(out, a.analysis)
    if not os.path.isfile(ck):
        fail("no checkpoint " + ck + " after the interruption")
    p = run(choc(a, out, ["--restart", ck], np_=np_restart), expect=0, log=out + ".restart.log")
    if not re.search(r"continuing from the checkpoint at t = \S+ s \(step %d\)" % n, p.stdout):
        fail("the log does not say where the run continued from")
    return out


def history_column(path, column):
    with open(path) as f:
        names = f.readline().strip().split(",")
        rows = [list(map(float, l.split(","))) for l in f if l.strip()]
    j = names.index(column)
    return [r[j] for r in rows]


def count_lines(path, pattern):
    with open(path) as f:
        return sum(1 for line in f if re.search(pattern, line))


def check_logged_once(a, ref, out):
    """--log-once: the pattern's line is on the reference's log once, and once on the stopped run's
    and the continued run's logs together (a message the run before the checkpoint gave is not given again)."""
    if not a.log_once:
        return
    counts = [count_lines(ref + ".log", a.log_once), count_lines(out + ".first.log", a.log_once),
              count_lines(out + ".restart.log", a.log_once)]
    print("/%s/: %d line(s) in the reference's log, %d before the stop, %d after it" % (a.log_once, *counts))
    if counts[0] != 1 or counts[1] + counts[2] != 1:
        fail("the line /%s/ is not logged exactly once (reference, before the stop, after it: %s)" % (a.log_once, counts))


def cmd_stops(a):
    ref, _ = reference(a)
    if a.contact_column:
        col = history_column(os.path.join(ref, a.analysis + ".history.csv"), a.contact_column)
        for n in a.contact_steps:
            if col[n] == 0.0:
                fail("step %d is not in contact (%s = 0): the test would not stop mid-contact" % (n, a.contact_column))
            print("step %d: %s = %g (in contact)" % (n, a.contact_column, col[n]))
    for n in a.steps:
        out = stop_and_restart(a, ref, n)
        compare(ref, out)
        check_logged_once(a, ref, out)
    print("OK")


def cmd_ranks(a):
    ref, _ = reference(a)
    for n in a.steps:
        compare(ref, stop_and_restart(a, ref, n, a.np_first, a.np_restart), a.tolerance)
    print("OK")


def cmd_kill(a):
    ref, wall = reference(a)
    print("reference run: %.2f s" % wall)
    for seed in a.seeds:
        rng = random.Random(seed)
        out = os.path.join(a.out, "kill%d" % seed)
        shutil.rmtree(out, ignore_errors=True)
        for k in range(a.kills):
            cks = glob.glob(os.path.join(out, "*.checkpoint"))
            extra = ["--restart", cks[0]] if cks else []
            delay = rng.uniform(0.05, 0.6) * wall
            proc = subprocess.Popen(choc(a, out, extra), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            time.sleep(delay)
            proc.send_signal(signal.SIGKILL)
            proc.wait()
            left = glob.glob(os.path.join(out, "*.checkpoint"))
            print("seed %d kill %d after %.2f s (%s): checkpoint %s" % (
                seed, k + 1, delay, "restart" if extra else "start", left[0] if left else "none yet"))
        cks = glob.glob(os.path.join(out, "*.checkpoint"))
        p = run(choc(a, out, ["--restart", cks[0]] if cks else []), expect=0)
        compare(ref, out)
    print("OK")


def one_line(p, pattern):
    lines = p.stderr.strip().splitlines()
    if "-" * 20 in p.stderr:  # mpirun's own report of the exit code follows choc's line
        lines = lines[: next(i for i, l in enumerate(lines) if l.startswith("-" * 20))]
    if len(lines) != 1:
        fail("stderr has %d lines, expected one:\n%s" % (len(lines), p.stderr))
    if not re.search(pattern, lines[0]):
        fail("stderr does not match /%s/: %s" % (pattern, lines[0]))
    print("  " + lines[0])


def cmd_fault(a):
    ref, _ = reference(a)
    out = os.path.join(a.out, "fault")
    shutil.rmtree(out, ignore_errors=True)
    # (PMIx keeps its data in memory and 2 ranks talk over TCP: their shared-memory files would
    # exceed the limit.)
    p = run(choc(a, out, np_=a.np_first), env={"PMIX_MCA_gds": "hash", "OMPI_MCA_btl": "self,tcp"},
            limit=a.file_size, expect=2)
    one_line(p, r"^choc: output failure: .*%s[^ ]*\.(exo|csv)[^ ]*.*(File too large|file-size limit)" % re.escape(out))
    cks = glob.glob(os.path.join(out, "*.checkpoint"))
    if not cks:
        fail("no checkpoint left after the fault")
    for f in glob.glob(os.path.join(out, "*.part")):
        fail("file left as .part: " + f)
    import netCDF4
    for f in glob.glob(os.path.join(out, "*.incomplete.exo")):
        with netCDF4.Dataset(f) as d:
            print("  %s: %d steps readable" % (os.path.basename(f), len(d.variables["time_whole"][:])))
    for f in glob.glob(os.path.join(out, "*.incomplete.csv")):
        with open(f) as h:
            rows = h.read().splitlines()
        print("  %s: %d rows" % (os.path.basename(f), len(rows) - 1))
    run(choc(a, out, ["--restart", cks[0]]), expect=0)
    # Written on 2 ranks and continued on 1: equal to the 1-rank reference to Newton's tolerance.
    compare(ref, out, 1e-8 if a.np_first > 1 else None)
    print("OK")


def edited_input(a, path, old, new):
    text = open(a.input).read()
    if old not in text:
        fail("cannot edit the input: %r not found" % old)
    # Relative mesh paths stay valid: the copy goes beside the original.
    with open(path, "w") as f:
        f.write(text.replace(old, new, 1))
    return path


def cmd_refuse(a):
    import netCDF4
    base = os.path.join(a.out, "refuse")
    shutil.rmtree(base, ignore_errors=True)
    n = a.steps[0]
    out = stop_and_restart_prefix = os.path.join(base, "run")
    run(choc(a, out), env={"CHOC_TEST_SIGNAL_AT_STEP": "%s:%d" % (a.analysis, n)}, expect=143)
    ck = checkpoint_of(out, a.analysis)
    before = sorted(os.listdir(out))

    def refused(label, inp, checkpoint, pattern, outdir=out):
        cmd = [a.choc, "run", inp, "-o", outdir, "--restart", checkpoint]
        p = run(cmd, expect=1)
        print(label + ":")
        one_line(p, pattern)
        if outdir == out and sorted(os.listdir(out)) != before:
            fail(label + ": the refused restart changed the results directory: %s" % sorted(os.listdir(out)))

    indir = os.path.dirname(os.path.abspath(a.input))
    other = os.path.join(indir, ".restart_test_other_%d.xml" % os.getpid())
    try:
        m = re.search(r'name="Time Step" type="double" value="([^"]+)"', open(a.input).read())
        edited_input(a, other, m.group(0), m.group(0).replace(m.group(1), repr(float(m.group(1)) * 0.5)))
        refused("another input", other, ck,
                r"^choc: input error: .*\.checkpoint: option '--restart': written by another input or mesh: "
                r"parameter 'Analyses/[^']+/Time Step' is '[^']+' in the input, '[^']+' in the checkpoint$")
        dt = float(m.group(1))
        m = re.search(r'name="End Time" type="double" value="([^"]+)"', open(a.input).read())
        end = "%.6e" % (dt * (n // 2))
        edited_input(a, other, m.group(0), m.group(0).replace(m.group(1), end))
        refused("end time before the checkpoint", other, ck,
                r"^choc: input error: .*option '--restart': the checkpoint is at t = \S+ s, not before "
                r"'Analyses/%s/End Time' = %s s\x3b raise End Time to continue the run$" % (re.escape(a.analysis), re.escape(end)))
    finally:
        if os.path.exists(other):
            os.remove(other)
    data = open(ck, "rb").read()
    trunc = os.path.join(base, "truncated.checkpoint")
    open(trunc, "wb").write(data[: len(data) // 2])
    refused("truncated", a.input, trunc, r"^choc: input error: .*truncated\.checkpoint: option '--restart': truncated or corrupt checkpoint")
    bad = os.path.join(base, "corrupt.checkpoint")
    flipped = bytearray(data)
    flipped[len(flipped) // 2] ^= 0x40
    open(bad, "wb").write(bytes(flipped))
    refused("corrupt", a.input, bad, r"^choc: input error: .*corrupt\.checkpoint: option '--restart': corrupt checkpoint \(checksum mismatch\)")
    refused("not a checkpoint", a.input, a.input, r"^choc: input error: .*option '--restart': not a choc checkpoint")
    # The results the checkpoint continues are gone: refused before anything is written.
    empty = os.path.join(base, "empty")
    os.makedirs(empty)
    p = run([a.choc, "run", a.input, "-o", empty, "--restart", ck], expect=1)
    print("results gone:")
    one_line(p, r"^choc: input error: .*cannot continue the (history|results) of the checkpointed run: no such file")
    # Another mesh under the same file name: the mesh hash differs.
    mesh_re = re.search(r'<ParameterList name="Mesh">\s*<Parameter name="File" type="string" value="([^"]+)"/>', open(a.input).read())
    if mesh_re and mesh_re.group(1).endswith(".exo"):
        mesh = os.path.normpath(os.path.join(indir, mesh_re.group(1)))
        copy_dir = os.path.join(base, "mesh")
        os.makedirs(copy_dir)
        moved = os.path.join(copy_dir, os.path.basename(mesh))
        shutil.copy(mesh, moved)
        inp2 = edited_input(a, os.path.join(indir, ".restart_test_mesh_%d.xml" % os.getpid()),
                            mesh_re.group(1), os.path.abspath(moved))
        try:
            out2 = os.path.join(base, "mesh_run")
            run([a.choc, "run", inp2, "-o", out2], env={"CHOC_TEST_SIGNAL_AT_STEP": "%s:%d" % (a.analysis, n)}, expect=143)
            with netCDF4.Dataset(moved, "a") as d:
                d.variables["coordx"][0] += 1e-9
            p = run([a.choc, "run", inp2, "-o", out2, "--restart", checkpoint_of(out2, a.analysis)], expect=1)
            print("another mesh:")
            one_line(p, r"^choc: input error: .*option '--restart': written by another input or mesh: the mesh differs from the checkpoint's")
        finally:
            os.remove(inp2)
    print("OK")


def with_checkpoints(a):
    """A copy of the input in OUT with 'Checkpoint/Interval Steps' in every transient (settings a
    restart may change) and the mesh path made absolute."""
    text = open(a.input).read()
    indir = os.path.dirname(os.path.abspath(a.input))
    text = re.sub(r'(<Parameter name="File" type="string"\s+value=")([^"/][^"]*)"',
                  lambda m: m.group(1) + os.path.normpath(os.path.join(indir, m.group(2))) + '"', text)
    if a.no_exodus:  # only the history grows: its write is the one that fails
        text = re.sub(r'<Parameter name="Exodus Interval" type="int" value="[0-9]+"/>',
                      '<Parameter name="Exodus Interval" type="int" value="0"/>', text)
    block = ('<ParameterList name="Checkpoint"><Parameter name="Interval Steps" type="int" value="%d"/>'
             '<Parameter name="Interval Seconds" type="double" value="%r"/></ParameterList>'
             % (a.checkpoint_steps, a.checkpoint_seconds))
    text, n = re.subn(r'(<Parameter name="Type" type="string" value="(Transient|Modal Transient)"/>)',
                      lambda m: m.group(1) + block, text)
    if n == 0:
        fail("no transient in " + a.input)
    path = os.path.join(a.out, os.path.basename(a.input))
    with open(path, "w") as f:
        f.write(text)
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mode", choices=["stops", "ranks", "kill", "fault", "refuse"])
    ap.add_argument("choc")
    ap.add_argument("input")
    ap.add_argument("out")
    ap.add_argument("--analysis")
    ap.add_argument("--steps", type=int, nargs="*", default=[])
    ap.add_argument("--contact-column")
    ap.add_argument("--log-once", help="stops: a log line's pattern that must be logged exactly once")
    ap.add_argument("--contact-steps", type=int, nargs="*", default=[])
    ap.add_argument("--np-first", type=int, default=1)
    ap.add_argument("--np-restart", type=int, default=1)
    ap.add_argument("--tolerance", type=float)
    ap.add_argument("--ignore", nargs="*", default=[],
                    help="columns and variables left out of a --tolerance comparison")
    ap.add_argument("--vector-peaks", action="store_true",
                    help="compare a vector field's components to the peak of all three")
    ap.add_argument("--seeds", type=int, nargs="*", default=[1])
    ap.add_argument("--kills", type=int, default=3)
    ap.add_argument("--file-size", type=int)
    ap.add_argument("--checkpoint-steps", type=int, default=0,
                    help="run a copy of the input with checkpoints every N steps")
    ap.add_argument("--no-exodus", action="store_true", help="with checkpoints: no Exodus output")
    ap.add_argument("--checkpoint-seconds", type=float, default=0.0,
                    help="run a copy of the input with checkpoints every T seconds of wall time")
    a = ap.parse_args()
    IGNORE.extend(a.ignore)
    VECTOR_PEAKS.extend(["--vector-peaks"] if a.vector_peaks else [])
    a.out = os.path.abspath(a.out)
    os.makedirs(a.out, exist_ok=True)
    if a.checkpoint_steps or a.checkpoint_seconds:
        a.input = with_checkpoints(a)
    {"stops": cmd_stops, "ranks": cmd_ranks, "kill": cmd_kill, "fault": cmd_fault, "refuse": cmd_refuse}[a.mode](a)


if __name__ == "__main__":
    main()
