#!/usr/bin/env python3
"""Large sliding without friction: input/sliding.xml, a block (6 x 3 x 3 HEX8) pressed
by 1e7 Pa on a foundation a thousand times stiffer (40 x 2 x 2 HEX8, non-matching faces) and
pushed at 10 m/s along it for 11 ms: 0.11 m, 22 of the foundation's 5 mm faces.

On the stiff foundation the exact contact pressure is uniform, p = 1e7 Pa (to the foundation's
compliance against the block's, about 1e-3). From 1 ms on (the ringing of the load applied at
once has settled), at every Exodus frame:
  - every slave node is in contact (the contact stays closed);
  - the nodal pressures' mean is p and their spread (max - min) / mean is below 1 %;
  - each slave node's CONTACT_SLIP equals its DISP_X (the foundation hardly moves) within 1 %;
and over the whole run the energy balance never exceeds +1e-3 of the initial energy (HHT
dissipates, a sliding contact without friction does no work) and Newton averages <= 2.5
iterations per step. The same with node to face and with mortar contact (the overlaps
integrated again before each step).

On a foundation of the block's own steel, the search must follow the block: at the end the
foundation's upper face is pressed under the block's final place (x in [0.13, 0.17] m) and has
sprung back where the block started (x in [0.02, 0.06] m): |DZ| there below 1 % of |DZ| under
the block. The same run with 'Search' = reference (paired once) leaves the dent behind, the
opposite, which shows the check tells the two apart.
usage: sliding.py CHOC SOURCE_DIR WORK_DIR"""
import csv
import os
import re
import sys

import netCDF4
import numpy as np

from deck_run import run_deck

choc, src, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
P = 1e7
failures = []


def run(name, edit=lambda s: s):
    return run_deck(choc, src, work, "sliding.xml", name, edit, "sliding")


def fields(out):
    d = netCDF4.Dataset(os.path.join(out, "lagrange.exo"))
    names = ["".join(c.decode() for c in n if c != b"").strip() for n in d["name_nod_var"][:]]
    get = lambda f, k: np.asarray(d[f"vals_nod_var{names.index(f) + 1}"][k])
    xyz = [np.asarray(d[c][:]) for c in ("coordx", "coordy", "coordz")]
    return d, get, xyz


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


# 1. The stiff foundation: uniform pressure, closed contact, slip, energy, Newton; node to face
# and mortar (integrated again before each step on the current faces).
def stiff(name, edit=lambda s: s):
    out, log = run(name, edit)
    d, get, (x, y, z) = fields(out)
    times = np.asarray(d["time_whole"][:])
    slave = None
    for k, t in enumerate(times):
        if t < 1e-3:
            continue
        status, p = get("CONTACT_STATUS", k), get("CONTACT_PRESSURE", k)
        if slave is None:
            slave = p != 0
        active = status[slave] > 0
        pm = p[slave].mean()
        spread = (p[slave].max() - p[slave].min()) / pm
        slip, dx = get("CONTACT_SLIP", k)[slave], get("DISP_X", k)[slave]
        slip_err = np.abs(slip - dx).max() / dx.max()
        check(active.all() and abs(pm / P - 1) <= 0.01 and spread <= 0.01 and slip_err <= 0.01,
              f"{name}, t = {t:.4g} s: {active.sum()}/{slave.sum()} slave nodes in contact, pressure "
              f"mean {pm:.6g} Pa (p = {P:g}), spread {spread:.2e}, slip against DX {slip_err:.1e}")
    check(slave is not None and slave.sum() == 28, f"{name}: 28 slave nodes (the block's lower face)")
    travel = get("DISP_X", len(times) - 1)[slave].mean()
    check(travel >= 20 * 0.005, f"{name}: the block slid {travel:.4f} m, across {travel / 0.005:.1f} faces of 5 mm")
    rows = list(csv.DictReader(open(os.path.join(out, "lagrange.history.csv"))))
    e0 = float(rows[0]["energy:total"])
    worst = max(float(r["energy:balance"]) for r in rows)
    check(worst <= 1e-3 * e0, f"{name}: energy balance at most {worst:.3e} J (E0 = {e0:.4g} J, bound +1e-3 E0)")
    m = re.search(r"\(([0-9.]+) per step", log)
    check(m is not None and float(m.group(1)) <= 2.5, f"{name}: Newton iterations per step: {m.group(1) if m else '?'}")


stiff("stiff")
stiff("stiff_mortar", lambda s: s.replace(
    '<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>',
    '<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>'
    '<Parameter name="Discretization" type="string" value="mortar"/>'))

# 2. The elastic foundation: the dent follows the block only when the search does.
steel = lambda s: s.replace('value="2e14"', 'value="2e11"')
for search in ("current", "reference"):
    edit = steel if search == "current" else lambda s: steel(s).replace(
        '<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>',
        '<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>'
        '<Parameter name="Search" type="string" value="reference"/>')
    out, _ = run("elastic_" + search, edit)
    d, get, (x, y, z) = fields(out)
    on_grid = np.isclose(y, 0) | np.isclose(y, 0.01) | np.isclose(y, 0.02)  # foundation's y
    top = (np.abs(z) < 1e-12) & on_grid
    dz = np.abs(get("DISP_Z", len(d["time_whole"]) - 1))
    start = dz[top & (x > 0.02 - 1e-9) & (x < 0.06 + 1e-9)].max()
    end = dz[top & (x > 0.13 - 1e-9) & (x < 0.17 + 1e-9)].max()
    follows = start <= 0.01 * end
    check(follows == (search == "current"),
          f"search {search}: foundation's |DZ| where the block started {start:.3e} m, under it at "
          f"the end {end:.3e} m: the dent {'follows' if follows else 'stays behind'}")
if failures:
    sys.exit(f"sliding: {len(failures)} check(s) failed")
