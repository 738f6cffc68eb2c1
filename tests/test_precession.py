"""Precession of the equinoxes: the secular formula, the averaged and the full model, hard cases, bad
scenes."""

import dataclasses

import numpy as np
import pytest
import yaml

from classical_dynamics.models import earth
from classical_dynamics.models import precession as prec
from classical_dynamics.solvers import rigid_body
from classical_dynamics.studies import validate
from classical_dynamics.studies.precession import averaged, fitting, full, secular

from .conftest import ROOT, assert_refused

YEAR = earth.JULIAN_YEAR_DAYS
EPS0 = 84381.406 * earth.ARCSEC
ALL = ("solar_torque", "lunar_torque", "orbit_eccentricity", "lunar_inclination", "node_regression")


def model(effects=ALL, H=earth.H_P03, obliquity=EPS0, orbits=None):
    return prec.assemble(H, obliquity, orbits or prec.modern(), {e: {} for e in effects})


def full_rate(m, years, step_hours=3.0):
    t, ms, qs = full.integrate(m, years * YEAR, step_hours / 24.0)
    psi, eps = prec.precession_angles(full.angular_momentum_axis(ms, qs))
    fp, fe, args = full.fit_series(m, t, psi, eps)
    return fp, fe, args, t, psi, eps


# --- rung 1: the secular formula (digest P1, P3, P4, P8) -----------------------------------------------


def test_solar_rate_with_lamb_like_inputs():
    m = model(("solar_torque",), H=0.00327, obliquity=np.radians(23.45), orbits=prec.lamb1920())
    per_year = m.solar_rate() * m.orbits.year_days / earth.ARCSEC
    # (3 n'^2/2n) H cos eps per year = 3 pi (n'/n) H cos eps, written out independently
    assert per_year == pytest.approx(
        3 * np.pi / 366.25 * 0.00327 * np.cos(np.radians(23.45)) / earth.ARCSEC, rel=1e-12
    )
    assert per_year == pytest.approx(15.92, abs=0.05)


def test_scalings_of_the_secular_rate():
    base = model(("solar_torque",))
    assert abs(model(("solar_torque",), obliquity=np.pi / 2).solar_rate()) < 1e-15 * base.solar_rate()
    assert model(("solar_torque",), H=2 * earth.H_P03).solar_rate() == pytest.approx(
        2 * base.solar_rate(), rel=1e-14
    )
    assert model(("solar_torque",), obliquity=0.3).solar_rate() / base.solar_rate() == pytest.approx(
        np.cos(0.3) / np.cos(EPS0), rel=1e-14
    )
    fast = prec.Orbits(
        **{**prec.modern().__dict__, "spin_turns_per_year": 2 * prec.modern().spin_turns_per_year}
    )
    assert model(("solar_torque",), orbits=fast).solar_rate() == pytest.approx(
        0.5 * base.solar_rate(), rel=1e-14
    )


def test_lamb_ratio_and_the_mass_convention():
    lamb = model(
        ("solar_torque", "lunar_torque", "lunar_inclination", "node_regression"),
        H=0.00327,
        obliquity=np.radians(23.45),
        orbits=prec.lamb1920(),
    )
    assert lamb.lunar_rate() / lamb.solar_rate() == pytest.approx(2.18, abs=0.01)
    # Kepler's law for the Moon wants M/(E + M): the ratio falls to about 2.15 (digest P4)
    o = prec.lamb1920()
    corrected = prec.Orbits(**{**o.__dict__, "moon_gm_over_a3": o.moon_gm_over_a3 * 81.4 / 82.4})
    m = model(
        ("solar_torque", "lunar_torque", "lunar_inclination", "node_regression"),
        H=0.00327,
        obliquity=np.radians(23.45),
        orbits=corrected,
    )
    assert m.lunar_rate() / m.solar_rate() == pytest.approx(2.153, abs=0.005)
    # Lamb's ratios as he gives them (Art. 61): n1/n' = 13.4 Moon's months a year, n/n' = 366.25, E/M = 81.4
    assert o.moon_n / o.sun_n == pytest.approx(13.4, rel=1e-15)
    assert o.spin_turns_per_year == 366.25 and o.sun_n == pytest.approx(2 * np.pi / 365.256363, rel=1e-15)
    assert o.moon_gm_over_a3 / o.moon_n**2 == pytest.approx(1 / 81.4, rel=1e-15)
    # the node's 18.6-year regression (Lamb gives no figure; the OCR leaves none): the IAU's rate of Omega
    # (Simon et al. 1994, 1934.1362891 degrees a century against the moving equinox, plus p_A), to that digit
    iau_years = 360.0 * 36525.0 / (1934.1362891 + 5028.796195 / 3600.0) / 365.256363
    assert o.node_period_days / o.year_days == pytest.approx(iau_years, abs=0.05)


def test_inverse_problem_returns_lamb_ellipticity(tmp_path):
    from classical_dynamics.results import Results

    scene = validate("precession", ROOT / "workflow/scenes/precession/lamb_1920.yaml")
    results = Results("precession", scene.name, scene.title)
    secular.run(scene, results)
    # Art. 47 prints .00327 as (C - A)/A: from 50″.5 the formula must return it to Lamb's three figures
    # (read as (C - A)/C the round trip gives 0.003262, which would print as .00326)
    assert round(results.numbers["C_minus_A_over_A_from_observed_rate"]["value"], 5) == 0.00327
    assert round(results.numbers["H_from_observed_rate"]["value"], 5) == 0.00326
    # forward, with .00327 as (C - A)/A, the total is Lamb's 50″.5 to his three figures
    assert round(results.numbers["secular_per_orbit_arcsec"]["value"], 1) == 50.5
    # and with today's constants, from IAU 2006's psi_A: within 0.1 % of P03's H
    scene = validate("precession", ROOT / "workflow/scenes/precession/secular_modern.yaml")
    results = Results("precession", scene.name, scene.title)
    secular.run(scene, results)
    assert results.numbers["H_from_observed_rate"]["value"] == pytest.approx(earth.H_P03, rel=1e-3)


def test_modern_secular_rate_against_iau2006():
    import erfa

    m = model()
    # psi_A from pyerfa by an independent route: its value after one Julian century
    psi_A = erfa.p06e(2451545.0, 36525.0)[1] / earth.ARCSEC / 100.0
    assert fitting.per_year_arcsec(m.secular_rate()) == pytest.approx(psi_A, rel=3e-3)
    assert secular.iau2006_rates()["psi_A"] == pytest.approx(5038.481507 / 100, rel=1e-9)


def test_first_order_rate_is_set_beside_p03_r0_and_the_moon_distance_convention_sized():
    """The like quantity of a first-order formula is P03's r0 (psi_A plus Table 3's 2.223176″/cy); the Moon at
    Kepler's distance for its sidereal month changes only the lunar part, as a^-3."""
    from classical_dynamics.results import Results

    scene = validate("precession", ROOT / "workflow/scenes/precession/secular_modern.yaml")
    results = Results("precession", scene.name, scene.title)
    secular.run(scene, results)
    n = {k: v["value"] for k, v in results.numbers.items()}
    assert n["p03_first_order_rate_arcsec_per_year"] == pytest.approx(
        (5038.481507 + 2.223176) / 100, rel=1e-9
    )
    month_s = 27.321662 * 86400.0  # the sidereal month, IERS GM_E and M/E: Kepler's third law by hand
    a = (3.986004418e14 * (1.0 + 0.0123000371) * month_s**2 / (4.0 * np.pi**2)) ** (1.0 / 3.0)
    assert n["kepler_moon_distance_km"] == pytest.approx(a / 1e3, rel=1e-12)
    assert n["kepler_moon_distance_km"] == pytest.approx(384748.0, abs=1.0)
    lunar, total = n["secular_lunar_rate_arcsec_per_year"], n["secular_rate_arcsec_per_year"]
    expected = lunar / total * ((384400.0e3 / a) ** 3 - 1.0)
    assert n["kepler_moon_distance_rate_change_relative"] == pytest.approx(expected, rel=1e-9)
    assert n["secular_rate_kepler_moon_distance_arcsec_per_year"] == pytest.approx(
        total * (1 + expected), rel=1e-12
    )


# --- rung 2: the averaged equations ---------------------------------------------------------------------


def test_node_average_by_quadrature():
    """P5: the Moon's couple averaged over the node is the ecliptic's with the factor (3cos^2 i - 1)/2."""
    m = model(("lunar_torque", "lunar_inclination", "node_regression"))
    p = prec.averaged_parameters(m)
    s = prec.initial_axis(0.3, EPS0)
    out, mean = np.empty(3), np.zeros(3)
    nodes = np.linspace(0.0, 2 * np.pi, 64, endpoint=False)
    for node in nodes:
        p[3], p[4] = node, 0.0
        prec.averaged_rhs(0.0, s, p, out)
        mean += out / len(nodes)
    i = m.moon_i
    k = np.array([0.0, 0.0, 1.0])
    expected = -p[1] * 0.5 * (3 * np.cos(i) ** 2 - 1) * np.dot(k, s) * np.cross(k, s)
    assert mean == pytest.approx(expected, rel=1e-12, abs=1e-22)


def test_averaged_rate_is_the_formula_for_orbits_in_the_ecliptic():
    m = model(("solar_torque", "lunar_torque", "orbit_eccentricity"))
    span = 3000 * YEAR
    t = np.linspace(0.0, span, 3001)
    sol = averaged.integrate(m, span, t)
    psi, eps = prec.precession_angles(sol.y_eval)
    assert np.polyfit(t, psi, 1)[0] == pytest.approx(m.secular_rate(), rel=1e-9)
    assert np.ptp(eps) < 1e-10  # constant, to the tolerance (rtol 1e-12) over 3000 years
    assert psi[-1] > 0  # westward: retrograde


def test_18p6_year_nutation_of_the_averaged_model():
    m = model()
    span = 200 * YEAR
    t = np.arange(0.0, span, 20.0)
    sol = averaged.integrate(m, span, t)
    psi, eps = prec.precession_angles(sol.y_eval)
    args = fitting.arguments(m, m.secular_rate())
    fp, fe = fitting.fit(t, psi, args), fitting.fit(t, eps, args)
    closed_psi, closed_eps = m.nutation_18p6yr()
    assert fitting.amplitude(fp, "18.6 yr") == pytest.approx(closed_psi, rel=2e-3)
    assert fitting.amplitude(fe, "18.6 yr") == pytest.approx(closed_eps, rel=2e-3)
    assert fitting.amplitude(fp, "18.6 yr") / fitting.amplitude(fe, "18.6 yr") == pytest.approx(
        2 / np.tan(2 * EPS0), rel=2e-3
    )
    # the IAU's phase convention: dpsi = -A sin(Omega), deps = +B cos(Omega)
    assert fp.sin["18.6 yr"] / earth.ARCSEC == pytest.approx(-17.27, abs=0.05)
    assert fe.cos["18.6 yr"] / earth.ARCSEC == pytest.approx(9.22, abs=0.05)


def test_a_fixed_inclined_node_lets_the_obliquity_swing():
    m = model(("solar_torque", "lunar_torque", "lunar_inclination"))
    span = 13000 * YEAR
    sol = averaged.integrate(m, span, np.linspace(0, span, 2001))
    _, eps = prec.precession_angles(sol.y_eval)
    assert np.degrees(np.ptp(eps)) > 5.0  # degrees, not arcseconds


# --- rung 3: the full model -----------------------------------------------------------------------------


def test_couple_against_maccullagh_in_vectors():
    """torque_body against N = 3 GM/r^5 r x (I r) assembled independently in the space frame."""
    m = model()
    p = m.parameters()
    rng = np.random.default_rng(1)
    for _ in range(5):
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        t = rng.uniform(0, 3000)
        out = np.empty(3)
        prec.torque_body(t, q, p, out)
        total = np.zeros(3)
        R = _matrix(q)
        I_space = R @ np.diag([1 - m.H, 1 - m.H, 1.0]) @ R.T
        for k in (prec.SUN, prec.MOON):
            x, y, z, a3 = prec._body_position(t, p, k)
            r = np.array([x, y, z])
            total += p[k + 1] / 3 * a3 * 3 * np.cross(r, I_space @ r)  # p[k+1] = 3 GM/a^3, r unit
        assert R.T @ total == pytest.approx(out, abs=1e-9 * np.linalg.norm(out))


def _matrix(q):
    w, x, y, z = q
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def test_kepler_orbit_positions():
    from scipy.optimize import brentq

    m = model()
    p = m.parameters()
    for t in (0.0, 91.3, 200.0, 1234.5):
        x, y, z, a3 = prec._body_position(t, p, prec.SUN)
        M = p[prec.SUN_L0] + p[prec.SUN_N] * t - p[prec.SUN_VARPI]
        e = p[prec.SUN_E]
        M = np.mod(M, 2 * np.pi)
        E = brentq(lambda E: E - e * np.sin(E) - M, 0, 2 * np.pi)
        nu = 2 * np.arctan2(np.sqrt(1 + e) * np.sin(E / 2), np.sqrt(1 - e) * np.cos(E / 2))
        lon = nu + p[prec.SUN_VARPI]
        assert (x, y, z) == pytest.approx((np.cos(lon), np.sin(lon), 0.0), abs=1e-12)
        assert a3 == pytest.approx((1 / (1 - e * np.cos(E))) ** 3, rel=1e-12)
        # the Moon's position lies in its orbit plane, tilted by i, node regressing
        x, y, z, _ = prec._body_position(t, p, prec.MOON)
        node = p[prec.NODE0] + p[prec.NODE_RATE] * t
        normal = np.array(
            [np.sin(m.moon_i) * np.sin(node), -np.sin(m.moon_i) * np.cos(node), np.cos(m.moon_i)]
        )
        assert np.dot(normal, (x, y, z)) == pytest.approx(0.0, abs=1e-14)
        assert np.linalg.norm((x, y, z)) == pytest.approx(1.0, rel=1e-14)


def test_a_body_not_listed_is_not_evaluated():
    m = model(("solar_torque",))
    p = m.parameters()
    p[prec.MOON + 1 : prec.NODE_RATE + 1] = np.nan  # garbage in the Moon's block: never read
    out = np.empty(3)
    prec.torque_body(10.0, np.array([0.9, 0.1, 0.3, 0.2]) / np.linalg.norm([0.9, 0.1, 0.3, 0.2]), p, out)
    assert np.all(np.isfinite(out))


def test_symmetric_free_flow_is_exact():
    A, C = 0.7, 1.0
    m0 = np.array([0.3, -0.2, 1.1])
    q0 = np.array([1.0, 0.0, 0.0, 0.0])
    one = (m0.copy(), q0.copy())
    rigid_body.symmetric_free_flow(*one, A, C, 37.0)
    many = (m0.copy(), q0.copy())
    for _ in range(1000):
        rigid_body.symmetric_free_flow(*many, A, C, 0.037)
    assert one[0] == pytest.approx(many[0], abs=1e-12) and one[1] == pytest.approx(many[1], abs=1e-11)
    # closed form: m1 + i m2 turns at lambda = (C - A) m3 / (A C) (Lamb Art. 47, in m)
    lam = (C - A) / (A * C) * m0[2]
    z = (m0[0] + 1j * m0[1]) * np.exp(1j * lam * 37.0)
    assert one[0][0] + 1j * one[0][1] == pytest.approx(z, abs=1e-13)
    # and L in space is fixed
    L0 = rigid_body.rotate_to_space(q0, m0)[0]
    assert rigid_body.rotate_to_space(one[1], one[0])[0] == pytest.approx(L0, abs=1e-13)


def test_splitting_orders_on_the_torqued_earth():
    m = model(("solar_torque", "lunar_torque", "orbit_eccentricity"))
    span = 20.0

    def axis(h, order):
        _, ms, qs = full.integrate(m, span, h, order, sample_days=span)
        v = full.angular_momentum_axis(ms[-1:], qs[-1:])[0]
        return v / np.linalg.norm(v)

    ref = axis(1 / 96, 4)
    for order, expected in ((2, 4.0), (4, 16.0)):
        e1 = np.linalg.norm(axis(0.5, order) - ref)
        e2 = np.linalg.norm(axis(0.25, order) - ref)
        assert e1 / e2 == pytest.approx(expected, rel=0.3)


def test_full_sun_only_matches_secular_and_semiannual():
    m = model(("solar_torque",))
    fp, fe, args, *_ = full_rate(m, 10)
    assert fp.rate == pytest.approx(m.secular_rate(), rel=2e-5)
    a_psi, a_eps = m.semiannual()
    assert fitting.amplitude(fp, "semi-annual") == pytest.approx(a_psi, rel=2e-3)
    assert fitting.amplitude(fe, "semi-annual") == pytest.approx(a_eps, rel=2e-3)


def test_precession_is_retrograde_and_the_sign_comes_from_the_bulge():
    oblate = model(("solar_torque",))
    fp, *_ = full_rate(oblate, 2)
    assert fp.rate > 0  # westward: retrograde
    prolate = model(("solar_torque",), H=-earth.H_P03)
    fp, *_ = full_rate(prolate, 2)
    assert fp.rate < 0


def test_full_century_against_averaged_and_iau2000b():
    import erfa

    m = model()
    fp, fe, args, t, psi, eps = full_rate(m, 40)
    sol = averaged.integrate(m, t[-1], t)
    fa = fitting.fit(t, prec.precession_angles(sol.y_eval)[0], args)
    assert fp.rate == pytest.approx(fa.rate, rel=2e-5)
    d_psi, d_eps = erfa.nut00b(2451545.0, t)
    iau = {k: v for k, v in fitting.iau_arguments().items() if k in args}
    ip, ie = fitting.fit(t, d_psi, iau), fitting.fit(t, d_eps, iau)
    # 18.6-yr terms to 1 % in amplitude and in phase (sin/cos coefficients, IAU convention)
    assert fp.sin["18.6 yr"] == pytest.approx(ip.sin["18.6 yr"], rel=1e-2)
    assert fe.cos["18.6 yr"] == pytest.approx(ie.cos["18.6 yr"], rel=1e-2)
    # the rigid Earth's semi-annual term: within 5 % of the non-rigid IAU value, and below it
    assert 0.95 < fitting.amplitude(fp, "semi-annual") / fitting.amplitude(ip, "semi-annual") < 1.0


# --- hard cases -----------------------------------------------------------------------------------------


def test_a_millennium_keeps_L_and_the_mean_obliquity():
    m = model()
    t, ms, qs = full.integrate(m, 1000 * YEAR, 0.125)
    norms = np.linalg.norm(ms, axis=1)
    assert np.max(np.abs(norms / norms[0] - 1)) < full.L_BOUND
    psi, eps = prec.precession_angles(full.angular_momentum_axis(ms, qs))
    _, fe, _ = full.fit_series(m, t, psi, eps)
    assert abs(fe.rate * 36525 / earth.ARCSEC) < full.OBLIQUITY_RATE_BOUND
    assert abs(fe.offset - EPS0) / earth.ARCSEC < 0.1  # the mean obliquity is the scene's


def test_fitted_rate_does_not_depend_on_the_window():
    m = model()
    fp, fe, args, t, psi, eps = full_rate(m, 60)
    bare, fitted = [], []
    for w in (19.3, 23.7, 31.3, 42.1, 60.0):
        inside = t <= w * YEAR
        bare.append(np.polyfit(t[inside], psi[inside], 1)[0])
        fitted.append(fitting.fit(t[inside], psi[inside], args).rate)
    assert np.ptp(fitted) / np.mean(fitted) < full.ALIASING_BOUND
    assert np.ptp(bare) / np.mean(bare) > 1e-3  # what a bare line does


def test_starting_on_the_forced_state_leaves_no_free_wobble():
    m = model()
    step = full.FREE_NUTATION_STEP_HOURS / 24
    axis = full.free_wobble_amplitude(m, step, 2, forced=False)
    forced = full.free_wobble_amplitude(m, step, 2, forced=True)
    _, q0 = prec.initial_state(m)
    expected = np.linalg.norm(prec.forced_offset(m, q0)) / m.n
    assert axis == pytest.approx(expected, rel=0.05)
    assert forced / axis < 2 * m.orbits.moon_n / m.n


def test_the_start_puts_the_figure_axis_on_the_start_angles_and_the_spin_on_it():
    """initial_state's attitude, read by scipy's Rotation: the figure axis e3 at obliquity eps, turned by psi
    about the ecliptic pole, (sin eps sin psi, sin eps cos psi, cos eps); without the forced start the body
    spins about e3 alone, m = (0, 0, n) (C = 1); with it, m_perp = A omega_perp, omega_perp = e3 x N/(Cn)."""
    from scipy.spatial.transform import Rotation

    m = model()
    psi, eps = prec.start(m)
    for forced in (False, True):
        m_body, q = prec.initial_state(m, forced=forced)
        e3 = Rotation.from_quat([*q[1:], q[0]]).apply([0.0, 0.0, 1.0])
        assert e3 == pytest.approx(
            [np.sin(eps) * np.sin(psi), np.sin(eps) * np.cos(psi), np.cos(eps)], abs=1e-15
        )
        assert m_body[2] == m.n
        expected = (1.0 - m.H) * prec.forced_offset(m, q) if forced else [0.0, 0.0]
        assert m_body[:2] == pytest.approx(expected, rel=1e-15, abs=0.0)
    assert np.linalg.norm(m_body[:2]) > 0.0
    assert np.array_equal(prec.initial_state(m)[0], m_body)  # forced is the default


def test_ellipticity_enters_as_H_never_as_a_difference():
    """C - A from A and C in kg m^2 loses ~2.5 digits; the model carries H itself."""
    rng = np.random.default_rng(0)
    H = rng.uniform(3.2e-3, 3.3e-3, 2000)
    C = 8.0365e37
    A = C * (1 - H)
    naive = (C - A) / C
    assert np.max(np.abs(naive / H - 1)) > 20 * np.finfo(float).eps
    for h in H[:20]:
        assert model(H=h).parameters()[prec.H_] == h


# --- units: one test per conversion ---------------------------------------------------------------------


def test_spin_is_the_stellar_day():
    import erfa

    # the Earth rotation angle advances 2 pi x 1.00273781191135448 per UT1 day
    d = erfa.era00(2451545.0, 1.0) - erfa.era00(2451545.0, 0.0)
    assert np.mod(d, 2 * np.pi) == pytest.approx(np.mod(prec.modern().spin, 2 * np.pi), abs=1e-12)


def test_julian_against_tropical_years_through_the_precession():
    # the Sun returns to the moving equinox sooner: 1/T_tropical = 1/T_sidereal + (psi'/360 deg)
    rate_turns_per_day = model().secular_rate() / (2 * np.pi)
    tropical = 1.0 / (1.0 / prec.SIDEREAL_YEAR_DAYS + rate_turns_per_day)
    assert tropical == pytest.approx(earth.TROPICAL_YEAR_DAYS, abs=2e-4)
    # and rates per Julian year convert to the IAU's per Julian century by 100 exactly
    assert fitting.per_year_arcsec(1e-7) * 100 == pytest.approx(1e-7 * 36525 / earth.ARCSEC, rel=1e-15)


def test_node_period_against_the_stars_and_the_equinox():
    # The model's frame is fixed, so the node it turns must regress against the stars. The published nodal
    # period, 18.61 yr = 6798.4 d (reference digest, modern values), is counted from the equinox, which itself
    # regresses at p_A = 5028.796195"/cy (IAU 2006): rates add, 1/P_stars = 1/P_equinox + p_A/360 deg.
    rate = model().parameters()[prec.NODE_RATE]  # rad/day, what the integrator uses
    against_stars = 1.0 / (1.0 / 6798.4 + 5028.796195 / 3600.0 / 360.0 / 36525.0)
    assert rate < 0  # the node regresses
    # 6798.4 is given to 0.05 d; forgetting p_A, or adding it with the wrong sign, is off by about 5 d
    assert -2 * np.pi / rate == pytest.approx(against_stars, abs=0.06)


# --- scenes ---------------------------------------------------------------------------------------------

GOOD = {
    "title": "x",
    "fidelity": "full",
    "constants": "modern",
    "earth": {
        "H": 0.00327,
        "H_definition": "(C-A)/C",
        "H_source": "s",
        "obliquity_deg": 23.4,
        "obliquity_source": "s",
    },
    "effects": {"solar_torque": None},
    "analysis": {"span_years": 1, "step_hours": 3},
}


@pytest.mark.parametrize(
    "change,field",
    [
        (lambda d: d["effects"].update(magic=None), "effects.magic"),
        (lambda d: d["earth"].update(obliquity_deg=200), "earth.obliquity_deg"),
        (lambda d: d["earth"].update(obliquity_deg=-1), "earth.obliquity_deg"),
        (lambda d: d["earth"].update(H=0), "earth.H"),
        (lambda d: d["earth"].update(H=-0.003), "earth.H"),
        (lambda d: d["analysis"].pop("step_hours"), "analysis.step_hours"),
        (lambda d: d["analysis"].update(step_hours=48), "analysis.step_hours"),
        (lambda d: d["effects"].update(node_regression=None), "effects.node_regression"),
        (lambda d: d.update(effects={"orbit_eccentricity": None}), "effects"),
    ],
)
def test_bad_scenes_name_the_field(tmp_path, change, field):
    import copy

    data = copy.deepcopy(GOOD)
    change(data)
    assert_refused(tmp_path, "precession", data, field)


def test_the_good_scene_and_every_shipped_scene_validate(tmp_path):
    path = tmp_path / "good.yaml"
    path.write_text(yaml.safe_dump(GOOD))
    validate("precession", path)
    for scene in sorted((ROOT / "workflow/scenes/precession").glob("*.yaml")):
        validate("precession", scene)


def test_lamb_examples_from_the_model():
    """Ex. VI.5 from the torque routine and Ex. XI.1 from Euler's equations, each against its closed form
    written out here from the example's data (not the module's own closed-form number) and Lamb's answer."""
    from classical_dynamics.studies.precession import examples

    line = examples.moon_line_offset(rho=60, declination_deg=28, C_minus_A=0.00109)
    d = np.radians(28)
    assert line.offset_radii == pytest.approx(3 * 0.00109 * np.sin(d) * np.cos(d) / 60, rel=1e-13)
    assert line.offset_radii == pytest.approx(0.0000225, rel=0.01)  # Lamb's answer
    assert line.offset_ft is None  # no Earth radius given
    gyro = examples.gyroscope_couple(
        weights_lb=[300, 35],
        radii_of_gyration_ft=[1.0, 2.5],
        spin_rev_per_s=20,
        turn_period_s=10,
        g=32.2,
        transverse_over_axial=0.3,
    )
    C = (300 * 1.0**2 + 35 * 2.5**2) / 32.2  # slug ft^2
    assert gyro.C == pytest.approx(C, rel=1e-14)
    # C n psi' with n = 2 pi 20 /s, psi' = 2 pi/10 /s
    assert gyro.couple == pytest.approx(C * 40 * np.pi * 0.2 * np.pi, rel=1e-13)
    assert gyro.closed_form == pytest.approx(C * 40 * np.pi * 0.2 * np.pi, rel=1e-14)  # the module's C n psi'
    assert gyro.couple == pytest.approx(1270, rel=0.005)  # Lamb: [1270 ft.-lbs.]


def test_the_suns_obliquity_sidebands_are_e_and_7e_over_3_of_the_semiannual_term():
    """The closed form against the couple itself: the obliquity rate goes as (a/r)^3 sin 2 lambda; its
    harmonics in the mean anomaly, from Kepler's equation solved here and an FFT, integrated over their
    frequencies (1, 2, 3 n'), give the annual, semi-annual and 122-day amplitudes."""
    from scipy.optimize import brentq

    e, varpi = 1e-3, 1.3  # a small e: the closed form is first order
    M = 2 * np.pi * np.arange(4096) / 4096
    E = np.array([brentq(lambda x: x - e * np.sin(x) - m, m - 1, m + 1) for m in M])
    nu = 2 * np.arctan2(np.sqrt(1 + e) * np.sin(E / 2), np.sqrt(1 - e) * np.cos(E / 2))
    rate = (1 / (1 - e * np.cos(E))) ** 3 * np.sin(2 * (nu + varpi))
    c = np.abs(np.fft.rfft(rate)) / len(M)
    annual, semiannual, day122 = c[1] / 1, c[2] / 2, c[3] / 3
    m = model(("solar_torque", "orbit_eccentricity"), orbits=dataclasses.replace(prec.modern(), sun_e=e))
    closed_annual, closed_122 = m.solar_obliquity_sidebands()
    assert closed_annual / m.semiannual()[1] == pytest.approx(annual / semiannual, rel=3e-3)
    assert closed_122 / m.semiannual()[1] == pytest.approx(day122 / semiannual, rel=3e-3)


def test_the_advancing_perigee_moves_the_monthly_term_to_the_anomalistic_month():
    """With the perigee fixed, l and 2L - l turn together and the Moon's 2L - l obliquity term (e times the
    fortnightly, first order) lands on the monthly argument; advancing, the monthly argument turns in the
    anomalistic month (27.55 d, IAU's l) and the rigid Earth's monthly obliquity term is small."""
    fixed = model(("lunar_torque", "orbit_eccentricity"))
    advancing = model(("lunar_torque", "orbit_eccentricity", "lunar_perigee_advance"))
    anomalistic = 2 * np.pi / (advancing.orbits.moon_n - advancing.perigee_rate)
    assert anomalistic == pytest.approx(27.554550, abs=1e-4)  # the anomalistic month (Simon et al. 1994)
    amplitudes = {}
    for name, m in (("fixed", fixed), ("advancing", advancing)):
        fp, fe, *_ = full_rate(m, 20)
        amplitudes[name] = fitting.amplitude(fe, "monthly"), fitting.amplitude(fe, "fortnightly")
    monthly, fortnightly = amplitudes["fixed"]
    assert monthly == pytest.approx(prec.modern().moon_e * fortnightly, rel=0.05)
    assert amplitudes["advancing"][0] < 0.1 * monthly


def test_the_perigee_advance_is_refused_where_it_cannot_act(tmp_path):
    data = yaml.safe_load((ROOT / "workflow/scenes/precession/averaged_cycle.yaml").read_text())
    data["effects"]["lunar_perigee_advance"] = None
    assert_refused(tmp_path, "precession", data, "effects.lunar_perigee_advance")
