"""Small spring chains derived with sympy: the characteristic polynomial and its roots in closed form.

The numerical eigensolver gives the numbers; this derivation checks them and the sources' printed formulas.
Masses get one symbol per distinct value (m1, m2, ...: equal masses share one), springs are k times their
ratio to the softest (k, 3k, k), so a source's formula is checked for every value of its symbols, not only
for the scene's numbers.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from ...models.chains import difference_matrix

k = sp.Symbol("k", positive=True)
m1, m2, m3 = sp.symbols("m1 m2 m3", positive=True)

# Formulas for ω² as the sources print them, in the symbols of derive() (a scene names one:
# analysis.closed_form).
SOURCE_FORMULAS = {
    # lecture notes: two equal masses between three equal springs
    "equal_springs": [k / m1, 3 * k / m1],
    # lecture notes: unequal masses m1, m2 between three equal springs
    "unequal_masses": [
        k / (m1 * m2) * ((m1 + m2) - sp.sqrt(m1**2 - m1 * m2 + m2**2)),
        k / (m1 * m2) * ((m1 + m2) + sp.sqrt(m1**2 - m1 * m2 + m2**2)),
    ],
    # handbook Ex. 2.4: springs k, 3k, k
    "springs_k_3k_k": [k / m1, 7 * k / m1],
    # lecture notes: the linear triatomic molecule m-M-m, free in space (m1 = m, m2 = M)
    "triatomic": [sp.Integer(0), k / m1, k * (m2 + 2 * m1) / (m1 * m2)],
    # Lamb Art. 90 Ex. 2: three equal particles on a string under tension P, spacing a: mu = P/(m a) = k/m1
    "three_on_string": [(2 - sp.sqrt(2)) * k / m1, 2 * k / m1, (2 + sp.sqrt(2)) * k / m1],
}

# Mode shapes as the sources print them, in the order of SOURCE_FORMULAS (Lamb Art. 90, Fig. 57:
# "the upper sign makes y1 = y3 = -y2/sqrt2, whilst the lower makes y1 = y3 = y2/sqrt2").
_ROOT = sp.sqrt(m1**2 - m1 * m2 + m2**2)
SOURCE_SHAPES = {
    "three_on_string": [[1, sp.sqrt(2), 1], [1, 0, -1], [1, -sp.sqrt(2), 1]],
    # lecture notes: the normal coordinates x1 + x2 and x1 - x2
    "equal_springs": [[1, 1], [1, -1]],
    # lecture notes: X2/X1 = [m2 - m1 -+ root]/m2, the upper sign with the upper root
    "unequal_masses": [[m2, m2 - m1 + _ROOT], [m2, m2 - m1 - _ROOT]],
    # lecture notes: the translation, (1, 0, -1) and (1, -2m/M, 1) (m1 = m, m2 = M)
    "triatomic": [[1, 1, 1], [1, 0, -1], [1, -2 * m1 / m2, 1]],
}


def _symbols_for(values, names):
    """One symbol per distinct value, in order of first appearance."""
    distinct = list(dict.fromkeys(float(v) for v in values))
    return [names[distinct.index(float(v))] for v in values], dict(zip(names, distinct))


def stiffness_and_mass(masses_kg, springs_n_per_m, ends: str):
    """K and M in symbols: one mass symbol per distinct mass, springs as k times their ratio to the
    softest."""
    masses, _ = _symbols_for(masses_kg, [m1, m2, m3])
    springs = np.atleast_1d(springs_n_per_m).astype(float)
    B = sp.Matrix(difference_matrix(len(masses), ends).astype(int))
    if springs.size == 1:
        springs = np.full(B.shape[0], springs[0])
    ratios = [sp.nsimplify(s / springs.min(), rational=True) for s in springs]
    return B.T * sp.diag(*[r * k for r in ratios]) * B, sp.diag(*masses)


def derive(masses_kg, springs_n_per_m, ends: str):
    """ω² of the chain in closed form (sympy), and the values of the symbols for this scene."""
    K, M = stiffness_and_mass(masses_kg, springs_n_per_m, ends)
    _, mass_values = _symbols_for(masses_kg, [m1, m2, m3])
    lam = sp.Symbol("lambda")
    polynomial = sp.factor((K - lam * M).det())
    roots = sorted(
        sp.roots(sp.Poly(polynomial, lam)).keys(), key=lambda r: float(r.subs({k: 1, **mass_values}))
    )
    values = {k: float(np.min(springs_n_per_m)), **mass_values}
    return polynomial, roots, values


def shapes_are_exact(K, M, roots, shapes) -> bool:
    """Each printed shape is annulled by K - omega^2 M at its printed omega^2, exactly."""
    return all(sp.simplify(((K - lam * M) * sp.Matrix(v)).norm()) == 0 for lam, v in zip(roots, shapes))


def rayleigh_symmetric_type(K, M):
    """Lamb Art. 94 Ex. 1: the Rayleigh quotient of the symmetric type y1 = y3 = theta y2, and its stationary
    thetas (the roots of its derivative), exactly."""
    theta = sp.Symbol("theta", real=True)
    y = sp.Matrix([theta, 1, theta])
    quotient = sp.simplify((y.T * K * y)[0] / (y.T * M * y)[0])
    stationary = sp.solve(sp.numer(sp.together(sp.diff(quotient, theta))), theta)
    return theta, quotient, sorted(stationary, key=float)


def separation_by_diagonal():
    """Lamb Art. 90 Ex. 1: for 2V = a x^2 + 2h xy + b y^2 and equal masses m, the frequency polynomial
    (a - m s)(b - m s) - h^2 takes the value -h^2 <= 0 at s = a/m and at s = b/m, so its two real roots lie
    outside [min(a, b)/m, max(a, b)/m]: the diagonal values separate them. Returns that value at both
    points."""
    a, b, h, m, s2 = sp.symbols("a b h m s2", real=True)
    f = sp.expand((a - m * s2) * (b - m * s2) - h**2)
    return sp.simplify(f.subs(s2, a / m)), sp.simplify(f.subs(s2, b / m)), -(h**2)


def damped_frequency_shift(n_modes: int, mode: int):
    """Lamb Arts. 96-97: small friction in normal coordinates, lambda^2 x + eps lambda C x + Sigma^2 x = 0
    (C symmetric, Sigma diagonal). Perturbation to second order in eps, solved order by order:
    lambda = i sigma_k + eps l1 + eps^2 l2. Returns (l1, l2) as functions of sigma_1..n and c_ij."""
    eps = sp.Symbol("epsilon")
    sigma = sp.symbols(f"sigma1:{n_modes + 1}", positive=True)
    C = sp.Matrix(n_modes, n_modes, lambda i, j: sp.Symbol(f"c{min(i, j) + 1}{max(i, j) + 1}"))
    l1, l2 = sp.symbols("l1 l2")
    x1 = sp.symbols(f"x1_1:{n_modes + 1}")
    others = [i for i in range(n_modes) if i != mode]
    x = sp.Matrix([1 if i == mode else eps * x1[i] for i in range(n_modes)])  # normalized: x_k = 1
    lam = sp.I * sigma[mode] + eps * l1 + eps**2 * l2
    residual = ((lam**2 * sp.eye(n_modes) + eps * lam * C + sp.diag(*[s**2 for s in sigma])) * x).applyfunc(
        sp.expand
    )
    first = sp.solve([r.coeff(eps, 1) for r in residual], [l1] + [x1[i] for i in others], dict=True)[0]
    second = sp.solve([sp.expand(residual[mode].coeff(eps, 2).subs(first))], [l2], dict=True)[0]
    return sigma, C, sp.simplify(first[l1]), sp.simplify(second[l2])


def hanging_chain_quotient_is_printed() -> bool:
    """Lamb Art. 94 Ex. 2: sigma^2 l/g of the type y = s + beta s^2/l (s from the top), from the energies
    T ~ int rho y'^2 ds and V ~ int g rho (l - s) y'^2 ds (tension: the weight below), derived, equals the
    printed (15 + 20 beta + 10 beta^2)/(10 + 15 beta + 6 beta^2) for every beta."""
    beta, s, l = sp.symbols("beta s l", positive=True)
    y = s + beta * s**2 / l
    quotient = sp.integrate((l - s) * sp.diff(y, s) ** 2, (s, 0, l)) / sp.integrate(y**2, (s, 0, l)) * l
    printed = (15 + 20 * beta + 10 * beta**2) / (10 + 15 * beta + 6 * beta**2)
    return sp.simplify(quotient - printed) == 0


def hanging_chain_tau():
    """Lamb Art. 90 Ex. 3: the time to run from the free end to x at the local wave speed sqrt(g x) is tau = 2
    sqrt(x/g); with x = g tau^2/4 the chain's g d/dx (x dy/dx) becomes y'' + y'/tau, the membrane's (19).
    Returns whether each holds exactly."""
    x, g, tau = sp.symbols("x g tau", positive=True)
    integral = sp.simplify(sp.integrate(1 / sp.sqrt(g * x), (x, 0, x)) - 2 * sp.sqrt(x / g)) == 0
    f = sp.Function("y")(tau)
    x_of_tau = g * tau**2 / 4
    d_dx = lambda e: sp.diff(e, tau) / sp.diff(x_of_tau, tau)
    chain = g * d_dx(x_of_tau * d_dx(f))
    membrane = sp.diff(f, tau, 2) + sp.diff(f, tau) / tau
    return integral, sp.simplify(chain - membrane) == 0


def string_parabola_quotient():
    """Lamb Ex. XIV.12: the type y = x (l - x) on a string (tension P, density rho) gives sigma^2 = 10 P/(rho
    l^2), the period 2 pi/sqrt(10) in units of l sqrt(rho/P). Returns sigma^2 rho l^2 / P, derived."""
    x, l = sp.symbols("x l", positive=True)
    y = x * (l - x)
    return sp.simplify(sp.integrate(sp.diff(y, x) ** 2, (x, 0, l)) / sp.integrate(y**2, (x, 0, l)) * l**2)


def formula_is_exact(formula, roots) -> bool:
    """The printed ω² are exactly the derived roots, for every value of the symbols."""
    # equal power sums: the same multiset of roots
    return len(formula) == len(roots) and all(
        sp.simplify(sp.expand(sum(f**p for f in formula) - sum(r**p for r in roots))) == 0
        for p in range(1, len(roots) + 1)
    )


def evaluate(expressions, values) -> np.ndarray:
    return np.array([float(sp.N(e.subs(values), 30)) for e in expressions])


# --- Lamb's stability (Arts. 92, 99; Exs. XIV.16, 18): the references of studies/chains/stability.py ------


def equal_root_minors():
    """Lamb Art. 92: three particles m on a closed ring of springs k, each tied down by k: K = k(I + L).
    Delta(lambda) = det(K - lambda M) has a double root; every first minor (the adjugate) vanishes there.
    Returns (all minors zero, the multiplicity)."""
    lam = sp.Symbol("lambda")
    L = sp.Matrix([[2, -1, -1], [-1, 2, -1], [-1, -1, 2]])
    K, M = k * (sp.eye(3) + L), m1 * sp.eye(3)
    roots = sp.roots(sp.Poly((K - lam * M).det(), lam))
    double, multiplicity = max(roots.items(), key=lambda item: item[1])
    adjugate = (K - double * M).adjugate().applyfunc(sp.simplify)
    return adjugate == sp.zeros(3, 3), int(multiplicity)


def kinetic_stability():
    """Lamb Art. 99 (1)-(3): a1 q1'' + beta q2' + c1 q1 = 0, a2 q2'' - beta q1' + c2 q2 = 0. Returns whether
    (3) is the discriminant of (2) in lambda^2, and whether the system's determinant is (2)."""
    a1, a2, c1, c2, beta, lam, x = sp.symbols("a1 a2 c1 c2 beta lambda x")
    system = sp.Matrix([[a1 * lam**2 + c1, beta * lam], [-beta * lam, a2 * lam**2 + c2]]).det()
    printed2 = a1 * a2 * lam**4 + (a1 * c2 + a2 * c1 + beta**2) * lam**2 + c1 * c2
    quadratic = sp.Poly(printed2.subs(lam**2, x), x)
    A, B, C = quadratic.all_coeffs()
    printed3 = beta**4 + 2 * beta**2 * (a1 * c2 + a2 * c1) + (a1 * c2 - a2 * c1) ** 2
    return sp.expand(B**2 - 4 * A * C - printed3) == 0, sp.expand(system - printed2) == 0


def gyroscopic_first_order_rho():
    """Lamb Art. 99 (7)-(10): with a dashpot eps on both coordinates (a1 = a2 = 1, c1 = c2 = c), the root
    i sigma moves by rho = -eps (dDelta/deps)/(dDelta/dlambda) at first order; real. In symbols c, beta,
    epsilon, sigma (no assumptions, so that a string substitutes)."""
    c, beta, eps, sigma, lam = sp.symbols("c beta epsilon sigma lambda")
    delta = (lam**2 + eps * lam + c) ** 2 + beta**2 * lam**2
    rho = -eps * sp.diff(delta, eps).subs(eps, 0) / sp.diff(delta, lam).subs(eps, 0)
    return sp.simplify(rho.subs(lam, sp.I * sigma))


def bowl_relative_equilibrium() -> bool:
    """Lamb Art. 99 Ex. 2: in the bowl turning at omega the effective potential per unit mass is -g a cos
    theta - omega^2 a^2 sin^2 theta / 2; its stationary point off the bottom is cos theta = g/(a omega^2), a
    minimum, and the bottom is then a maximum (omega^2 > g/a)."""
    g, a, w, th = sp.symbols("g a omega theta", positive=True)
    U = -g * a * sp.cos(th) - w**2 * a**2 * sp.sin(th) ** 2 / 2
    dU = sp.diff(U, th)
    cone = sp.acos(g / (a * w**2))
    stationary = sp.simplify(dU.subs(th, cone)) == 0
    curvature = sp.simplify(sp.diff(U, th, 2).subs(th, cone) - w**2 * a**2 * sp.sin(cone) ** 2) == 0
    bottom = sp.simplify(sp.diff(U, th, 2).subs(th, 0) - (g * a - w**2 * a**2)) == 0
    return bool(stationary and curvature and bottom)


def exponential_force_bounds():
    """Lamb Ex. XIV.16: a circular orbit under an attraction f(r) is stable while d(r^3 f)/dr > 0. The roots
    (over a) of d(r^3 f)/dr for f = e^{-r/a}/r^2 (printed bound a) and e^{-r/a}/r (the OCR's reading), each
    checked to be the only sign change (positive below, negative above)."""
    r, a = sp.symbols("r a", positive=True)
    bounds = []
    for power in (2, 1):
        d = sp.diff(r**3 * sp.exp(-r / a) / r**power, r)
        (root,) = sp.solve(d, r)
        assert d.subs(r, root / 2) > 0 and d.subs(r, 2 * root) < 0
        bounds.append(sp.simplify(root / a))
    return tuple(bounds)


REVOLVING = sp.symbols("M m a b mu", positive=True)


def revolving_string():
    """Lamb Ex. XIV.18: particles M, m at a and a + b from O on a light string, revolving in a plane with
    angular momentum mu. phi the first link's angle (cyclic), psi the second's relative to it; Routh's
    reduction: the Routhian's kinetic part in psi and the effective potential mu^2/(2 A(psi)). Returns
    sigma^2, whether it is mu^2/[Mab(Ma^2 + m(a + b)^2)], and sigma^2/Omega^2 for M = m, a = b."""
    M, m, a, b, mu = REVOLVING
    psi = sp.Symbol("psi")
    A = (M + m) * a**2 + m * b**2 + 2 * m * a * b * sp.cos(psi)  # p_phi = A phi' + B psi'
    B = m * b**2 + m * a * b * sp.cos(psi)
    inertia = (m * b**2 - B**2 / A).subs(psi, 0)  # the Routhian's coefficient of psi'^2/2
    potential = mu**2 / (2 * A)
    assert sp.simplify(sp.diff(potential, psi).subs(psi, 0)) == 0  # the straight form is a steady motion
    sigma2 = sp.simplify(sp.diff(potential, psi, 2).subs(psi, 0) / inertia)
    printed = mu**2 / (M * a * b * (M * a**2 + m * (a + b) ** 2))
    omega = sp.Symbol("Omega", positive=True)
    equal = sp.simplify(
        (sigma2 / omega**2).subs(mu, omega * (M * a**2 + m * (a + b) ** 2)).subs({M: m, b: a})
    )
    return sigma2, sp.simplify(sigma2 - printed) == 0, equal
