"""Lamb Ex. X.10: a symmetric body under a retarding couple -kappa omega about the instantaneous axis.

Euler's equations with that couple (body frame, moments A, A, C):
    A p' = (A - C) q r - kappa p,   A q' = (C - A) r p - kappa q,   C r' = -kappa r.
So |p + iq| falls as exp(-kappa t/A) and r as exp(-kappa t/C), and tan(theta) = |p + iq|/r, theta the angle
between the instantaneous axis and the axis of symmetry, as exp(-kappa (1/A - 1/C) t): the axis of rotation
closes on the axis of symmetry when C > A, and leaves it when C < A. Unlike the internal friction of the
damped scene, this couple is external: |L| decays too. Units: C = 1, the initial spin n = 1.
"""

from __future__ import annotations

import numpy as np

from ...formatting import shortest
from ...models import rigid_body
from ...solvers.ode import Problem, solve

RTOL = 1e-12
SAMPLES = 2001


def decay_rate(a, kappa, tilt, span):
    """Fitted rate of -log tan(theta) over the run, and |L| at the end over |L| at the start."""
    w0 = np.array([np.sin(tilt), 0.0, np.cos(tilt)])
    t = np.linspace(0.0, span, SAMPLES)
    sol = solve(
        Problem(rigid_body.retarded_euler, w0, (0.0, span), np.array([a, kappa]), name="retarded"),
        "dop853",
        rtol=RTOL,
        atol=1e-20,
        t_eval=t,
    )
    w = sol.y_eval
    log_tan = np.log(np.hypot(w[:, 0], w[:, 1]) / w[:, 2])
    slope = float(np.polyfit(t, log_tan, 1)[0])
    L = np.linalg.norm(w * np.array([a, a, 1.0]), axis=1)
    return -slope, float(L[-1] / L[0])


def run(scene, results, quick):
    spec = scene.data["body"]
    kappa, tilt = spec["kappa_over_Cn"], np.radians(spec["tilt_deg"])
    results.number("retarding_kappa_over_Cn", kappa, "1", note=spec["source"])
    results.number(
        "retarding_tilt_deg", spec["tilt_deg"], "°", note="initial angle between $\\omega$ and the axis"
    )
    for name, a in (("oblate", spec["oblate_A_over_C"]), ("prolate", spec["prolate_A_over_C"])):
        closed = kappa * (1.0 / a - 1.0)
        span = spec["e_folds"] / abs(closed)
        rate, L_ratio = decay_rate(a, kappa, tilt, span)
        results.number(f"{name}_A_over_C", a, "1")
        results.number(
            f"{name}_tan_decay_rate",
            rate,
            "1",
            note=f"fitted rate (per $1/n$) at which $\\tan\\theta$ falls, $A/C$ = {a:.3g}, over "
            f"{shortest(spec['e_folds'])} e-folds",
        )
        results.number(f"{name}_tan_decay_rate_closed_form", closed, "1", note="$\\kappa(1/A - 1/C)$")
        results.number(
            f"{name}_rate_relative_error", rate / closed - 1.0, "1", note="fitted against closed form"
        )
        results.number(
            f"{name}_L_final_over_initial", L_ratio, "1", note="$|\\mathbf L|$ decays: the couple is external"
        )
        results.hard_case(
            f"retarding_{name}",
            f"Retarding couple, $A/C$ = {a:.3g}: the fitted rate of "
            "$\\tan\\theta$ against $\\kappa(1/A - 1/C)$ (relative)",
            rate / closed - 1.0,
            1e-6,
        )
