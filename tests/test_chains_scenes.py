"""The chains study's discrete analyses run directly on the report's own scenes (quick), in seconds, each
checked against a closed form the module does not compute: Laguerre's zeros for the hanging particles,
Lagrange's sine law for the loaded string and the spring chain, the determinant of two masses on three springs
written out by hand, and the carbon dioxide molecule's textbook modes."""

from pathlib import Path
from types import SimpleNamespace

import matplotlib.pyplot as plt
import numpy as np
import pytest
import yaml
from scipy.special import j0, jn_zeros, roots_laguerre

from classical_dynamics.results import Results
from classical_dynamics.studies.chains import discrete

SCENES = Path(__file__).resolve().parents[1] / "workflow" / "scenes" / "chains"
DISCRETE = sorted(
    path.stem
    for path in SCENES.glob("*.yaml")
    if yaml.safe_load(path.read_text())["chain"]["model"] in ("particles", "links")
)


def run(name, without_analysis=False):
    data = yaml.safe_load((SCENES / f"{name}.yaml").read_text())
    if without_analysis:
        del data["analysis"]
    results = Results("chains", name, name)
    discrete.run(SimpleNamespace(name=name, title=name, data=data), results, True)
    return (
        data,
        results,
        {
            k: np.asarray(v["value"]) if isinstance(v["value"], list) else v["value"]
            for k, v in results.numbers.items()
        },
    )


@pytest.mark.parametrize("name", DISCRETE)
def test_every_discrete_scene_runs_and_its_hard_cases_hold(name):
    """Every scene's frequencies are finite, non-negative and ascending, and its named hard cases hold."""
    _, results, got = run(name)
    w = np.asarray(got["frequencies_rad_per_s"])
    assert w.size >= 2 and np.all(np.isfinite(w)) and np.all(w >= -1e-9) and np.all(np.diff(w) >= -1e-9)
    # the run's own hard-case verdicts as the report prints them, not a reference (the other asserts are)
    assert all(case["holds"] for case in results.stability), [c for c in results.stability if not c["holds"]]


def test_hanging_particles_are_laguerres_zeros():
    """n equal particles hanging on a light string: sigma² a/g are the zeros of L_n (Lamb Art. 100)."""
    data, results, got = run("hanging_particles")
    n = data["chain"]["n"]
    zeros = roots_laguerre(n)[0]
    k = len(got["frequencies_sqrt_g_over_l"])
    np.testing.assert_allclose(got["frequencies_sqrt_g_over_l"], np.sqrt(n * zeros[:k]), rtol=1e-10)
    # beside the particles, the continuum's modes J0(j_s sqrt(x/l)) drawn over the chain's height, 0 to l
    fig, _ = results.figures["mode_shapes"]
    curves = [line for line in fig.axes[0].lines if line.get_linestyle() == "-" and len(line.get_ydata()) > 2]
    assert len(curves) == 3
    for s, line in enumerate(curves):
        height, swing = np.asarray(line.get_ydata()), np.asarray(line.get_xdata())
        assert (height.min(), height.max()) == (0.0, 1.0)
        np.testing.assert_allclose(swing, j0(jn_zeros(0, 3)[s] * np.sqrt(height)), atol=1e-12)
    plt.close(fig)


@pytest.mark.parametrize("without_analysis", [False, True])
def test_the_loaded_string_is_lagranges_sine_law(without_analysis):
    """n particles of M/n at intervals a = l/(n + 1) under tension P: 2 sqrt(P/(m a)) sin(s pi/(2(n + 1)));
    a scene without an analysis block (the schema makes it optional) gives its frequencies all the same."""
    data, _, got = run("loaded_string", without_analysis)
    n, M, l = data["chain"]["n"], data["chain"]["mass_kg"], data["chain"]["length_m"]
    P = data["effects"]["tension"]["newton"]
    s = np.arange(1, len(got["frequencies_rad_per_s"]) + 1)
    exact = 2 * np.sqrt(P / ((M / n) * l / (n + 1))) * np.sin(s * np.pi / (2 * (n + 1)))
    np.testing.assert_allclose(got["frequencies_rad_per_s"], exact, rtol=1e-10)


def test_the_spring_chain_is_the_sine_law_too():
    data, _, got = run("spring_chain")
    n, m, k = (
        data["chain"]["n"],
        data["chain"]["mass_kg"] / data["chain"]["n"],
        data["effects"]["springs"]["k_n_per_m"],
    )
    s = np.arange(1, len(got["frequencies_rad_per_s"]) + 1)
    np.testing.assert_allclose(
        got["frequencies_rad_per_s"], 2 * np.sqrt(k / m) * np.sin(s * np.pi / (2 * (n + 1))), rtol=1e-10
    )


def test_two_masses_on_three_springs_and_two_unequal_masses_by_their_determinants():
    # equal masses 1, springs 1, 3, 1: in phase sqrt(k/m), out of phase sqrt(7k/m)
    _, _, got = run("two_masses_three_springs")
    np.testing.assert_allclose(got["frequencies_rad_per_s"][:2], [1.0, np.sqrt(7.0)], rtol=1e-12)
    # masses 1 and 2, three unit springs: (2 - w²)(2 - 2w²) = 1, so w² = (3 -+ sqrt 3)/2
    _, _, got = run("two_unequal_masses")
    np.testing.assert_allclose(
        got["frequencies_rad_per_s"][:2], np.sqrt([(3 - np.sqrt(3)) / 2, (3 + np.sqrt(3)) / 2]), rtol=1e-12
    )


def test_the_triatomic_molecule_has_a_translation_and_the_textbook_stretches():
    """O-C-O on two springs k, free: 0, sqrt(k/m_O) (symmetric), sqrt(k/m_O (1 + 2 m_O/m_C)) (asymmetric)."""
    data, _, got = run("triatomic_molecule")
    mO, mC, _ = data["chain"]["masses_kg"]
    k = data["effects"]["springs"]["k_n_per_m"]
    w = got["frequencies_rad_per_s"][:3]
    assert abs(w[0]) < 1e-6
    np.testing.assert_allclose(w[1:], [np.sqrt(k / mO), np.sqrt(k / mO * (1 + 2 * mO / mC))], rtol=1e-10)


# the sources' values, each naming the scene number it is compared with
CLAIMS = yaml.safe_load((Path(discrete.__file__).parent / "claims.yaml").read_text(encoding="utf-8"))


@pytest.mark.parametrize(
    "name", ["three_particles_string", "triatomic_molecule", "three_particles_forced", "two_unequal_masses"]
)
def test_every_number_a_claim_compares_is_recorded(name):
    """claims.yaml (the sources' printed values, written apart from the code) names a number of the scene for
    each claim: the scene's run records every one of them (the small scenes, a second each)."""
    wanted = {c["computed"]["number"] for c in CLAIMS if c.get("computed", {}).get("scene") == name}
    assert wanted
    _, results, _ = run(name)
    assert sorted(wanted - set(results.numbers)) == []


def test_a_chain_without_ends_hangs_from_its_top():
    """'ends' left out is fixed-free, a chain hanging from its top: sigma^2 a/g are the zeros of L_n."""
    data = yaml.safe_load((SCENES / "hanging_particles.yaml").read_text())
    chain = {k: v for k, v in data["chain"].items() if k != "ends"}
    n, g, length = chain["n"], data["effects"]["gravity"]["g_m_per_s2"], chain["length_m"]
    values = discrete.spectrum(chain, data["effects"], 5).values
    np.testing.assert_allclose(values, np.sqrt(roots_laguerre(n)[0][:5] * g / (length / n)), rtol=1e-10)


def test_the_equal_springs_scene_and_its_indefinite_neighbour():
    """Lamb Arts. 85-89 from the scene's k and m: two masses on three springs k have lambda = k/m and 3k/m
    (the smallest 1 in k/m); springs k, -k, k give K the eigenvalues -k and k, and the state matrix the real
    root sqrt(k/m), at which a small start grows (fitted over lambda t = 15 to 30)."""
    _, _, got = run("two_masses_equal_springs")
    assert got["scene_smallest_stiffness_eigenvalue"] == pytest.approx(1.0, rel=1e-12)
    np.testing.assert_allclose(sorted(got["indefinite_V_eigenvalues_over_k"]), [-1.0, 1.0], rtol=1e-14)
    assert abs(got["indefinite_real_root_vs_exact"]) < 1e-12
    assert got["indefinite_growth_rate_over_root"] == pytest.approx(1.0, abs=1e-3)
