#!/usr/bin/env python3
"""Hertz impact (docs/verification/hertz.md): a run of input/hertz.xml against Hertz's closed form.

usage: tools/oracles/hertz.py RUN_DIR [--analysis NAME ...] [--tolerance T] [--rebound-tolerance V]
                      [--energy-tolerance E] [--fraction F] [--plot FILE.png]
       tools/oracles/hertz.py --static RUN_DIR   (input/hertz_static.xml's run)

Hertz (quasi-static elastic sphere on a rigid plane): E* = E/(1 - nu^2), m = rho 4 pi R^3/3,
delta_max = (15 m v^2 / (16 E* sqrt(R)))^(2/5), F_max = (4/3) E* sqrt(R) delta_max^(3/2),
t_c = 2.9432 delta_max / v; the force history from m delta'' = -(4/3) E* sqrt(R) delta^(3/2)
(integrated here by RK4). From each analysis' history (RUN_DIR/<analysis>.history.csv):
the peak of '<pair>:force', the contact duration (first to last recorded step with a force),
the largest approach (-C:DY, the centre's displacement towards the plane), the rebound
velocity from the momentum balance (-v + impulse / m, the impulse integrated by the
trapezoidal rule), and the largest energy:balance over E0. Prints them against Hertz; exits 1
when the force, duration or approach differ by more than T, the rebound velocity by more than
V (default 0.02), or the balance exceeds E (default 1e-3) times E0. T defaults to a/R at
Hertz's peak (0.081): Hertz's half-space theory leaves out terms of that order for a finite
sphere (the far-field compliance of the sphere is not the half-space's), which the static
press measures. --fraction F: the model holds the fraction F of the sphere (0.25 for the
quarter of input/hertz_3d.xml, cut by two symmetry planes), so its force, impulse, mass and
energy are F times the whole sphere's; the force is divided by F before it is compared.
--plot draws the force histories over Hertz's curve.

--static: the force of the plane pressing the lower half sphere (rising at 0.1 m/s) against
Hertz's law F = (4/3) E* sqrt(R) d^(3/2) at the plane's travel d; prints F / F_Hertz with
a/R = sqrt(d/R), and exits 1 when |F / F_Hertz - 1| exceeds a/R at some travel.
"""
import argparse
import math
import os
import sys

import numpy as np

R, E, NU, RHO, V = 0.01, 2e11, 0.3, 7800.0, 5.0


def hertz(radius=R, young=E, poisson=NU, density=RHO, speed=V):
    """Hertz's figures for a sphere (the steel sphere of input/hertz.xml by default)."""
    es = young / (1 - poisson * poisson)
    m = density * 4.0 / 3.0 * math.pi * radius ** 3
    k = 4.0 / 3.0 * es * math.sqrt(radius)
    dmax = (15.0 * m * speed * speed / (16.0 * es * math.sqrt(radius))) ** 0.4
    return {"m": m, "k": k, "dmax": dmax, "fmax": k * dmax ** 1.5, "tc": 2.9432 * dmax / speed,
            "v": speed, "R": radius}


def hertz_curve(h, dt=None):
    """F(t) of m d'' = -k d^1.5, d(0) = 0, d'(0) = v, until d returns to 0 (RK4, by default
    with 40,000 steps over Hertz's duration)."""
    dt = dt or h["tc"] / 4e4
    def acc(d):
        return -h["k"] * max(d, 0.0) ** 1.5 / h["m"]
    t, d, v, ts, fs = 0.0, 0.0, h["v"], [0.0], [0.0]
    while True:
        k1 = (v, acc(d))
        k2 = (v + 0.5 * dt * k1[1], acc(d + 0.5 * dt * k1[0]))
        k3 = (v + 0.5 * dt * k2[1], acc(d + 0.5 * dt * k2[0]))
        k4 = (v + dt * k3[1], acc(d + dt * k3[0]))
        d += dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        v += dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        t += dt
        if d <= 0:
            break
        ts.append(t)
        fs.append(h["k"] * d ** 1.5)
    return np.array(ts), np.array(fs)


def measure(path, h, fraction=1.0):
    d = np.genfromtxt(path, delimiter=",", names=True)
    t = d["time"]
    fcol = [c for c in d.dtype.names if c.endswith("force")][0]
    f = d[fcol] / fraction
    on = np.nonzero(f > 0)[0]
    impulse = float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(t)))
    e0 = d["energytotal"][0]
    return {
        "peak force": (float(f.max()), h["fmax"]),
        "contact duration": (float(t[on[-1]] - t[on[0]]) if len(on) else 0.0, h["tc"]),
        "largest approach": (float(-d["CDY"].min()), h["dmax"]),
        "rebound velocity": (-h["v"] + impulse / h["m"], h["v"]),
        "_balance": float(d["energybalance"].max() / e0),
        "_t": t, "_f": f,
    }


def plot_forces(h, curves, path, ylabel="contact force [kN]"):
    """Plots each measured force history (label -> measure()) over Hertz's curve into path."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ht, hf = hertz_curve(h)
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(ht * 1e6, hf / 1e3, "k--", label="Hertz (quasi-static)")
    for label, m in curves.items():
        ax.plot(m["_t"] * 1e6, m["_f"] / 1e3, label=label)
    ax.set_xlabel("time [us]")
    ax.set_ylabel(ylabel)
    ax.set_xlim(0, 1.2 * h["tc"] * 1e6)
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def static_press(run_dir, h, speed=0.1):
    d = np.genfromtxt(os.path.join(run_dir, "press.history.csv"), delimiter=",", names=True)
    worst = 0.0
    for t, f in zip(d["time"], d["planeforce"]):
        travel = speed * t
        if travel < 4.9e-6:
            continue
        ratio, aR = f / (h["k"] * travel ** 1.5), math.sqrt(travel / R)
        worst = max(worst, abs(ratio - 1) / aR)
        if abs(round(travel * 1e6) - travel * 1e6) < 1e-6 and round(travel * 1e6) % 10 in (0, 5):
            print(f"travel {travel * 1e6:5.1f} um  a/R {aR:.3f}  F {f:9.1f} N  Hertz "
                  f"{h['k'] * travel ** 1.5:9.1f} N  ratio {ratio:.4f}")
    print(f"largest |F / F_Hertz - 1| / (a/R): {worst:.3f}")
    if not worst <= 1.0:
        sys.exit("hertz: the static press departs from Hertz's law by more than a/R")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run_dir")
    ap.add_argument("--analysis", nargs="+", default=["axisymmetric"])
    ap.add_argument("--tolerance", type=float)
    ap.add_argument("--rebound-tolerance", type=float, default=0.02)
    ap.add_argument("--energy-tolerance", type=float, default=1e-3)
    ap.add_argument("--fraction", type=float, default=1.0)
    ap.add_argument("--static", action="store_true")
    ap.add_argument("--plot")
    a = ap.parse_args()
    h = hertz()
    if a.static:
        return static_press(a.run_dir, h)
    if a.tolerance is None:
        a.tolerance = math.sqrt(h["dmax"] / R)
    print(f"Hertz: delta_max {h['dmax'] * 1e6:.2f} um, F_max {h['fmax']:.0f} N, "
          f"t_c {h['tc'] * 1e6:.2f} us, m {h['m'] * 1e3:.4f} g")
    failures, runs = [], {}
    for name in a.analysis:
        m = measure(os.path.join(a.run_dir, f"{name}.history.csv"), h, a.fraction)
        runs[name] = m
        for q, value in m.items():
            if q.startswith("_"):
                continue
            got, ref = value
            err = got / ref - 1
            print(f"{name:14s} {q:18s} {got:12.6g}  Hertz {ref:12.6g}  {100 * err:+6.2f}%")
            tol = a.rebound_tolerance if q == "rebound velocity" else a.tolerance
            if not abs(err) <= tol:
                failures.append(f"{name} {q} {100 * err:+.2f}%")
        # The impact statistics (<analysis>.impacts.csv): one impact, closing at -5 m/s, whose
        # impulse is the momentum change of an elastic rebound, 2 m V, to 0.5 % (what the sphere
        # keeps as vibration after the impact, a fraction of a percent of E0, lowers it).
        impacts = os.path.join(a.run_dir, f"{name}.impacts.csv")
        if os.path.exists(impacts):
            rows = open(impacts).read().splitlines()[1:]
            if len(rows) != 1:
                failures.append(f"{name}: {len(rows)} impacts in {impacts}, one expected")
            else:
                f = rows[0].split(",")
                impulse, velocity = float(f[7]), float(f[8])
                ref = 2 * h["m"] * V * a.fraction
                print(f"{name:14s} {'impulse':18s} {impulse:12.6g}  2 m V {ref:12.6g}  "
                      f"{100 * (impulse / ref - 1):+6.3f}%; impact velocity {velocity:+.6g} m/s")
                if not abs(impulse / ref - 1) <= 5e-3:
                    failures.append(f"{name} impulse {100 * (impulse / ref - 1):+.3f}% of 2 m V")
                if not abs(velocity + V) <= 1e-3 * V:
                    failures.append(f"{name} impact velocity {velocity} m/s, -{V} expected")
        print(f"{name:14s} {'energy balance':18s} max {100 * m['_balance']:+.4f}% of E0")
        if not m["_balance"] <= a.energy_tolerance:
            failures.append(f"{name} energy balance {100 * m['_balance']:+.4f}% of E0")
    if a.plot:
        plot_forces(h, {f"choc, {name}": m for name, m in runs.items()}, a.plot)
    if failures:
        sys.exit("hertz: outside the tolerances: " + "; ".join(failures))


if __name__ == "__main__":
    main()
