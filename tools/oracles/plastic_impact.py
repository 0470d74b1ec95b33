#!/usr/bin/env python3
"""An elastic-plastic sphere on a rigid plane (docs/verification/plastic-impact.md): the yield
velocity, Thornton's coefficient of restitution and a run's measured one.

Yield velocity. Hertz's contact (E* = E / (1 - nu^2), a = (3 F R / (4 E*))^(1/3), p0 = 3 F /
(2 pi a^2)) first yields below the surface, on the axis, where von Mises' sigma_r - sigma_z is
largest (the stresses of Hertz's pressure on a half-space, Johnson, Contact Mechanics, 1985:
sigma_z = -p0 / (1 + z^2/a^2), sigma_r = p0 (-(1 + nu)(1 - (z/a) atan(a/z)) + 1 / (2 (1 +
z^2/a^2)))): p0_y = 1.61 Y at z = 0.48 a for nu = 0.3 (computed here for any nu). The impact
speed whose Hertz peak force reaches it: (1/2) m v_y^2 = (8/15) E* sqrt(R) delta_y^(5/2),
delta_y = a_y^2 / R, a_y = pi p0_y R / (2 E*).

Thornton (J. Appl. Mech. 64, 1997, 383): Hertz's pressure capped at p_y = p0_y, which gives
with r = v_y / v > 0 (v >= v_y)

    e = sqrt(6 sqrt(3) / 5) sqrt(1 - r^2 / 6) (r / (r + 2 sqrt(6/5 - r^2 / 5)))^(1/4),

1 at r = 1 and 1.185 r^(1/4) for v >> v_y. Finite-element studies of elastic-perfectly plastic
spheres (Zhang and Vu-Quoc 2002; Wu, Li and Thornton 2003) found the same (v_y/v)^(1/4) decay at
high speeds with restitutions above Thornton's: the pressure is not capped at p0_y but rises
towards about 3 Y as the plastic zone reaches the surface, so less work goes into plastic flow.

A run (impacts.csv, history.csv): e = impulse / (m v) - 1 (the momentum of the rigid rebound);
the plastic work W_p (energy:plastic at the end) and the energy the rebound leaves in the
sphere, E0 - (1/2) m (e v)^2 - W_p (vibration and residual stresses: >= 0).

usage: plastic_impact.py RUN_DIR --speed-ratio V_OVER_VY [--analysis impact]
  prints e, Thornton's e, W_p / E0; exits 1 when e exceeds 1 + 1e-3, the energy left in the
  sphere is negative beyond 1e-3 E0, or energy:balance exceeds 1e-3 E0."""
import argparse
import math
import os
import sys

E, NU, RHO, R, Y = 2e11, 0.3, 7800.0, 0.01, 2e9


def yield_pressure_ratio(nu=NU):
    """p0_y / Y: Hertz's peak pressure at first yield (the largest von Mises stress on the axis)."""
    def mises(z):  # z in units of a
        sz = -1 / (1 + z * z)
        sr = -(1 + nu) * (1 - z * math.atan(1 / z)) + 0.5 / (1 + z * z)
        return abs(sr - sz)
    lo, hi = 1e-3, 3.0
    for _ in range(200):  # golden-section search of the single maximum
        m1, m2 = lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo)
        if mises(m1) < mises(m2):
            lo = m1
        else:
            hi = m2
    return 1 / mises(0.5 * (lo + hi))


def sphere(young=E, poisson=NU, density=RHO, radius=R, yield_stress=Y):
    """The sphere's mass, E*, p0_y and yield velocity."""
    es = young / (1 - poisson ** 2)
    m = density * 4 / 3 * math.pi * radius ** 3
    p0y = yield_pressure_ratio(poisson) * yield_stress
    ay = math.pi * p0y * radius / (2 * es)
    dy = ay * ay / radius
    vy = math.sqrt(2 * (8 / 15) * es * math.sqrt(radius) * dy ** 2.5 / m)
    return {"m": m, "es": es, "p0y": p0y, "ay": ay, "vy": vy}


def thornton(speed_ratio):
    """Thornton's restitution at v / v_y (1 at and below yield)."""
    if speed_ratio <= 1:
        return 1.0
    r = 1 / speed_ratio
    return (math.sqrt(6 * math.sqrt(3) / 5) * math.sqrt(1 - r * r / 6)
            * (r / (r + 2 * math.sqrt(6 / 5 - r * r / 5))) ** 0.25)


def measure(run_dir, speed, analysis="impact", s=None):
    """e, the plastic work, the energy left in the sphere and the largest balance, over E0."""
    s = s or sphere()
    with open(os.path.join(run_dir, f"{analysis}.impacts.csv")) as f:
        rows = [r.split(",") for r in f.read().splitlines()[1:]]
    impulse = sum(float(r[7]) for r in rows)
    with open(os.path.join(run_dir, f"{analysis}.history.csv")) as f:
        header = f.readline().strip().split(",")
        last = None
        balance = -math.inf
        for line in f:
            last = [float(x) for x in line.split(",")]
            balance = max(balance, last[header.index("energy:balance")])
    e0 = 0.5 * s["m"] * speed * speed
    e = impulse / (s["m"] * speed) - 1
    plastic = last[header.index("energy:plastic")] if "energy:plastic" in header else 0.0
    peak = max((float(r[5]) for r in rows), default=0.0)
    return {"e": e, "impacts": len(rows), "plastic": plastic / e0, "left": 1 - e * e - plastic / e0,
            "balance": balance / e0, "peak_force": peak}


def failures(r, tag=""):
    """What a measured run (measure()) breaks: e above 1, more energy out than in, energy created."""
    bad = []
    if not r["e"] <= 1 + 1e-3:
        bad.append(f"{tag}e = {r['e']:.5f} > 1")
    if not r["left"] >= -1e-3:
        bad.append(f"{tag}the rebound and the plastic work exceed E0 by {-r['left']:.2e} E0")
    if not r["balance"] <= 1e-3:
        bad.append(f"{tag}energy:balance {r['balance']:+.2e} E0")
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run_dir")
    ap.add_argument("--speed-ratio", type=float, required=True)
    ap.add_argument("--analysis", default="impact")
    a = ap.parse_args()
    s = sphere()
    r = measure(a.run_dir, a.speed_ratio * s["vy"], a.analysis, s)
    print(f"v_y {s['vy']:.4f} m/s (p0_y = {s['p0y'] / Y:.4f} Y); v = {a.speed_ratio:g} v_y: e {r['e']:.4f}, "
          f"Thornton {thornton(a.speed_ratio):.4f}; plastic work {r['plastic']:.4f} E0, left in the sphere "
          f"{r['left']:.2e} E0, largest balance {r['balance']:+.2e} E0, impacts {r['impacts']}")
    bad = failures(r)
    if bad:
        sys.exit("plastic_impact: " + "; ".join(bad))


if __name__ == "__main__":
    main()
