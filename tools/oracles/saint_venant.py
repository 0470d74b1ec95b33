"""Saint-Venant's problem (shared/BENCHMARKS.md section 15): a rigid mass M at v0 strikes the free
end x = 0 of an elastic bar (length L, section A, density rho, wave speed c) fixed at x = L, and
stays on it while the end pushes it (compression).

With the particle velocity F(t - x/c) + G(t + x/c), the fixed end gives G(s) = -F(s - T), T = 2L/c,
and the mass's equation M [F'(t) - F'(t - T)] = -Z [F(t) + F(t - T)], Z = rho c A, beta = Z / M.
On the k-th interval (t = kT + s, 0 <= s < T) F(t) = exp(-beta s) P_k(s), P_k a polynomial:
  P_0 = v0;   P_k' = P_{k-1}' - 2 beta P_{k-1},   P_k(0) = exp(-beta T) P_{k-1}(T) + v0
(F jumps by v0 at each kT: the mass's velocity V(t) = F(t) - F(t - T) is continuous). So on that
interval, exactly (polynomials, no time stepping):
  stress at the struck end  sigma(0, t) = rho c exp(-beta s) [P_k(s) + P_{k-1}(s)]  (compression > 0),
  the mass's velocity       V(t) = exp(-beta s) [P_k(s) - P_{k-1}(s)]   (P_{-1} = 0).
Contact ends at the first zero of sigma (found by bisection to 1e-14 T); the mass then leaves
at V there, and the bar keeps the energy 1/2 M (v0^2 - V^2).

With bonded=True the mass is tied to the end (the same equations, no separation).

Used as a module (SaintVenant) by tests/cli/scripts/saint_venant.py; as a script it prints the
contact duration, rebound velocity and energy left for the mass ratios rho A L / M = 0.5, 1, 2.
"""
import math
import sys

from numpy.polynomial import Polynomial as P


class SaintVenant:
    def __init__(self, L, A, rho, E, M, v0, intervals=40, bonded=False):
        self.L, self.A, self.rho, self.E, self.M, self.v0 = L, A, rho, E, M, v0
        self.c = math.sqrt(E / rho)
        self.Z = rho * self.c * A
        self.beta = self.Z / M
        self.T = 2 * L / self.c
        self.P = [P([v0])]
        for _ in range(1, intervals):
            prev = self.P[-1]
            start = math.exp(-self.beta * self.T) * prev(self.T) + v0
            rate = prev.deriv() - 2 * self.beta * prev
            self.P.append(rate.integ(lbnd=0, k=start))
        # an infinite mass (a punch driven at v0): the end's stress rho c v0 (2k + 1), no separation
        # bonded: the mass is tied to the end (it never leaves, the end's stress may turn to tension)
        self.duration = self._separation() if math.isfinite(M) and not bonded else math.inf

    def _pieces(self, t):
        k = int(t // self.T)
        if k >= len(self.P):
            raise ValueError(f"t = {t} beyond the {len(self.P)} intervals computed")
        s = t - k * self.T
        prev = self.P[k - 1](s) if k > 0 else 0.0
        return math.exp(-self.beta * s), self.P[k](s), prev

    def stress(self, t):
        """Compression at the struck end [Pa] while the mass is on it (t >= 0)."""
        e, now, prev = self._pieces(t)
        return self.rho * self.c * e * (now + prev)

    def force(self, t):
        """The contact force [N] (0 after separation)."""
        return self.A * self.stress(t) if 0 <= t < self.duration else 0.0

    def mass_velocity(self, t):
        """The mass's velocity towards the bar [m/s] until separation, constant after."""
        e, now, prev = self._pieces(min(t, self.duration))
        return e * (now - prev)

    def _separation(self):
        n = 20000
        dt = len(self.P) * self.T / n
        a = dt * 1e-9
        for i in range(1, n):
            b = i * dt
            if self.stress(b) <= 0.0:
                lo, hi = max(a, (i - 1) * dt), b
                while hi - lo > 1e-14 * self.T:
                    mid = 0.5 * (lo + hi)
                    lo, hi = (mid, hi) if self.stress(mid) > 0 else (lo, mid)
                return 0.5 * (lo + hi)
        raise ValueError("no separation within the intervals computed")

    def rebound_velocity(self):
        return self.mass_velocity(self.duration)

    def bar_energy(self):
        return 0.5 * self.M * (self.v0 ** 2 - self.rebound_velocity() ** 2)

    def l1_error(self, t, F):
        """A computed contact force F at the times t: its L1 error over the exact contact,
        relative to the exact impulse (trapezoidal rule on the history's times)."""
        import numpy as np
        t, F = np.asarray(t), np.asarray(F)
        exact = np.array([self.force(x) for x in t])
        m = t <= self.duration
        return np.trapz(np.abs(F - exact)[m], t[m]) / np.trapz(exact[m], t[m])

    def window_errors(self, t, F, clearance):
        """The mean force's error over windows of T/10 that keep `clearance` [s] away from the
        exact force's jumps (0, T, 2T, ... and the separation), in units of Z v0, up to the
        separation or the history's end."""
        import numpy as np
        t, F = np.asarray(t), np.asarray(F)
        exact = np.array([self.force(x) for x in t])
        until = min(self.duration, t[-1])
        jumps = [k * self.T for k in range(int(until / self.T) + 1)] + [self.duration]
        w, out = self.T / 10, []
        for k in range(int(until / w)):
            a, b = k * w, (k + 1) * w
            if any(a - clearance < j < b + clearance for j in jumps):
                continue
            m = (t >= a) & (t <= b)
            out.append((np.trapz(F[m], t[m]) - np.trapz(exact[m], t[m])) / (w * self.Z * self.v0))
        return np.asarray(out)


def main():
    L, A, rho, E, v0 = 1.0, 4e-4, 7800.0, 2e11, 1.0
    for ratio in (0.5, 1.0, 2.0):
        sv = SaintVenant(L, A, rho, E, rho * A * L / ratio, v0)
        print(f"rho A L / M = {ratio}: contact {sv.duration / sv.T:.6f} T = {sv.duration:.6e} s, "
              f"rebound {sv.rebound_velocity():+.6f} m/s, bar energy {sv.bar_energy() / (0.5 * sv.M * v0 ** 2):.6f} "
              f"of the mass's")


if __name__ == "__main__":
    sys.exit(main())
