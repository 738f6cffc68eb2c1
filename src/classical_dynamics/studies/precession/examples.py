"""Lamb's worked examples on the couple and the precession, computed with the precession scenes' own model.

polhode_circle    Art. 29, Ex.: the instantaneous axis makes with the figure axis the angle beta,
                  sin beta = psi' sin(eps)/n (the rolling cones), so the polhode cone cuts the Earth's
                  surface in a circle of radius R sin beta: the scene's secular rate, Lamb's R.
moon_line_offset  Ex. VI.5: the Moon's attraction on the Earth is a force through the centre and a couple
                  (MacCullagh's); the line of the resultant misses the centre by couple/force. The couple is
                  the full rung's torque routine (models.precession.torque_body), the Moon at the given
                  distance and declination; the force gamma M E / rho^2.
gyroscope_couple  Ex. XI.1: the couple that keeps a rotor (spin n about its axis) turning at Omega about a
                  perpendicular axis, from Euler's equations (models.rigid_body.euler_free) along that
                  prescribed motion: N = I (omega' - f(omega)), f the torque-free right-hand side.
distant_mass_couple, least_axis_stable, whirling_helix, added_mass, uniaxal_products
                  Art. 19 Ex. 2, Exs. VI.4, IV.16, VII.15, VII.16: the couple of a distant mass by quadrature,
                  the stable equilibria under it (sympy, librations), a whirling chain (sympy, a bead chain),
                  the moments after an added mass (eigh), a uniaxal body's products (sympy).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ...models import earth
from ...models import precession as prec
from ...models import rigid_body as rb
from ...solvers.ode import Problem, solve

CM_PER_FT = 30.48  # exact (international foot)


def run(scene, model, results) -> None:
    analysis = scene.data.get("analysis", {})
    if "polhode_circle" in analysis:
        spec = analysis["polhode_circle"]
        _record_polhode_circle(results, polhode_circle(model, spec["earth_radius_cm"]), spec["source"])
    if "moon_line_offset" in analysis:
        spec, polhode = analysis["moon_line_offset"], analysis.get("polhode_circle")
        values = moon_line_offset(
            spec["moon_distance_radii"],
            spec["declination_deg"],
            spec["C_minus_A_over_Ea2"],
            None if polhode is None else polhode["earth_radius_cm"],
        )
        _record_moon_line_offset(results, values)
    if "gyroscope_couple" in analysis:
        spec = analysis["gyroscope_couple"]
        values = gyroscope_couple(
            spec["weights_lb"],
            spec["radii_of_gyration_ft"],
            spec["spin_rev_per_s"],
            spec["turn_period_s"],
            spec["g_ft_per_s2"],
            spec["transverse_over_axial"],
        )
        _record_gyroscope_couple(results, values)
    if "distant_mass_couple" in analysis:
        spec = analysis["distant_mass_couple"]
        values = couple_of_distant_mass(spec["c_over_a"], spec["axis_angle_deg"], spec["distances_radii"])
        _record_couple_of_distant_mass(results, values)
    if "least_axis_stable" in analysis:
        spec = analysis["least_axis_stable"]
        values = least_axis_stable(spec["moments"], spec["start_offset_rad"], spec["span"])
        _record_least_axis_stable(results, values)
    if "whirling_helix" in analysis:
        spec = analysis["whirling_helix"]
        _record_whirling_helix(results, whirling_helix(spec["slope_deg"], spec["bead_steps_rad"]))
    if "added_mass" in analysis:
        spec = analysis["added_mass"]
        _record_added_mass(results, added_mass(spec["moments"], spec["seed"], spec["epsilons"]))
    if analysis.get("uniaxal_products"):
        _record_uniaxal_products(results, uniaxal_products())
    if "lamb_art61" in analysis:
        spec = analysis["lamb_art61"]
        _record_lamb_art61(results, lamb_art61(model, spec["samples"], spec["seed"]))


class PolhodeCircle(NamedTuple):
    earth_radius_cm: float
    beta: float  # the polhode cone's half-angle (rad)
    radius_cm: float  # R sin(beta)


def polhode_circle(model, earth_radius_cm) -> PolhodeCircle:
    """Lamb Art. 29: psi' = omega sin(beta)/sin(alpha), alpha the obliquity, omega ~ n: the polhode's
    radius."""
    beta = np.arcsin(model.secular_rate() * np.sin(model.obliquity) / model.n)
    return PolhodeCircle(earth_radius_cm, beta, earth_radius_cm * np.sin(beta))


def _record_polhode_circle(results, values: PolhodeCircle, source):
    results.number("earth_radius_cm", values.earth_radius_cm, "cm", note=source)
    results.number(
        "polhode_cone_angle_mas",
        values.beta / earth.MAS,
        "mas",
        note="$\\beta$: $\\sin\\beta = \\dot\\psi\\sin\\varepsilon/n$, the secular rate of this scene "
        "(Lamb Art. 29)",
    )
    results.number(
        "polhode_circle_radius_cm",
        values.radius_cm,
        "cm",
        note="where the polhode cone meets the Earth's surface: $R\\sin\\beta$",
    )


class MoonLineOffset(NamedTuple):
    moon_distance_radii: float  # rho
    declination_deg: float
    C_minus_A_over_Ea2: float
    offset_radii: float  # couple/force, from the torque routine
    closed_form_radii: float  # 3(C - A) sin(delta) cos(delta)/rho
    offset_ft: float | None  # the same on Lamb's radius of Art. 29; None without it


def moon_line_offset(rho, declination_deg, C_minus_A, earth_radius_cm=None) -> MoonLineOffset:
    """Lamb Ex. VI.5: couple/force of the Moon on the Earth, in Earth radii (units: E = a = gamma M = 1)."""
    delta = np.radians(declination_deg)
    # torque_body returns N/C with H = (C - A)/C; C = 1 (in E a^2) makes H = C - A, and N = that output
    p = np.zeros(prec.N_PARAMS)
    p[prec.H_] = C_minus_A
    p[prec.MOON], p[prec.MOON_K] = 1.0, 3.0 / rho**3  # 3 gamma M / rho^3, circular orbit: (a/r)^3 = 1
    p[prec.MOON_L0] = np.pi / 2  # the Moon at ecliptic longitude 90 deg ...
    # ... and the figure axis tilted by delta toward it (a turn by -delta about x): declination delta
    q = np.array([np.cos(delta / 2), -np.sin(delta / 2), 0.0, 0.0])
    torque = np.empty(3)
    prec.torque_body(0.0, q, p, torque)
    couple, force = float(np.linalg.norm(torque)), 1.0 / rho**2
    offset = couple / force
    return MoonLineOffset(
        rho,
        declination_deg,
        C_minus_A,
        offset,
        3.0 * C_minus_A * np.sin(delta) * np.cos(delta) / rho,
        None if earth_radius_cm is None else offset * earth_radius_cm / CM_PER_FT,
    )


def _record_moon_line_offset(results, values: MoonLineOffset):
    results.number(
        "moon_line_offset_radii",
        values.offset_radii,
        "1",
        note=f"Lamb Ex. VI.5: couple/force of the Moon at {values.moon_distance_radii:g} radii and "
        f"declination {values.declination_deg:g}°, $C - A$ = {values.C_minus_A_over_Ea2:g} "
        "$Ea^2$ (the couple from the full rung's torque routine)",
    )
    results.number(
        "moon_line_offset_closed_form_radii",
        values.closed_form_radii,
        "1",
        note="$3(C - A)\\sin\\delta\\cos\\delta/(E\\rho)$",
    )
    if values.offset_ft is not None:
        results.number(
            "moon_line_offset_ft",
            values.offset_ft,
            "ft",
            note="the same on Lamb's radius of Art. 29, 30.48 cm to the foot",
        )


class GyroscopeCouple(NamedTuple):
    g: float  # ft/s^2
    C: float  # axial moment, slug ft^2
    couple: float  # largest over the rotor's turn, ft-lb
    closed_form: float  # C n psi'


def gyroscope_couple(
    weights_lb, radii_of_gyration_ft, spin_rev_per_s, turn_period_s, g, transverse_over_axial
) -> GyroscopeCouple:
    """Lamb Ex. XI.1: the pitching couple of a rotary engine and propeller on an aeroplane turning in a
    circle."""
    C = sum(w * k**2 for w, k in zip(weights_lb, radii_of_gyration_ft)) / g  # slug ft^2
    A = transverse_over_axial * C
    I = np.array([A, A, C])
    n = 2.0 * np.pi * spin_rev_per_s
    Omega = 2.0 * np.pi / turn_period_s
    coefficients = rb.euler_coefficients(I)
    worst = 0.0
    for phase in np.linspace(0.0, 2.0 * np.pi, 7)[:-1]:
        # body frame: spin axis e3 horizontal; the vertical (the turning axis) at angle -phase about e3
        z_body = np.array([np.cos(phase), -np.sin(phase), 0.0])
        omega = Omega * z_body + np.array([0.0, 0.0, n])
        omega_dot = -n * Omega * np.cross([0.0, 0.0, 1.0], z_body)  # the vertical turns at -n in the body
        free = np.empty(3)
        rb.euler_free(0.0, omega, coefficients, free)
        couple = I * (omega_dot - free)
        worst = max(worst, float(np.linalg.norm(couple)))
    return GyroscopeCouple(g, C, worst, C * n * Omega)


def _record_gyroscope_couple(results, values: GyroscopeCouple):
    g = values.g
    results.number(
        "gyroscope_axial_moment_slug_ft2",
        values.C,
        "slug ft²",
        note=f"$C = \\sum Wk^2/g$ (Lamb Ex. XI.1; $g$ = {g:g} ft s$^{{-2}}$)",
    )
    results.number(
        "gyroscope_couple_ft_lb",
        values.couple,
        "ft-lb",
        note="the couple that keeps the rotor turning with the aeroplane, from Euler's equations "
        "(largest over the rotor's turn; the transverse moment does not enter)",
    )
    results.number("gyroscope_couple_closed_form_ft_lb", values.closed_form, "ft-lb", note="$Cn\\dot\\psi$")


# --- Lamb Ch. III-VII: the couple of a distant mass, and the moments of inertia -----------------------------


def _spheroid_couple(a, c, rho, s_hat, nodes=24):
    """The couple about the centre of a uniform spheroid (semi-axes a, a, c; mass 1) from a unit mass at rho
    s_hat (gamma = 1), by Gauss-Legendre quadrature over the body: sum of r x (rho s - r)/|rho s - r|^3 dm."""
    x, wx = np.polynomial.legendre.leggauss(nodes)
    r = 0.5 * (x + 1.0)  # radius in the unit ball, on [0, 1]
    wr = 0.5 * wx * r**2
    mu, wmu = x, wx  # cos(theta) on [-1, 1]
    phi = (np.arange(2 * nodes) + 0.5) * np.pi / nodes
    wphi = np.full(2 * nodes, np.pi / nodes)
    R, MU, PHI = np.meshgrid(r, mu, phi, indexing="ij")
    W = np.einsum("i,j,k->ijk", wr, wmu, wphi).ravel()
    S = np.sqrt(1.0 - MU**2)
    pts = np.stack([a * R * S * np.cos(PHI), a * R * S * np.sin(PHI), c * R * MU], axis=-1).reshape(-1, 3)
    W = W / W.sum()  # mass 1, uniform (the map to the spheroid has constant Jacobian)
    P = rho * np.asarray(s_hat, float)
    d = P - pts
    force = d / np.linalg.norm(d, axis=1)[:, None] ** 3
    return np.einsum("i,ij->j", W, np.cross(pts, force))


class DistantMassCouple(NamedTuple):
    c_over_a: float
    distances: np.ndarray  # rho/a
    far_difference: float  # quadrature against MacCullagh at the farthest distance (relative)
    slope: float  # the difference's fitted log-log slope in rho
    axial: float  # largest |N| about the symmetry axis over |N|


def couple_of_distant_mass(c_over_a, axis_angle_deg, distances_radii) -> DistantMassCouple:
    """Lamb Art. 19, Ex. 2: MacCullagh's couple (3 gamma M/rho^3) s x I s depends on A, B, C only; A = B makes
    its component about the axis vanish. Quadrature over a uniform spheroid against that form."""
    a, c = 1.0, c_over_a
    A, C = (a**2 + c**2) / 5.0, 2.0 * a**2 / 5.0  # uniform spheroid, mass 1: A = B about the equator
    I = np.array([A, A, C])
    theta = np.radians(axis_angle_deg)
    s = np.array([np.sin(theta), 0.0, np.cos(theta)])
    distances = np.asarray(distances_radii, float)
    errors, along = [], 0.0
    for rho in distances:
        N = _spheroid_couple(a, c, rho, s)
        mac = 3.0 / rho**3 * np.cross(s, I * s)
        errors.append(np.linalg.norm(N - mac) / np.linalg.norm(mac))
        along = max(along, abs(N[2]) / np.linalg.norm(N))
    slope = float(np.polyfit(np.log(distances), np.log(errors), 1)[0])
    return DistantMassCouple(c, distances, float(errors[-1]), slope, float(along))


def _record_couple_of_distant_mass(results, values: DistantMassCouple):
    c, distances = values.c_over_a, values.distances
    results.number(
        "maccullagh_relative_difference_far",
        values.far_difference,
        "1",
        note=f"quadrature couple against $(3\\gamma M/\\rho^3)\\hat{{\\mathbf s}}\\times I\\hat{{\\mathbf "
        f"s}}$ at $\\rho/a$ = {distances[-1]:g} (uniform spheroid, $c/a$ = {c:g})",
    )
    results.number(
        "maccullagh_difference_slope",
        -values.slope,
        "1",
        note=f"the difference falls as $(a/\\rho)^k$: $k$ fitted over $\\rho/a$ = {distances[0]:g} to "
        f"{distances[-1]:g}",
    )
    results.number(
        "maccullagh_axial_component",
        values.axial,
        "1",
        note="largest $|N|$ about the symmetry axis over the whole couple",
    )


class LeastAxisStable(NamedTuple):
    stable: int  # axis equilibria with a positive definite Hessian, of six
    on_least_axis: int  # 1 if both lie on the axis of least moment
    growth_least: float  # largest angle of OP from the least axis over the start's
    growth_others: float  # the same about the mean and greatest axes (the smaller)


def least_axis_stable(moments, start_offset_rad, span) -> LeastAxisStable:
    """Lamb Ex. VI.4: the potential (3 gamma M/2 rho^3) s.Is + const on the sphere of directions s of OP in
    the body; sympy's Hessian at the six axis equilibria, and a libration integrated about each
    (dop853)."""
    import sympy as sp

    I = [sp.Rational(str(x)) for x in moments]
    u, v = sp.symbols("u v", real=True)
    stable = []
    for i in range(3):
        j, k = [x for x in range(3) if x != i]
        for sign in (1, -1):
            s = [0, 0, 0]
            s[i], s[j], s[k] = sign, u, v
            V = sum(I[m] * s[m] ** 2 for m in range(3)) / sum(x**2 for x in s)
            Hs = sp.hessian(V, (u, v)).subs({u: 0, v: 0})
            if all(ev > 0 for ev in Hs.eigenvals()):
                stable.append(i)
    least = int(np.argmin(moments))
    # librations about each axis from rest (models.rigid_body.distant_attraction), sampled every 0.25 time
    # units: the angle of OP from the axis it started near
    moments = np.asarray(moments, float)
    t = np.linspace(0.0, span, int(np.ceil(span / 0.25)) + 1)
    growth = []
    kick = start_offset_rad
    for i in range(3):
        s0 = np.zeros(3)
        s0[i] = 1.0
        s0[(i + 1) % 3] = s0[(i + 2) % 3] = kick
        s0 /= np.linalg.norm(s0)
        sol = solve(
            Problem(rb.distant_attraction, np.concatenate([np.zeros(3), s0]), (0.0, span), moments),
            "dop853",
            rtol=1e-10,
            atol=1e-13,
            t_eval=t,
        )
        off = np.sqrt(np.maximum(1.0 - sol.y_eval[:, 3 + i] ** 2, 0.0))
        growth.append(float(np.max(off) / np.sqrt(1.0 - s0[i] ** 2)))
    return LeastAxisStable(
        len(stable),
        int(len(stable) == 2 and set(stable) == {least}),
        growth[least],
        float(min(g for n, g in enumerate(growth) if n != least)),
    )


def _record_least_axis_stable(results, values: LeastAxisStable):
    results.number(
        "stable_equilibria",
        values.stable,
        "1",
        note="axis equilibria with a positive definite Hessian of $\\hat{\\mathbf s}\\cdot I\\hat{"
        "\\mathbf s}$ (sympy), of six",
    )
    results.number(
        "stable_equilibria_on_least_axis",
        values.on_least_axis,
        "1",
        note="1 if both lie on the axis of least moment",
    )
    results.number(
        "libration_growth_least",
        values.growth_least,
        "1",
        note="largest angle of $OP$ from the least axis over the start's angle",
    )
    results.number(
        "libration_growth_others",
        values.growth_others,
        "1",
        note="the same about the mean and greatest axes (the smaller)",
    )


class WhirlingHelix(NamedTuple):
    sympy_holds: int  # 1 if sympy reduces the intrinsic equation to zero
    slope_deg: float  # alpha
    steps: np.ndarray  # the bead chains' angle steps (rad)
    tension_difference: float  # at the finest step, relative
    order: float  # of that difference in the step


def whirling_helix(slope_deg, bead_steps_rad) -> WhirlingHelix:
    """Lamb Ex. IV.16: a helix (radius a, tangent at alpha to the axis) turning rigidly at omega about its
    axis is a relative equilibrium of a free chain with T = mu omega^2 a^2/sin^2 alpha. sympy on the intrinsic
    equation d(T t)/ds + mu omega^2 r_perp = 0; and a bead chain (equal beads at angle steps Delta) whose
    radial balance fixes the link tension, converging to that T as Delta -> 0."""
    import sympy as sp

    s, a, w, mu, al = sp.symbols("s a omega mu alpha", positive=True)
    phi = s * sp.sin(al) / a
    r = sp.Matrix([a * sp.cos(phi), a * sp.sin(phi), s * sp.cos(al)])
    t = r.diff(s)
    T = mu * w**2 * a**2 / sp.sin(al) ** 2
    residual = (T * t).diff(s) + mu * w**2 * sp.Matrix([r[0], r[1], 0])
    unit = sp.simplify(t.dot(t) - 1)
    holds = int(sp.simplify(residual) == sp.zeros(3, 1) and unit == 0)
    alpha = np.radians(slope_deg)
    steps = np.asarray(bead_steps_rad, float)
    exact = 1.0 / np.sin(alpha) ** 2  # units mu = omega = a = 1
    diffs = []
    for D in steps:
        chord = np.sqrt(2.0 * (1.0 - np.cos(D)) + (D / np.tan(alpha)) ** 2)
        bead = D / np.sin(alpha)  # the arc each bead stands for, its mass
        # radial balance of a bead: T |d+ + d-|/chord = bead * omega^2 a, |d+ + d-| = 2a(1 - cos D)
        tension = bead * chord / (2.0 * (1.0 - np.cos(D)))
        diffs.append(abs(tension / exact - 1.0))
    order = float(np.polyfit(np.log(steps), np.log(diffs), 1)[0])
    return WhirlingHelix(holds, slope_deg, steps, float(diffs[-1]), order)


def _record_whirling_helix(results, values: WhirlingHelix):
    results.number(
        "helix_sympy",
        values.sympy_holds,
        "1",
        note="sympy: $d(T\\mathbf t)/ds + \\mu\\omega^2\\mathbf r_\\perp = 0$ with $T = \\mu\\omega^2"
        "a^2/\\sin^2\\alpha$, $s$ the arc (1 if it holds)",
    )
    results.number(
        "helix_bead_tension_difference",
        values.tension_difference,
        "1",
        note=f"bead chain at step {values.steps[-1]:g} rad, $\\alpha$ = {values.slope_deg:g}°: link tension "
        "against $\\mu\\omega^2a^2/\\sin^2\\alpha$ (relative)",
    )
    results.number("helix_bead_order", values.order, "1", note="order of that difference in the step")


class AddedMass(NamedTuple):
    moment_order: float  # order in eps of the moments' error against the first-order moments
    axis_order: float  # of the axis' error


def added_mass(moments, seed, epsilons) -> AddedMass:
    """Lamb Ex. VII.15: diag(A, B, C) plus eps times a symmetric tensor (moments A', B', C', products F', G',
    H'): eigh against the first-order moments A + A', ... and the axis near Ox, (1, -H'/(A - B), -G'/(A - C))
    eps."""
    A = np.asarray(moments, float)
    rng = np.random.default_rng(seed)
    P = rng.normal(size=(3, 3))
    P = 0.5 * (P + P.T)  # diagonal A', B', C'; off-diagonal -H', -G', -F'
    eps = np.asarray(epsilons, float)
    e_mom, e_axis = [], []
    for e in eps:
        values, vectors = np.linalg.eigh(np.diag(A) + e * P)
        e_mom.append(float(np.max(np.abs(values - (A + e * np.diag(P))))) / float(A.max()))
        x = vectors[:, 0] * np.sign(vectors[0, 0])
        first = np.array([1.0, e * P[1, 0] / (A[0] - A[1]), e * P[2, 0] / (A[0] - A[2])])
        e_axis.append(float(np.linalg.norm(x - first / np.linalg.norm(first))))
    return AddedMass(
        float(np.polyfit(np.log(eps), np.log(e_mom), 1)[0]),
        float(np.polyfit(np.log(eps), np.log(e_axis), 1)[0]),
    )


def _record_added_mass(results, values: AddedMass):
    results.number(
        "added_mass_moment_order",
        values.moment_order,
        "1",
        note="order in $\\epsilon$ of the moments' error against $A + A'$, $B + B'$, $C + C'$",
    )
    results.number(
        "added_mass_axis_order",
        values.axis_order,
        "1",
        note="order in $\\epsilon$ of the axis' error against $(1, -H'/(A - B), -G'/(A - C))$",
    )


def uniaxal_products() -> int:
    """Lamb Ex. VII.16: the tensor A 1 + (C - A) n n^T of a uniaxal body, axis (l, m, n): its products of
    inertia (sum m y z, ..., the negatives of the off-diagonal elements) are (A - C) m n, (A - C) n l, (A - C)
    l m."""
    import sympy as sp

    A_, C_, l, m, n = sp.symbols("A C l m n", real=True)
    u = sp.Matrix([l, m, n])
    tensor = A_ * sp.eye(3) + (C_ - A_) * u * u.T
    products = [-tensor[1, 2], -tensor[2, 0], -tensor[0, 1]]
    lamb = [(A_ - C_) * m * n, (A_ - C_) * n * l, (A_ - C_) * l * m]
    return int(all(sp.expand(x - y) == 0 for x, y in zip(products, lamb)))  # 1 if all three agree


def _record_uniaxal_products(results, agree: int):
    results.number(
        "uniaxal_products_sympy",
        agree,
        "1",
        note="sympy: the products of $A\\mathbf 1 + (C - A)\\hat{\\mathbf n}\\hat{\\mathbf n}^T$ are "
        "Lamb's (1 if all three agree)",
    )


class LambArt61(NamedTuple):
    solar_couple_residual: int  # 0: MacCullagh's couple with B = A is (4) identically
    samples: int  # random longitudes of the Sun
    torque_routine_deviation: float  # largest, over kappa sin(eps)
    triangle_residual: int  # (13)-(15) that do not hold identically
    mean_factor_residual: int  # 0: the mean over chi is (16)'s factor
    inclination: float  # the lunar orbit's (rad)
    mean_factor_quadrature: float  # over sin(eps) cos(eps)
    mean_factor_relative_deviation: float
    lunar_rate_arcsec_per_year: float  # with the factor by quadrature
    lunar_rate_over_formula: float


def lamb_art61(model, samples, seed) -> LambArt61:
    """Lamb Art. 61: the Sun's couple (4), the lunar triangle (13)-(15) and the mean factor (16).

    sympy: (4) from MacCullagh's couple (3 gamma S/r^3) s x I s with B = A, in Lamb's axes (x in the equator
    90° from the equinoxes, y along the line of equinoxes, z the polar axis: the averaged couple M of (5) then
    has its axis along the line of equinoxes, as the precession needs); (14)-(15) from unit vectors; the mean
    over chi. Numerically: the full rung's torque routine (models.precession.torque_body) against (4) at
    random l; the mean factor by quadrature over chi of the triangle built from vectors; the secular lunar
    rate recomputed from it.
    """
    import sympy as sp
    from scipy.integrate import quad

    l, e, i, chi = sp.symbols("l epsilon i chi", real=True)
    k3 = sp.Symbol("k3", positive=True)  # 3 gamma S (C - A)/r^3 = 2 kappa
    s = sp.Matrix([-sp.sin(l) * sp.cos(e), sp.cos(l), sp.sin(l) * sp.sin(e)])  # the Sun in Lamb's axes
    # (3 gamma S/r^3) s x I s, B = A: (C - A)(s_y s_z, -s_x s_z, 0)
    couple = k3 * sp.Matrix([s[1] * s[2], -s[0] * s[2], 0])
    kappa = k3 / 2
    lamb4 = sp.Matrix(
        [kappa * sp.sin(e) * sp.sin(2 * l), kappa * sp.sin(e) * sp.cos(e) * (1 - sp.cos(2 * l)), 0]
    )
    residual = sp.simplify(sp.expand_trig(couple - lamb4))
    # the torque routine of the spin-resolved rung: the Sun fixed at longitude l on a circle, the figure axis
    # at the obliquity eps, body axes (equinox, in the equator, pole) = Lamb's (y, -x, z)
    rng = np.random.default_rng(seed)
    eps = model.obliquity
    p = np.zeros(prec.N_PARAMS)
    p[prec.H_] = model.H
    p[prec.SUN], p[prec.SUN_K] = 1.0, 3.0  # 3 gamma S/r^3 = 3 (units): kappa/C = 3H/2
    q = np.array([np.cos(eps / 2), -np.sin(eps / 2), 0.0, 0.0])
    worst = 0.0
    out = np.empty(3)
    kappa_over_C = 1.5 * model.H
    for lon in rng.uniform(0.0, 2.0 * np.pi, samples):
        p[prec.SUN_L0] = lon
        prec.torque_body(0.0, q, p, out)
        L, M, N = -out[1], out[0], out[2]
        ref = kappa_over_C * np.array(
            [np.sin(eps) * np.sin(2 * lon), np.sin(eps) * np.cos(eps) * (1 - np.cos(2 * lon)), 0.0]
        )
        worst = max(worst, float(np.max(np.abs(np.array([L, M, N]) - ref)) / (kappa_over_C * np.sin(eps))))
    # (13)-(15): Z the ecliptic pole, C the figure pole at eps, M the lunar orbit's pole at i, angle MZC = chi
    Z = sp.Matrix([0, 0, 1])
    C = sp.Matrix([sp.sin(e), 0, sp.cos(e)])
    Mv = sp.Matrix([sp.sin(i) * sp.cos(chi), sp.sin(i) * sp.sin(chi), sp.cos(i)])
    cos_MC = (Mv.T * C)[0]
    # sin MC cos ZCM: the tangents at C toward Z and toward M, (C x Z).(C x M)/|C x Z|, |C x Z| = sin eps
    sin_cos = (C.cross(Z).T * C.cross(Mv))[0] / sp.sin(e)
    r14 = sp.simplify(cos_MC - (sp.cos(i) * sp.cos(e) + sp.sin(i) * sp.sin(e) * sp.cos(chi)))
    r15 = sp.simplify(sin_cos - (sp.cos(i) * sp.sin(e) - sp.sin(i) * sp.cos(e) * sp.cos(chi)))
    r13 = sp.simplify(cos_MC * sp.cos(e) + sp.sin(e) * sin_cos - sp.cos(i))
    mean = sp.simplify(sp.integrate(sp.expand(cos_MC * sin_cos), (chi, 0, 2 * sp.pi)) / (2 * sp.pi))
    r16 = sp.simplify(sp.expand_trig(mean - sp.sin(e) * sp.cos(e) * (3 * sp.cos(i) ** 2 - 1) / 2))
    inc = model.orbits.moon_i_rad
    f = sp.lambdify(chi, (cos_MC * sin_cos).subs({e: eps, i: inc}), "numpy")
    quadrature = quad(f, 0.0, 2.0 * np.pi, epsabs=0.0, epsrel=1e-13)[0] / (2.0 * np.pi)
    closed = np.sin(eps) * np.cos(eps) * 0.5 * (3.0 * np.cos(inc) ** 2 - 1.0)
    # the Moon's secular rate about the ecliptic pole: the rate about M (alpha cos MC) times sin MC cos ZCM
    # over sin eps, averaged over chi
    alpha_moon = model.alphas()[1]
    rate = alpha_moon * quadrature / np.sin(eps)
    return LambArt61(
        0 if residual == sp.zeros(3, 1) else 1,
        samples,
        worst,
        int(r13 != 0) + int(r14 != 0) + int(r15 != 0),
        0 if r16 == 0 else 1,
        inc,
        quadrature / (np.sin(eps) * np.cos(eps)),
        quadrature / closed - 1.0,
        rate * earth.JULIAN_YEAR_DAYS / earth.ARCSEC,
        rate / model.lunar_rate(),
    )


def _record_lamb_art61(results, values: LambArt61):
    results.number(
        "sympy_solar_couple_residual",
        values.solar_couple_residual,
        "1",
        note="0: MacCullagh's couple with $B = A$ is Lamb's (4) identically in $l$, $\\varepsilon$",
    )
    results.number(
        "solar_couple_torque_routine_deviation",
        values.torque_routine_deviation,
        "1",
        note=f"the full rung's torque routine against (4) at {values.samples} random longitudes "
        "(largest difference over $\\kappa\\sin\\varepsilon$)",
    )
    results.number(
        "sympy_lunar_triangle_residual",
        values.triangle_residual,
        "1",
        note="0: (13), (14) and (15) hold identically (the triangle built from unit vectors)",
    )
    results.number(
        "sympy_lunar_mean_factor_residual",
        values.mean_factor_residual,
        "1",
        note="0: the mean over $\\chi$ of $\\cos MC\\sin MC\\cos ZCM$ is "
        "$\\sin\\varepsilon\\cos\\varepsilon\\cdot\\tfrac12(3\\cos^2 i - 1)$",
    )
    results.number(
        "lunar_mean_factor_quadrature",
        values.mean_factor_quadrature,
        "1",
        note=f"the mean by quadrature over $\\chi$ at $i$ = {np.degrees(values.inclination):.4g}°, over "
        "$\\sin\\varepsilon\\cos\\varepsilon$",
    )
    results.number(
        "lunar_mean_factor_relative_deviation",
        values.mean_factor_relative_deviation,
        "1",
        note="against $\\tfrac12(3\\cos^2 i - 1)\\sin\\varepsilon\\cos\\varepsilon$",
    )
    results.number(
        "lunar_rate_from_quadrature_arcsec_per_year",
        values.lunar_rate_arcsec_per_year,
        "″/yr",
        note="the Moon's secular rate with the factor by quadrature",
    )
    results.number(
        "lunar_rate_quadrature_over_formula",
        values.lunar_rate_over_formula,
        "1",
        note="over the secular rung's lunar rate (the factor (16) in closed form)",
    )
