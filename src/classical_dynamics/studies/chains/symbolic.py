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

# Formulas for ω² as the sources print them, in the symbols of derive() (a scene names one: analysis.closed_form).
SOURCE_FORMULAS = {
    # lecture notes: two equal masses between three equal springs
    "equal_springs": [k / m1, 3 * k / m1],
    # lecture notes: unequal masses m1, m2 between three equal springs
    "unequal_masses": [k / (m1 * m2) * ((m1 + m2) - sp.sqrt(m1**2 - m1 * m2 + m2**2)),
                       k / (m1 * m2) * ((m1 + m2) + sp.sqrt(m1**2 - m1 * m2 + m2**2))],
    # handbook Ex. 2.4: springs k, 3k, k
    "springs_k_3k_k": [k / m1, 7 * k / m1],
    # lecture notes: the linear triatomic molecule m-M-m, free in space (m1 = m, m2 = M)
    "triatomic": [sp.Integer(0), k / m1, k * (m2 + 2 * m1) / (m1 * m2)],
}


def _symbols_for(values, names):
    """One symbol per distinct value, in order of first appearance."""
    distinct = list(dict.fromkeys(float(v) for v in values))
    return [names[distinct.index(float(v))] for v in values], dict(zip(names, distinct))


def derive(masses_kg, springs_n_per_m, ends: str):
    """ω² of the chain in closed form (sympy), and the values of the symbols for this scene."""
    masses, mass_values = _symbols_for(masses_kg, [m1, m2, m3])
    springs = np.atleast_1d(springs_n_per_m).astype(float)
    B = difference_matrix(len(masses), ends)
    if springs.size == 1:
        springs = np.full(B.shape[0], springs[0])
    softest = springs.min()
    ratios = [sp.nsimplify(s / softest, rational=True) for s in springs]
    K = sp.Matrix(B.astype(int)).T * sp.diag(*[r * k for r in ratios]) * sp.Matrix(B.astype(int))
    M = sp.diag(*masses)
    lam = sp.Symbol("lambda")
    polynomial = sp.factor((K - lam * M).det())
    roots = sorted(sp.roots(sp.Poly(polynomial, lam)).keys(), key=lambda r: float(r.subs({k: 1, **mass_values})))
    values = {k: float(softest), **mass_values}
    return polynomial, roots, values


def formula_is_exact(formula, roots) -> bool:
    """The printed ω² are exactly the derived roots, for every value of the symbols."""
    return len(formula) == len(roots) and all(
        sp.simplify(sp.expand(sum(f**p for f in formula) - sum(r**p for r in roots))) == 0
        for p in range(1, len(roots) + 1))          # equal power sums: the same multiset of roots


def evaluate(expressions, values) -> np.ndarray:
    return np.array([float(sp.N(e.subs(values), 30)) for e in expressions])
