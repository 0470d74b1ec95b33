"""Inflation of a thick-walled hollow sphere of compressible neo-Hookean material (inner radius
A, outer B), in Python, for docs/verification/thick-sphere.md and cli.thick_sphere.

The material is choc's (docs/theory/finite-strain.md): W = mu/2 (I1 - 3) - mu ln J +
lambda/2 (ln J)^2. A spherically symmetric motion R -> r(R) has the principal stretches
l_r = r'(R) (radial) and l_t = r / R (twice, hoop), J = l_r l_t^2, and the principal nominal
(first Piola-Kirchhoff) stresses
    P_r = dW/dl_r = mu (l_r - 1/l_r) + lambda ln J / l_r,
    P_t = (1/2) dW/dl_t = mu (l_t - 1/l_t) + lambda ln J / l_t.
Equilibrium in the reference sphere: dP_r/dR + 2 (P_r - P_t) / R = 0, which gives l_r' from
dP_r/dR = dP_r/dl_r l_r' + dP_r/dl_t (l_r - l_t) / R. The boundary conditions of a dead
pressure p0 on the inner reference surface (choc's 'Pressures' on a finite-strain block: a
nominal traction) and a free outer surface: P_r(A) = -p0, P_r(B) = 0.

Solved by shooting: for a trial inner radius a, l_t(A) = a / A and l_r(A) from P_r(A) = -p0 (a
scalar Newton solve: P_r grows monotonically with l_r), r and l_r integrated from A to B by the
classical Runge-Kutta rule on `steps` intervals (fourth order: 400 steps give 1e-11 here), and a
bracketed secant (Illinois) on a until P_r(B) = 0 to `tol` of mu.

The true (Cauchy) pressure on the deformed inner surface is p = p0 (A / a)^2. For an
incompressible material (lambda -> infinity) the classical closed form (e.g. Ogden, Non-linear
Elastic Deformations, 1984, section 5.3) is
    p / mu = f(l_b) - f(l_a), f(l) = 2 / l + 1 / (2 l^4),  l_b^3 = 1 + (l_a^3 - 1) (A / B)^3,
against which closed_form_check() tests this solver at nu -> 1/2.
"""
import math


def lame(E, nu):
    """(mu, lambda) of Young's modulus and Poisson's ratio."""
    return E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))


def _stresses(lr, lt, mu, lam):
    lnJ = math.log(lr * lt * lt)
    pr = mu * (lr - 1 / lr) + lam * lnJ / lr
    pt = mu * (lt - 1 / lt) + lam * lnJ / lt
    return pr, pt


def _radial_stretch(p_target, lt, mu, lam):
    """l_r with P_r(l_r, l_t) = p_target (Newton from the isochoric l_r = 1 / l_t^2, where P_r
    grows with l_r; kept positive)."""
    lr = 1.0 / lt ** 2
    for _ in range(100):
        pr, _ = _stresses(lr, lt, mu, lam)
        dpr = mu + mu / lr ** 2 + lam * (1 - math.log(lr * lt * lt)) / lr ** 2
        step = (pr - p_target) / dpr
        lr = max(lr - step, 0.5 * lr)
        if abs(step) < 1e-14 * lr:
            return lr
    raise RuntimeError(f"thick_sphere: no radial stretch for P_r = {p_target}, l_t = {lt}")


def _rhs(R, r, lr, mu, lam):
    lt = r / R
    pr, pt = _stresses(lr, lt, mu, lam)
    dpr_dlr = mu + mu / lr ** 2 + lam * (1 - math.log(lr * lt * lt)) / lr ** 2
    dpr_dlt = 2 * lam / (lr * lt)
    dlr = (-2 * (pr - pt) / R - dpr_dlt * (lr - lt) / R) / dpr_dlr
    return lr, dlr


def outer_stress(a, p0, A, B, mu, lam, steps=400):
    """P_r(B) and r(B) of the motion with inner radius a under the dead inner pressure p0."""
    r, lr = a, _radial_stretch(-p0, a / A, mu, lam)
    h = (B - A) / steps
    R = A
    for _ in range(steps):
        k1 = _rhs(R, r, lr, mu, lam)
        k2 = _rhs(R + h / 2, r + h / 2 * k1[0], lr + h / 2 * k1[1], mu, lam)
        k3 = _rhs(R + h / 2, r + h / 2 * k2[0], lr + h / 2 * k2[1], mu, lam)
        k4 = _rhs(R + h, r + h * k3[0], lr + h * k3[1], mu, lam)
        r += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        lr += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        R += h
    return _stresses(lr, r / B, mu, lam)[0], r


def inflation(p0, A, B, mu, lam, tol=1e-13, steps=400):
    """(a, b): the inner and outer deformed radii under the dead inner pressure p0 >= 0."""
    if p0 == 0:
        return A, B
    lo, hi = A, A * (1 + 1e-3)
    f_lo = outer_stress(lo, p0, A, B, mu, lam, steps)[0]
    f_hi = outer_stress(hi, p0, A, B, mu, lam, steps)[0]
    while (f_hi < 0) == (f_lo < 0):
        lo, f_lo = hi, f_hi
        hi *= 1.02
        f_hi = outer_stress(hi, p0, A, B, mu, lam, steps)[0]
    side = 0
    for _ in range(200):
        a = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        f = outer_stress(a, p0, A, B, mu, lam, steps)[0]
        if abs(f) < tol * mu or hi - lo < 1e-15 * A:
            return a, outer_stress(a, p0, A, B, mu, lam, steps)[1]
        if (f < 0) == (f_lo < 0):
            lo, f_lo = a, f
            if side == -1:
                f_hi /= 2
            side = -1
        else:
            hi, f_hi = a, f
            if side == 1:
                f_lo /= 2
            side = 1
    raise RuntimeError(f"thick_sphere: shooting did not converge for p0 = {p0}")


def follower_inflation(p, A, B, mu, lam, tol=1e-12, steps=400):
    """(a, b) under the true (follower) inner pressure p, on the rising branch of the true
    pressure (below its maximum, 832.6 kPa at a = 1.83 A for choc's scene): the dead pressure p0
    with p0 (A / a(p0))^2 = p, by bisection from [p, 4 p] (p0 >= p since a >= A)."""
    if p == 0:
        return A, B
    true = lambda p0: p0 * (A / inflation(p0, A, B, mu, lam, steps=steps)[0]) ** 2  # noqa: E731
    lo, hi = p, 4 * p
    if not true(hi) > p:
        raise ValueError(f"thick_sphere: no inflation under the true pressure {p} below p0 = {hi}")
    while hi - lo > tol * hi:
        mid = 0.5 * (lo + hi)
        if true(mid) < p:
            lo = mid
        else:
            hi = mid
    return inflation(0.5 * (lo + hi), A, B, mu, lam, steps=steps)


def incompressible_pressure(la, A, B, mu):
    """The closed form's true pressure p at the inner hoop stretch la (lambda -> infinity)."""
    lb = (1 + (la ** 3 - 1) * (A / B) ** 3) ** (1 / 3)
    f = lambda l: 2 / l + 1 / (2 * l ** 4)  # noqa: E731
    return mu * (f(lb) - f(la))


def closed_form_check(A=0.05, B=0.1, E=3e6, nu=0.4999, p0=2.5e6):
    """(d, mu / lambda): the relative difference d of this solver's true pressure from the
    incompressible closed form at the same inner stretch, and the compressibility mu / lambda
    that bounds it (d tends to 0 with mu / lambda: 0.14 mu / lambda at nu = 0.45 ... 0.49999)."""
    mu, lam = lame(E, nu)
    a, _ = inflation(p0, A, B, mu, lam, steps=800)
    p = p0 * (A / a) ** 2
    return abs(p - incompressible_pressure(a / A, A, B, mu)) / p, mu / lam


if __name__ == "__main__":
    d, bound = closed_form_check()
    print(f"closed form (nu -> 1/2) against the shooting solver: {d:.2e} (mu / lambda = {bound:.2e})")
    mu, lam = lame(3e6, 0.45)
    for p0 in (0.5e6, 1e6, 2e6, 3e6):
        a, b = inflation(p0, 0.05, 0.1, mu, lam)
        print(f"p0 = {p0:.3g}: a / A = {a / 0.05:.6f}, b / B = {b / 0.1:.6f}, p = {p0 * (0.05 / a) ** 2:.6g}")
