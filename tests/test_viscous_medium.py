"""Lee §5: the generalized sine and cosine integrals, and the symmetric body in a viscous medium.

References: mpmath at 30 digits (the incomplete gamma function, itself checked against mpmath's
oscillatory quadrature), scipy's Fresnel integrals, Euler's equations integrated, and the reference
digest's own numbers (§6 items 13, 18, 24, 25)."""

from __future__ import annotations

import copy
import math

import mpmath
import numpy as np
import pytest
from scipy import special

from classical_dynamics.models.viscous_medium import ViscousMedium, symmetric_axis, viscous_symmetric
from classical_dynamics.solvers import sine_cosine_integrals as sc
from classical_dynamics.solvers.ode import Problem, solve

from .conftest import ROOT, assert_refused

W = [0.3 + 0.4j, 1.7 + 0.5j, 1.6, 2.6 + 0.72j, 3.3 - 0.2j, 4.45 + 1.0j]


def test_reference_is_the_integral_itself():
    """The incomplete-gamma reference against mpmath's oscillatory quadrature of the definition, at 18 digits:
    they agree to 5e-20, four orders under the 1e-15 asked (20 digits: 4e-22, in 2.2 s rather than 1.3)."""
    with mpmath.workdps(18):
        for w, x in ((0.3 + 0.4j, 2.0), (1.7 + 0.5j, 0.7), (1.6, 5.0)):
            si = -mpmath.quadosc(lambda u: mpmath.sin(u) * u ** (-mpmath.mpc(w)), [x, mpmath.inf], omega=1)
            ci = -mpmath.quadosc(lambda u: mpmath.cos(u) * u ** (-mpmath.mpc(w)), [x, mpmath.inf], omega=1)
            ref_si, ref_ci = sc.reference(x, w)
            assert abs(si - ref_si) < 1e-15 and abs(ci - ref_ci) < 1e-15


@pytest.mark.parametrize("w", W)
@pytest.mark.parametrize("x", [0.05, 0.5, 2.0, 8.0])
def test_series_with_the_reduction_within_its_bound(w, x):
    """(5.38)/(5.39) lifted by (5.32)/(5.33) to K = 0..4: error within the stated bound, and small."""
    ref_si, ref_ci = (complex(v) for v in sc.reference(x, w))
    v = sc.series(x, w)
    error = max(abs(v.si - ref_si), abs(v.ci - ref_ci))
    assert error <= v.bound
    assert error <= 1e-13 * max(1.0, abs(ref_si), abs(ref_ci))


@pytest.mark.parametrize("w", W)
@pytest.mark.parametrize("x", [25.0, 30.0, 60.0])
def test_asymptotic_expansion_within_its_bound(w, x):
    ref_si, ref_ci = (complex(v) for v in sc.reference(x, w))
    v = sc.asymptotic(x, w)
    assert max(abs(v.si - ref_si), abs(v.ci - ref_ci)) <= v.bound < 1e-11


@pytest.mark.parametrize("x", [0.5, 2.0, 10.0, 16.0, 30.0])
def test_quadrature_and_the_automatic_choice(x):
    w = 1.6 + 0.72j
    ref_si, ref_ci = (complex(v) for v in sc.reference(x, w))
    for v in (sc.quadrature(x, w), sc.si_ci(x, w)):
        assert max(abs(v.si - ref_si), abs(v.ci - ref_ci)) < 1e-13


def test_digest_numbers_for_the_series_and_the_expansion():
    """Digest §6 item 24: x = 2, w' = 0.3 + 0.4i, N = 6 terms: the error of si is 1.5e-7, under the bound
    (5.40), x^(2N+1-a)/((2N)!(2N+1-a)) = 1.1e-6 (the Value's bound also covers ci, whose (5.41) is larger).
    Item 25 says the expansion at x = 30 is good to about 1e-10 with 4 terms; we find 2.3e-6 with 4 terms,
    2.9e-9 with 4 of H and 4 of G, and 1e-10 needs 10 (digest disagreement, reported in the issue note). What
    must hold is the remainder bound (5.45), for every count."""
    ref_si, ref_ci = (complex(v) for v in sc.reference(2.0, 0.3 + 0.4j))
    v = sc.series(2.0, 0.3 + 0.4j, terms=6)
    assert abs(v.si - ref_si) == pytest.approx(1.5e-7, rel=0.05)
    assert abs(v.si - ref_si) < 2.0**12.7 / (math.factorial(12) * 12.7) == pytest.approx(1.1e-6, rel=0.02)
    assert max(abs(v.si - ref_si), abs(v.ci - ref_ci)) <= v.bound
    ref_si, ref_ci = (complex(v) for v in sc.reference(30.0, 0.3 + 0.4j))
    errors = []
    for terms in (2, 4, 8, 12, 20):
        v = sc.asymptotic(30.0, 0.3 + 0.4j, terms=terms)
        errors.append(max(abs(v.si - ref_si), abs(v.ci - ref_ci)))
        assert errors[-1] <= v.bound
    assert errors == sorted(errors, reverse=True) and errors[-1] < 1e-12


@pytest.mark.parametrize("x", [0.3, 2.0, 7.0, 40.0])
def test_order_one_half_is_fresnel(x):
    """Digest item 26: int_0^x sin u/sqrt(u) du = sqrt(2 pi) S(sqrt(2x/pi)), and C likewise."""
    S, C = special.fresnel(np.sqrt(2 * x / np.pi))
    v = sc.si_ci(x, 0.5)
    assert abs(v.si + sc.A(0.5) - np.sqrt(2 * np.pi) * S) < 1e-13
    assert abs(v.ci + sc.B(0.5) - np.sqrt(2 * np.pi) * C) < 1e-13


def test_integer_order_is_refused():
    for w in (1.0, 2.0, 3.0 + 0.5j, -0.5):
        with pytest.raises(ValueError, match="Re w"):
            sc.series(1.0, w)


# --- the body in the medium -------------------------------------------------------------------------


def lee(m3=0.0, r0=2.0, nu=0.3, mu=0.5, h=0.6):
    return ViscousMedium(h, nu, mu, (0.4, -0.2, m3), (0.5, 0.8, r0))


def test_digest_reference_values_and_the_limit():
    """Digest §6 items 13 and 18 (its own computation, not this code's)."""
    y, _ = lee().closed_form([2.0])
    assert y[0, 0] == pytest.approx(0.7763809212, abs=1e-9) and y[0, 1] == pytest.approx(
        -0.7731868358, abs=1e-9
    )
    V = lee(m3=0.3)
    y, _ = V.closed_form([4.0])
    assert y[0, 0] == pytest.approx(0.0837643573, abs=1e-9) and y[0, 1] == pytest.approx(
        -1.0299593254, abs=1e-9
    )
    assert V.limit() == pytest.approx([0.21857923, -0.92896175, 0.6], abs=1e-8)


@pytest.mark.parametrize(
    "V,case",
    [
        (lee(r0=0.0), "I"),
        (lee(), "II"),
        (lee(m3=0.3), "III"),
        (lee(m3=0.3, r0=-2.0), "III"),
        (lee(m3=0.3, r0=0.6), "III (g = 0)"),
        (lee(m3=0.3, h=0.0), "IV"),
        (lee(m3=0.3, h=-0.4), "III"),
        (lee(nu=0.0, mu=0.0), "II"),
        (lee(m3=0.3, nu=0.0, mu=0.0), "III"),
        (lee(m3=0.3, r0=-2.0, nu=0.0, mu=0.0), "III"),
    ],
)
def test_lees_quadratures_against_eulers_equations(V, case):
    """Every case of §5.3, with and without friction (Fresnel's form for frictionless Case III)."""
    assert V.case == case
    t = np.linspace(0.0, 25.0, 51)
    ode = solve(
        Problem(viscous_symmetric, list(V.omega0), (0.0, t[-1]), V.parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        t_eval=t,
    )
    y, bound = V.closed_form(t)
    assert np.max(np.abs(y - ode.y_eval)) < 1e-10
    assert np.all(bound < 1e-9)


def test_large_order_the_bound_warns():
    """Hard case (digest §7 item 9): with mu small against nu, w = 7.4 + 72i and the integrals are tiny
    numbers multiplied by |g|^(nu/mu)/mu ~ 1e12. The formula loses digits, and its own bound says so (it
    holds)."""
    V = ViscousMedium(0.6, 0.32, 0.05, (0.4, -0.2, 0.3), (0.5, 0.8, 2.0))
    t = np.array([5.0, 20.0, 40.0])
    y, bound = V.closed_form(t)
    exact, _ = V.closed_form(t, integrals=sc.reference_value)
    error = np.hypot(*(y[:, :2] - exact[:, :2]).T)
    assert np.all(error <= bound + 1e-13)
    assert bound.max() > 1e-6  # it does warn


def test_limit_bounds_and_circles_from_the_equations():
    """Theorem 3 (with friction): omega tends to the stated rotation; Theorem 1 bounds hold. Theorem 2
    (no friction, m3 = 0): circles about (m2/(h r0), -m1/(h r0)) with period 2 pi/|h r0|."""
    V = lee(m3=0.3)
    ode = solve(
        Problem(viscous_symmetric, list(V.omega0), (0.0, 80.0), V.parameters()),
        "dop853",
        rtol=1e-12,
        atol=1e-14,
        t_eval=np.linspace(0, 80, 801),
    )
    assert np.max(np.abs(ode.y_eval[-1] - V.limit())) < 1e-9
    pq, r = V.bounds()
    assert np.max(np.abs(ode.y_eval[:, :2])) < pq and np.max(np.abs(ode.y_eval[:, 2])) < r
    V = lee(nu=0.0, mu=0.0)
    period = 2 * np.pi / abs(V.h * V.omega0[2])
    ode = solve(
        Problem(viscous_symmetric, list(V.omega0), (0.0, period), V.parameters()),
        "dop853",
        rtol=1e-13,
        atol=1e-15,
        t_eval=np.linspace(0, period, 101),
    )
    center = V.circle_center()
    radius = np.hypot(ode.y_eval[:, 0] - center[0], ode.y_eval[:, 1] - center[1])
    assert np.ptp(radius) < 1e-11 and np.max(np.abs(ode.y_eval[-1] - ode.y_eval[0])) < 1e-11


def test_symmetric_axis_in_any_order():
    assert symmetric_axis([1.0, 2.5, 2.5]) == (2.5, 1.0) == symmetric_axis([2.5, 1.0, 2.5])
    assert symmetric_axis([3.0, 2.2, 1.2]) is None


def _scene():
    import yaml

    return yaml.safe_load((ROOT / "workflow/scenes/self_excited/viscous_constant_torque.yaml").read_text())


@pytest.mark.parametrize(
    "change,field",
    [
        (lambda d: d["body"].update(moments=[3.0, 2.2, 1.2]), "body.moments"),
        (lambda d: d["effects"]["drag"].update(nu=1.0), "effects.drag.nu"),  # nu/mu = 2: w' = 0
        (lambda d: d["effects"]["drag"].update(mu=0.0), "effects.drag.mu"),
        (lambda d: d["effects"]["body_torque"].update(m=[0.0, 0.0, 0.0]), "effects.body_torque.m"),
        (lambda d: d["viscous"].update(nu=0.3), "viscous.nu"),  # now effects.drag.nu
        (lambda d: d.update(torque_axis="largest"), "torque_axis"),
        (lambda d: d["viscous"].update(omega0=[0.5, float("nan"), 2.0]), "viscous.omega0"),
    ],
)
def test_bad_viscous_scenes_name_the_field(tmp_path, change, field):
    data = copy.deepcopy(_scene())
    change(data)
    assert_refused(tmp_path, "self_excited", data, field)
