#!/usr/bin/env python3
"""Shock links in the direct transient, against independent paths to the same physics:
  1. SDNL32's stop (input/sdnl32_direct.xml, the PLAN_Y link) and the same stop as a penalty
     contact pair of the tip node on a plane: the same spring at t_{n+1}, solved by the links'
     difference tangent on one side and the contact active set on the other. DY, VY of the tip
     and the stop's force agree to 1e-8 of their peaks (Newton's tolerance, 1e-8 of the step's
     forces; measured 1e-11).
  2. SDNL111 A (input/sdnl111a_direct.xml without the dashpot, which the contact lacks) and the
     link as a node-to-node penalty contact: DX, VX of A and the force to 1e-8 of their peaks.
  3. The same with the link as BI_CERCLE in the plane x-z (axis y): with DX the only unknown the
     radius is |x_C - x_A|, the gap of the planes: the histories equal the planes' to 1e-8.
  4. SDNL32's tip in a ring, BI_CERC_INT (fixed obstacle, clearance 2 mm, 1e5 N/m), hitting
     both sides: the direct run (dt = 1e-6 s) against the modal run on all 31 modes (central
     differences, dt = 1e-6 s), two integrators with nothing in common but the law. They agree
     to 4 times the direct run's own error against itself at dt/2 (measured here: 1.3e-5 of
     the peak of DY; the two runs' time errors, first order at the impacts, with a margin of 2;
     measured 2.4e-5). The tip must hit both sides.
  5. SDNL111 A at dt = 2e-6 s, where a step has no solution with the dashpot (its force jumps
     at closure): solved without it for that step, said in the log, the check still passes.
  6. A fixed obstacle's 'Obstacle Origin': SDND100's plane, DIST_1 = 0.5 m above P's
     initial position, written instead as the plane through the origin 0 0 0.5 with DIST_1 = 0:
     the same gap, so every analysis (modal, direct implicit and explicit) gives the same
     history to round-off (1e-12 of each peak; measured: bit for bit).
usage: direct_links.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import subprocess
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
failures = []


def deck(name):
    return open(os.path.join(src, "input", name)).read().replace('value="../meshes/', f'value="{src}/meshes/')


def run(text, name):
    path = os.path.join(work, name + ".xml")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(work, name)
    p = subprocess.run([choc, "run", path, "-o", out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode not in (0, 3):
        sys.exit(f"{name}: choc exited {p.returncode}:\n{p.stdout[-3000:]}")
    return out, p.stdout


def history(out, analysis):
    with open(os.path.join(out, analysis + ".history.csv")) as f:
        cols = f.readline().strip().split(",")
        return cols, np.loadtxt(f, delimiter=",", ndmin=2)


def compare(label, a, b, pairs, tol, analysis_a="direct", analysis_b="direct", interpolate=False):
    ca, da = history(a, analysis_a)
    cb, db = history(b, analysis_b)
    worst = 0.0
    for qa, qb in pairs:
        ya = da[:, ca.index(qa)]
        yb = db[:, cb.index(qb)]
        if interpolate:
            yb = np.interp(da[:, 0], db[:, 0], yb)
        peak = np.max(np.abs(ya))
        err = np.max(np.abs(ya - yb)) / peak
        worst = max(worst, err)
        print(f"{label}: {qa} vs {qb}: {err:.3e} of the peak {peak:.4e}")
    if not worst <= tol:
        failures.append(f"{label}: {worst:.3e} > {tol:g}")
    return worst


def replace_block(text, start_marker, end_marker, new):
    i = text.index(start_marker)
    j = text.index(end_marker, i)
    return text[:i] + new + text[j:]


def penalty_pair(stiffness, name, pair):
    """A 'Contact' list: one penalty pair NAME whose parameters are the XML lines PAIR, with the
    standard mass (the link's node keeps its mass; the default 'auto' would make it massless)."""
    return f'''      <Parameter name="Contact Mass" type="string" value="standard"/>
      <ParameterList name="Contact">
        <Parameter name="Method" type="string" value="Penalty"/>
        <Parameter name="Penalty Stiffness" type="double" value="{stiffness}"/>
        <ParameterList name="Pairs">
          <ParameterList name="{name}">{pair}
          </ParameterList>
        </ParameterList>
      </ParameterList>
'''


LINKS_START = '      <ParameterList name="Shock Links">'
IC_START = '      <ParameterList name="Initial Conditions">'

# 1. SDNL32: link and contact pair.
s32 = deck("sdnl32_direct.xml")
pair32 = replace_block(s32, LINKS_START, IC_START, penalty_pair("18000", "stop", '''
            <Parameter name="Slave Node Set" type="string" value="N11"/>
            <ParameterList name="Obstacle">
              <Parameter name="Shape" type="string" value="plane"/>
              <Parameter name="Point" type="string" value="0.783 0 0"/>
              <Parameter name="Normal" type="string" value="0 1 0"/>
            </ParameterList>'''))
a, _ = run(s32, "sdnl32_link")
b, _ = run(pair32, "sdnl32_pair")
compare("SDNL32 link vs contact pair", a, b, [("N11:DY", "N11:DY"), ("N11:VY", "N11:VY"),
                                              ("stop:force", "stop:force")], 1e-8)

# 2. SDNL111 A: link (no dashpot) and node-to-node contact pair.
s111 = deck("sdnl111a_direct.xml").replace('<Parameter name="Normal Damping" type="double" value="2e4"/>', "")
pair111 = replace_block(s111, LINKS_START, IC_START, penalty_pair("5e9", "shock", '''
            <Parameter name="Slave Node Set" type="string" value="A"/>
            <Parameter name="Master Node Set" type="string" value="C"/>
            <Parameter name="Node Normal" type="string" value="1 0 0"/>
            <Parameter name="Node Offset" type="double" value="1e-5"/>'''))
a, _ = run(s111, "sdnl111a_link")
b, _ = run(pair111, "sdnl111a_pair")
compare("SDNL111 A link vs node-to-node pair", a, b, [("A:DX", "A:DX"), ("A:VX", "A:VX"),
                                                      ("shock:force", "shock:force")], 1e-8)

# 3. The circle in the plane x-z.
circle = s111.replace('<Parameter name="Obstacle" type="string" value="BI_PLAN_Z"/>',
                      '<Parameter name="Obstacle" type="string" value="BI_CERCLE"/>')
circle = circle.replace('<Parameter name="Axis" type="string" value="0 0 1"/>',
                        '<Parameter name="Axis" type="string" value="0 1 0"/>')
assert circle.count("BI_CERCLE") == 1 and circle.count('value="0 1 0"') == 1
c, _ = run(circle, "sdnl111a_circle")
compare("SDNL111 A circle vs planes", c, a, [("A:DX", "A:DX"), ("shock:force", "shock:force")], 1e-8)

# 4. SDNL32's tip in a ring: direct against modal on all modes.
RING = '''      <ParameterList name="Shock Links">
        <ParameterList name="ring">
          <Parameter name="Node 1" type="string" value="N11"/>
          <Parameter name="Obstacle" type="string" value="BI_CERC_INT"/>
          <Parameter name="Axis" type="string" value="0 0 1"/>
          <Parameter name="DIST_1" type="double" value="0"/>
          <Parameter name="DIST_2" type="double" value="0.002"/>
          <Parameter name="Normal Stiffness" type="double" value="1e5"/>
        </ParameterList>
      </ParameterList>
'''


def with_ring(text):
    i = text.index(LINKS_START)
    j = text.index("      </ParameterList>\n", text.index("      </ParameterList>\n", i) + 1)
    return text[:i] + RING + text[j + len("      </ParameterList>\n"):]


def at_dt(text, dt):
    return re.sub(r'<Parameter name="Time Step" type="double" value="[^"]*"/>',
                  f'<Parameter name="Time Step" type="double" value="{dt!r}"/>', text)


direct_ring = with_ring(s32)
d1, _ = run(at_dt(direct_ring, 1e-6), "ring_direct")
d2, _ = run(at_dt(direct_ring, 5e-7), "ring_direct_half")
self_err = compare("ring: direct at dt vs dt/2", d1, d2, [("N11:DY", "N11:DY")], 1.0, interpolate=True)
modal = deck("sdnl32.xml")
modal = modal[:modal.index('    <ParameterList name="run1_exact_tip">')] + "  </ParameterList>\n</ParameterList>\n"
modal = re.sub(r"      <ParameterList name=\"Checks\">.*?\n      </ParameterList>\n", "", modal, flags=re.S)
modal = modal.replace('<Parameter name="Number of Modes" type="int" value="10"/>',
                      '<Parameter name="Number of Modes" type="int" value="31"/>')
modal = modal.replace('<Parameter name="Modal Damping" type="double" value="0.01"/>',
                      '<Parameter name="Modal Damping" type="double" value="0"/>\n'
                      '      <Parameter name="Stability Check" type="string" value="substep"/>')
modal = at_dt(with_ring(modal), 1e-6)
m, log = run(modal, "ring_modal")
ca, da = history(d1, "direct")
closed = np.sum(np.diff((da[:, ca.index("ring:status")] > 0).astype(int)) == 1)
gaps = da[:, ca.index("N11:DY")]
print(f"ring: {closed} closures, DY in [{gaps.min():.4e}, {gaps.max():.4e}] m")
if closed < 2 or gaps.max() < 0.002 or gaps.min() > -0.002:
    failures.append("ring: the tip must hit both sides of the ring")
compare("ring: direct vs modal (31 modes)", d1, m, [("N11:DY", "N11:DY")], 4 * self_err,
        analysis_b="run1", interpolate=True)

# 5. SDNL111 A at dt = 2e-6 s: at the first steps the link closes while approaching and its
#    dashpot's jump leaves a step without solution; the step is solved without the dashpot, the
#    log says so, and the run keeps the input's check against d'Alembert.
out, log = run(at_dt(deck("sdnl111a_direct.xml"), 2e-6), "sdnl111a_dt2e-6")
drop = re.search(r"a dashpot was dropped in (\d+) step", log)
print(f"SDNL111 A at dt = 2e-6 s: dashpot dropped in {drop.group(1) if drop else 0} step(s); "
      f"{'checks pass' if ' 0 NOOK' in log else 'a check failed'}")
if not drop or " 0 NOOK" not in log:
    failures.append("SDNL111 A at dt = 2e-6 s: expected a dropped dashpot and the check passed")

# 6. The plane through 'Obstacle Origin' against the same plane by DIST_1.
sd = deck("sdnd100.xml")
origin = sd.replace('<Parameter name="DIST_1" type="double" value="0.5"/>',
                    '<Parameter name="Obstacle Origin" type="string" value="0 0 0.5"/>')
assert origin != sd
a, _ = run(sd, "sdnd100_dist")
b, _ = run(origin, "sdnd100_origin")
for analysis in ("deck", "direct", "explicit"):
    compare(f"SDND100 {analysis}: origin vs DIST_1", a, b,
            [("P:DX", "P:DX"), ("P:DY", "P:DY"), ("plane:force", "plane:force"), ("plane:gap", "plane:gap")],
            1e-12, analysis_a=analysis, analysis_b=analysis)

if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("OK")
