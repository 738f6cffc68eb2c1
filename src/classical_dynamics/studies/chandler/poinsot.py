"""Poinsot's kinematics of the free rigid body (Lamb 1920, Arts. 25, 30, 46-48), measured on integrations.

poinsot_body  a physical triaxial body (A < B < C, each moment below the sum of the other two), Euler's
              equations and the attitude integrated together (DOP853): the momental ellipsoid's tangent
              plane at the instantaneous axis stays fixed in space at the distance sqrt(2T)/H (Art. 46);
              the component of omega along the invariable line is 2T/H (Art. 48 (10)); the herpolhode
              lies between two circles whose radii follow from T, H and the moments, and never inflects
              (Art. 46, footnote); polhode and herpolhode have the same length (rolling without slipping).
              Beside it: the momentum plane conjugate to the axis (Art. 30), the triangle inequality of
              the moments (Art. 25), and the invariable cone (Art. 48 (5)-(6)) by sympy and on the
              separatrix H^2 = 2BT.
cone_rates    the symmetric Earth (Art. 47 (3)): the measured rate of the plane ZOC about the invariable
              line and of J round the polhode against omega sin(beta)/sin(alpha) and
              omega sin(alpha - beta)/sin(alpha); and Omega_b sin(theta_b) = Omega_s sin(theta_s).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ...models import rigid_body as rb
from ...solvers.ode import Problem, solve

RTOL = 1e-13


def _integrate(I, w0, span, samples):
    """(t, omega_body (n, 3), q (n, 4)) of a free body, DOP853 at RTOL, q0 = 1."""
    y0 = np.concatenate([np.asarray(w0, float), [1.0, 0.0, 0.0, 0.0]])
    t = np.linspace(0.0, span, samples)
    sol = solve(
        Problem(rb.free_attitude, y0, (0.0, span), np.asarray(I, float), name="free_attitude"),
        "dop853",
        rtol=RTOL,
        atol=RTOL * float(np.max(np.abs(w0))),
        t_eval=t,
    )
    y = sol.y_eval
    q = y[:, 3:] / np.linalg.norm(y[:, 3:], axis=1)[:, None]
    return t, y[:, :3], q


def _to_space(q, v):
    w, u = q[:, :1], q[:, 1:]
    t = 2.0 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


def herpolhode_radii(I, w0):
    """Closed-form least and greatest distance of the instantaneous axis's point on the invariable plane from
    the invariable line (the two circles of Art. 46, footnote), with the point x = omega/sqrt(2T) on the
    ellipsoid x.Ix = 1. On the polhode omega^2 is linear in one squared component, so its extremes lie where
    the polhode crosses a principal plane: solve A_i w_i^2 + A_k w_k^2 = 2T, A_i^2 w_i^2 + A_k^2 w_k^2 =
    H^2."""
    I = np.asarray(I, float)
    w0 = np.asarray(w0, float)
    T2 = float(np.sum(I * w0**2))
    H2 = float(np.sum((I * w0) ** 2))
    # the axis the polhode circles is the one whose component never vanishes: C if H^2 > 2BT, else A
    keep = 2 if H2 > I[1] * T2 else 0
    values = []
    for zero in (i for i in range(3) if i != keep):
        other = [i for i in range(3) if i not in (zero, keep)][0]
        M = np.array([[I[other], I[keep]], [I[other] ** 2, I[keep] ** 2]])
        sq = np.linalg.solve(M, [T2, H2])
        values.append(float(np.sum(sq)))
    radius2 = np.array(values) / T2 - T2 / H2  # |x|^2 - (the plane's distance)^2, x = omega/sqrt(2T)
    return float(np.sqrt(np.min(radius2))), float(np.sqrt(np.max(radius2)))


def _peak(y):
    """The greatest value of equally spaced samples, refined by the parabola through it and its neighbours."""
    i = int(np.clip(np.argmax(y), 1, len(y) - 2))
    a, b, c = y[i - 1], y[i], y[i + 1]
    return float(b + 0.125 * (c - a) ** 2 / (2 * b - a - c))


def _curvature(I, w):
    """Signed curvature of the herpolhode about the invariable line, from the body-frame derivatives:
    the space velocity of omega is R omega', its acceleration R(omega x omega' + omega'')."""
    A, B, C = I
    f = lambda v: np.stack(
        [(B - C) / A * v[:, 1] * v[:, 2], (C - A) / B * v[:, 2] * v[:, 0], (A - B) / C * v[:, 0] * v[:, 1]],
        axis=1,
    )
    wd = f(w)
    wdd = np.stack(
        [
            (B - C) / A * (wd[:, 1] * w[:, 2] + w[:, 1] * wd[:, 2]),
            (C - A) / B * (wd[:, 2] * w[:, 0] + w[:, 2] * wd[:, 0]),
            (A - B) / C * (wd[:, 0] * w[:, 1] + w[:, 0] * wd[:, 1]),
        ],
        axis=1,
    )
    L = w * I
    L_hat = L / np.linalg.norm(L, axis=1)[:, None]
    acc = np.cross(w, wd) + wdd
    return np.einsum("ij,ij->i", L_hat, np.cross(wd, acc)) / np.linalg.norm(wd, axis=1) ** 3


class PoinsotBody(NamedTuple):
    """What poinsot_body measures on one free body (lengths in units of the momental ellipsoid)."""

    moments: np.ndarray  # A, B, C
    plane_distance_error: float
    plane_normal_turn: float  # rad
    plane_error: float
    invariable_component_change: float
    herpolhode_radius_min: float
    herpolhode_radius_max: float
    herpolhode_radius_min_closed_form: float
    herpolhode_radius_max_closed_form: float
    herpolhode_bounds_error: float
    herpolhode_curvature_ratio: float
    rolling_arc_difference: float
    half_periods: int  # sign changes of p
    herpolhode_shown: np.ndarray  # the contact point in space over the periods drawn
    invariable_line: np.ndarray  # the starting normal H/H in space
    periods_shown: int


def poinsot_body(moments, omega, span, samples) -> PoinsotBody:
    """Lamb Arts. 46-48 measured on a free body with moments A, B, C started at omega, integrated over span
    with samples points."""
    I = np.asarray(moments, float)
    w0 = np.asarray(omega, float)
    span, samples = float(span), int(samples)
    t, w, q = _integrate(I, w0, span, samples)
    L_body = w * I
    T2 = np.einsum("ij,ij->i", w, L_body)  # 2T
    H = np.linalg.norm(L_body, axis=1)
    # Art. 46: the tangent plane of x.Ix = 1 at x = omega/sqrt(2T): normal Ix/|Ix| = L/H, distance x.n
    x = w / np.sqrt(T2)[:, None]
    normal = L_body / H[:, None]
    distance = np.einsum("ij,ij->i", x, normal)
    d0 = np.sqrt(T2[0]) / H[0]
    distance_error = float(np.max(np.abs(distance / d0 - 1.0)))
    n_space = _to_space(q, normal)
    normal_turn = float(np.max(np.linalg.norm(np.cross(n_space, n_space[0]), axis=1)))
    # Art. 48 (10): omega . n = 2T/H, with n the starting normal carried in space
    w_space = _to_space(q, w)
    along = w_space @ n_space[0]
    component_change = float(np.max(np.abs(along / (T2[0] / H[0]) - 1.0)))
    # the herpolhode: the point x in space, its distance from the invariable line
    x_space = _to_space(q, x)
    radial = x_space - np.outer(x_space @ n_space[0], n_space[0])
    rho = np.linalg.norm(radial, axis=1)
    lo, hi = herpolhode_radii(I, w0)
    rho_min, rho_max = -_peak(-rho), _peak(rho)
    kappa = _curvature(I, w)
    # rolling without slipping: the paths of the contact point on the body and on the plane have equal length
    body_arc = float(np.sum(np.linalg.norm(np.diff(x, axis=0), axis=1)))
    space_arc = float(np.sum(np.linalg.norm(np.diff(x_space, axis=0), axis=1)))
    crossings = int(np.sum(np.diff(np.sign(w[:, 0])) != 0))
    shown = 2  # polhode periods drawn: more fill the ring
    change = np.flatnonzero(np.diff(np.sign(w[:, 0])) != 0)
    end = change[2 * shown] + 1 if len(change) > 2 * shown else len(w)
    return PoinsotBody(
        moments=I,
        plane_distance_error=distance_error,
        plane_normal_turn=normal_turn,
        plane_error=max(distance_error, normal_turn),
        invariable_component_change=component_change,
        herpolhode_radius_min=rho_min,
        herpolhode_radius_max=rho_max,
        herpolhode_radius_min_closed_form=lo,
        herpolhode_radius_max_closed_form=hi,
        herpolhode_bounds_error=float(max(abs(rho_min / lo - 1), abs(rho_max / hi - 1))),
        herpolhode_curvature_ratio=float(np.min(kappa) / np.max(kappa)),
        rolling_arc_difference=abs(space_arc / body_arc - 1.0),
        half_periods=crossings,
        herpolhode_shown=x_space[:end],
        invariable_line=n_space[0],
        periods_shown=shown,
    )


def record_poinsot_body(results, body: PoinsotBody, source) -> None:
    """poinsot_body's numbers, hard case and herpolhode figure; source notes the moments."""
    for name, value in zip("ABC", body.moments):
        results.number(f"poinsot_{name}", float(value), "1", note=source)
    results.number(
        "poinsot_plane_distance_error",
        body.plane_distance_error,
        "1",
        note="largest relative change of the tangent plane's distance from $O$ against "
        "$\\sqrt{2T}/H$ at the start",
    )
    results.number(
        "poinsot_plane_normal_turn",
        body.plane_normal_turn,
        "rad",
        note="largest angle of the plane's normal $\\mathbf{H}/H$, carried to space, from its start",
    )
    results.number(
        "poinsot_plane_error",
        body.plane_error,
        "1",
        note="the larger of the two: the plane is fixed in space",
    )
    results.hard_case(
        "poinsot_plane_fixed",
        "The momental ellipsoid's tangent plane at the instantaneous axis "
        "stays fixed in space (Lamb Art. 46; distance and normal, relative)",
        body.plane_error,
        1e-11,
    )
    results.number(
        "invariable_component_change",
        body.invariable_component_change,
        "1",
        note="largest relative change of $\\boldsymbol\\omega\\cdot\\hat{\\mathbf{H}}$ against "
        "$2T/H$ (fixed $\\hat{\\mathbf{H}}$ in space)",
    )
    results.number(
        "herpolhode_radius_min", body.herpolhode_radius_min, "1", note="least sample, refined by a parabola"
    )
    results.number(
        "herpolhode_radius_max",
        body.herpolhode_radius_max,
        "1",
        note="greatest sample, refined by a parabola",
    )
    results.number("herpolhode_radius_min_closed_form", body.herpolhode_radius_min_closed_form, "1")
    results.number("herpolhode_radius_max_closed_form", body.herpolhode_radius_max_closed_form, "1")
    results.number(
        "herpolhode_bounds_error",
        body.herpolhode_bounds_error,
        "1",
        note="measured extremes of the herpolhode's radius against the closed forms (relative)",
    )
    results.number(
        "herpolhode_curvature_ratio",
        body.herpolhode_curvature_ratio,
        "1",
        note="least over greatest signed curvature of the herpolhode along the run: positive, no inflexion",
    )
    results.number(
        "rolling_arc_difference",
        body.rolling_arc_difference,
        "1",
        note="herpolhode length over polhode length, less 1, over the run",
    )
    results.number("poinsot_half_periods", body.half_periods, "1", note="sign changes of $p$ over the run")
    _herpolhode_figure(
        results,
        body.herpolhode_shown,
        body.invariable_line,
        body.herpolhode_radius_min_closed_form,
        body.herpolhode_radius_max_closed_form,
        body.periods_shown,
        body.moments,
    )


def _herpolhode_figure(results, x_space, n0, lo, hi, periods, I):
    """The herpolhode on the fixed plane between its two circles (a half-width figure)."""
    from ...figure_style import TEXT_WIDTH_IN
    from ...formatting import shortest
    from ...results import new_figure

    e1 = np.cross(n0, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n0, e1)
    fig, ax = new_figure(0.5 * TEXT_WIDTH_IN, 2.25)
    turn = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(x_space @ e1, x_space @ e2, lw=0.9, color="C4")
    for radius in (lo, hi):
        ax.plot(radius * np.cos(turn), radius * np.sin(turn), ls="--", lw=0.7, color="0.3")
    ax.plot([0], [0], "k+", ms=7)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(r"$\xi$ (ellipsoid units)")
    ax.set_ylabel(r"$\eta$ (ellipsoid units)")
    moments = " : ".join(shortest(float(v)) for v in I)
    results.figure(
        "herpolhode",
        fig,
        f"The herpolhode of a free body with $A : B : C$ = {moments} over {periods} "
        "polhode periods: the path of the point of contact on the fixed plane, about the invariable line "
        "(+), in units in which the momental ellipsoid is $\\mathbf x\\cdot I\\mathbf x = 1$. It "
        "touches alternately the two circles (dashed) whose radii follow from $T$, $H$ and the moments, "
        "and it has no inflexion (Lamb Art. 46, footnote).",
    )


class ConjugatePlane(NamedTuple):
    midplane_error: float  # relative to the chord
    momentum_parallel_only_on_axes: int  # 1 if the sympy checks hold
    chords: int


def conjugate_plane(I, chords=2000, seed=20) -> ConjugatePlane:
    """Art. 30: the plane of the couple (normal I omega) is the diametral plane of x.Ix = 1 conjugate to
    omega: it holds the midpoints of all chords parallel to omega. Chords found by solving each line's
    quadratic."""
    rng = np.random.default_rng(seed)
    worst = 0.0
    for _ in range(chords):
        d = rng.normal(size=3)
        x0 = rng.uniform(-0.4, 0.4, size=3)
        a, b, c = d @ (I * d), 2.0 * x0 @ (I * d), x0 @ (I * x0) - 1.0
        if b * b - 4 * a * c <= 0:
            continue
        root = np.sqrt(b * b - 4 * a * c)
        s1, s2 = (-b - root) / (2 * a), (-b + root) / (2 * a)
        mid = x0 + 0.5 * (s1 + s2) * d
        end = x0 + s1 * d
        worst = max(worst, abs(mid @ (I * d)) / (np.linalg.norm(I * d) * np.linalg.norm(end)))
    import sympy as sp

    A_, B_, C_ = sp.symbols("A B C", positive=True)
    p, q, r = sp.symbols("p q r", real=True)
    cross = sp.Matrix([p, q, r]).cross(sp.Matrix([A_ * p, B_ * q, C_ * r]))
    # omega x I omega = ((C - B) q r, (A - C) r p, (B - A) p q): zero for distinct moments only on an axis
    expected = sp.Matrix([(C_ - B_) * q * r, (A_ - C_) * r * p, (B_ - A_) * p * q])
    residual = sp.simplify(cross - expected)
    solutions = sp.solve(list(cross.subs({A_: 1, B_: 2, C_: 3})), [p, q, r], dict=True)
    axes = all(sum(1 for v in (s.get(p, p), s.get(q, q), s.get(r, r)) if v != 0) <= 1 for s in solutions)
    sphere = cross.subs({B_: A_, C_: A_})
    return ConjugatePlane(
        float(worst), int(residual == sp.zeros(3, 1) and axes and sphere == sp.zeros(3, 1)), chords
    )


def record_conjugate_plane(results, plane: ConjugatePlane) -> None:
    results.number(
        "conjugate_midplane_error",
        plane.midplane_error,
        "1",
        note="largest distance of a chord's midpoint from the plane normal to $I\\boldsymbol\\omega$ "
        f"({plane.chords} random chords parallel to $\\boldsymbol\\omega$, relative to the chord)",
    )
    results.number(
        "momentum_parallel_only_on_axes",
        plane.momentum_parallel_only_on_axes,
        "1",
        note="sympy: $\\boldsymbol\\omega\\times I\\boldsymbol\\omega = ((C - B)qr, (A - C)rp, "
        "(B - A)pq)$ vanishes for $A, B, C$ = 1, 2, 3 only on a principal axis, and "
        "identically for $A = B = C$ (1 if all hold)",
    )


class TriangleInequality(NamedTuple):
    least_margin: float  # least (I_j + I_k - I_i)/I_i
    identity_residual: float
    hnw_margin: float  # the Hairer-Norsett-Wanner test problem's (I_1 + I_2 - I_3)/I_3
    bodies: int


def triangle_inequality(bodies=2000, seed=25) -> TriangleInequality:
    """Art. 25: any two principal moments exceed the third, since I1 + I2 - I3 = 2 sum m z^2 (principal axes).
    Random clouds of point masses: the least margin (I_j + I_k - I_i)/I_i, and the identity's residual."""
    rng = np.random.default_rng(seed)
    least, residual = np.inf, 0.0
    for _ in range(bodies):
        n = rng.integers(4, 12)
        m = rng.uniform(0.1, 1.0, n)
        r = rng.normal(size=(n, 3)) * rng.uniform(0.01, 1.0, 3)
        r -= m @ r / m.sum()
        J = np.einsum("i,ij,ik->jk", m, r, r)  # second moments sum m x_j x_k
        tensor = np.trace(J) * np.eye(3) - J
        moments, axes = np.linalg.eigh(tensor)
        z2 = np.einsum("i,ij->j", m, (r @ axes) ** 2)  # sum m z^2 along each principal axis
        for i in range(3):
            j, k = [x for x in range(3) if x != i]
            margin = moments[j] + moments[k] - moments[i]
            least = min(least, margin / moments[i])
            residual = max(residual, abs(margin - 2.0 * z2[i]) / moments.max())
    hnw = np.array([0.5, 2.0, 3.0])
    return TriangleInequality(
        float(least), float(residual), float((hnw[0] + hnw[1] - hnw[2]) / hnw[2]), bodies
    )


def record_triangle_inequality(results, triangle: TriangleInequality) -> None:
    results.number(
        "triangle_least_margin",
        triangle.least_margin,
        "1",
        note=f"least $(I_j + I_k - I_i)/I_i$ over {triangle.bodies} random bodies of point masses (flat "
        "bodies come near 0)",
    )
    results.number(
        "triangle_identity_residual",
        triangle.identity_residual,
        "1",
        note="largest $|I_j + I_k - I_i - 2\\sum m x_i^2|/I_\\mathrm{max}$",
    )
    results.number(
        "hnw_triangle_margin",
        triangle.hnw_margin,
        "1",
        note="the Hairer–Nørsett–Wanner test problem's $(I_1 + I_2 - I_3)/I_3$, $I$ = (0.5, 2, 3): "
        "negative, no rigid body",
    )


class InvariableCone(NamedTuple):
    sympy_checks: int  # 1 if (6) and the signs hold
    planes_residual: float
    span: float  # time units


def invariable_cone(I, span=8.0) -> InvariableCone:
    """Art. 48: 2CT - H^2 = A(C - A)p^2 + B(C - B)q^2 (6); the cone's coefficients H^2 - 2 I_i T keep their
    signs for A < B < C; on H^2 = 2BT the invariable line stays in the planes A(B - A)p^2 = C(C - B)r^2."""
    import sympy as sp

    A_, B_, C_ = sp.symbols("A B C", positive=True)
    p, q, r = sp.symbols("p q r", real=True)
    T2 = A_ * p**2 + B_ * q**2 + C_ * r**2
    H2 = A_**2 * p**2 + B_**2 * q**2 + C_**2 * r**2
    identity = sp.expand(C_ * T2 - H2 - (A_ * (C_ - A_) * p**2 + B_ * (C_ - B_) * q**2))
    # with A < B < C: B = A + b, C = A + b + c, b, c > 0: every term of the first coefficient is positive
    a_, b_, c_ = sp.symbols("a b c", positive=True)
    order = {A_: a_, B_: a_ + b_, C_: a_ + b_ + c_}
    first = sp.expand((H2 - A_ * T2).subs(order))
    third = sp.expand((C_ * T2 - H2).subs(order))
    signs = all(t.could_extract_minus_sign() is False for t in sp.Add.make_args(first)) and all(
        t.could_extract_minus_sign() is False for t in sp.Add.make_args(third)
    )
    # the separatrix: start in the plane A(B - A)p^2 = C(C - B)r^2, off the mean axis
    A, B, C = I
    r0 = 0.6
    p0 = r0 * np.sqrt(C * (C - B) / (A * (B - A)))
    t, w, _ = _integrate(I, [p0, 1e-3, r0], span, 2001)
    planes = A * (B - A) * w[:, 0] ** 2 - C * (C - B) * w[:, 2] ** 2
    scale = A * (B - A) * w[:, 0] ** 2 + C * (C - B) * w[:, 2] ** 2
    return InvariableCone(int(identity == 0 and signs), float(np.max(np.abs(planes) / scale)), span)


def record_invariable_cone(results, cone: InvariableCone) -> None:
    results.number(
        "invariable_cone_sympy",
        cone.sympy_checks,
        "1",
        note="sympy: (6) holds identically, and with $A < B < C$ every term of $H^2 - 2AT$ and of "
        "$2CT - H^2$ is positive (1 if both hold)",
    )
    results.number(
        "invariable_planes_residual",
        cone.planes_residual,
        "1",
        note="$H^2 = 2BT$: largest $|A(B - A)p^2 - C(C - B)r^2|$ relative to the sum of the two "
        f"terms over {cone.span:g} time units",
    )


class ConeRates(NamedTuple):
    """Lamb Art. 47 (3) on the rigid symmetric Earth, rates in rad/d."""

    psi_dot_measured: float
    psi_dot_closed_form: float
    chi_dot_measured: float
    chi_dot_closed_form: float
    cone_rates_error: float
    no_slip_cones_ratio: float


def cone_rates(model, amplitude, days=2.0) -> ConeRates:
    """Lamb Art. 47 (3) on the rigid symmetric Earth: psi' and chi' measured from an integration of the body
    with its attitude (DOP853), against the forms in the measured alpha = ZOC and beta = JOC."""
    from ...models import wobble

    a = model.parameters()[wobble.A_C]
    I = np.array([a, a, 1.0])
    w0 = model.n * np.array([amplitude, 0.0, 1.0])
    t, w, q = _integrate(I, w0, days, 4001)
    L_body = w * I
    L_hat = _to_space(q[:1], L_body[:1])[0]
    L_hat /= np.linalg.norm(L_hat)
    # psi': the figure axis OC about OZ in space
    e1 = np.cross(L_hat, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(L_hat, e1)
    axis = _to_space(q, np.tile([0.0, 0.0, 1.0], (len(t), 1)))
    psi_dot = float(np.polyfit(t, np.unwrap(np.arctan2(axis @ e2, axis @ e1)), 1)[0])
    # chi': Euler's third rate, the body about OC relative to the plane ZOC; in body axes that plane, and J
    # in it, turn about OC at -chi' (prograde for C > A, where chi' < 0): minus the phase rate of p + iq
    chi_dot = -float(np.polyfit(t, np.unwrap(np.arctan2(w[:, 1], w[:, 0])), 1)[0])
    omega = float(np.mean(np.linalg.norm(w, axis=1)))
    wn, Ln = np.linalg.norm(w[0]), np.linalg.norm(L_body[0])
    sin_alpha = np.hypot(L_body[0, 0], L_body[0, 1]) / Ln  # ZOC
    sin_beta = np.hypot(w[0, 0], w[0, 1]) / wn  # JOC
    # alpha - beta, the angle from J to Z: signed, from omega x L = (C - A) r (q, -p, 0) (no cancellation)
    cross = np.cross(w[0], L_body[0])
    sin_alpha_minus_beta = -np.linalg.norm(cross) / (wn * Ln)  # C > A: beta > alpha
    psi_form = float(omega * sin_beta / sin_alpha)
    chi_form = float(omega * sin_alpha_minus_beta / sin_alpha)
    return ConeRates(
        psi_dot_measured=psi_dot,
        psi_dot_closed_form=psi_form,
        chi_dot_measured=chi_dot,
        chi_dot_closed_form=chi_form,
        cone_rates_error=float(max(abs(psi_dot / psi_form - 1.0), abs(chi_dot / chi_form - 1.0))),
        # lecture notes: the body cone rolls on the space cone, Omega_b sin(theta_b) = Omega_s sin(theta_s)
        no_slip_cones_ratio=float(abs(chi_dot) * sin_beta / (psi_dot * abs(sin_alpha_minus_beta))),
    )


def record_cone_rates(results, rates: ConeRates) -> None:
    psi_dot, psi_form = rates.psi_dot_measured, rates.psi_dot_closed_form
    chi_dot, chi_form = rates.chi_dot_measured, rates.chi_dot_closed_form
    results.number("psi_dot_measured", psi_dot, "rad/d", note="the plane $ZOC$ about the invariable line")
    results.number("psi_dot_closed_form", psi_form, "rad/d", note="$\\omega\\sin\\beta/\\sin\\alpha$")
    results.number("psi_dot_relative_error", psi_dot / psi_form - 1.0, "1")
    results.number(
        "chi_dot_measured",
        chi_dot,
        "rad/d",
        note="the body about $OC$ relative to the plane $ZOC$: $J$ runs round the polhode at "
        "$-\\dot\\chi$ in body axes",
    )
    results.number(
        "chi_dot_closed_form", chi_form, "rad/d", note="$\\omega\\sin(\\alpha - \\beta)/\\sin\\alpha$"
    )
    results.number("chi_dot_relative_error", chi_dot / chi_form - 1.0, "1")
    results.number(
        "cone_rates_error",
        rates.cone_rates_error,
        "1",
        note="the larger relative error of $\\dot\\psi$ and $\\dot\\chi$ against Lamb Art. 47 (3)",
    )
    results.number(
        "no_slip_cones_ratio",
        rates.no_slip_cones_ratio,
        "1",
        note="$\\Omega_\\mathrm{b}\\sin\\theta_\\mathrm{b}/(\\Omega_\\mathrm{s}\\sin\\theta_\\mathrm{s})$, "
        "measured rates, $\\theta_\\mathrm{b} = \\beta$, $\\theta_\\mathrm{s} = \\beta - \\alpha$",
    )
