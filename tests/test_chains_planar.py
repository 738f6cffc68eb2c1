"""Direct unit tests of studies/chains/planar.py: the rotating ring (Lamb Art. 98) and the triangle of three
atoms (lecture notes), each against a reference the module does not compute: force balance by hand, a
stiffness matrix written out, the notes' and Lamb's printed frequencies and speeds."""

import numpy as np
import pytest
import sympy as sp

from classical_dynamics.studies.chains import planar


def test_equilibrium_tension_holds_each_bead_on_its_circle():
    # Newton by hand: the two neighbours' pulls T along the chords must give bead j its centripetal m w^2 a
    n, a, mass, w = 7, 1.3, 2.1, 0.8
    theta, positions, m, tension = planar.equilibrium(n, a, mass, w)
    assert m == pytest.approx(mass / n, rel=1e-15)
    assert np.allclose(np.hypot(*positions.T), a, rtol=1e-15)
    for j in range(n):
        pull = sum(
            tension * (positions[i] - positions[j]) / np.linalg.norm(positions[i] - positions[j])
            for i in ((j - 1) % n, (j + 1) % n)
        )
        assert pull == pytest.approx(-m * w**2 * positions[j], rel=1e-12, abs=1e-14)


def test_a_single_pretensioned_spring_written_out():
    # one spring along x of length l: k in the x block, T/l (the string's sideways stiffness) in the y block
    k, T, l = 5.0, 0.7, 2.0
    K = planar.spring_stiffness(np.array([[0.0, 0.0], [l, 0.0]]), [(0, 1)], k, T)
    one = np.array([[k, 0.0], [0.0, T / l]])
    assert K == pytest.approx(np.block([[one, -one], [-one, one]]), abs=1e-15)
    # and along y the two roles swap
    K = planar.spring_stiffness(np.array([[0.0, 0.0], [0.0, l]]), [(0, 1)], k, T)
    one = np.array([[T / l, 0.0], [0.0, k]])
    assert K == pytest.approx(np.block([[one, -one], [-one, one]]), abs=1e-15)


def test_triangle_frequencies_are_the_notes():
    # lecture notes (ozone): w^2 = 0 three times, 3k/2m twice, 3k/m once; numpy's eigenvalues of the
    # module's numeric stiffness, and the roots of its sympy determinant (built separately) alike
    k, m, side = 2.0, 0.5, 1.7
    angles = np.pi / 2 + 2 * np.pi * np.arange(3) / 3
    positions = side / np.sqrt(3) * np.column_stack([np.cos(angles), np.sin(angles)])
    K = planar.spring_stiffness(positions, [(0, 1), (1, 2), (2, 0)], k)
    expected = np.array([0, 0, 0, 1.5, 1.5, 3.0]) * k / m
    assert np.linalg.eigvalsh(K / m) == pytest.approx(expected, abs=1e-12)
    _, roots = planar.triangle_polynomial()
    assert roots == {sp.Integer(0): 3, sp.Rational(3, 2): 2, sp.Integer(3): 1}


def test_dispersion_roots_are_lambs():
    # Lamb (44) has roots -s w and s w (s^2 - 3)/(s^2 + 1); numpy's roots of the quadratic at s = 3, w = 1
    roots, exact = planar.dispersion()
    assert exact
    s, w = sp.symbols("s omega", positive=True)
    numeric = sorted(float(r.subs({s: 3, w: 1})) for r in roots)
    assert numeric == pytest.approx(sorted(np.roots([10.0, 12.0, -54.0]).real), rel=1e-12)
    assert numeric == pytest.approx([-3.0, 1.8], rel=1e-12)


def _speeds(n, s, k=1e6):
    theta, positions, m, tension = planar.equilibrium(n, 1.0, 1.0, 1.0)
    lam, wave = planar.modes(theta, positions, *planar.matrices(positions, m, 1.0, k, tension))
    # upper half plane, wave number +-s, the slow branch (the springs' stretching modes are at sqrt(k/m))
    keep = (lam.imag > 1e-3) & (np.abs(wave) == s) & (lam.imag < 50)
    return -lam[keep].imag / wave[keep]


@pytest.mark.parametrize("s", [2, 3])
def test_ring_patterns_turn_at_lambs_speeds(s):
    # Lamb Art. 98, the inextensible ring at w = 1: relative speeds -w and w (s^2 - 3)/(s^2 + 1). A ring of n
    # beads differs by O((s/n)^2); doubling n must cut the gap about fourfold (so it is discretisation).
    lamb = np.array([-1.0, (s**2 - 3) / (s**2 + 1)])
    gaps = []
    for n in (32, 64):
        speeds = _speeds(n, s)
        gap = np.array([np.min(np.abs(speeds - v)) for v in lamb])
        assert np.all(gap < 2 * (s / n) ** 2), (n, speeds)
        gaps.append(gap)
    assert np.all(gaps[0] / gaps[1] > 3.0)


def test_the_ozone_scene_runs_to_the_notes_modes():
    # through the study's dispatch (chains.run on the shipped scene, validated): the frequencies are the
    # notes' 0, 0, 0, 3/2, 3/2, 3 (k/m), exactly; the mode shapes' angles to the rigid motions, the radial
    # breathing and the plane left over are at rounding (a spring missing or of the wrong sign leaves a
    # zero mode that is no rigid motion, and no degenerate pair)
    from classical_dynamics.studies import chains, validate

    from .bad_scenes import ROOT

    results = chains.run(validate("chains", ROOT / "workflow/scenes/chains/ozone_molecule.yaml"))
    n = {k: v["value"] for k, v in results.numbers.items()}
    notes = [0.0, 0.0, 0.0, 1.5, 1.5, 3.0]
    assert np.asarray(n["omega_squared_over_k_per_m"]) == pytest.approx(notes, abs=1e-12)
    assert n["sympy_roots_over_k_per_m"] == notes
    assert n["solver_vs_sympy"] < 1e-12
    assert n["zero_modes_vs_rigid"] < 1e-12 and n["breathing_mode_vs_radial"] < 1e-12
    assert n["degenerate_pair_subspace"] < 1e-12
    (case,) = results.stability
    assert case["name"] == "degenerate_pair" and case["measured"] == n["degenerate_pair_subspace"]


def test_the_rings_table_is_lambs_speeds_and_its_deviation_from_them():
    # ring() on 64 beads: each row's speeds against Lamb's -1 and (s^2 - 3)/(s^2 + 1), written here (s >= 2),
    # its deviation the larger gap, the space-frame speeds one more, and the steady tension Lamb's rho w^2 a^2
    chain = {"n": 64, "length_m": 2 * np.pi, "mass_kg": 1.0}
    effects = {"rotation": {"omega_rad_per_s": 1.0}, "springs": {"k_n_per_m": 1e6}}
    r = planar.ring(chain, effects, 4)
    waves = r.waves.set_index("s")
    assert list(waves.index) == [1, 2, 3, 4]
    for s, row in waves.iterrows():
        lamb = (-1.0, (s**2 - 3) / (s**2 + 1))
        gaps = (abs(row.relative_1 - lamb[0]), abs(row.relative_2 - lamb[1]))
        assert row.deviation == pytest.approx(max(gaps), rel=1e-12, abs=1e-15)
        if s >= 2:  # s = 1 is the defective pair (a displaced circle), split by rounding on 64 beads
            assert row.deviation < 2 * (s / 64) ** 2
        assert row.lamb_space_2 == pytest.approx(2 * (s**2 - 1) / (s**2 + 1), rel=1e-15)
        assert (row.space_1, row.space_2) == pytest.approx(
            (row.relative_1 + 1, row.relative_2 + 1), rel=1e-15
        )
    assert r.stiffness_ratio == pytest.approx(1e6 / (1.0 / 64), rel=1e-12)
    assert r.tension_ratio == pytest.approx(1.0, rel=1e-3) and r.dispersion_exact
    assert r.largest_real_part < 1e-6
