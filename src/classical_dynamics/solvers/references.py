"""Exact reference solutions for the work-precision harness and the hard cases.

free rigid body        Jacobi elliptic functions, robust near the separatrix (m -> 1)
HNW rigid body         Hairer-Norsett-Wanner I p. 244, I = (0.5, 2, 3), y0 = (1, 0, 0.9)
DETEST B5              (sn, cn, dn)(t | 0.51)
Bodewadt               axisymmetric body, constant body-fixed torque: Fresnel integrals
Riccati (Lee 2.4)      p' = m + mu p^2: tan / tanh / coth forms and the blow-up time
"""

from __future__ import annotations

import numpy as np
from scipy import special


def _ellipj_agm(w, m):
    """sn, cn, dn, am for 0 <= w <= K by the arithmetic-geometric mean (A&S 16.4), any 0 <= m < 1."""
    a, b, c = [1.0], np.sqrt(1.0 - m), [np.sqrt(m)]
    twon = 1.0
    while abs(c[-1] / a[-1]) > np.finfo(float).eps and len(a) < 40:
        ai = a[-1]
        c.append(0.5 * (ai - b))
        a.append(0.5 * (ai + b))
        b = np.sqrt(ai * b)
        twon *= 2.0
    phi = twon * a[-1] * w
    for i in range(len(a) - 1, 0, -1):
        phi = 0.5 * (np.arcsin(np.clip(c[i] * np.sin(phi) / a[i], -1.0, 1.0)) + phi)
    sn, cn = np.sin(phi), np.cos(phi)
    # dn^2 = 1 - m sn^2 = (1 - m) + m cn^2: no cancellation as sn -> 1 and m -> 1 (1 - m is exact)
    dn = np.sqrt((1.0 - m) + m * cn * cn)
    return sn, cn, dn, phi


def ellipj(u, m):
    """Jacobi sn, cn, dn, am, correct for every 0 <= m < 1, the separatrix side included.

    scipy.special.ellipj switches to A&S 16.15 for 1 - m < 1e-9, whose error grows like e^{2u}
    (scipy #8480: 3e11 at m = 1 - 1e-10 over a period). Here u is reduced to [0, K] by the
    quarter-period symmetries (sn(u + 2K) = -sn u, cn(u + 2K) = -cn u, dn(u + 2K) = dn u;
    sn(2K - u) = sn u, cn(2K - u) = -cn u) and the AGM is used for every m.
    """
    u = np.asarray(u, dtype=float)
    if not 0.0 <= m < 1.0:
        raise ValueError(f"parameter m must be in [0, 1), got {m}")
    K = special.ellipk(m)
    sign_u = np.where(u < 0, -1.0, 1.0)
    v = np.abs(u)
    half_periods = np.floor(v / (2 * K))
    v = v - 2 * K * half_periods  # v in [0, 2K)
    flip = np.where(np.mod(half_periods, 2) == 1, -1.0, 1.0)
    mirror = v > K
    w = np.where(mirror, 2 * K - v, v)  # w in [0, K]
    sn, cn, dn, ph = _ellipj_agm(w, m)
    cn = np.where(mirror, -cn, cn)
    return sign_u * flip * sn, flip * cn, dn, ph


def free_rigid_body(I, m0, t):
    """Body angular velocity omega(t) of a free body with I1 < I2 < I3 and omega(0) = m0 / I."""
    I = np.asarray(I, float)
    if not (I[0] < I[1] < I[2]):
        raise ValueError("order the axes so that I1 < I2 < I3")
    w0 = np.asarray(m0, float) / I
    if _about_largest_axis(I, w0):
        return _free_body_branch(I, w0, t)
    # about the axis of least moment: swap axes 1 and 3 and flip the middle (Euler's form is kept)
    perm = np.array([2, 1, 0])
    w = _free_body_branch(I[perm], w0[perm] * np.array([1.0, -1.0, 1.0]), t)
    return (w * np.array([1.0, -1.0, 1.0]))[..., perm]


def free_rigid_body_period(I, m0) -> float:
    """Period of omega(t) (4K / rate) of the free body of free_rigid_body."""
    rate, m = free_rigid_body_rate_and_parameter(I, m0)
    return 4.0 * special.ellipk(m) / rate


def free_rigid_body_rate_and_parameter(I, m0):
    """(rate lambda, parameter m = k^2) of the elliptic functions of free_rigid_body."""
    I = np.asarray(I, float)
    w0 = np.asarray(m0, float) / I
    if not _about_largest_axis(I, w0):
        I, w0 = I[::-1], w0[::-1]
    return _rate_and_parameter(I, w0)


def _about_largest_axis(I, w0) -> bool:
    return float(np.sum(I * w0 * w0 * (I - I[1]))) >= 0.0  # M^2 - 2E I2, summed term by term


def _differences(I, w0):
    """E2 I3 - M2 and M2 - E2 I1 (E2 = 2E, M2 = |L|^2) summed term by term: for a small wobble about
    the largest axis the first is ~(wobble)^2 times M2, which M2 - E2 I3 computed whole would lose."""
    d31 = float(np.sum(I * w0 * w0 * (I[2] - I)))
    d13 = float(np.sum(I * w0 * w0 * (I - I[0])))
    return d31, d13


def _rate_and_parameter(I, w0):
    I1, I2, I3 = I
    d31, d13 = _differences(I, w0)
    rate = np.sqrt(max((I3 - I2) * d13 / (I1 * I2 * I3), 0.0))
    return rate, (I2 - I1) * d31 / ((I3 - I2) * d13)


def _free_body_branch(I, w0, t):
    I1, I2, I3 = I
    s3 = 1.0 if w0[2] >= 0 else -1.0  # (w1, w2, w3) -> (-w1, w2, -w3) is a symmetry
    w0 = w0 * np.array([s3, 1.0, s3])
    d31, d13 = _differences(I, w0)
    # in the swapped branch numerators and denominators are both negative: the ratios stay positive
    a1 = np.sqrt(max(d31 / (I1 * (I3 - I1)), 0.0))
    a2 = np.sqrt(max(d31 / (I2 * (I3 - I2)), 0.0))
    a3 = np.sqrt(max(d13 / (I3 * (I3 - I1)), 0.0))
    rate, m = _rate_and_parameter(I, w0)
    phi0 = np.arctan2(w0[1] / a2 if a2 > 0 else 0.0, w0[0] / a1 if a1 > 0 else 1.0)
    u0 = (
        special.ellipkinc(phi0, m)
        if abs(phi0) <= np.pi / 2
        else (np.sign(phi0) * 2 * special.ellipk(m) - special.ellipkinc(np.sign(phi0) * np.pi - phi0, m))
    )
    direction = 1.0 if I3 > I1 else -1.0  # the swapped branch runs Landau's form backwards
    sn, cn, dn, _ = ellipj(direction * rate * np.asarray(t, float) + u0, m)
    w = np.stack([a1 * cn, a2 * sn, a3 * dn], axis=-1)
    return w * np.array([s3, 1.0, s3])


HNW_I = np.array([0.5, 2.0, 3.0])
HNW_Y0 = np.array([1.0, 0.0, 0.9])


def hnw_rigid_body(t):
    """y = omega(t) for HNW's rigid body: (cn, a sn, b dn)(lambda t | 25/81), a = sqrt(0.625), b = 0.9."""
    a, b = np.sqrt(0.625), 0.9
    sn, cn, dn, _ = ellipj(2 * a * b * np.asarray(t, float), 25 / 81)
    return np.stack([cn, a * sn, b * dn], axis=-1)


HNW_PERIOD = 4 * special.ellipk(25 / 81) / (2 * np.sqrt(0.625) * 0.9)


def detest_b5(t):
    """DETEST B5: y1' = y2 y3, y2' = -y1 y3, y3' = -0.51 y1 y2, y0 = (0, 1, 1): (sn, cn, dn)(t | 0.51)."""
    sn, cn, dn, _ = ellipj(np.asarray(t, float), 0.51)
    return np.stack([sn, cn, dn], axis=-1)


def bodewadt(I, I3, torque, omega0, t):
    """Axisymmetric body (I1 = I2 = I), constant body-fixed torque: omega(t) in closed form.

    omega3 = omega30 + (M3/I3) t; Omega = omega1 + i omega2 obeys Omega' = i lambda(t) Omega + mu,
    lambda = k omega3, k = (I3 - I)/I, mu = (M1 + i M2)/I, so
    Omega = e^{i Phi} [Omega0 + mu int_0^t e^{-i Phi(s)} ds], Phi = lambda0 t + lambda1 t^2 / 2,
    and completing the square turns the integral into Fresnel integrals.
    """
    t = np.asarray(t, float)
    M1, M2, M3 = torque
    k = (I3 - I) / I
    lam0, lam1 = k * omega0[2], k * M3 / I3
    mu = (M1 + 1j * M2) / I
    Omega0 = omega0[0] + 1j * omega0[1]
    phi = lam0 * t + 0.5 * lam1 * t * t
    if lam1 == 0.0:
        integral = t if lam0 == 0.0 else (1 - np.exp(-1j * lam0 * t)) / (1j * lam0)
    else:
        sign = 1.0 if lam1 > 0 else -1.0  # for lam1 < 0 take the complex conjugate problem
        a = abs(lam1)
        shift = lam0 / lam1
        scale = np.sqrt(a / np.pi)
        S1, C1 = special.fresnel((t + shift) * scale)
        S0, C0 = special.fresnel(shift * scale)
        core = np.sqrt(np.pi / a) * ((C1 - C0) - 1j * sign * (S1 - S0))
        integral = np.exp(1j * sign * a * shift * shift / 2) * core
    Omega = np.exp(1j * phi) * (Omega0 + mu * integral)
    return np.stack([Omega.real, Omega.imag, omega0[2] + M3 / I3 * t], axis=-1)


def riccati(m, mu, p0, t):
    """p(t) for p' = m + mu p^2 (Lee 1964, eq. 2.4, all cases); NaN past a blow-up."""
    t = np.asarray(t, float)
    if mu == 0:
        return m * t + p0
    if m == 0:
        return np.zeros_like(t) if p0 == 0 else 1.0 / (1.0 / p0 - mu * t)
    k, w = np.sqrt(abs(m / mu)), np.sqrt(abs(m * mu))
    if m > 0 and mu > 0:
        return k * np.tan(w * t + np.arctan(p0 / k))
    if m < 0 and mu < 0:
        return k * np.tan(np.arctan(p0 / k) - w * t)
    s = 1.0 if m > 0 else -1.0  # m mu < 0: tanh or coth about the equilibria +-k
    if abs(p0) < k:
        return s * k * np.tanh(w * t + s * np.arctanh(p0 / k))
    if abs(p0) == k:
        return np.full_like(t, p0)
    return s * k / np.tanh(w * t + s * np.arctanh(k / p0))


def riccati_blow_up_time(m, mu, p0):
    """The time at which p' = m + mu p^2 leaves every bound, or inf if it never does."""
    if mu == 0:
        return np.inf
    if m == 0:
        return 1.0 / (mu * p0) if mu * p0 > 0 else np.inf
    k, w = np.sqrt(abs(m / mu)), np.sqrt(abs(m * mu))
    if m > 0 and mu > 0:
        return (np.pi / 2 - np.arctan(p0 / k)) / w
    if m < 0 and mu < 0:
        return (np.arctan(p0 / k) + np.pi / 2) / w
    if abs(p0) <= k:
        return np.inf
    s = 1.0 if m > 0 else -1.0
    # coth(w t + s artanh(k/p0)) hits its pole where the argument is 0
    t_star = -s * np.arctanh(k / p0) / w
    return t_star if t_star > 0 else np.inf
