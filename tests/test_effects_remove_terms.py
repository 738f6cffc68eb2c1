"""Issue 34: in every study the model is its scene's effects. Removing one effect removes its term, and the
result changes as the physics says: each check is a closed form written out here (Lamb, Lee, the string's
modes), not a number the model computes about itself. (What each effect costs is measured by
benchmarks/, never here: no test reads the clock.)"""

from __future__ import annotations

import numpy as np
import pytest

from classical_dynamics.models import chains, earth, wobble
from classical_dynamics.models import heavy_top as top_model
from classical_dynamics.models import precession as prec
from classical_dynamics.models import self_excited as se
from classical_dynamics.models.viscous_medium import viscous_symmetric
from classical_dynamics.solvers.ode import Problem, solve
from classical_dynamics.studies.self_excited import viscous
from classical_dynamics.studies.solvers import EFFECTS as SOLVER_EFFECTS


# --- chains: a string of beads with springs beside its tension ------------------------------------------
def _squared_frequencies(effects, n=5, length_m=1.2, mass_kg=0.2):
    chain = chains.particle_chain(n, "fixed-fixed", length_m, mass_kg, effects)
    return np.linalg.eigvalsh(chain.stiffness_matrix()) / mass_kg


@pytest.mark.parametrize("removed", [None, "tension", "springs"])
def test_chains_removing_tension_or_springs_removes_its_stiffness(removed):
    """n equal beads, fixed ends: omega_s^2 = (4 kappa/m) sin^2(s pi / 2(n + 1)), with the segment stiffness
    kappa = P/a + k the sum of what is listed (Lamb's loaded string, Rayleigh's springs)."""
    n, length, m, P, k = 5, 1.2, 0.2, 2.0, 3.0
    effects = {"tension": {"newton": P}, "springs": {"k_n_per_m": k}}
    effects.pop(removed, None)
    a = length / (n + 1)
    kappa = (P / a if "tension" in effects else 0.0) + (k if "springs" in effects else 0.0)
    s = np.arange(1, n + 1)
    expected = 4.0 * kappa / m * np.sin(s * np.pi / (2 * (n + 1))) ** 2
    assert _squared_frequencies(effects, n, length, m) == pytest.approx(expected, rel=1e-12)


def test_chains_removing_friction_leaves_no_damping():
    listed = chains.particle_chain(
        4, "fixed-fixed", 1.0, 0.1, {"tension": {"newton": 1.0}, "friction": {"b_kg_per_s": 0.3}}
    )
    bare = chains.particle_chain(4, "fixed-fixed", 1.0, 0.1, {"tension": {"newton": 1.0}})
    assert listed.damping == pytest.approx(np.full(4, 0.3)) and bare.damping is None
    assert set(bare.contributions) == {"tension"}


# --- Chandler: elastic yielding and dissipation ----------------------------------------------------------
def _wobble(effects, H=earth.H_P03, periods=3.0):
    """y = omega/n from a 1e-6 tilt; (measured rate of y1 + i y2 in rad/day, slope of log|y1 + i y2|)."""
    model = wobble.assemble(H, effects)
    euler_period = 2 * np.pi / (model.n * H / (1 - H))
    t = np.linspace(0.0, periods * 1.6 * euler_period, 4001)
    sol = solve(
        Problem(wobble.liouville, [1e-6, 0.0, 1.0], (0.0, t[-1]), model.parameters()),
        rtol=1e-12,
        atol=1e-16,
        t_eval=t,
    )
    z = sol.y_eval[:, 0] + 1j * sol.y_eval[:, 1]
    rate = np.polyfit(t, np.unwrap(np.angle(z)), 1)[0]
    decay = np.polyfit(t, np.log(np.abs(z)), 1)[0]
    return model, abs(rate), decay


def test_chandler_removing_elastic_yielding_gives_eulers_period_back():
    """Rigid: sigma/n = (C - A)/A = H/(1 - H) (Lamb Art. 47); elastic: (C - A - beta n^2)/(A + beta n^2)
    (Art. 71 (14)), with beta n^2 the effect's own input (k2 = 0.30)."""
    H = earth.H_P03
    _, rigid, _ = _wobble({})
    model, elastic, _ = _wobble({"elastic_yielding": {"k2": 0.30}})
    n, b = model.n, model.beta_n2
    assert rigid == pytest.approx(n * H / (1 - H), rel=1e-7)
    assert elastic == pytest.approx(n * (H - b) / (1 - H + b), rel=1e-7)
    assert 2 * np.pi / elastic > 1.4 * 2 * np.pi / rigid  # Newcomb's lengthening: from 305 d to over 430


def test_chandler_removing_dissipation_stops_the_decay():
    """With Q the amplitude falls as exp(-sigma t / 2Q), sigma the wobble's rate; without it, it keeps."""
    _, _, kept = _wobble({})
    _, damped_rate, decay = _wobble({"dissipation": {"Q": 50.0}})
    assert abs(kept) < 1e-12
    assert decay == pytest.approx(-damped_rate / (2 * 50.0), rel=2e-3)


# --- precession: the Moon's couple ----------------------------------------------------------------------
def _averaged_rate(effects, years=200.0):
    """The equinox's westward rate (rad/day) from the averaged equations, a linear fit of its longitude."""
    eps = np.radians(23.44)
    model = prec.assemble(earth.H_P03, eps, prec.modern(), {name: {} for name in effects})
    t = np.linspace(0.0, years * 365.25, 201)
    s0 = np.array([0.0, np.sin(eps), np.cos(eps)])  # the equinox on the x-axis
    sol = solve(
        Problem(prec.averaged_rhs, s0, (0.0, t[-1]), prec.averaged_parameters(model)),
        rtol=1e-12,
        atol=1e-15,
        t_eval=t,
    )
    s = sol.y_eval
    longitude = np.unwrap(np.arctan2(-s[:, 0], s[:, 1]))
    return model, -np.polyfit(t, longitude, 1)[0], eps


def test_precession_removing_the_moons_couple_leaves_the_suns_rate():
    """Lamb Art. 61 (7): each body adds (3/2)(GM/a^3)(H/n) cos eps (circular orbits in the ecliptic here);
    the Moon's share is about twice the Sun's (Lamb: 2.18)."""
    model, sun_only, eps = _averaged_rate(["solar_torque"])
    _, both, _ = _averaged_rate(["solar_torque", "lunar_torque"])
    o, k = model.orbits, 1.5 * model.H / model.n * np.cos(eps)
    assert sun_only == pytest.approx(k * o.sun_gm_over_a3, rel=1e-6)
    assert both == pytest.approx(k * (o.sun_gm_over_a3 + o.moon_gm_over_a3), rel=1e-6)
    assert 2.0 < (both - sun_only) / sun_only < 2.4


# --- the self-excited body: the quadratic torque, the constant torque, the medium's drag -------------------
def _plane_run(effects, delta=1.0, tau=20.0):
    m1, nu = se.plane_torque(effects)
    L = se.LargestAxis.for_scene(se.Body(3.0, 2.2, 1.2), m1, -nu, delta)
    t = np.linspace(0.0, tau, 801)
    sol = solve(
        Problem(se.plane_largest, [0.3, 0.8], (0.0, tau), [L.m1, L.mu1, 1.0]),
        rtol=1e-12,
        atol=1e-14,
        t_eval=t,
    )
    phi, p1 = sol.y_eval.T
    return L, t, phi, p1


def test_self_excited_removing_the_quadratic_torque_makes_the_plane_conservative():
    """Lee (2.10), phi2'' = m1 + sin phi2 + mu1 p1^2: without mu1, E = p1^2/2 + cos phi2 - m1 phi2 is kept;
    with it, dE/dtau = mu1 p1^3."""
    listed = {"body_torque": {"m1": 0.5}, "quadratic_torque": {"nu": 0.1}}
    L, t, phi, p1 = _plane_run(listed)
    E = 0.5 * p1**2 + np.cos(phi) - L.m1 * phi
    gained = np.concatenate(
        [[0.0], np.cumsum(0.5 * np.diff(t) * (L.mu1 * p1[1:] ** 3 + L.mu1 * p1[:-1] ** 3))]
    )
    assert np.max(np.abs(E - E[0] - gained)) < 1e-4 * np.max(np.abs(gained))
    L, t, phi, p1 = _plane_run({"body_torque": {"m1": 0.5}})
    assert L.mu == 0.0
    E = 0.5 * p1**2 + np.cos(phi) - L.m1 * phi
    assert np.max(np.abs(E - E[0])) < 1e-8  # rounding of rtol 1e-12 over 20 time units


def test_self_excited_removing_every_torque_leaves_eulers_free_body():
    """No effect listed: no torque at all (m = mu = 0), and Euler's equations keep 2T and |L|^2."""
    L = se.LargestAxis.for_scene(se.Body(3.0, 2.2, 1.2), *se.plane_torque({}), 1.0)
    assert (L.m, L.mu) == (0.0, 0.0)
    w0 = L.from_plane(0.3, 0.8)
    sol = solve(Problem(se.euler_largest, w0, (0.0, 30.0), L.euler_parameters()), rtol=1e-12, atol=1e-14)
    end = sol.y  # the final state
    moments = np.array([3.0, 2.2, 1.2])
    assert np.sum(moments * end**2) == pytest.approx(np.sum(moments * w0**2), rel=1e-10)  # 2T
    assert np.sum((moments * end) ** 2) == pytest.approx(np.sum((moments * w0) ** 2), rel=1e-10)  # |L|^2


@pytest.mark.parametrize("drag", [True, False])
def test_self_excited_removing_the_drag_lets_the_axial_spin_grow(drag):
    """Lee (5.49), r' = m3 - mu r: with drag r = m3/mu + (r0 - m3/mu) e^{-mu t}; without it r = r0 + m3 t."""
    m, nu, mu, r0 = [0.4, -0.2, 0.3], 0.3, 0.5, 2.0
    effects = {"body_torque": {"m": m}, **({"drag": {"nu": nu, "mu": mu}} if drag else {})}
    V = viscous.medium(
        {"body": {"moments": [2.5, 2.5, 1.0]}, "viscous": {"omega0": [0.5, 0.8, r0]}, "effects": effects}
    )
    t = np.linspace(0.0, 10.0, 51)
    sol = solve(
        Problem(viscous_symmetric, [0.5, 0.8, r0], (0.0, 10.0), V.parameters()),
        rtol=1e-12,
        atol=1e-14,
        t_eval=t,
    )
    expected = m[2] / mu + (r0 - m[2] / mu) * np.exp(-mu * t) if drag else r0 + m[2] * t
    assert sol.y_eval[:, 2] == pytest.approx(expected, rel=1e-10)


# --- solvers: the heavy top's gravity ---------------------------------------------------------------------
def test_solvers_removing_gravity_leaves_a_free_top():
    """Without the weight, Euler's free symmetric top: omega_3 and the equatorial |omega| are constant and
    omega_perp turns at (C - A) omega_3 / A (Lamb Art. 47)."""
    A, C = 1.0, 0.6
    for effects, Mgh in (({"gravity": {"Mgh": 0.8}}, 0.8), ({}, 0.0)):
        assert SOLVER_EFFECTS.assemble(effects, None).get("gravity", 0.0) == Mgh
    w0 = np.array([0.3, 0.0, 5.0])
    y0 = np.concatenate([w0, [0.2, 0.0, np.sqrt(1 - 0.04)], [1.0, 0.0, 0.0]])
    t = np.linspace(0.0, 3.0, 31)
    sol = solve(Problem(top_model.top_gravity, y0, (0.0, 3.0), [A, C, 0.0]), rtol=1e-12, atol=1e-14, t_eval=t)
    lam = (C - A) * w0[2] / A
    z = (w0[0] + 1j * w0[1]) * np.exp(1j * lam * t)
    assert sol.y_eval[:, 0] + 1j * sol.y_eval[:, 1] == pytest.approx(z, abs=1e-11)
    heavy = solve(
        Problem(top_model.top_gravity, y0, (0.0, 3.0), [A, C, 0.8]), rtol=1e-12, atol=1e-14, t_eval=t
    )
    assert np.max(np.abs(heavy.y_eval[:, 0] + 1j * heavy.y_eval[:, 1] - z)) > 1e-2


def test_a_scene_without_a_constant_torque_reduces_by_lees_definitions():
    """Lee §2: without body_torque m = 0, and mu1 = mu/(2 sqrt(bc)), m1 = mu delta^2 (b + c)/(delta^2 R),
    R = sqrt(a^2 bc + mu^2 (b - c)^2), with a, b, c = (B - C)/A, (A - C)/B, (A - B)/C written out here."""
    A, B, C = 3.0, 2.2, 1.2
    a, b, c = (B - C) / A, (A - C) / B, (A - B) / C
    mu1, delta = -0.15, 0.8
    L = se.LargestAxis.for_scene(se.Body(A, B, C), None, mu1, delta)
    mu = 2.0 * np.sqrt(b * c) * mu1
    R = np.sqrt(a**2 * b * c + mu**2 * (b - c) ** 2)
    assert L.m == 0.0 and L.mu == pytest.approx(mu, rel=1e-15)
    assert L.m1 == pytest.approx(mu * delta**2 * (b + c) / (delta**2 * R), rel=1e-14)
