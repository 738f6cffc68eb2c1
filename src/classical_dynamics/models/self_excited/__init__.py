"""The self-excited rigid body (Lee 1964): Euler's equations under a torque fixed in the body, one module per
case of Lee's thesis:

  body.py            the body: principal moments A > B > C and the inertia numbers a, b, c (a - b + c = abc)
  effects.py         the effects a scene may list (body_torque, quadratic_torque, drag)
  largest_axis.py    §2: the torque along the largest axis, the plane (2.10), separatrices, limit cycles
  smallest_axis.py   §2 with p <-> r, a <-> c: the torque along the smallest axis
  other_torques.py   §2.6: other torques that reduce to the same planes (Grammel's, M + mu0 (q^2 + r^2))
  middle_axis.py     §3: the torque along the middle axis, its four planes and the rare case
  (the viscous medium of §5 is models/viscous_medium.py)

The studies use them through this package (`from ...models import self_excited as se`; se.LargestAxis, ...).
"""

from .body import Body, InertiaNumbers
from .effects import EFFECTS, medium_torque, plane_torque
from .largest_axis import (
    LargestAxis,
    cylinder,
    energy,
    euler_largest,
    euler_largest_angles,
    euler_largest_attitude,
    euler_largest_phase,
    invariant_spread,
    lee_c1,
    limit_cycle_p1,
    limit_cycle_period,
    nu_star,
    plane_by_phase,
    plane_largest,
    plane_largest_force,
    separatrix_p1_squared,
    series_period,
    singular_points,
)
from .middle_axis import (
    FORMS,
    RESONANCE,
    MiddleAxis,
    euler_middle,
    euler_middle_phase,
    hyperbola,
    lyapunov_period,
    middle_c1,
    middle_energy,
    middle_g,
    middle_g_terms,
    middle_invariant,
    middle_invariant_spread,
    middle_potential,
    middle_series_period,
    plane_middle,
    resonant,
)
from .other_torques import euler_grammel, euler_largest_yz
from .smallest_axis import euler_smallest
