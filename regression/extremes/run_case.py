#!/usr/bin/env python3
"""Runs one 'extremes' case (regression/extremes/CMakeLists.txt) and asserts its outcome.

usage: run_case.py CHOC INPUT OUT [options]
  --mesh FILE=ARGS     generate FILE in OUT with 'choc mesh ARGS' (repeatable); the input names
                       the mesh by its bare file name and is run from a copy in OUT
  --expect ok|numerical|input|energy
      ok:        exit 0; every history and Exodus file finite; energy bounded (below)
      numerical: exit 2 with one line on stderr matching --stderr; no file with a complete
                 result's name beside a *.incomplete.* one, and every incomplete history finite
      input:     exit 1 with one line on stderr matching --stderr
      energy:    exit 3 with the energy-balance check NOOK in checks.csv (the run created
                 energy and says so), every history and Exodus file finite
  --energy-tol X       max over the history of energy:total <= E0 (1 + X)
  --leapfrog           add the leapfrog energy bound r^2 / (1 - r^2), r = h / dt_crit, with h the
                       (sub-)step and dt_crit the critical step printed in the log (explicit modal)
  --stderr REGEX       (numerical, input) the message
  --log REGEX          a line of the run log that must be present (repeatable)
  --max-seconds S      wall-time limit of the run
Stdlib only, except the Exodus check, which uses netCDF4 when it is importable.
"""
import argparse, csv, glob, math, os, re, shutil, subprocess, sys, time


def fail(msg):
    print("extremes: FAIL: " + msg)
    sys.exit(1)


def read_history(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names = rows[0]
    data = []
    for i, r in enumerate(rows[1:], start=2):
        vals = []
        for j, x in enumerate(r):
            v = float(x)  # 'nan', 'inf' parse too: checked below
            if not math.isfinite(v):
                fail(f"{path}: line {i}, column {names[j]}: {x} (not finite)")
            vals.append(v)
        data.append(vals)
    return names, data


def check_exodus(path):
    try:
        import netCDF4, numpy  # noqa: E401
    except ImportError:
        print(f"  {os.path.basename(path)}: netCDF4 not available, finiteness not checked")
        return
    with netCDF4.Dataset(path) as d:
        for name, var in d.variables.items():
            if var.dtype.kind != "f" or var.size == 0:
                continue
            a = numpy.asarray(var[:])
            if not numpy.all(numpy.isfinite(a)):
                fail(f"{path}: variable {name} holds NaN or inf")
    print(f"  {os.path.basename(path)}: every floating-point variable finite")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("choc"), ap.add_argument("input"), ap.add_argument("out")
    ap.add_argument("--mesh", action="append", default=[])
    ap.add_argument("--expect", choices=["ok", "numerical", "input", "energy"], default="ok")
    ap.add_argument("--energy-tol", type=float, default=None)
    ap.add_argument("--leapfrog", action="store_true")
    ap.add_argument("--stderr", default=None)
    ap.add_argument("--log", action="append", default=[])
    ap.add_argument("--max-seconds", type=float, default=60.0)
    a = ap.parse_args()

    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    for m in a.mesh:
        name, args = m.split("=", 1)
        subprocess.run([a.choc, "mesh"] + args.split() + ["-o", os.path.join(a.out, name)],
                       check=True, stdout=subprocess.DEVNULL)
    inp = os.path.join(a.out, os.path.basename(a.input))
    shutil.copy(a.input, inp)
    res = os.path.join(a.out, "results")
    t0 = time.monotonic()
    p = subprocess.run([a.choc, "run", inp, "-o", res], capture_output=True, text=True)
    wall = time.monotonic() - t0
    log = p.stdout
    with open(os.path.join(a.out, "run.log"), "w") as f:
        f.write(log + "\n--- stderr ---\n" + p.stderr)
    print("\n".join(log.splitlines()[-25:]))
    print(f"--- stderr ---\n{p.stderr}--- exit {p.returncode}, {wall:.2f} s")
    if wall > a.max_seconds:
        fail(f"the run took {wall:.1f} s (limit {a.max_seconds} s)")
    for rx in a.log:
        if not re.search(rx, log, re.M):
            fail(f"no log line matches '{rx}'")
    errlines = [l for l in p.stderr.splitlines() if l.strip()]

    if a.expect in ("numerical", "input"):
        code = 2 if a.expect == "numerical" else 1
        if p.returncode != code:
            fail(f"exit {p.returncode}, {code} expected")
        if len(errlines) != 1:
            fail(f"{len(errlines)} lines on stderr, one expected")
        if a.stderr and not re.search(a.stderr, errlines[0]):
            fail(f"stderr does not match '{a.stderr}'")
        for inc in glob.glob(os.path.join(res, "*.incomplete.*")):
            stem, ext = re.match(r"(.*)\.incomplete\.(\w+)$", inc).groups()
            if os.path.exists(f"{stem}.{ext}"):
                fail(f"{stem}.{ext} exists beside {inc}")
            if ext == "csv" and stem.endswith(".impacts"):  # rows of text and numbers
                print(f"  {os.path.basename(inc)}: {len(open(inc).read().splitlines()) - 1} impacts")
            elif ext == "csv":
                names, data = read_history(inc)
                print(f"  {os.path.basename(inc)}: {len(data)} finite rows")
            elif ext == "exo":
                check_exodus(inc)
        print("extremes: OK")
        return

    if a.expect == "energy":
        # The run completes and says it created energy: exit 3, the energy check NOOK in
        # checks.csv, finite results.
        if p.returncode != 3:
            fail(f"exit {p.returncode}, 3 expected (energy created: a failed energy check)")
        rows = open(os.path.join(res, "checks.csv")).read().splitlines()
        if not any("energy:balance / reference energy, largest" in r and ",NOOK," in r for r in rows):
            fail("checks.csv has no failed energy-balance row")
        for exo in sorted(glob.glob(os.path.join(res, "*.exo"))):
            check_exodus(exo)
        for h in sorted(glob.glob(os.path.join(res, "*.history.csv"))):
            read_history(h)
        print("extremes: OK")
        return
    if p.returncode != 0:
        fail(f"exit {p.returncode}, 0 expected")
    hist = sorted(glob.glob(os.path.join(res, "*.history.csv")))
    if not hist:
        fail("no history written")
    for exo in sorted(glob.glob(os.path.join(res, "*.exo"))):
        check_exodus(exo)
    for h in hist:
        names, data = read_history(h)
        tot = [r[names.index("energy:total")] for r in data]
        e0, emax = tot[0], max(tot)
        imax = tot.index(emax)
        tol = a.energy_tol or 0.0
        parts = [f"{tol:g} (stated)"]
        if a.leapfrog:
            m = re.search(r"critical step (\S+) s .*dt = (\S+) s", log)
            if not m:
                fail("no critical step in the log")
            crit, dt = float(m.group(1)), float(m.group(2))
            s = re.search(r": (\d+) sub-steps per step", log)
            hstep = dt / (int(s.group(1)) if s else 1)
            r = hstep / crit
            if r >= 1:
                fail(f"step {hstep:g} s above the critical step {crit:g} s")
            tol += r * r / (1 - r * r)
            parts.append(f"{r*r/(1-r*r):.3e} (leapfrog, h/dt_crit = {r:.3f})")
        bal = [r[names.index("energy:balance")] for r in data] if "energy:balance" in names else [0.0]
        print(f"  {os.path.basename(h)}: {len(data)} rows, E0 = {e0:.6e} J, max E_total = {emax:.6e} J "
              f"at t = {data[imax][0]:.4e} s: growth {(emax - e0) / e0:+.3e} of E0, tolerance "
              f"{tol:.3e} = {' + '.join(parts)}; energy:balance in [{min(bal):+.3e}, {max(bal):+.3e}] J")
        if a.energy_tol is not None or a.leapfrog:
            if not emax <= e0 * (1 + tol):
                fail(f"{h}: energy:total grows to {emax:.6e} J > E0 (1 + {tol:.3e}) = {e0*(1+tol):.6e} J")
    print("extremes: OK")


if __name__ == "__main__":
    main()
