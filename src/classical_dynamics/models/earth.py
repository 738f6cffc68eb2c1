"""The Earth's constants and units, each with its source, shared by the precession and wobble studies.

C - A is a small difference of large numbers, so the body is parameterized by the dynamical
ellipticity H = (C - A)/C (or Lamb's (C - A)/A) and moments are kept in units of C.
"""

from __future__ import annotations

import numpy as np

# Units. The stellar (sidereal) day is the period of the Earth rotation angle (IERS Conventions 2010,
# eq. 5.15: ERA rate 1.00273781191135448 turns per UT1 day); the true sidereal day differs by 8 ms.
SIDEREAL_PER_SOLAR_DAY = 1.00273781191135448  # turns of the Earth per mean solar day
SECONDS_PER_DAY = 86400.0
JULIAN_YEAR_DAYS = 365.25
TROPICAL_YEAR_DAYS = 365.242190  # mean tropical year at J2000 (Laskar 1986)
ARCSEC = np.pi / (180.0 * 3600.0)  # radians per arcsecond
MAS = ARCSEC / 1000.0

# IERS Conventions (2010), Table 1.1 (numerical standards).
GM_M3_PER_S2 = 3.986004418e14
EQUATORIAL_RADIUS_M = 6378136.6
J2 = 1.0826359e-3
OMEGA_RAD_PER_S = 7.292115e-5

# Dynamical ellipticity H = (C - A)/C: Capitaine et al. 2003 (P03), 3.27379448e-3; the issue's
# 0.0032737949 is the MHB2000 value (Mathews et al. 2002). Lamb (Art. 47) uses (C - A)/A = 0.00327.
H_P03 = 3.27379448e-3
H_MHB2000 = 3.2737949e-3
LAMB_C_MINUS_A_OVER_A = 0.00327
# Degree-2 order-2 gravity coefficient, unnormalized (EGM2008: normalized 2.43938e-6 x sqrt(5/12)):
# B - A = 4 C22 M a^2, and C = (C - A)/H = J2 M a^2 / H to leading order.
C22 = 1.5745e-6
SPIN_RAD_PER_DAY = 2.0 * np.pi * SIDEREAL_PER_SOLAR_DAY


def b_minus_a_over_c(H: float = H_P03) -> float:
    """(B - A)/C = 4 C22 H / J2 (about 1.9e-5): the Earth's equatorial ellipticity."""
    return 4.0 * C22 * H / J2


def h_over_c(value: float, definition: str) -> float:
    """(C - A)/C from either form of the dynamical ellipticity: '(C-A)/C' or '(C-A)/A'."""
    if definition == "(C-A)/C":
        return value
    if definition == "(C-A)/A":
        return value / (1.0 + value)
    raise ValueError(f"unknown definition of the ellipticity {definition!r}")


def moments_over_c(H: float, b_minus_a_over_c: float = 0.0) -> tuple[float, float]:
    """(A/C, B/C) for a body with (C - (A + B)/2)/C = H and (B - A)/C given."""
    return 1.0 - H - 0.5 * b_minus_a_over_c, 1.0 - H + 0.5 * b_minus_a_over_c


def euler_period_sidereal_days(H: float) -> float:
    """Rigid symmetric Earth: A/(C - A) turns, i.e. sidereal days (Lamb Art. 47 (7))."""
    return (1.0 - H) / H


def sidereal_to_solar_days(days: float) -> float:
    return days / SIDEREAL_PER_SOLAR_DAY


def solar_to_sidereal_days(days: float) -> float:
    return days * SIDEREAL_PER_SOLAR_DAY


def triaxial_wobble_frequency(H: float, b_minus_a_over_c: float) -> float:
    """Small-amplitude free wobble of a rigid triaxial body, in units of the spin: sqrt((C-A)(C-B)/(AB))."""
    a, b = moments_over_c(H, b_minus_a_over_c)
    return np.sqrt((1.0 - a) * (1.0 - b) / (a * b))


def centrifugal_parameter() -> float:
    """q = Omega^2 a^3 / GM: centrifugal over gravitational acceleration at the equator."""
    return OMEGA_RAD_PER_S**2 * EQUATORIAL_RADIUS_M**3 / GM_M3_PER_S2


def secular_love_number() -> float:
    """k_s = 3 J2 / q: the Love number of a fluid Earth in hydrostatic equilibrium with its spin.

    A spin n raises a bulge C - A = k_s n^2 a^5 / (3G); read backwards, this is k_s from J2 and q.
    """
    return 3.0 * J2 / centrifugal_parameter()


def elastic_beta_n2_over_c(k2: float, H: float) -> float:
    """Lamb's beta n^2 (Art. 71), in units of C, from the Love number k2.

    A spin n tilted by a small angle raises products of inertia beta n (p, q) with beta = k2 a^5/(3G)
    (the same response that, for a fluid, k_s, built the whole bulge), so beta n^2 = (k2/k_s)(C - A).
    """
    return k2 / secular_love_number() * H


def elastic_wobble_frequency(H: float, beta_n2: float, b_minus_a_over_c: float = 0.0) -> float:
    """Lamb Art. 71 (14): sigma/n = (C - A - beta n^2)/(A + beta n^2), moments in units of C.

    For a triaxial body each equatorial moment is shifted by beta n^2 in the same way.
    """
    a, b = moments_over_c(H, b_minus_a_over_c)
    a_e, b_e = a + beta_n2, b + beta_n2
    return np.sqrt((1.0 - a_e) * (1.0 - b_e) / (a_e * b_e))


def beta_n2_for_period(H: float, period_solar_days: float) -> float:
    """The beta n^2 (units of C) that gives a symmetric elastic Earth a wobble of the given period."""
    s = 1.0 / (period_solar_days * SIDEREAL_PER_SOLAR_DAY)  # sigma/n
    a = 1.0 - H
    # s (a + x) = 1 - a - x  =>  x = (1 - a - s a) / (1 + s)
    return (1.0 - a - s * a) / (1.0 + s)
