"""Lamb's free rigid body (Arts. 48-55, Examples X, Ex. XIII.11) and the lecture notes' free precession.

Each statement is checked twice: a sympy derivation of the closed form (for every value of its symbols), and
an integration of Euler's equations with the attitude (scipy's DOP853 on omega and the rotation matrix, not
the study's own integrators) measured against that closed form.

free_body(results, spec)           a strongly triaxial body (the scene's moments A < B < C), a rectangular
                                   plate and a forced spin (scene: triaxial, analysis.lamb_free_body)
symmetric_earth(model, amplitude)  the rigid symmetric Earth: the space frequency, the Eulerian nutation, the
                                   sense of the body frequency, the oblateness (scene: rigid_modern,
                                   analysis.lamb_symmetric)
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import sympy as sp
from scipy.special import ellipk

from ...models import earth, rigid_body
from ...solvers.ode import Events, Problem, solve

RTOL = 1e-12
INDEPENDENT = "scipy:DOP853"  # not the study's own compiled integrators


# --- an independent integrator: Euler's equations and the rotation matrix (body -> space) -------------------
def integrate(I, omega0, span, samples=2001, rtol=RTOL):
    """omega (body, (n, 3)) and R (body -> space, (n, 3, 3)) at `samples` times over [0, span]."""
    t = np.linspace(0.0, span, samples)
    y0 = np.concatenate([omega0, np.eye(3).ravel()])
    sol = solve(
        Problem(rigid_body.free_attitude_matrix, y0, (0.0, span), np.asarray(I, float)),
        INDEPENDENT,
        rtol=rtol,
        atol=rtol * 1e-6 * np.linalg.norm(omega0),
        t_eval=t,
    )
    return t, sol.y_eval[:, :3], sol.y_eval[:, 3:].reshape(-1, 3, 3)


def polhode_period(I, omega0):
    """4K(k)/lambda (Landau & Lifshitz, Mechanics, §37), for I1 < I2 < I3, either side of the separatrix."""
    I1, I2, I3 = I
    L2 = float(np.sum((I * omega0) ** 2))
    E2 = float(np.sum(I * omega0**2))  # 2T
    if L2 > E2 * I2:  # about the greatest axis
        k2 = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1))
        lam = np.sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3))
    else:  # about the least axis: I1 and I3 exchanged
        k2 = (I3 - I2) * (L2 - E2 * I1) / ((I2 - I1) * (E2 * I3 - L2))
        lam = np.sqrt((I2 - I1) * (E2 * I3 - L2) / (I1 * I2 * I3))
    return 4.0 * float(ellipk(k2)) / lam, k2


# --- sympy: the closed forms, for every value of their symbols ----------------------------------------------
A_, B_, C_ = sp.symbols("A B C", positive=True)
p_, q_, r_ = sp.symbols("p q r", real=True)


def symbolic_residuals() -> dict:
    """name -> 0 when sympy reduces the statement to an identity (else the number of the residual's terms)."""
    out = {}
    H2 = A_**2 * p_**2 + B_**2 * q_**2 + C_**2 * r_**2
    T2 = A_ * p_**2 + B_ * q_**2 + C_ * r_**2  # 2T
    # Art. 52 (10): A^2p^2 + C^2r^2 < B(Ap^2 + Cr^2) is k^2 < 1, k^2 = (A - B)(H^2 - 2CT)/((B - C)(2AT -
    # H^2)): for Lamb's order A > B > C the denominator is positive, so k^2 < 1 is (B - C)(2AT - H^2) - (A -
    # B)(H^2 - 2CT) > 0, and that is (A - C)(2BT - H^2), 2BT - H^2 being (10)'s B(Ap^2 + Cr^2) - A^2p^2 -
    # C^2r^2
    lhs = (B_ - C_) * (A_ * T2 - H2) - (A_ - B_) * (H2 - C_ * T2)
    out["art52_10_is_k2_lt_1"] = sp.expand(
        lhs - (A_ - C_) * (B_ * (A_ * p_**2 + C_ * r_**2) - A_**2 * p_**2 - C_**2 * r_**2)
    )
    # Ex. X.1: the central section of Ax^2 + By^2 + Cz^2 = 1 by the plane with unit normal n has the area
    # pi/sqrt(det of the form on the plane), and that determinant is -det([[Q, n], [n^T, 0]]) = ABC n.Q^-1 n;
    # with n = (Ap, Bq, Cr)/H it is ABC 2T/H^2, so the area is pi H/sqrt(2ABCT)
    n = sp.Matrix([A_ * p_, B_ * q_, C_ * r_]) / sp.sqrt(H2)
    Q = sp.diag(A_, B_, C_)
    border = sp.Matrix(sp.BlockMatrix([[Q, n], [n.T, sp.zeros(1, 1)]]))
    out["ex_x_1_area"] = sp.simplify(-border.det() - A_ * B_ * C_ * T2 / H2)
    # ... and the bordered determinant is the form's determinant on the plane: an explicit orthonormal basis
    # of the plane normal to a unit vector (sin a cos b, sin a sin b, cos a)
    a, b = sp.symbols("a b", real=True)
    u = sp.Matrix([sp.sin(a) * sp.cos(b), sp.sin(a) * sp.sin(b), sp.cos(a)])
    e1 = sp.Matrix([sp.cos(a) * sp.cos(b), sp.cos(a) * sp.sin(b), -sp.sin(a)])
    e2 = sp.Matrix([-sp.sin(b), sp.cos(b), 0])
    P = e1.row_join(e2)
    on_plane = (P.T * Q * P).det()
    bordered = -sp.Matrix(sp.BlockMatrix([[Q, u], [u.T, sp.zeros(1, 1)]])).det()
    out["ex_x_1_restricted_form"] = sp.simplify(sp.expand_trig(on_plane - bordered))
    # Ex. X.4: sum over the axes of (1 - n_i^2)/I_i is 1/A + 1/B + 1/C - 2T/H^2
    total = sum((1 - n[i] ** 2) / (A_, B_, C_)[i] for i in range(3))
    out["ex_x_4_sum"] = sp.simplify(total - (1 / A_ + 1 / B_ + 1 / C_ - T2 / H2))
    # Ex. X.5: x = s n on x^2/A + y^2/B + z^2/C = 1 needs s^2 = H^2/2T (constant); the normal (x/A, y/B, z/C)
    # is s omega/H, along omega; the distance 1/|normal| from the centre to the tangent plane is H/(s|omega|)
    s = sp.sqrt(H2 / T2)
    x = s * n
    out["ex_x_5_on_ellipsoid"] = sp.simplify(x[0] ** 2 / A_ + x[1] ** 2 / B_ + x[2] ** 2 / C_ - 1)
    normal = sp.Matrix([x[0] / A_, x[1] / B_, x[2] / C_])
    out["ex_x_5_normal_along_omega"] = sp.simplify(
        (normal - s / sp.sqrt(H2) * sp.Matrix([p_, q_, r_])).norm()
    )
    # Ex. X.22: the plane of OZ (along H) and the axis A turns about OZ at psi' = H(Bq^2 + Cr^2)/(B^2q^2 +
    # C^2r^2) (the Euler-angle rate about the invariable line, axis A as the polar axis); with cos(alpha) =
    # Ap/H, sin^2(alpha) psi' = 2T/H - (H/A) cos^2(alpha)
    psi_dot = sp.sqrt(H2) * (B_ * q_**2 + C_ * r_**2) / (B_**2 * q_**2 + C_**2 * r_**2)
    cos_alpha = A_ * p_ / sp.sqrt(H2)
    out["ex_x_22_rate"] = sp.simplify(
        (1 - cos_alpha**2) * psi_dot - (T2 / sp.sqrt(H2) - sp.sqrt(H2) / A_ * cos_alpha**2)
    )
    # Ex. X.3: the circular cylinder that envelopes Ax^2 + By^2 + Cz^2 = 1 along d = (sin phi, 0, cos phi):
    # its shadow on the plane normal to d has the form B along y and AC/(A sin^2 + C cos^2) across; circular
    # when that is B. It touches along the diametral plane conjugate to d, d.Qx = 0: A sin(phi) x + C cos(phi)
    # z = 0, so (z/x)^2 = A^2 tan^2(phi)/C^2; the separatrix planes A(A - B)x^2 = C(B - C)z^2 (2BT = H^2) have
    # (z/x)^2 = A(A - B)/(C(B - C))
    phi, t2 = sp.symbols("phi t2", positive=True)
    d = sp.Matrix([sp.sin(phi), 0, sp.cos(phi)])
    e_perp = sp.Matrix([sp.cos(phi), 0, -sp.sin(phi)])
    across = (e_perp.T * Q * e_perp)[0] - (e_perp.T * Q * d)[0] ** 2 / (d.T * Q * d)[0]
    out["ex_x_3_shadow_form"] = sp.simplify(
        across - A_ * C_ / (A_ * sp.sin(phi) ** 2 + C_ * sp.cos(phi) ** 2)
    )
    # circular: A sin^2 + C cos^2 = AC/B, i.e. (divide by cos^2, t2 = tan^2) A t2 + C = AC(1 + t2)/B
    tan2 = sp.solve(sp.Eq(A_ * t2 + C_, A_ * C_ * (1 + t2) / B_), t2)[0]
    out["ex_x_3_contact_plane"] = sp.simplify(A_**2 * tan2 / C_**2 - A_ * (A_ - B_) / (C_ * (B_ - C_)))
    # Lamb's separatrix planes are the polhode cone at 2BT = H^2
    sep = sp.expand(B_ * T2 - H2)
    out["ex_x_3_separatrix"] = sp.expand(sep - (A_ * (B_ - A_) * p_**2 + C_ * (B_ - C_) * r_**2))
    return {k: (0 if v == 0 else len(sp.Add.make_args(v))) for k, v in out.items()}


# --- the analyses -------------------------------------------------------------------------------------------
def free_body(results, spec) -> None:
    I = np.array(spec["moments"], float)
    if not (I[0] < I[1] < I[2]):
        raise ValueError("lamb_free_body.moments: A < B < C")
    for name, residual in symbolic_residuals().items():
        results.number(
            f"sympy_{name}",
            residual,
            "1",
            note="0: sympy reduces the statement to an identity (else the residual's number of terms)",
        )
    _record_polhode_side(results, polhode_side(I, spec["samples"], spec["seed"]))
    _record_stable_axes(results, stable_axes(I, np.radians(spec["tilt_deg"])))
    _record_poinsot(results, poinsot_examples(I))
    _record_separatrix(results, separatrix(I))
    _record_plate(results, plate(*spec["plate_half_sides"]))
    _record_constraining_couples(results, constraining_couples(I, spec["spin_over_turn"]))


class PolhodeSide(NamedTuple):
    moments: np.ndarray
    samples: int  # random directions of omega
    agreements: int  # where (10) and the integration agree
    round_least: int  # predicted round the least axis
    smallest_margin: float  # nearest start to the separatrix


def polhode_side(I, samples, seed) -> PolhodeSide:
    """Art. 52 (10): which axis the polhode surrounds, predicted from the start, against 1000 integrations."""
    A, B, C = I
    rng = np.random.default_rng(seed)
    w = rng.normal(size=(samples, 3))
    w /= np.linalg.norm(w, axis=1)[:, None]
    p, q, r = w.T
    least = A**2 * p**2 + C**2 * r**2 < B * (A * p**2 + C * r**2)  # Lamb (10): round the least axis A
    span = 1.05 * max(polhode_period(I, wi)[0] for wi in w)
    t = np.linspace(0.0, span, 4001)
    sol = solve(
        Problem(rigid_body.euler_free_many, w.T.ravel(), (0.0, span), np.asarray(I, float)),
        INDEPENDENT,
        rtol=1e-11,
        atol=1e-13,
        t_eval=t,
    )
    pp, _, rr = sol.y_eval.T.reshape(3, samples, -1)
    keeps_p = np.all(pp * p[:, None] > 0, axis=1)  # the least axis' component keeps its sign
    keeps_r = np.all(rr * r[:, None] > 0, axis=1)
    agree = (least & keeps_p & ~keeps_r) | (~least & keeps_r & ~keeps_p)
    margin = np.abs(B * (A * p**2 + C * r**2) - A**2 * p**2 - C**2 * r**2)
    return PolhodeSide(I, samples, int(np.sum(agree)), int(np.sum(least)), float(np.min(margin)))


def _record_polhode_side(results, values: PolhodeSide):
    results.number(
        "polhode_side_samples",
        values.samples,
        "1",
        note="random directions of ω, moments " + _moments(values.moments),
    )
    results.number(
        "polhode_side_agreements",
        values.agreements,
        "1",
        note="(10) predicts the axis the polhode surrounds, and the integration agrees (the component "
        "along that axis keeps its sign for 1.05 of the longest period, the other changes sign)",
    )
    results.number("polhode_side_round_least", values.round_least, "1")
    results.number(
        "polhode_side_smallest_margin",
        values.smallest_margin,
        "1",
        note="nearest start to the separatrix: $|B(Ap_0^2 + Cr_0^2) - A^2p_0^2 - C^2r_0^2|$",
    )


def _moments(I):
    return "(" + ", ".join(f"{v:g}" for v in I) + ")"


class StableAxes(NamedTuple):
    tilt: float  # rad
    conic_ratio: (
        dict  # per axis ("greatest", "least"): largest |omega_2| over a period over the conic's value
    )
    largest_angle_deg: dict  # per axis: largest angle of omega from it over a period
    middle_axis_largest_angle_deg: float  # over two periods from `tilt` off the middle axis


def stable_axes(I, tilt) -> StableAxes:
    """The lecture notes' conic near an axis: tilted by `tilt`, the other transverse rate's largest value."""
    conic_ratio, largest_angle = {}, {}
    I1, I2, I3 = I
    d = np.tan(tilt)
    cases = {  # start, measured index, conic's prediction of the largest |omega_j|
        "greatest": ((d, 0.0, 1.0), 1, d * np.sqrt(I1 * (I3 - I1) / (I2 * (I3 - I2)))),
        "least": ((1.0, 0.0, d), 1, d * np.sqrt(I3 * (I3 - I1) / (I2 * (I2 - I1)))),
    }
    for name, (w0, j, predicted) in cases.items():
        w0 = np.array(w0)
        period, _ = polhode_period(I, w0)
        t, w, _ = integrate(I, w0, period, samples=20001)
        axis = 2 if name == "greatest" else 0
        angle = np.degrees(np.arccos(np.abs(w[:, axis]) / np.linalg.norm(w, axis=1)))
        conic_ratio[name] = float(np.max(np.abs(w[:, j]))) / predicted
        largest_angle[name] = float(np.max(angle))
    w0 = np.array([d, 1.0, 0.0])
    t, w, _ = integrate(I, w0, 2.0 * polhode_period(I, w0)[0], samples=20001)
    angle = np.degrees(np.arccos(np.clip(w[:, 1] / np.linalg.norm(w, axis=1), -1, 1)))
    return StableAxes(tilt, conic_ratio, largest_angle, float(np.max(angle)))


def _record_stable_axes(results, values: StableAxes):
    tilt = values.tilt
    for name in values.conic_ratio:
        results.number(
            f"{name}_axis_conic_ratio",
            values.conic_ratio[name],
            "1",
            note=f"largest $|\\omega_2|$ over a period from {np.degrees(tilt):g}° off the {name} axis, "
            "over the conic's value",
        )
        results.number(f"{name}_axis_largest_angle_deg", values.largest_angle_deg[name], "°")
    results.number(
        "middle_axis_largest_angle_deg",
        values.middle_axis_largest_angle_deg,
        "°",
        note=f"{np.degrees(tilt):g}° off the middle axis: ω swings over to the opposite side",
    )


class PoinsotExamples(NamedTuple):
    """Exx. X.1, X.4, X.5, X.22 on one motion: largest deviations from the closed forms (relative unless
    named)."""

    moments: np.ndarray
    modulus_squared: float  # k^2 of the motion
    section_area_max_relative_deviation: float
    poinsot_sum_max_relative_deviation: float
    gyration_point_off_ellipsoid: float
    gyration_normal_angle_rad: float
    gyration_perpendicular_times_omega_drift: float
    gyration_omega_range: float
    plane_rate_max_relative_deviation: float
    plane_rate_range: float
    plane_rate_differences_max_relative_deviation: float
    difference_step: float  # time step of the differenced azimuth


def poinsot_examples(I) -> PoinsotExamples:
    """Exx. X.1, X.4, X.5, X.22 along one integrated motion, measured in space and against the closed
    forms."""
    A, B, C = I
    w0 = np.array([0.8, 0.5, 0.6])
    period, k2 = polhode_period(I, w0)
    t, w, R = integrate(I, w0, 3.0 * period, samples=3001)
    L_space = I * w0  # R(0) = 1
    H = float(np.linalg.norm(L_space))
    T2 = float(np.sum(I * w0**2))
    L_hat = L_space / H
    n = np.einsum("kji,j->ki", R, L_hat)  # the invariable line in the body, from the attitude
    # Ex. X.1: the section's area from the form on the plane (an orthonormal basis of the plane, by SVD)
    Q = np.diag(I)
    areas = []
    for nk in n:
        P = np.linalg.svd(nk[None, :])[2][1:].T
        areas.append(np.pi / np.sqrt(np.linalg.det(P.T @ Q @ P)))
    areas = np.array(areas)
    closed = np.pi * H / np.sqrt(T2 * A * B * C)  # pi H / sqrt(2ABCT), 2T = T2
    section_area = float(np.max(np.abs(areas / closed - 1.0)))
    # Ex. X.4: the ends of the axes (1/sqrt I_i along e_i) from the invariable line
    ends = np.eye(3) / np.sqrt(I)[:, None]
    dist2 = sum(np.linalg.norm(np.cross(ends[i], n), axis=1) ** 2 for i in range(3))
    closed = 1 / A + 1 / B + 1 / C - T2 / H**2
    poinsot_sum = float(np.max(np.abs(dist2 / closed - 1.0)))
    # Ex. X.5: the point s n, s fixed at the start, stays on x^2/A + y^2/B + z^2/C = 1; the normal there is
    # along omega; the distance from the centre to the tangent plane times |omega| is constant
    s = 1.0 / np.sqrt(np.sum(n[0] ** 2 / I))
    x = s * n
    on = np.abs(np.sum(x**2 / I, axis=1) - 1.0)
    normal = x / I
    sinang = np.linalg.norm(np.cross(normal, w), axis=1) / (
        np.linalg.norm(normal, axis=1) * np.linalg.norm(w, axis=1)
    )
    perp = 1.0 / np.linalg.norm(normal, axis=1)
    product = perp * np.linalg.norm(w, axis=1)
    # Ex. X.22: the rate at which the plane of OZ and the axis A turns about OZ, from the attitude (space
    # frame)
    eA = R[:, :, 0]
    w_space = np.einsum("kij,kj->ki", R, w)
    u = eA - np.outer(eA @ L_hat, L_hat)
    u_dot = np.cross(w_space, eA)
    u_dot -= np.outer(u_dot @ L_hat, L_hat)
    measured = np.einsum("ki,ki->k", np.cross(u, u_dot), np.broadcast_to(L_hat, u.shape)) / np.sum(
        u**2, axis=1
    )
    cos_a = eA @ L_hat
    formula = (T2 / H - H / A * cos_a**2) / (1.0 - cos_a**2)
    # ... and the same rate by differences of the plane's azimuth (no kinematics): 2nd-order central
    # differences
    e1 = np.cross(L_hat, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(L_hat, e1)
    azimuth = np.unwrap(np.arctan2(u @ e2, u @ e1))
    fd = np.gradient(azimuth, t, edge_order=2)
    return PoinsotExamples(
        moments=I,
        modulus_squared=k2,
        section_area_max_relative_deviation=section_area,
        poinsot_sum_max_relative_deviation=poinsot_sum,
        gyration_point_off_ellipsoid=float(np.max(on)),
        gyration_normal_angle_rad=float(np.max(np.arcsin(np.minimum(sinang, 1.0)))),
        gyration_perpendicular_times_omega_drift=float(np.max(np.abs(product / product[0] - 1))),
        gyration_omega_range=float(np.ptp(np.linalg.norm(w, axis=1)) / np.linalg.norm(w0)),
        plane_rate_max_relative_deviation=float(np.max(np.abs(measured / formula - 1.0))),
        plane_rate_range=float(np.ptp(measured) / np.mean(measured)),
        plane_rate_differences_max_relative_deviation=float(np.max(np.abs(fd[1:-1] / formula[1:-1] - 1.0))),
        difference_step=t[1] - t[0],
    )


def _record_poinsot(results, values: PoinsotExamples):
    results.number(
        "poinsot_modulus_squared",
        values.modulus_squared,
        "1",
        note="$k^2$ of the motion, moments " + _moments(values.moments),
    )
    results.number(
        "section_area_max_relative_deviation",
        values.section_area_max_relative_deviation,
        "1",
        note="Ex. X.1: the central section by the plane normal to $\\mathbf{H}$, against "
        "$\\pi H/\\sqrt{2ABCT}$, over three polhode periods",
    )
    results.number(
        "poinsot_sum_max_relative_deviation",
        values.poinsot_sum_max_relative_deviation,
        "1",
        note="Ex. X.4: sum of the squared distances against $1/A + 1/B + 1/C - 2T/H^2$",
    )
    results.number(
        "gyration_point_off_ellipsoid",
        values.gyration_point_off_ellipsoid,
        "1",
        note="Ex. X.5: largest $|x^2/A + y^2/B + z^2/C - 1|$ at the fixed point of the invariable line",
    )
    results.number(
        "gyration_normal_angle_rad",
        values.gyration_normal_angle_rad,
        "rad",
        note="largest angle between the normal there and $\\boldsymbol\\omega$",
    )
    results.number(
        "gyration_perpendicular_times_omega_drift",
        values.gyration_perpendicular_times_omega_drift,
        "1",
        note="largest relative change of (perpendicular on the tangent plane) × $|\\boldsymbol\\omega|$",
    )
    results.number(
        "gyration_omega_range",
        values.gyration_omega_range,
        "1",
        note="how much $|\\boldsymbol\\omega|$ itself varies (relative): the test is not empty",
    )
    results.number(
        "plane_rate_max_relative_deviation",
        values.plane_rate_max_relative_deviation,
        "1",
        note="Ex. X.22: $\\dot\\psi$ of the plane $ZOA$ about $OZ$ measured in space against "
        "$(2T/H - (H/A)\\cos^2\\alpha)/\\sin^2\\alpha$ at the measured $\\alpha$",
    )
    results.number(
        "plane_rate_range",
        values.plane_rate_range,
        "1",
        note="how much that rate varies along the motion (relative)",
    )
    results.number(
        "plane_rate_differences_max_relative_deviation",
        values.plane_rate_differences_max_relative_deviation,
        "1",
        note=f"the azimuth differenced (central differences, step {values.difference_step:.3g})",
    )


class Separatrix(NamedTuple):
    largest_offset: float  # rad, of omega from the plane A(B - A)p^2 = C(C - B)r^2
    y_range: float  # how far omega moves within the plane (relative)
    cylinder_contact_vs_separatrix_angle: float  # rad
    cylinder_shadow_radius_times_sqrt_B: float
    cylinder_contact_curve_roundness: float


def separatrix(I) -> Separatrix:
    """Ex. X.3: a start in the separatrix plane (2BT = H^2) stays in it (the cylinders' plane of contact)."""
    A, B, C = I
    p0 = 0.8
    r0 = p0 * np.sqrt(A * (B - A) / (C * (C - B)))
    w0 = np.array([p0, 0.2, r0])
    normal = np.array([np.sqrt(A * (B - A)), 0.0, -np.sqrt(C * (C - B))])
    normal /= np.linalg.norm(normal)
    t, w, _ = integrate(I, w0, 10.0 / np.linalg.norm(w0), samples=2001)
    off = np.abs(w @ normal) / np.linalg.norm(w, axis=1)
    # the plane of contact of the enveloping circular cylinder, numerically: tan^2 phi = C(A - B)/(A(B - C)),
    # the normal (A sin phi, 0, C cos phi) of the diametral plane conjugate to its axis
    phi = np.arctan(np.sqrt(C * (A - B) / (A * (B - C))))
    contact = np.array([A * np.sin(phi), 0.0, C * np.cos(phi)])
    contact /= np.linalg.norm(contact)
    mirror = normal * np.array([1.0, 1.0, -1.0])  # the other separatrix plane
    radius, roundness = _shadow_radius(I, np.array([np.sin(phi), 0.0, np.cos(phi)]))
    return Separatrix(
        largest_offset=float(np.max(off)),
        y_range=float(np.ptp(w[:, 1]) / np.linalg.norm(w0)),
        cylinder_contact_vs_separatrix_angle=float(
            np.arccos(min(1.0, max(abs(contact @ normal), abs(contact @ mirror))))
        ),
        cylinder_shadow_radius_times_sqrt_B=radius * np.sqrt(B),
        cylinder_contact_curve_roundness=roundness,
    )


def _record_separatrix(results, values: Separatrix):
    results.number(
        "separatrix_largest_offset",
        values.largest_offset,
        "rad",
        note="Ex. X.3: largest angle of $\\boldsymbol\\omega$ from the plane $A(B - A)p^2 = C(C - B)r^2$ "
        "over the run, from a start in it",
    )
    results.number(
        "separatrix_y_range",
        values.y_range,
        "1",
        note="how far ω moves within the plane (relative): the test is not empty",
    )
    results.number(
        "cylinder_contact_vs_separatrix_angle",
        values.cylinder_contact_vs_separatrix_angle,
        "rad",
        note="angle between the enveloping cylinder's plane of contact and a separatrix plane",
    )
    results.number(
        "cylinder_shadow_radius_times_sqrt_B",
        values.cylinder_shadow_radius_times_sqrt_B,
        "1",
        note="the enveloping cylinder's radius (largest distance of the ellipsoid from its axis, by "
        "sampling) × $\\sqrt B$: 1 for a circular cylinder through the middle axis' ends",
    )
    results.number(
        "cylinder_contact_curve_roundness",
        values.cylinder_contact_curve_roundness,
        "1",
        note="the spread of those distances over their mean: 0 for a circular cylinder",
    )


def _shadow_radius(I, d, n=2001):
    """Largest and smallest distances from the axis d of the ellipsoid's silhouette (points with normal ⊥ d),
    by sampling the contact curve: (mean distance, spread over mean), the spread 0 for a circular cylinder."""
    # the contact curve: points of the ellipsoid in the plane Q x . d = 0
    Q = np.diag(I)
    m = Q @ d
    m /= np.linalg.norm(m)
    a = np.cross(m, [0.0, 1.0, 0.0]) if abs(m[1]) < 0.9 else np.cross(m, [1.0, 0.0, 0.0])
    a /= np.linalg.norm(a)
    b = np.cross(m, a)
    th = np.linspace(0.0, 2 * np.pi, n)
    dirs = np.outer(np.cos(th), a) + np.outer(np.sin(th), b)
    pts = dirs / np.sqrt(np.einsum("ki,ij,kj->k", dirs, Q, dirs))[:, None]
    dist = np.linalg.norm(pts - np.outer(pts @ d, d), axis=1)
    return float(np.mean(dist)), float(np.ptp(dist) / np.mean(dist))


class Plate(NamedTuple):
    a: float  # half-sides
    b: float
    other_diagonal_time: float  # time units 1/|omega|
    half_period_closed_form: float  # 2K(k)/lambda
    modulus_squared: float
    angle_from_other_diagonal_rad: float


def plate(a, b) -> Plate:
    """Ex. X.15: a plate (edges 2a, 2b) spun about a diagonal spins about the other after half a period."""
    I = np.array([b * b, a * a, a * a + b * b]) / 3.0  # M = 1
    order = np.argsort(I)
    if not np.all(order == [0, 1, 2]):
        raise ValueError("lamb_free_body.plate_half_sides: a > b (moments b²/3 < a²/3 < (a² + b²)/3)")
    w0 = np.array([a, b, 0.0]) / np.hypot(a, b)
    half, k2 = polhode_period(I, w0)
    half /= 2.0

    y0 = np.concatenate([w0, np.eye(3).ravel()])
    sol = solve(
        Problem(rigid_body.free_attitude_matrix, y0, (0.0, 1.5 * half), I),
        INDEPENDENT,
        rtol=1e-13,
        atol=1e-16,
        events=Events(rigid_body.axis_component, 1),
    )
    after = sol.event_t > 1e-9 * half
    times = sol.event_t[after]
    t_star = times[0]
    w_star = sol.event_y[after][0][:3]
    other = np.array([a, -b, 0.0]) / np.hypot(a, b)
    angle = np.arcsin(min(1.0, np.linalg.norm(np.cross(w_star, other)) / np.linalg.norm(w_star)))
    return Plate(a, b, t_star, half, k2, float(angle))


def _record_plate(results, values: Plate):
    a, b, t_star, half = values.a, values.b, values.other_diagonal_time, values.half_period_closed_form
    results.number(
        "plate_other_diagonal_time",
        t_star,
        "time units",
        note=(
            f"Ex. X.15: first time ω is again in the plate, half-sides a = {a:g}, b = {b:g} (time unit "
            "$1/|\\boldsymbol\\omega|$)"
        ),
    )
    results.number(
        "plate_half_period_closed_form", half, "time units", note="$2K(k)/\\lambda$, Landau & Lifshitz §37"
    )
    results.number("plate_time_relative_error", t_star / half - 1.0, "1")
    results.number("plate_modulus_squared", values.modulus_squared, "1")
    results.number(
        "plate_angle_from_other_diagonal_rad",
        values.angle_from_other_diagonal_rad,
        "rad",
        note="then the angle between ω and the other diagonal",
    )


class ConstrainingCouples(NamedTuple):
    """Ex. XIII.11: the couples against Lamb's (relative deviations)."""

    moments: np.ndarray
    spin_over_turn: float  # n/v0
    one_turn_ratio: (
        dict  # {"0": ..., "90": ...}: mean in-plane couple over one turn from chi, over (A + B)v'/2
    )
    in_plane_deviation: float
    perpendicular_deviation: float
    along_axis: float
    in_plane_phase_spread: float


def constraining_couples(I, spin_over_turn, phases=64) -> ConstrainingCouples:
    """Ex. XIII.11: the axis OC turned in one plane at v(t), spin n about OC held: the couple dH/dt.

    Space frame: the plane of the turning is xy, OC = (cos phi, sin phi, 0), phi' = v = v0 (1 + sin(w t)/2).
    Body: R(t) = Rz(phi) R0 R3(chi), R0 taking e3 to x and (e1, e2) to (y, z), chi = n t + chi0. The couple
    dH/dt is taken by the complex step (exact to rounding); the average over the body's phase chi0 (64 phases:
    exact for the couple's harmonics) against (A + B) v'/2 about z and C n v about z x OC.
    """
    A, B, C = I
    v0, w_mod = 1.0, 0.37
    n = spin_over_turn * v0

    def phi(t):
        return v0 * t - 0.5 * v0 / w_mod * np.cos(w_mod * t)

    def v(t):
        return v0 * (1.0 + 0.5 * np.sin(w_mod * t))

    def v_dot(t):
        return 0.5 * v0 * w_mod * np.cos(w_mod * t)

    def rot(axis, angle):
        c, s = np.cos(angle), np.sin(angle)
        if axis == 2:
            return np.array([[c, -s, 0 * c], [s, c, 0 * c], [0 * c, 0 * c, 1 + 0 * c]])
        raise ValueError(axis)

    R0 = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])

    def momentum(t, chi0):
        R = rot(2, phi(t)) @ R0 @ rot(2, n * t + chi0)
        c_hat = np.array([np.cos(phi(t)), np.sin(phi(t)), 0 * t])
        omega = v(t) * np.array([0.0, 0.0, 1.0]) + n * c_hat
        return R @ (I * (R.T @ omega))

    h = 1e-20
    worst_z = worst_perp = worst_along = 0.0
    spread = 0.0
    for tk in np.linspace(0.0, 20.0, 41):
        G = np.array(
            [np.imag(momentum(tk + 1j * h, c0)) / h for c0 in np.linspace(0, 2 * np.pi, phases + 1)[:-1]]
        )
        Gm = G.mean(axis=0)
        c_hat = np.array([np.cos(phi(tk)), np.sin(phi(tk)), 0.0])
        perp = np.cross([0.0, 0.0, 1.0], c_hat)
        z_expected, perp_expected = 0.5 * (A + B) * v_dot(tk), C * n * v(tk)
        scale_z = 0.5 * (A + B) * 0.5 * v0 * w_mod
        worst_z = max(worst_z, abs(Gm[2] - z_expected) / scale_z)
        # dH/dt = C n dc/dt = C n v z x c: the couple's axis is along z x OC, at right angles to the plane of
        # OC's turning (the couple "at right angles to it")
        worst_perp = max(worst_perp, abs(Gm @ perp - perp_expected) / perp_expected)
        worst_along = max(worst_along, abs(Gm @ c_hat) / perp_expected)
        spread = max(spread, float(np.ptp(G[:, 2])) / scale_z)
    # over one turn of the body at a fixed phase the mean in-plane couple is (H_z(t0 + P) - H_z(t0))/P, and
    # H_z = v(A sin^2 chi + B cos^2 chi) (at chi = 0 the body's e2 is along z): the mean is about B v' from a
    # turn starting at chi = 0 and A v' from chi = pi/2, not (A + B) v'/2, however fast the spin: only the
    # average over the phase gives Lamb's value
    period, t0 = 2 * np.pi / n, 3.0
    one_turn = {}
    for label, c0 in (("0", 0.0), ("90", 0.5 * np.pi)):
        c0 -= n * t0  # the body's phase at t0 is chi = n t0 + chi0
        mean = (momentum(t0 + period, c0)[2] - momentum(t0, c0)[2]).real / period
        one_turn[label] = mean / (0.5 * (A + B) * v_dot(t0 + period / 2))
    return ConstrainingCouples(I, spin_over_turn, one_turn, worst_z, worst_perp, worst_along, spread)


def _record_constraining_couples(results, values: ConstrainingCouples):
    for label, ratio in values.one_turn_ratio.items():
        results.number(
            f"constraining_one_turn_ratio_chi0_{label}",
            ratio,
            "1",
            note=f"mean in-plane couple over one turn from $\\chi$ = {label}°, over "
            "$\\tfrac12(A + B)\\dot v$",
        )
    results.number(
        "constraining_spin_over_turn",
        values.spin_over_turn,
        "1",
        note="$n/v_0$, moments " + _moments(values.moments),
    )
    results.number(
        "constraining_in_plane_deviation",
        values.in_plane_deviation,
        "1",
        note="Ex. XIII.11: the couple about the normal to the plane, averaged over the body's phase, "
        "against $\\tfrac12(A + B)\\dot v$ (largest over 41 times, relative to its largest value)",
    )
    results.number(
        "constraining_perpendicular_deviation",
        values.perpendicular_deviation,
        "1",
        note="the couple about $\\hat z\\times OC$ against $Cnv$ (relative)",
    )
    results.number(
        "constraining_along_axis", values.along_axis, "1", note="the mean couple about $OC$, over $Cnv$"
    )
    results.number(
        "constraining_in_plane_phase_spread",
        values.in_plane_phase_spread,
        "1",
        note="how much the in-plane couple swings with the body's phase (over the largest "
        "$\\tfrac12(A + B)\\dot v$): why Lamb says 'on the average'",
    )


class SymmetricEarth(NamedTuple):
    """The rigid symmetric Earth over `days` (rates in rad/d unless named)."""

    days: float
    space_rate: float  # the plane of omega and the figure axis about L, fitted
    space_rate_over_L_over_A: float
    space_rate_over_eulerian_nutation: float
    eulerian_nutation_spread: float
    body_rate: float  # the pole about the figure axis, right-handed about e3
    omega_b: float  # the notes' Omega_b = (I1 - I3) omega3 / I1
    C_minus_A_over_A: float
    omega2_R_over_g: float


def symmetric_earth(model, amplitude, days=20.0) -> SymmetricEarth:
    """The rigid symmetric Earth (units C = 1, days): the plane of omega and the figure axis turns about L at
    |L|/A (the space frequency, Lamb's Eulerian nutation Cn/(A cos theta)); the pole turns about the figure
    axis in the spin's sense; the oblateness (C - A)/A and omega^2 R/g against the notes' 1/300."""
    from ...models import wobble

    a = model.parameters()[wobble.A_C]
    I = np.array([a, a, 1.0])
    w0 = model.n * np.array([amplitude, 0.0, 1.0])
    t, w, R = integrate(I, w0, days, samples=4001, rtol=1e-13)
    L_space = I * w0
    L = float(np.linalg.norm(L_space))
    L_hat = L_space / L
    # the normal of the plane (omega, e3, L), formed in the body where nothing cancels, carried into space
    Lb = I * w
    N_space = np.einsum("kij,kj->ki", R, np.column_stack([Lb[:, 1], -Lb[:, 0], np.zeros_like(t)]))
    e1 = np.cross(L_hat, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(L_hat, e1)
    azimuth = np.unwrap(np.arctan2(N_space @ e2, N_space @ e1))
    space_rate = float(np.polyfit(t, azimuth, 1)[0])
    cos_theta = R[:, :, 2] @ L_hat  # the figure axis against L, from the attitude
    n_spin = w[:, 2]  # Lamb's n: the spin about the figure axis
    euler = n_spin / (a * cos_theta)  # Cn/(A cos theta), C = 1
    phase = np.unwrap(np.arctan2(w[:, 1], w[:, 0]))
    body_rate = float(np.polyfit(t, phase, 1)[0])  # right-handed about e3
    omega_b = (a - 1.0) * model.n / a  # the notes' Omega_b = (I1 - I3) omega3 / I1
    g = earth.GM_M3_PER_S2 / earth.EQUATORIAL_RADIUS_M**2
    return SymmetricEarth(
        days=days,
        space_rate=space_rate,
        space_rate_over_L_over_A=space_rate / (L / a),
        space_rate_over_eulerian_nutation=space_rate / float(np.mean(euler)),
        eulerian_nutation_spread=float(np.ptp(euler) / np.mean(euler)),
        body_rate=body_rate,
        omega_b=omega_b,
        C_minus_A_over_A=1.0 / a - 1.0,
        omega2_R_over_g=earth.OMEGA_RAD_PER_S**2 * earth.EQUATORIAL_RADIUS_M / g,
    )


def record_symmetric_earth(results, values: SymmetricEarth) -> None:
    days, body_rate, omega_b = values.days, values.body_rate, values.omega_b
    results.number(
        "space_rate_measured_rad_per_s",
        values.space_rate / earth.SECONDS_PER_DAY,
        "rad/s",
        note=f"the plane of $\\boldsymbol\\omega$ and the figure axis about $\\mathbf{{L}}$, fitted over "
        f"{days:g} days of the integrated attitude",
    )
    results.number(
        "space_rate_over_L_over_A", values.space_rate_over_L_over_A, "1", note="over $|\\mathbf{L}|/A$"
    )
    results.number(
        "space_rate_over_eulerian_nutation",
        values.space_rate_over_eulerian_nutation,
        "1",
        note="over $Cn/(A\\cos\\theta)$ (Lamb Art. 55 (7)), $\\theta$ from the attitude",
    )
    results.number("eulerian_nutation_spread", values.eulerian_nutation_spread, "1")
    results.number(
        "body_rate_measured_rad_per_s",
        body_rate / earth.SECONDS_PER_DAY,
        "rad/s",
        note="the pole about the figure axis, right-handed about $\\hat e_3$ (spin positive)",
    )
    results.number(
        "body_rate_over_notes_omega_b",
        body_rate / omega_b,
        "1",
        note="over the notes' $\\Omega_\\mathrm{b} = (I_1 - I_3)\\omega_3/I_1$: −1, the pole turns at "
        "$-\\Omega_\\mathrm{b}$, prograde",
    )
    results.number(
        "notes_omega_b_sign",
        float(np.sign(omega_b)),
        "1",
        note="sign of $\\Omega_\\mathrm{b}$ for the oblate Earth (spin positive)",
    )
    results.number("C_minus_A_over_A", values.C_minus_A_over_A, "1", note="$(I_3 - I_1)/I_1$ of this scene")
    results.number(
        "omega2_R_over_g",
        values.omega2_R_over_g,
        "1",
        note="$\\omega^2R/g$, $g = GM/R^2$, IERS (2010) constants, $R$ the equatorial radius",
    )
