#!/usr/bin/env python3
"""SDNV104 (docs/verification/sdnv104.md) over the whole history, QUAD4 and QUAD8
(input/sdnv104_quad4.xml, input/sdnv104_quad8.xml): the 7,000 kg pad, tied by springs
k = 24,000 N/m, pressed by N = 70 kN and pushed by F = 200 kN (both ramped from 0 to full at
0.07 s), slides with Coulomb friction mu = 0.3 along the frame.

1. The motion: DX of the pad against the 1-DOF closed form, m x'' + k x = r(t) (F - s mu N)
   while sliding in direction s (the ramp's response, then half-cosines about (F -+ mu N) / k
   from each stop, slipping on while |F - k x| > mu N), at every step to 0.5 % of the peak
   (the bound of the inputs' rows; the deck asks 5 %).
2. The friction work: mu N r(t) times the distance the pad's own history slid, at every step
   after the ramp, to 0.5 % (the same bound).
3. The law and the loads: the tangential force never above mu times the normal force (1e-9);
   equal to it while the pad moves faster than 0.1 m/s (1e-6); the normal force equal to
   N r(t) after 0.2 s to 0.5 % (the pad does not move vertically; its vibrations are damped).
4. The energy balance never above +0.1 % of the largest total energy (the pad starts at rest:
   E0 = 0), with the external work of ramped pressures.
The same checks hold for QUAD4 with mortar contact, by Lagrange, Penalty and Continuous (the pad's LINE2 edges against the frame's,
integrated again before each step as the pad slides 15 m): friction on mortar pairs acts on the
slave node's motion relative to its dual function's average of the master nodes.
5. Frame invariance (docs/verification/properties.md), QUAD4: the scene turned by 0.7 rad about z (the
   mesh by gmsh, the springs' direction with it; the pressures follow the faces) gives the same
   motion, R^T u, to 1e-8 of the peak; the same normal force and friction work (mu times it)
   to 1e-6 of their peaks: the normal force is the sum of 5 multipliers, each known to Newton's
   residual tolerance, 1e-8 of the residual's reference, which is below the applied, spring and
   inertia forces' 1e6 N: 5 x 1e-8 x 1e6 N = 0.05 N, 7e-7 of the 70 kN; the same Newton
   iterations within 10 %.
usage: sdnv104.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import re
import subprocess
import sys

import numpy as np

from deck_run import run_deck

choc, src, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
m, k, F, N, mu, T = 7000.0, 24000.0, 2e5, 7e4, 0.3, 0.07
w = math.sqrt(k / m)
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def ramp(t):
    return np.minimum(np.maximum(t, 0.0) / T, 1.0)


def exact(times):
    """The closed form: sliding forward through the ramp to the first stop, then half-cosines."""
    a = (F - mu * N) / k

    def forward(t):  # response to the ramped (F - mu N), from rest
        if t < T:
            return a * (t / T - math.sin(w * t) / (w * T))
        return a * (1 - (math.sin(w * t) - math.sin(w * (t - T))) / (w * T))

    def velocity(t):
        if t < T:
            return a * (1 - math.cos(w * t)) / T
        return -a * (math.cos(w * t) - math.cos(w * (t - T))) / T

    lo, hi = 1.0, 2.0  # the first stop: bisection on the velocity
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if velocity(mid) > 0 else (lo, mid)
    stops = [(lo, forward(lo))]
    while stops[-1][0] < times[-1] + 1:
        t0, x0 = stops[-1]
        if abs(F - k * x0) <= mu * N:
            stops.append((math.inf, x0))  # sticks for good
            break
        s = 1.0 if F - k * x0 > 0 else -1.0
        c = (F - s * mu * N) / k
        stops.append((t0 + math.pi / w, 2 * c - x0))
    x = []
    for t in times:
        if t <= stops[0][0]:
            x.append(forward(t))
            continue
        for (t0, x0), (t1, _) in zip(stops, stops[1:]):
            if t0 < t <= t1:
                if t1 == math.inf:
                    x.append(x0)
                else:
                    s = 1.0 if F - k * x0 > 0 else -1.0
                    c = (F - s * mu * N) / k
                    x.append(c + (x0 - c) * math.cos(w * (t - t0)))
                break
    return np.array(x)


MORTAR = ('<Parameter name="Slave Side Set" type="string" value="PAD_BOTTOM"/>',
          '<Parameter name="Slave Side Set" type="string" value="PAD_BOTTOM"/>'
          '<Parameter name="Discretization" type="string" value="mortar"/>')
LAGRANGE = '<Parameter name="Method" type="string" value="Lagrange"/>'


def method(name):
    """The deck's contact method replaced (Penalty with a stiffness 1e4 times the springs' k
    per slave node: the pad sinks N / (5 x 1e10) = 1.4e-6 m, nothing against the 15 m)."""
    extra = '<Parameter name="Penalty Stiffness" type="double" value="1e10"/>' if name == "Penalty" else ""
    return lambda d: d.replace(*MORTAR).replace(LAGRANGE, LAGRANGE.replace("Lagrange", name) + extra)


for element, deck, edit in (("quad4", "quad4", lambda d: d), ("quad8", "quad8", lambda d: d),
                            ("quad4_mortar", "quad4", lambda d: d.replace(*MORTAR)),
                            ("quad4_mortar_penalty", "quad4", method("Penalty")),
                            ("quad4_mortar_continuous", "quad4", method("Continuous"))):
    out, log = run_deck(choc, src, work, f"sdnv104_{deck}.xml", element, edit, label="sdnv104")
    if "mortar" in element:
        used = open(os.path.join(work, element + ".xml")).read()
        wanted = element.split("_")[-1].capitalize() if element.count("_") > 1 else "Lagrange"
        check("mortar" in used and f'value="{wanted}"' in used, f"{element}: the pair is mortar, {wanted}")
    h = np.genfromtxt(os.path.join(out, "lagrange.history.csv"), delimiter=",", names=True)
    t, x, v = h["time"], h["PAD_SPRINGDX"], h["PAD_SPRINGVX"]
    ref = exact(t)
    err = np.abs(x - ref).max() / np.abs(ref).max()
    check(err <= 5e-3, f"{element}: DX against the 1-DOF closed form within {err:.1e} of its peak "
          f"({np.abs(ref).max():.3f} m)")
    check(x.max() > 14.8 and x[-1] < 4.0, f"{element}: slid forward to {x.max():.3f} m and back to {x[-1]:.3f} m")
    # 2. mu N r(t) times the distance slid, by the midpoint of each step's ramp.
    tm = 0.5 * (t[1:] + t[:-1])
    slid = np.concatenate([[0.0], np.cumsum(mu * N * ramp(tm) * np.abs(np.diff(x)))])
    after = t > 2 * T
    rel = np.abs(h["padfriction_work"][after] - slid[after]) / slid[after]
    check(rel.max() <= 5e-3, f"{element}: friction work = mu N x distance slid within {rel.max():.1e}")
    # 3. The law and the normal force.
    fn, ft = np.abs(h["padforce"]), np.abs(h["padtangential_force"])
    over = (ft - mu * fn).max() / (mu * N)
    check(over <= 1e-9, f"{element}: tangential force <= mu x normal force (excess {over:.1e} of mu N)")
    moving = np.abs(v) > 0.1
    cone = np.abs(ft[moving] - mu * fn[moving]).max() / (mu * N)
    check(cone <= 1e-6, f"{element}: tangential force = mu x normal force while moving ({cone:.1e})")
    late = t > 0.2
    dn = np.abs(fn[late] - N * ramp(t[late])).max() / N
    check(dn <= 5e-3, f"{element}: normal force = N r(t) within {dn:.1e} after 0.2 s")
    # 4. The energy.
    growth = h["energybalance"].max() / np.abs(h["energytotal"]).max()
    check(growth <= 1e-3, f"{element}: largest energy balance {growth:+.1e} of the largest total energy")


# 5. Frame invariance: the QUAD4 scene as drawn and turned by ANGLE about z.
ANGLE = 0.7
c, s_ = math.cos(ANGLE), math.sin(ANGLE)
runs = {}
for label, angle in (("as_drawn", 0.0), ("turned", ANGLE)):
    mesh = os.path.join(work, label + ".msh")
    subprocess.run(["gmsh", "-2", "-format", "msh41", "-setnumber", "angle", repr(angle),
                    os.path.join(src, "meshes", "sdnv104.geo"), "-o", mesh],
                   check=True, stdout=subprocess.DEVNULL)
    direction = f"{math.cos(angle)!r} {math.sin(angle)!r} 0"

    def turn(deck):
        deck = deck.replace(f"{src}/meshes/sdnv104_quad4.msh", mesh)
        deck = deck.replace('name="Direction" type="string" value="1 0 0"',
                            f'name="Direction" type="string" value="{direction}"')
        deck = deck.replace('value="PAD_SPRING:DX PAD_SPRING:VX"', 'value="PAD_SPRING:DX PAD_SPRING:DY"')
        return re.sub(r'<ParameterList name="Checks">.*?\n      </ParameterList>\n', "", deck, flags=re.S)

    out, log = run_deck(choc, src, work, "sdnv104_quad4.xml", label, turn, "sdnv104")
    check(mesh in open(os.path.join(work, label + ".xml")).read(), f"{label}: the run reads the {label} mesh")
    newton = int(re.search(r"(\d+) Newton iterations", log).group(1))
    runs[label] = (np.genfromtxt(os.path.join(out, "lagrange.history.csv"), delimiter=",", names=True), newton)
(h0, n0), (h1, n1) = runs["as_drawn"], runs["turned"]
u0 = np.column_stack([h0["PAD_SPRINGDX"], h0["PAD_SPRINGDY"]])
u1 = np.column_stack([c * h1["PAD_SPRINGDX"] + s_ * h1["PAD_SPRINGDY"],
                      -s_ * h1["PAD_SPRINGDX"] + c * h1["PAD_SPRINGDY"]])  # R^T u
diff = np.abs(u1 - u0).max() / np.abs(u0).max()
check(diff <= 1e-8, f"turned by {ANGLE} rad: R^T u equals u within {diff:.1e} of the peak")
for column, what in (("padforce", "normal force"), ("padfriction_work", "friction work")):
    d = np.abs(h1[column] - h0[column]).max() / np.abs(h0[column]).max()
    check(d <= 1e-6, f"turned: the {what} equal within {d:.1e} of its peak")
check(abs(n1 - n0) <= 0.1 * n0, f"turned: {n1} Newton iterations against {n0}")

if failures:
    sys.exit("sdnv104: " + "; ".join(failures))
print("sdnv104: all checks hold")
