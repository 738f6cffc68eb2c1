"""Lee §3 and §4.1 by computer algebra (sympy), independent of the study's numerical code:

k_constants:   Lee's general solution (3.3) put into Euler's q equation gives (3.8) with his m0, k1, k2;
mu_c_regimes:  k1 - k2 and k1 + k2 factor, so that below mu_c |k1| > |k2| with k1 < 0 and above it |k2| > |k1|
               with k2 < 0; and a sweep over random bodies, cylinders and drags counts the exceptions;
nu_c:          a - b + c = abc for every body, so nu_c = b/(2(a + c)) < 1/2; a sweep over bodies;
lindstedt:     the Lindstedt-Poincare expansion of Lee's Lyapunov system (4.1) to third order, against his
               printed h1, theta2 (4.6), h2, theta3 (4.7) and h3 (4.8), coefficient by coefficient.
"""

from __future__ import annotations

import numpy as np
import sympy as sp


def k_constants():
    """Residual of (3.8) after putting (3.3) into q' - mu q^2 = -b r p + m + mu (p^2 + r^2): 0 if Lee's m0,
    k1, k2 hold. Returns the number of terms (of e^{2X}, e^{-2X}, 1) that do not cancel."""
    a, b, c, m, mu, a1, a2, X = sp.symbols("a b c m mu alpha1 alpha2 X", real=True)
    p = a1 * sp.sqrt(a) * sp.cosh(X) + a2 * sp.sqrt(a) * sp.sinh(X)
    r = a1 * sp.sqrt(c) * sp.sinh(X) + a2 * sp.sqrt(c) * sp.cosh(X)
    lhs = -b * r * p + m + mu * (p**2 + r**2)
    m0 = m + sp.Rational(1, 2) * mu * (a - c) * (a1**2 - a2**2)
    k1 = mu * (a + c) * a1 * a2 - sp.Rational(1, 2) * b * sp.sqrt(a * c) * (a1**2 + a2**2)
    k2 = sp.Rational(1, 2) * mu * (a + c) * (a1**2 + a2**2) - b * sp.sqrt(a * c) * a1 * a2
    # sqrt(a) sqrt(c) = sqrt(ac) for positive a, c; the half-angle X of (3.3) against the double angle 2X of
    # (3.8)
    diff = (lhs - m0 - k1 * sp.sinh(2 * X) - k2 * sp.cosh(2 * X)).rewrite(sp.exp)
    diff = sp.expand(diff.subs({a: sp.Symbol("a", positive=True), c: sp.Symbol("c", positive=True)}))
    E = sp.Symbol("E", positive=True)
    poly = sp.Poly(sp.expand(diff.subs(sp.exp(X), E) * E**2), E)
    return sum(sp.simplify(coeff) != 0 for coeff in poly.all_coeffs())


def mu_c_regimes(rng, samples=2000):
    """The factorisations of k1 -+ k2 for mu = -|mu| (Lee's drag) and a sweep: random bodies (A > B > C, A < B
    + C), cylinders (alpha1, alpha2) and |mu| in (0, 2 mu_c), avoiding 1e-9 about mu_c; the exceptions to
    Lee's rule (|mu| < mu_c: |k1| > |k2|, k1 < 0; |mu| > mu_c: |k2| > |k1|, k2 < 0) are counted. k1, k2 come
    from sympy's expansion of (3.3) in Euler's equations (the coefficients of sinh 2X, cosh 2X), not from the
    study's code."""
    a, b, c = sp.symbols("a b c", positive=True)
    a1, a2, s = sp.symbols("alpha1 alpha2 s", real=True)  # s = |mu|, mu = -s
    mu = -s
    k1 = mu * (a + c) * a1 * a2 - sp.Rational(1, 2) * b * sp.sqrt(a * c) * (a1**2 + a2**2)
    k2 = sp.Rational(1, 2) * mu * (a + c) * (a1**2 + a2**2) - b * sp.sqrt(a * c) * a1 * a2
    mu_c = b * sp.sqrt(a * c) / (a + c)
    minus = sp.simplify(k1 - k2 - sp.Rational(1, 2) * (a1 - a2) ** 2 * (a + c) * (s - mu_c))
    plus = sp.simplify(k1 + k2 + sp.Rational(1, 2) * (a1 + a2) ** 2 * (a + c) * (s + mu_c))
    factor_mismatch = int(minus != 0) + int(plus != 0)
    f = sp.lambdify((a, b, c, a1, a2, s), (k1, k2, mu_c), "numpy")
    C = rng.uniform(0.05, 1.0, samples)
    B = C + rng.uniform(0.0, 1.0, samples) * (1.0 - C)
    A = B + rng.uniform(0.0, 1.0, samples) * (np.minimum(B + C, 1.0 + B) - B)
    ok = (A > B) & (B > C) & (A < B + C)
    A, B, C = A[ok], B[ok], C[ok]
    ai, bi, ci = (B - C) / A, (A - C) / B, (A - B) / C
    al1, al2 = rng.normal(size=(2, A.size))
    muc = bi * np.sqrt(ai * ci) / (ai + ci)
    size = rng.uniform(0.0, 2.0, A.size) * muc
    keep = (np.abs(size / muc - 1.0) > 1e-9) & (np.abs(np.abs(al1) - np.abs(al2)) > 1e-9)
    k1v, k2v, _ = f(ai[keep], bi[keep], ci[keep], al1[keep], al2[keep], size[keep])
    below = size[keep] < muc[keep]
    good = np.where(below, (np.abs(k1v) > np.abs(k2v)) & (k1v < 0), (np.abs(k2v) > np.abs(k1v)) & (k2v < 0))
    return factor_mismatch, int(np.sum(~good)), int(keep.sum()), int(below.sum())


def nu_c(rng, samples=100000):
    """a - b + c - abc simplified (0 for every body), the exact nu_c of the study's body, and the largest nu_c
    over random bodies A > B > C with A < B + C."""
    A, B, C = sp.symbols("A B C", positive=True)
    a, b, c = (B - C) / A, (A - C) / B, (A - B) / C
    identity = sp.simplify(a - b + c - a * b * c)
    exact = sp.nsimplify(b / (2 * (a + c))).subs({A: 3, B: sp.Rational(11, 5), C: sp.Rational(6, 5)})
    x = rng.uniform(0.0, 1.0, (3, samples))
    Cn = x[0]
    Bn = Cn + x[1] * (1.0 - Cn)
    An = Bn + x[2] * (np.minimum(Bn + Cn, 2.0) - Bn)
    ok = (An > Bn) & (Bn > Cn) & (An < Bn + Cn) & (Cn > 0)
    An, Bn, Cn = An[ok], Bn[ok], Cn[ok]
    an, bn, cn = (Bn - Cn) / An, (An - Cn) / Bn, (An - Bn) / Cn
    largest = float(np.max(bn / (2 * (an + cn))))
    return int(identity != 0), sp.nsimplify(exact), largest, int(ok.sum())


def lindstedt():
    """Lindstedt-Poincare for (4.4): theta = eta cos s + eta^2 theta2 + eta^3 theta3, H = h1 eta + h2 eta^2 +
    h3 eta^3, theta_ss + theta = -((1 + H)^2 - 1) theta + (1 + H)^2/k^2 (beta2/2 theta^2 + beta3/6 theta^3 +
    beta4/24 theta^4) + mu1 theta_s^2, each theta_i 2 pi-periodic with theta_i(0) = theta_i'(0) = 0, the cos s
    term removed at each order. Functions of s as Laurent polynomials in z = e^{is}. Returns Lee's printed
    coefficients that differ (out of 10: h1; the three of theta2; h2; c0..c3; h3), and the coefficients
    found."""
    k2, b2, b3, b4, m1, eta = sp.symbols("k2 beta2 beta3 beta4 mu1 eta")  # k2 = k^2
    h = sp.symbols("h1 h2 h3")
    z = sp.Symbol("z")

    def cos_(n):
        return (z**n + z**-n) / 2

    def d_ds(expr):  # d/ds of a Laurent polynomial in z = e^{is}: z d/dz times i
        return sp.expand(sp.I * z * sp.diff(expr, z))

    def fourier(expr):  # cosine coefficients {n: a_n} of an even Laurent polynomial
        c = {}
        for term in sp.Add.make_args(sp.expand(expr)):
            v, n = term.as_coeff_exponent(z)
            c[int(n)] = c.get(int(n), 0) + v
        out = {n: sp.cancel(c.get(n, 0) + (c.get(-n, 0) if n else 0)) for n in range(max(c) + 1)}
        return {n: v for n, v in out.items() if v != 0}

    def mul(x, y, top=4):  # truncated products of series in eta: lists of coefficients
        return [sp.expand(sum(x[i] * y[n - i] for i in range(n + 1))) for n in range(top + 1)]

    theta = [0, cos_(1), 0, 0, 0]  # coefficients of eta^0 .. eta^4
    one_h = [1, h[0], h[1], h[2], 0]  # 1 + H
    found = {}
    for order in (2, 3, 4):
        sq = mul(one_h, one_h)
        th2 = mul(theta, theta)
        th3 = mul(th2, theta)
        th4 = mul(th3, theta)
        ths = [d_ds(t) for t in theta]
        nonlin = [b2 / 2 * th2[n] + b3 / 6 * th3[n] + b4 / 24 * th4[n] for n in range(5)]
        sq_minus = [0] + sq[1:]
        rhs = [
            -a_ + b_ / k2 + c_
            for a_, b_, c_ in zip(mul(sq_minus, theta), mul(sq, nonlin), mul([m1, 0, 0, 0, 0], mul(ths, ths)))
        ]
        a = fourier(rhs[order])
        hk = h[order - 2]
        sol = sp.solve(a.get(1, 0), hk)
        hv = sp.cancel(sol[0]) if sol else sp.Integer(0)
        found[f"h{order - 1}"] = hv
        one_h = [sp.sympify(x).subs(hk, hv) for x in one_h]
        theta = [sp.expand(sp.sympify(t).subs(hk, hv)) for t in theta]
        if order == 4:
            break
        a = {n: sp.cancel(v.subs(hk, hv)) for n, v in a.items()}
        part = sum((v if n == 0 else v / (1 - n**2) * cos_(n)) for n, v in a.items() if n != 1)
        A1 = -sum(v if n == 0 else v / (1 - n**2) for n, v in a.items() if n != 1)
        theta[order] = sp.expand(part + A1 * cos_(1))
        coeffs = fourier(theta[order])
        for n in range(order + 1):
            found[f"theta{order}_{n}"] = sp.cancel(coeffs.get(n, 0))
    lee = {
        "h1": 0,
        "theta2_0": b2 / (4 * k2) + m1 / 2,
        "theta2_1": -(b2 / (6 * k2) + 2 * m1 / 3),
        "theta2_2": -(b2 / (12 * k2) - m1 / 6),
        "h2": (5 * b2**2 + 10 * b2 * k2 * m1 + 3 * b3 * k2 + 8 * k2**2 * m1**2) / (48 * k2**2),
        "theta3_0": -(b2**2) / (12 * k2**2) - b2 * m1 / (2 * k2) - sp.Rational(2, 3) * m1**2,
        "theta3_1": sp.Rational(29, 576) * b2**2 / k2**2
        + sp.Rational(137, 288) * b2 * m1 / k2
        + b3 / (192 * k2)
        + sp.Rational(61, 72) * m1**2,
        "theta3_2": b2**2 / (36 * k2**2) + b2 * m1 / (18 * k2) - sp.Rational(2, 9) * m1**2,
        "theta3_3": b2**2 / (192 * k2**2) - b2 * m1 / (32 * k2) - b3 / (192 * k2) + m1**2 / 24,
    }
    lee["h3"] = -(b2 + 4 * k2 * m1) / (3 * k2) * lee["h2"]
    differ = [name for name, value in lee.items() if sp.simplify(found.get(name, 0) - value) != 0]
    return differ, len(lee), found
