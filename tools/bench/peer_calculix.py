#!/usr/bin/env python3
"""choc against CalculiX on the same deck (`make bench-peer`).

usage: tools/bench/peer_calculix.py [--build DIR] [--sizes 3x100,5x200,9x500] [--end-time T]
                                    [--repeat N] [--time-limit S] [--keep DIR] [--json PATH]

The scene is SDNL111's two-bar impact in 3D with lateral motion blocked (so that d'Alembert's
solution with the oedometric wave speed is exact): two steel bars of 1 m and section
0.02 x 0.02 m, ACROSS x ACROSS x ALONG HEX8 each (`choc mesh --dim 3`), bar 1 at -1 m/s
towards bar 2 (gap 1e-5 m), bar 2 clamped at its far end. For each size the same mesh is
run by
  - choc: input written here, HHT alpha = -0.1, dt = 1e-6 s, the default (direct) linear
    solver, one rank, twice: with the deck's penalty contact (1e10 N/m per slave node, the
    standard mass) and with choc's exact contact (Lagrange, the default contact mass);
  - CalculiX (ccx, Debian's calculix-ccx, installed by `make bench-peer`): the deck written
    here from the same Exodus mesh (C3D8, the same nodes and elements), *DYNAMIC, DIRECT (the
    same fixed increments), ALPHA = -0.1 (HHT), node-to-face penalty contact with a linear
    pressure-overclosure law whose slope is the same spring per slave node (1e10 N/m over
    an interior slave node's area), one thread.
Both errors are those of A:DZ (the contact end of bar 1) against d'Alembert's solution over
the whole history, relative to its peak (tools/oracles/bar_exact.py). Reported per size: unknowns,
wall times (median of --repeat runs, start-up included), their ratio and both errors, and for
choc (from its wave.summary.json) the Newton iterations per step and the impacts; CalculiX's
figures come from its own .dat and .sta files. Writes results/bench/peer_calculix.json. A
CalculiX run that exceeds --time-limit (default 600 s) is stopped, reported as such, and the
larger sizes are skipped.
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

chocrun.add_tool_path("study", "oracles")
from bar_convergence import E, NU, RHO, LENGTH, GAP, V0, deck as bar_deck  # noqa: E402  the same scene
from bar_exact import BarImpactExact, history_error  # noqa: E402

TOP = chocrun.TOP
SIDE = 0.02
DT, ALPHA, PENALTY = 1e-6, -0.1, 1e10
# Exodus HEX8 side -> CalculiX C3D8 face (both number the nodes alike).
EXO_TO_CCX_FACE = {1: "S3", 2: "S4", 3: "S5", 4: "S6", 5: "S1", 6: "S2"}

# choc's two settings: the deck's penalty (the reference decks' standard mass, as CalculiX)
# and exact contact with choc's defaults.
CHOC_CONTACT = {
    "penalty": (f'<Parameter name="Method" type="string" value="Penalty"/>'
                f'<Parameter name="Penalty Stiffness" type="double" value="{PENALTY:g}"/>'),
    "lagrange": '<Parameter name="Method" type="string" value="Lagrange"/>',
}


def read_exodus(path):
    import netCDF4
    d = netCDF4.Dataset(path)

    def names(var):
        return [b"".join(x).decode().strip("\x00") for x in d.variables[var][:].data]

    m = {"xyz": np.stack([d.variables[c][:].data for c in ("coordx", "coordy", "coordz")], axis=1)}
    m["blocks"] = {n: d.variables[f"connect{i + 1}"][:].data for i, n in enumerate(names("eb_names"))}
    m["nsets"] = {n: d.variables[f"node_ns{i + 1}"][:].data for i, n in enumerate(names("ns_names"))}
    m["ssets"] = {n: (d.variables[f"elem_ss{i + 1}"][:].data, d.variables[f"side_ss{i + 1}"][:].data)
                  for i, n in enumerate(names("ss_names"))}
    d.close()
    return m


def lines_of(ids, per_line=8):
    ids = [str(int(i)) for i in ids]
    return "\n".join(", ".join(ids[i:i + per_line]) for i in range(0, len(ids), per_line))


def write_ccx_deck(mesh, across, end, path):
    """The CalculiX deck of the scene on the mesh read by read_exodus."""
    out = ["*HEADING", "choc peer benchmark: SDNL111 in 3D, lateral motion blocked", "*NODE, NSET=NALL"]
    out += [f"{i + 1}, {x:.13g}, {y:.13g}, {z:.13g}" for i, (x, y, z) in enumerate(mesh["xyz"])]
    first = 1
    for name, conn in mesh["blocks"].items():
        out.append(f"*ELEMENT, TYPE=C3D8, ELSET={name}")
        out += [f"{first + k}, " + ", ".join(str(int(n)) for n in row) for k, row in enumerate(conn)]
        first += len(conn)
    for name in ("POU1", "A", "CL_POU2"):
        out += [f"*NSET, NSET={name}", lines_of(mesh["nsets"][name])]
    for name, surf in (("CNT_POU1", "MASTER"), ("CNT_POU2", "SLAVE")):
        elems, sides = mesh["ssets"][name]
        out.append(f"*SURFACE, NAME={surf}")
        out += [f"{int(e)}, {EXO_TO_CCX_FACE[int(s)]}" for e, s in zip(elems, sides)]
    slope = PENALTY / (SIDE / across) ** 2  # the spring per interior slave node, per its area
    out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}", "*DENSITY", f"{RHO:g}"]
    out += [f"*SOLID SECTION, ELSET={b}, MATERIAL=STEEL" for b in mesh["blocks"]]
    out += ["*CONTACT PAIR, INTERACTION=PEN, TYPE=NODE TO SURFACE, SMALL SLIDING", "SLAVE, MASTER",
            "*SURFACE INTERACTION, NAME=PEN", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
            f"{slope:.6e}, 1e-3"]
    out += ["*BOUNDARY", "NALL, 1, 2", "CL_POU2, 3, 3"]
    out += ["*INITIAL CONDITIONS, TYPE=VELOCITY", f"POU1, 3, {V0:g}"]
    steps = int(round(end / DT))
    out += [f"*STEP, INC={steps + 10}", f"*DYNAMIC, DIRECT, ALPHA={ALPHA:g}", f"{DT:g}, {end:g}",
            "*NODE PRINT, NSET=A, FREQUENCY=1", "U", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def read_ccx_history(dat):
    """Times and DZ of the node of set A from CalculiX's .dat file (rows of *NODE PRINT; the
    regular expression reads CalculiX's output, not choc's)."""
    times, dz = [0.0], [0.0]
    block = re.compile(r"displacements \(vx,vy,vz\) for set A and time\s+(\S+)\s*\n\s*\n\s*\d+\s+\S+\s+\S+\s+(\S+)")
    for m in block.finditer(open(dat).read()):
        times.append(float(m.group(1)))
        dz.append(float(m.group(2)))
    return np.array(times), np.array(dz)


def ccx_iterations_per_step(sta):
    """Mean Newton iterations per increment from CalculiX's .sta file (STEP INC ATT ITRS ...)."""
    its = [int(f[3]) for f in (line.split() for line in open(sta)) if len(f) == 7 and f[0].isdigit()]
    return f"{sum(its) / len(its):.2f}" if its else "?"


def read_choc_history(run_dir):
    h = chocrun.read_history(run_dir, "wave")
    return h["time"], h["N1:DZ"]  # N1: the node of set A


def exact():
    c = BarImpactExact.oedometric_wave_speed(E, NU, RHO)
    return BarImpactExact(LENGTH, c, RHO * c * SIDE * SIDE, V0, GAP / abs(V0))


def timed(cmd, cwd, env=None, limit=None):
    """(wall time, stdout) of a run that must succeed; (None, "") when it exceeds limit [s]."""
    t0 = time.monotonic()
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, env=env, timeout=limit)
    except subprocess.TimeoutExpired:
        return None, ""
    wall = time.monotonic() - t0
    if p.returncode != 0:
        sys.exit(f"peer_calculix: {' '.join(cmd)} failed ({p.returncode}) in {cwd}:\n"
                 f"{p.stdout[-3000:]}{p.stderr[-2000:]}")
    return wall, p.stdout


def one_size(choc, work, across, along, end, repeat, limit):
    d = os.path.join(work, f"{across}x{along}")
    os.makedirs(d, exist_ok=True)
    exo = os.path.join(d, "bars.exo")
    subprocess.run([choc, "mesh", "--dim", "3", "--axis", "z", "--along1", str(along), "--along2", str(along),
                    "--across1", str(across), "--across2", str(across), "--width", str(SIDE),
                    "--height", str(SIDE), "--gap", str(GAP), "-o", exo], check=True, stdout=subprocess.DEVNULL)
    for name, contact in CHOC_CONTACT.items():
        with open(os.path.join(d, f"{name}.xml"), "w") as f:
            f.write(bar_deck(f"choc against CalculiX, {name}", "bars.exo", "3D", DT, None, "HHT", ALPHA,
                             end_time=end, contact=contact))
    write_ccx_deck(read_exodus(exo), across, end, os.path.join(d, "peer.inp"))
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1", CCX_NPROC_STIFFNESS="1")
    res = {"across": across, "along": along}
    walls = {name: [] for name in list(CHOC_CONTACT) + ["ccx"]}
    for _ in range(repeat):
        for name in CHOC_CONTACT:
            walls[name].append(chocrun.run(choc, f"{name}.xml", name, cwd=d).wall)
            s = chocrun.require_completed(chocrun.read_summary(os.path.join(d, name), "wave"))
            res["unknowns"] = chocrun.summary_value(s, "unknowns")
            res[name + "_newton"] = "%.2f" % (chocrun.summary_value(s, "newton/iterations") /
                                              chocrun.summary_value(s, "steps"))
            res[name + "_impacts"] = chocrun.summary_value(s, "impacts/interface/number_of_impacts")
            res["choc_commit"] = chocrun.summary_value(s, "choc/commit")
        w, _ = timed(["ccx", "-i", "peer"], d, env, limit)
        if w is None:  # CalculiX did not finish: choc's figures only
            del walls["ccx"]
            res["ccx"] = None
            break
        walls["ccx"].append(w)
        res["ccx_newton"] = ccx_iterations_per_step(os.path.join(d, "peer.sta"))
    ref = exact()
    for name in walls:
        res[name] = statistics.median(walls[name])
        t, u = (read_ccx_history(os.path.join(d, "peer.dat")) if name == "ccx" else
                read_choc_history(os.path.join(d, name)))
        if len(t) < int(round(end / DT)):
            sys.exit(f"peer_calculix: {name} wrote {len(t)} rows for {int(round(end / DT))} steps ({d})")
        res[name + "_err"] = history_error(t, u, ref.displacement(t))
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(TOP, "build"))
    ap.add_argument("--sizes", default="3x100,5x200,9x500", help="ACROSSxALONG,... (elements per bar)")
    ap.add_argument("--end-time", type=float, default=4e-4)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--time-limit", type=float, default=600.0)
    ap.add_argument("--keep", default=None, help="work directory to keep (default: a temporary one)")
    ap.add_argument("--json", default=None, help="the figures' file (default results/bench/<bench>.json)")
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    if not shutil.which("ccx"):
        sys.exit("peer_calculix: ccx not found (apt-get install calculix-ccx; `make bench-peer` does it)")
    work = a.keep or tempfile.mkdtemp(prefix="choc-peer-")
    print(f"scene: SDNL111 bars in 3D, lateral motion blocked, HHT alpha {ALPHA}, dt {DT:g} s to "
          f"{a.end_time:g} s, penalty {PENALTY:g} N/m per slave node; error of A:DZ against "
          f"d'Alembert (oedometric) over the whole history, of its peak; wall times: median of "
          f"{a.repeat}, one core each (load {chocrun.load_average()})", flush=True)
    rows, commit = [], None
    for size in a.sizes.split(","):
        across, along = map(int, size.lower().split("x"))
        r = one_size(choc, work, across, along, a.end_time, a.repeat, a.time_limit)
        commit = r.get("choc_commit", commit)
        mesh = f"{across} x {across} x {along} HEX8"
        for name, label in (("penalty", "choc, penalty 1e10 N/m, standard mass"),
                            ("lagrange", "choc, Lagrange, default mass"), ("ccx", "CalculiX 2.20, penalty")):
            row = {"mesh": mesh, "unknowns": r["unknowns"], "run": label, "repeat": a.repeat}
            if r["ccx"] is None and name == "ccx":
                row["wall"] = f"> {a.time_limit:g} (stopped)"
                rows.append(row)
                continue
            e = r[name + "_err"]
            row.update({"wall_s": r[name], "wall": f"{r[name]:.2f}",
                        "ccx_ratio": (f"> {a.time_limit / r[name]:.1f}" if r["ccx"] is None else
                                      f"{r['ccx'] / r[name]:.1f}"),
                        "max_error_pct": 100 * e["max_rel"], "rms_error_pct": 100 * e["rms_rel"],
                        "errors": f"{100 * e['max_rel']:.2f} % / {100 * e['rms_rel']:.2f} %",
                        "newton_per_step": r[name + "_newton"], "impacts": r.get(name + "_impacts")})
            rows.append(row)
        print(f"{mesh}: " + "; ".join(f"{x['run']} {x['wall']} s" for x in rows[-3:]), flush=True)
        if r["ccx"] is None:
            print(f"(CalculiX did not finish in {a.time_limit:g} s at this size: larger sizes skipped)")
            break
    tables = [{"title": f"choc against CalculiX, SDNL111's bars in 3D to {a.end_time:g} s (medians of {a.repeat} runs, "
                        "one core each)",
               "columns": [["mesh", "mesh per bar", ""], ["unknowns", "unknowns", ",d"], ["run", "run", ""],
                           ["wall", "wall [s]", ""], ["ccx_ratio", "CalculiX / this", ""],
                           ["errors", "A:DZ max / RMS error", ""], ["newton_per_step", "Newton per step", ""],
                           ["impacts", "impacts", ""]],
               "note": "errors of A:DZ against d'Alembert (oedometric) over the whole history, of its peak; "
                       "wall times start-up included"}]
    chocrun.print_tables(rows, tables)
    chocrun.write_bench_json("peer_calculix", "choc against CalculiX on the same deck", rows, tables, vars(a),
                             a.json, choc_commit=commit)
    if not a.keep:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
