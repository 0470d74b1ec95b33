#!/usr/bin/env python3
"""The exact motion of SDND100's oscillator with an elastic-plastic Coulomb link, an
oracle for the shock links' friction independent of choc: mass m on a spring K, a friction
force that is an elastic stick spring Kt, bounded by mu N (slip along the velocity), starting
at rest from x0 with the stick spring unloaded. Piecewise analytic:
  stick: m x'' = -K x + f_a - Kt (x - x_a)   (f_a, x_a: the friction force and position when
         the stick began), until |f_a - Kt (x - x_a)| reaches mu N: then slip;
  slip:  m x'' = -K x - mu N sign(v), until v = 0: then stick from f_a = the slip force.
With Kt -> infinity it is the rigid-plastic closed form of the deck (the amplitude drops by
2 mu N / K every half period). Both laws of choc's links (elastic-plastic and velocity
reversal) follow this motion in one direction.
  friction_oscillator.py [--kt 4e5] [--times t1 t2 ...]   prints x(t) along the line"""
import argparse
import math


def motion(m=1.0, k=1e4, kt=4e5, friction=1.0, x0=0.85e-3, t_end=0.3):
    """The segments of the motion: (t0, t1, c, a, b, omega) with x(t) = c + a cos(w (t - t0)) +
    b sin(w (t - t0)) on [t0, t1]."""
    segments = []
    t, x, v = 0.0, x0, 0.0
    stick, fa, xa = True, 0.0, x0
    direction = 0.0  # sign of the velocity while slipping
    for _ in range(100000):
        if t >= t_end:
            break
        if stick:
            w = math.sqrt((k + kt) / m)
            c = (fa + kt * xa) / (k + kt)
        else:
            w = math.sqrt(k / m)
            c = -friction * direction / k
        a, b = x - c, v / w
        r, phi = math.hypot(a, b), math.atan2(b, a)  # x = c + r cos(w s - phi)
        candidates = []
        if stick:
            for target in (xa + (fa - friction) / kt, xa + (fa + friction) / kt):
                q = (target - c) / r if r > 0 else 2.0
                if abs(q) <= 1.0:
                    for root in (math.acos(q), -math.acos(q)):
                        s = (root + phi) % (2 * math.pi) / w
                        if s > 1e-15:
                            candidates.append(s)
        else:
            s = (phi % math.pi) / w  # v = -r w sin(w s - phi) = 0
            if s <= 1e-15:
                s += math.pi / w
            candidates.append(s)
        s = min(candidates) if candidates else t_end - t
        s = min(s, t_end - t)
        segments.append((t, t + s, c, a, b, w))
        x = c + a * math.cos(w * s) + b * math.sin(w * s)
        v = w * (-a * math.sin(w * s) + b * math.cos(w * s))
        t += s
        if t >= t_end:
            break
        if stick:
            # |f| reached mu N: it slips the way the spring force (-K x + f) pushes it.
            stick = False
            direction = math.copysign(1.0, v) if v != 0.0 else math.copysign(1.0, -k * x + fa - kt * (x - xa))
        else:
            # Stopped: it sticks, the stick spring holding the slip force.
            stick, fa, xa = True, -friction * direction, x
            v = 0.0
    return segments


def position(segments, t):
    for t0, t1, c, a, b, w in segments:
        if t0 <= t <= t1:
            return c + a * math.cos(w * (t - t0)) + b * math.sin(w * (t - t0))
    raise ValueError("t outside the motion")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--kt", type=float, default=4e5)
    ap.add_argument("--times", type=float, nargs="*", default=[n * math.pi / 100 for n in (1, 2, 3, 4)])
    a = ap.parse_args()
    seg = motion(kt=a.kt)
    for t in a.times:
        print("%.10g %.10e" % (t, position(seg, t)))


if __name__ == "__main__":
    main()
