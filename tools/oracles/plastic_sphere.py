#!/usr/bin/env python3
"""A thick-walled elastic-perfectly plastic sphere under internal pressure (small strain; Hill,
The Mathematical Theory of Plasticity, 1950, ch. V): inner radius a, outer b, yield stress Y,
Young's modulus E, Poisson's ratio nu. Under spherical symmetry von Mises and Tresca coincide,
sigma_theta - sigma_r = Y in the plastic zone a <= r <= c, and the elastic shell c <= r <= b
carries the pressure of its own first yield at c:

    p(c)   = 2 Y ln(c / a) + 2 Y / 3 (1 - c^3 / b^3),        a <= c <= b,
    u(b)   = Y (1 - nu) c^3 / (E b^2)                         (the outer radius' motion),

first yield at p(a) = 2 Y / 3 (1 - a^3 / b^3), collapse at p(b) = 2 Y ln(b / a). Below first
yield the elastic shell:  u(b) = 3 (1 - nu) p a^3 b / (2 E (b^3 - a^3)).
u(b) is exact whatever the plastic zone's compressibility: the elastic shell alone sets it."""
import math


def first_yield(a, b, Y):
    return 2 * Y / 3 * (1 - (a / b) ** 3)


def collapse(a, b, Y):
    return 2 * Y * math.log(b / a)


def pressure(c, a, b, Y):
    return 2 * Y * math.log(c / a) + 2 * Y / 3 * (1 - (c / b) ** 3)


def front(p, a, b, Y):
    """The plastic front c at pressure p (first_yield <= p < collapse), by bisection: p(c) rises
    with c on [a, b]."""
    lo, hi = a, b
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if pressure(mid, a, b, Y) < p:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def outer_displacement(p, a, b, E, nu, Y):
    """u(b) at pressure p (0 <= p < collapse)."""
    if p <= first_yield(a, b, Y):
        return 1.5 * (1 - nu) * p * a ** 3 * b / (E * (b ** 3 - a ** 3))
    c = front(p, a, b, Y)
    return Y * (1 - nu) * c ** 3 / (E * b ** 2)


def self_check():
    """Continuity at first yield (both formulas), and the front's inverse: the largest
    relative difference."""
    a, b, E, nu, Y = 0.05, 0.1, 200e9, 0.3, 250e6
    py = first_yield(a, b, Y)
    elastic = 1.5 * (1 - nu) * py * a ** 3 * b / (E * (b ** 3 - a ** 3))
    plastic = Y * (1 - nu) * a ** 3 / (E * b ** 2)
    d1 = abs(elastic - plastic) / plastic
    c = 0.0731
    d2 = abs(front(pressure(c, a, b, Y), a, b, Y) - c) / c
    return max(d1, d2)


if __name__ == "__main__":
    print(f"self check: {self_check():.2e}")
    a, b, E, nu, Y = 0.05, 0.1, 200e9, 0.3, 250e6
    print(f"first yield {first_yield(a, b, Y) / 1e6:.3f} MPa, collapse {collapse(a, b, Y) / 1e6:.3f} MPa, "
          f"c = 0.8 b at {pressure(0.08, a, b, Y) / 1e6:.3f} MPa, u(b) = {outer_displacement(pressure(0.08, a, b, Y), a, b, E, nu, Y):.6e} m")
