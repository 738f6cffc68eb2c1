"""The work-precision harness (solvers/workprecision.py): its error figures against closed forms, its fitted
orders against errors built to a known order, and its figures' data."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import pytest

from classical_dynamics.figure_style import legend_below
from classical_dynamics.models.rigid_body import oscillator
from classical_dynamics.solvers import references
from classical_dynamics.solvers import workprecision as wp
from classical_dynamics.solvers.ode import Problem


def oscillator_case(t1=3.0, a=1.0):
    """x'' = -x from (a, 0): a (cos t, -sin t); the energy x^2 + v^2 is a^2."""
    return wp.Case(
        "oscillator",
        Problem(oscillator, np.array([a, 0.0]), (0.0, t1), np.array([1.0])),
        lambda t: a * np.stack([np.cos(t), -np.sin(t)], axis=-1),
        {"energy": lambda y: y[:, 0] ** 2 + y[:, 1] ** 2},
    )


def test_sweep_reports_the_errors_of_a_run_it_is_given():
    """A stand-in method whose every output is the closed form plus a known offset: each figure of the row
    is that offset, worked out here."""
    case = oscillator_case()
    t = np.linspace(0.0, 3.0, 7)
    exact = case.exact

    w = np.array([3.0, 0, 1, 1, 1, 1, 1])[:, None]  # the worst step is the first

    def run(setting, record):
        off = np.array([setting, -2 * setting])
        y_steps = exact(t) + w * off
        return wp.Run(t, y_steps, exact(case.dense_t) + off / 2, exact(3.0) + off, 11, 6)

    frame = wp.sweep(case, [wp.Entry("stand-in", "tolerance", run, [1e-3, 1e-6])], repeats=1, budget_s=0.0)
    assert list(frame.setting) == [1e-3, 1e-6]
    scale = np.max(np.abs(exact(3.0)))  # |cos 3| > |sin 3|
    for _, row in frame.iterrows():
        e = row.setting
        assert row.error_final == pytest.approx(2 * e, rel=1e-9)
        assert row.error_max_steps == pytest.approx(6 * e, rel=1e-9)
        assert row.error_dense == pytest.approx(e, rel=1e-9)
        assert row.digits == pytest.approx(-np.log10(2 * e / abs(np.cos(3.0))), rel=1e-9)
        assert scale == pytest.approx(abs(np.cos(3.0)))
        assert (row.steps, row.evaluations, row.problem, row.kind) == (6, 11, "oscillator", "tolerance")
        energy = (np.cos(t) + w[:, 0] * e) ** 2 + (-np.sin(t) - 2 * w[:, 0] * e) ** 2
        assert row.energy_drift == pytest.approx(np.max(np.abs(energy - energy[0])) / energy[0], rel=1e-6)
        assert row.seconds >= 0 and row.runs >= 1


def test_adaptive_entry_errors_against_the_closed_form():
    """Amplitude 1e-4: the absolute tolerance (reltol/1000) decides the error."""
    a = 1e-4
    case = oscillator_case(a=a)
    entry = wp.adaptive(case, "dop853")
    entry.settings = [1e-5, 1e-10]
    frame = wp.sweep(case, [entry], repeats=1, budget_s=0.0)
    loose, tight = frame.iloc[0], frame.iloc[1]
    run = entry.run(1e-10, True)
    assert tight.error_final == pytest.approx(
        np.max(np.abs(run.y_final - a * np.array([np.cos(3), -np.sin(3)])))
    )
    assert tight.error_final < 1e-9 * a < loose.error_final < 1e-3 * a
    assert run.t_steps[0] == 0.0 and run.t_steps[-1] == 3.0 and len(run.y_dense) == 100
    assert tight.steps > loose.steps and tight.evaluations > loose.evaluations


def test_splitting_entry_converges_at_its_order_to_the_elliptic_solution():
    I = np.array([1.0, 2.0, 3.0])
    m0 = I * np.array([0.4, 0.2, 0.9])
    case = wp.Case(
        "free body",
        Problem(oscillator, m0 / I, (0.0, 9.9), np.array([1.0])),  # the rhs is not used by a splitting
        lambda t: references.free_rigid_body(I, m0, np.asarray(t)),
        {},
    )
    two, four = wp.splitting(case, I, 2), wp.splitting(case, I, 4)
    two.settings = four.settings = [0.1, 0.05, 0.025]  # 99, 198 and 396 steps: the steps are these
    frame = wp.sweep(case, [two, four], repeats=1, budget_s=0.0)
    orders = wp.fitted_orders(frame)
    assert orders["splitting, order 2"] == pytest.approx(2.0, abs=0.1)
    assert orders["splitting, order 4"] == pytest.approx(4.0, abs=0.2)
    assert set(frame.steps % 99) == {0}  # the 100 dense points fall on steps
    assert list(frame.evaluations) == [n * k for n, k in zip(frame.steps, [5, 5, 5, 15, 15, 15])]


def test_a_splittings_order_is_fitted_against_the_step_it_took():
    """Over a span of 5, h = 0.1 and 0.05 both round to 99 steps (a multiple of 99): fitted against the
    nominal h the order-2 splitting would read as order 1 or less; against span/steps it reads 2."""
    I = np.array([1.0, 2.0, 3.0])
    m0 = I * np.array([0.4, 0.2, 0.9])
    case = wp.Case(
        "free body",
        Problem(oscillator, m0 / I, (0.0, 5.0), np.array([1.0])),
        lambda t: references.free_rigid_body(I, m0, np.asarray(t)),
        {},
    )
    two = wp.splitting(case, I, 2)
    two.settings = [0.1, 0.05, 0.0125]  # 99, 99 and 396 steps
    frame = wp.sweep(case, [two], repeats=1, budget_s=0.0)
    assert list(frame.steps) == [99, 99, 396]
    assert wp.fitted_orders(frame)["splitting, order 2"] == pytest.approx(2.0, abs=0.1)


def test_fitted_orders_of_errors_built_to_an_order():
    h = np.array([0.1, 0.05, 0.02, 0.01])
    frame = pd.DataFrame(
        {
            "method": ["a"] * 4 + ["b"] * 4 + ["c"] * 4 + ["d"] * 2,
            "kind": ["step"] * 8 + ["tolerance"] * 4 + ["step"] * 2,
            "setting": np.concatenate([h, h, h, [0.1, 0.05]]),
            "steps": np.round(1.0 / np.concatenate([h, h, h, [0.1, 0.05]])).astype(int),  # a span of 1
            "error_final": np.concatenate([3 * h**2, 0.5 * h**3, h, [1e-16, 1e-3]]),
        }
    )
    orders = wp.fitted_orders(frame)
    assert orders == {"a": pytest.approx(2.0, rel=1e-12), "b": pytest.approx(3.0, rel=1e-12)}


def test_names_keys_and_best_settings():
    assert wp.method_key("scipy:DOP853") == "scipy_DOP853"
    assert wp.method_key("splitting, order 2") == "splitting2"
    assert wp.method_key("rk (4/5) x") == "rk_4_5_x"
    assert wp.nominal_order("splitting, order 4") == 4 and wp.nominal_order("dop853") is None
    frame = pd.DataFrame(
        {"method": ["x", "x", "scipy:RK45"], "setting": [1.0, 2.0, 3.0], "error_final": [1e-5, 1e-7, 1e-2]}
    )
    assert wp.best_by_method(frame) == {"x": (1e-7, 2.0), "scipy_RK45": (1e-2, 3.0)}


def test_figures_draw_each_method_with_its_data_and_reference_slopes():
    h = np.array([0.1, 0.05, 0.025])
    frame = pd.DataFrame(
        {
            "method": ["splitting, order 2"] * 3 + ["scipy:RK45"] * 3 + ["mine"] * 3,
            "kind": ["step"] * 3 + ["tolerance"] * 6,
            "setting": np.concatenate([h, [1e-3, 1e-6, 1e-9], [1e-3, 1e-6, 1e-9]]),
            "error_final": np.concatenate([h**2, [1e-4, 1e-7, 1e-20], [1e-4, 1e-7, 1e-10]]),
            "seconds": [1.0, 2.0, 4.0, 0.1, 0.2, 0.3, 0.01, 0.02, 0.03],
        }
    )
    fig, ax = plt.subplots(figsize=(4, 3))
    wp.plot(frame, ax, orders={"splitting, order 2": 2.0})
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert set(lines) == {"splitting, order 2 (fitted order 2.00)", "scipy:RK45", "mine"}
    np.testing.assert_array_equal(lines["scipy:RK45"].get_xdata(), [1e-4, 1e-7, 1e-17])  # floored
    assert lines["scipy:RK45"].get_linestyle() == "--" and lines["mine"].get_linestyle() == "-"
    assert len({line.get_color() for line in lines.values()}) == 3
    assert ax.xaxis_inverted()
    assert legend_below(fig) is not None
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(4, 3))
    wp.plot_convergence(frame, ax, orders={"splitting, order 2": 2.0})
    data, slope = ax.get_lines()
    np.testing.assert_array_equal(data.get_ydata(), np.sort(h) ** 2)  # sorted by step
    x, y = slope.get_xdata(), slope.get_ydata()
    assert np.polyfit(np.log(x), np.log(y), 1)[0] == pytest.approx(2.0, rel=1e-12)
    # through the points' centre, a factor 4 below it
    centre = np.exp(np.mean(np.log(h)))
    assert np.interp(np.log(centre), np.log(x), np.log(y)) == pytest.approx(np.log(centre**2 / 4), rel=1e-9)
    plt.close(fig)
