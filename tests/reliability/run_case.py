#!/usr/bin/env python3
"""Runs choc on a reliability input and checks how the run ends.

  run_case.py CHOC INPUT OUTDIR --rc N --stderr REGEX [--signal TERM|INT --after-file F
              --delay S --within S] [--present F ...] [--absent F ...]
              [--incomplete-exo F ...] [--incomplete-history F ...] [--log REGEX ...]

Asserts: the exit code; stderr is exactly one line matching REGEX (its named group 't', when
present, is the time of the failure); each --present file exists; no --absent file and no
'*.part' file exists; each --incomplete-exo file is readable with netCDF4, has at least one
step, and its time_whole is finite, strictly increasing and not past the failure time; each
--incomplete-history file parses, has finite values and increasing times not past the
failure time; each --log regex matches stdout. With --signal: the signal is sent --delay
seconds after the output file --after-file appears (stdout is buffered: no log line is
reliable), and the process must end within --within s.
"""
import argparse
import glob
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time

failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("choc")
    ap.add_argument("input")
    ap.add_argument("outdir")
    ap.add_argument("--rc", type=int, required=True)
    ap.add_argument("--stderr", required=True)
    ap.add_argument("--signal", choices=["TERM", "INT"])
    ap.add_argument("--after-file", default="", help="signal DELAY s after this output file appears")
    ap.add_argument("--delay", type=float, default=1.0)
    ap.add_argument("--within", type=float, default=5.0)
    ap.add_argument("--present", nargs="*", default=[])
    ap.add_argument("--absent", nargs="*", default=[])
    ap.add_argument("--incomplete-exo", nargs="*", default=[])
    ap.add_argument("--incomplete-history", nargs="*", default=[])
    ap.add_argument("--log", nargs="*", default=[])
    a = ap.parse_args()

    shutil.rmtree(a.outdir, ignore_errors=True)
    os.makedirs(a.outdir)
    # A complete-looking result of an earlier run must not survive a failed one.
    for f in a.absent:
        open(os.path.join(a.outdir, f), "w").write("stale result of an earlier run\n")
    out_path = os.path.join(a.outdir, "stdout.log")
    cmd = [a.choc, "run", a.input, "-o", a.outdir]
    print("running: " + " ".join(cmd))
    with open(out_path, "w") as out:
        p = subprocess.Popen(cmd, stdout=out, stderr=subprocess.PIPE, text=True)
        if a.signal:
            start = time.time()
            while p.poll() is None and time.time() - start < 120:
                if os.path.exists(os.path.join(a.outdir, a.after_file)):
                    break
                time.sleep(0.05)
            if p.poll() is not None:
                fail("the run ended before it could be interrupted (rc %s)" % p.returncode)
            time.sleep(a.delay)
            if p.poll() is not None:
                fail("the run ended before the signal (rc %s): make the input longer" % p.returncode)
            sent = time.time()
            p.send_signal(getattr(signal, "SIG" + a.signal))
            try:
                err = p.communicate(timeout=a.within + 30)[1]
            except subprocess.TimeoutExpired:
                p.kill()
                err = p.communicate()[1]
                fail("the run did not end within %g s of SIG%s" % (a.within + 30, a.signal))
            took = time.time() - sent
            print("ended %.2f s after SIG%s" % (took, a.signal))
            if took > a.within:
                fail("the run took %.2f s to end after SIG%s (limit %g s)" % (took, a.signal, a.within))
        else:
            err = p.communicate(timeout=600)[1]
    log = open(out_path).read()
    print("exit code %d; stderr:\n%s" % (p.returncode, err))
    if p.returncode != a.rc:
        fail("exit code %d, expected %d" % (p.returncode, a.rc))
    lines = err.splitlines()
    t_fail = math.inf
    if len(lines) != 1:
        fail("stderr has %d lines, expected exactly one" % len(lines))
    else:
        m = re.search(a.stderr, lines[0])
        if not m:
            fail("stderr does not match /%s/" % a.stderr)
        elif "t" in m.groupdict() and m.group("t"):
            t_fail = float(m.group("t"))
            # The message prints the time with %.6e (7 significant digits): a stored time may
            # exceed the printed one by up to half a unit of the 7th digit, no more.
            t_fail += 0.5e-6 * abs(t_fail)
    for f in a.present:
        if not os.path.isfile(os.path.join(a.outdir, f)):
            fail("missing file " + f)
    for f in a.absent:
        if os.path.exists(os.path.join(a.outdir, f)):
            fail("file with the name of a complete result left behind: " + f)
    for f in glob.glob(os.path.join(a.outdir, "*.part")):
        fail("partial file left as .part: " + os.path.basename(f))
    for rx in a.log:
        if not re.search(rx, log):
            fail("the log does not match /%s/" % rx)

    for f in a.incomplete_exo:
        path = os.path.join(a.outdir, f)
        if not os.path.isfile(path):
            continue  # reported above if listed in --present
        try:
            import netCDF4
            with netCDF4.Dataset(path) as ds:
                t = [float(x) for x in ds.variables["time_whole"][:]]
                nodes = ds.dimensions["num_nodes"].size
                disp = ds.variables["vals_nod_var1"][:] if "vals_nod_var1" in ds.variables else None
        except Exception as e:  # noqa: BLE001 - any failure to read is the finding
            fail("%s is not readable: %s" % (f, e))
            continue
        print("%s: %d steps, time %s .. %s, %d nodes" % (f, len(t), t[0] if t else "-", t[-1] if t else "-", nodes))
        if not t:
            fail(f + " has no time step")
        if not all(math.isfinite(x) for x in t):
            fail(f + ": time_whole is not finite")
        if any(b <= a_ for a_, b in zip(t, t[1:])):
            fail(f + ": time_whole is not strictly increasing")
        if t and t[-1] > t_fail:
            fail("%s: last step at t = %g is past the failure at %g" % (f, t[-1], t_fail))
        if disp is not None and not all(math.isfinite(float(x)) for x in disp.flatten()):
            fail(f + ": non-finite nodal values")

    for f in a.incomplete_history:
        path = os.path.join(a.outdir, f)
        if not os.path.isfile(path):
            continue
        rows = [l.split(",") for l in open(path).read().splitlines()]
        if not rows or rows[0][0] != "time":
            fail(f + ": no 'time' header")
            continue
        vals = []
        for i, r in enumerate(rows[1:]):
            try:
                vals.append([float(x) for x in r])
            except ValueError:
                fail("%s: row %d is not numeric (torn line?): %r" % (f, i + 2, r))
        times = [v[0] for v in vals]
        print("%s: %d rows, last time %s" % (f, len(vals), times[-1] if times else "-"))
        if len(vals) < 2:
            fail(f + ": fewer than 2 rows")
        if not all(math.isfinite(x) for v in vals for x in v):
            fail(f + ": non-finite values")
        if any(b <= a_ for a_, b in zip(times, times[1:])):
            fail(f + ": time is not increasing")
        if times and times[-1] > t_fail:
            fail("%s: last row at t = %g is past the failure at %g" % (f, times[-1], t_fail))

    if failures:
        print("\n--- stdout (last 30 lines) ---\n" + "\n".join(log.splitlines()[-30:]))
        return 1
    print("OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
