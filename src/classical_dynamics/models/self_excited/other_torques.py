"""Lee §2.6: other torques along the largest axis that reduce to the same planes."""

from __future__ import annotations

from ...solvers.runge_kutta import rhs_function


@rhs_function
def euler_largest_yz(t, w, p, out):
    """Lee §2.6: the torque along x is M + mu0 (q^2 + r^2): p' = a q r + m + mu (q^2 + r^2); p = (a, b, c, m,
    mu). q and r obey (2.5) as before, and p the conservative plane (2.8) (mu1 = 0) with the same m1."""
    out[0] = p[0] * w[1] * w[2] + p[3] + p[4] * (w[1] * w[1] + w[2] * w[2])
    out[1] = -p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1]


@rhs_function
def euler_grammel(t, w, p, out):
    """Lee §2.6, Grammel's torque M - mu0 p^2 along x: p' = a q r + m - mu p^2; p = (a, b, c, m, mu), mu > 0.
    It reduces to the plane (2.25) with sigma1 = 0, mu1 = -mu/(2 sqrt(bc)), m1 = 2m/(delta^2 a sqrt(bc))."""
    out[0] = p[0] * w[1] * w[2] + p[3] - p[4] * w[0] * w[0]
    out[1] = -p[1] * w[2] * w[0]
    out[2] = p[2] * w[0] * w[1]
