"""A planar cantilever under a dead end force and an end moment at large deflection, in Python,
for docs/verification/elastica.md and cli.elastica.

The beam (length L, clamped at s = 0 along +x) is Reissner's geometrically exact beam: the
section turned by theta(s), the force it carries the end force P = (Px, Py) (dead: no load along
the span), its moment m(s) = M0 + (r(L) - r(s)) x P, and the linear section laws
    m = EI theta',   N = P . t = EA eps,   V = P . n = kGA gamma,
    r' = (1 + eps) t + gamma n,   t = (cos theta, sin theta), n = (-sin theta, cos theta).
EA and kGA infinite give Euler's elastica (inextensible, no shear). m' = -(r' x P) closes the
system; it is solved by shooting on the root moment m(0) (classical Runge-Kutta on `steps`
intervals, fourth order: 4,000 steps leave 1e-13 here) until m(L) = M0, by the secant method
from a guess (the caller continues along a load ramp from the last solution).

Closed forms it is checked against (closed_form_checks):
  * an end moment alone: a circle of radius EI / M0, tip (R sin(L/R), R (1 - cos(L/R)));
  * a force normal to the undeformed axis (the elastica's classical case, e.g. Bisshopp and
    Drucker, Q. Appl. Math. 3, 1945): the first integral EI theta'^2 / 2 = P (sin theta0 -
    sin theta) gives L sqrt(2 P / EI) = int_0^theta0 dtheta / sqrt(sin theta0 - sin theta), the
    tip x(L) = sqrt(2 sin theta0 / k) L (k = P L^2 / EI) and y(L) by the same quadrature of
    sin theta / sqrt(...), evaluated here with the substitution theta = theta0 - w^2 (smooth) and
    Gauss-Legendre;
  * small loads: Timoshenko's tip deflection P L^3 / (3 EI) + P L / kGA.
"""
import math

_GAUSS = (  # 8-point Gauss-Legendre on [-1, 1]
    (-0.9602898564975363, 0.1012285362903763), (-0.7966664774136267, 0.2223810344533745),
    (-0.5255324099163290, 0.3137066458778873), (-0.1834346424956498, 0.3626837833783620),
    (0.1834346424956498, 0.3626837833783620), (0.5255324099163290, 0.3137066458778873),
    (0.7966664774136267, 0.2223810344533745), (0.9602898564975363, 0.1012285362903763))


def _quadrature(f, a, b, panels=200):
    h = (b - a) / panels
    s = 0.0
    for k in range(panels):
        c = a + (k + 0.5) * h
        for x, w in _GAUSS:
            s += w * f(c + 0.5 * h * x)
    return 0.5 * h * s


class Beam:
    """Section stiffnesses: EI [N m2], EA [N] and kGA [N] (math.inf: inextensible / no shear)."""

    def __init__(self, length, EI, EA=math.inf, kGA=math.inf):
        self.L, self.EI, self.EA, self.kGA = length, EI, EA, kGA

    def _rhs(self, state, P):
        x, y, th, m = state
        c, s = math.cos(th), math.sin(th)
        N = P[0] * c + P[1] * s
        V = -P[0] * s + P[1] * c
        eps = N / self.EA if math.isfinite(self.EA) else 0.0
        gam = V / self.kGA if math.isfinite(self.kGA) else 0.0
        dx = (1 + eps) * c - gam * s
        dy = (1 + eps) * s + gam * c
        return (dx, dy, m / self.EI, -(dx * P[1] - dy * P[0]))

    def integrate(self, m0, P, steps=4000, record=False):
        """The state (x, y, theta, m) at s = L from the root moment m0 (and the states along s)."""
        h = self.L / steps
        st = (0.0, 0.0, 0.0, m0)
        path = [st]
        for _ in range(steps):
            k1 = self._rhs(st, P)
            k2 = self._rhs(tuple(a + 0.5 * h * b for a, b in zip(st, k1)), P)
            k3 = self._rhs(tuple(a + 0.5 * h * b for a, b in zip(st, k2)), P)
            k4 = self._rhs(tuple(a + h * b for a, b in zip(st, k3)), P)
            st = tuple(a + h / 6 * (b1 + 2 * b2 + 2 * b3 + b4) for a, b1, b2, b3, b4 in zip(st, k1, k2, k3, k4))
            if record:
                path.append(st)
        return path if record else st

    def solve(self, P, M0=0.0, guess=None, steps=4000, tol=1e-12):
        """(x, y, theta, m0) at the tip for the end force P and end moment M0, and the root
        moment; `guess` is the root moment to start from (the linear one if None)."""
        scale = abs(M0) + math.hypot(*P) * self.L + 1e-300
        m_a = guess if guess is not None else M0 + P[1] * self.L - 0.0 * P[0]
        m_b = m_a + 1e-3 * scale
        f_a = self.integrate(m_a, P, steps)[3] - M0
        f_b = self.integrate(m_b, P, steps)[3] - M0
        for _ in range(100):
            if f_b == f_a:
                break
            m_c = m_b - f_b * (m_b - m_a) / (f_b - f_a)
            m_a, f_a = m_b, f_b
            m_b = m_c
            f_b = self.integrate(m_b, P, steps)[3] - M0
            if abs(f_b) <= tol * scale:
                x, y, th, _ = self.integrate(m_b, P, steps)
                return x, y, th, m_b
        raise RuntimeError(f"elastica: no equilibrium found for P = {P}, M0 = {M0}")

    def ramp(self, P, M0=0.0, fractions=(1.0,), substeps=20, steps=4000):
        """The tip (x, y, theta) at each fraction of (P, M0), continued from zero load."""
        out, guess, done = [], None, 0.0
        for f in fractions:
            for k in range(1, substeps + 1):  # continuation: the root moment of the last state
                g = done + (f - done) * k / substeps
                x, y, th, guess = self.solve((g * P[0], g * P[1]), g * M0, guess, steps)
            done = f
            out.append((x, y, th))
        return out


def normal_load_closed_form(k):
    """Euler's elastica under an end force normal to the undeformed axis, k = P L^2 / EI:
    (x(L) / L, y(L) / L, theta0), by the first integral (module docstring)."""
    def length_integral(th0):
        # int_0^th0 dtheta / sqrt(sin th0 - sin theta), theta = th0 - w^2
        return _quadrature(lambda w: 2 * w / math.sqrt(math.sin(th0) - math.sin(th0 - w * w)) if w > 0
                           else 2 / math.sqrt(math.cos(th0)), 0.0, math.sqrt(th0))
    lo, hi = 1e-9, math.pi / 2 - 1e-12
    target = math.sqrt(2 * k)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if length_integral(mid) < target:
            lo = mid
        else:
            hi = mid
    th0 = 0.5 * (lo + hi)
    x = math.sqrt(2 * math.sin(th0) / k)
    y = _quadrature(lambda w: 2 * w * math.sin(th0 - w * w) / math.sqrt(math.sin(th0) - math.sin(th0 - w * w))
                    if w > 0 else 0.0, 0.0, math.sqrt(th0)) / target
    return x, y, th0


def closed_form_checks():
    """The largest relative differences between the shooting solution and each closed form."""
    EI, L = 2.0, 1.5
    out = {}
    beam = Beam(L, EI)
    M0 = 1.7 * math.pi * EI / L  # 306 degrees
    x, y, th, _ = beam.solve((0.0, 0.0), M0)
    R = EI / M0
    out["end moment (circle)"] = max(abs(x - R * math.sin(L / R)), abs(y - R * (1 - math.cos(L / R))),
                                     abs(th - L / R) * L) / L
    worst = 0.0
    guess = None
    for i in range(1, 21):  # k from 0.5 to 10, continued
        k = 0.5 * i
        P = k * EI / L ** 2
        x, y, th, guess = beam.solve((0.0, P), 0.0, guess)
        if i in (1, 4, 10, 20):
            xc, yc, thc = normal_load_closed_form(k)
            worst = max(worst, abs(x / L - xc), abs(y / L - yc), abs(th - thc))
    out["normal end force (first integral)"] = worst
    timo = Beam(L, EI, EA=1e3, kGA=50.0)
    P = 1e-6 * EI / L ** 2
    _, y, _, _ = timo.solve((0.0, P))
    lin = P * L ** 3 / (3 * EI) + P * L / 50.0
    out["small load (Timoshenko)"] = abs(y - lin) / lin
    return out


if __name__ == "__main__":
    for name, err in closed_form_checks().items():
        print(f"{name}: {err:.2e}")
