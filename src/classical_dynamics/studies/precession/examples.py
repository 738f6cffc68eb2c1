"""Lamb's worked examples on the couple and the precession, computed with the precession scenes' own model.

  polhode_circle    Art. 29, Ex.: the instantaneous axis makes with the figure axis the angle beta,
                    sin beta = psi' sin(eps)/n (the rolling cones), so the polhode cone cuts the Earth's
                    surface in a circle of radius R sin beta: the scene's secular rate, Lamb's R.
  moon_line_offset  Ex. VI.5: the Moon's attraction on the Earth is a force through the centre and a couple
                    (MacCullagh's); the line of the resultant misses the centre by couple/force. The couple is
                    the full rung's torque routine (models.precession.torque_body), the Moon at the given
                    distance and declination; the force gamma M E / rho^2.
  gyroscope_couple  Ex. XI.1: the couple that keeps a rotor (spin n about its axis) turning at Omega about a
                    perpendicular axis, from Euler's equations (models.rigid_body.euler_free) along that
                    prescribed motion: N = I (omega' - f(omega)), f the torque-free right-hand side.
"""

from __future__ import annotations

import numpy as np

from ...models import earth
from ...models import precession as prec
from ...models import rigid_body as rb

CM_PER_FT = 30.48            # exact (international foot)


def run(scene, model, results) -> None:
    analysis = scene.data.get("analysis", {})
    if "polhode_circle" in analysis:
        polhode_circle(results, model, analysis["polhode_circle"])
    if "moon_line_offset" in analysis:
        moon_line_offset(results, analysis["moon_line_offset"], analysis.get("polhode_circle"))
    if "gyroscope_couple" in analysis:
        gyroscope_couple(results, analysis["gyroscope_couple"])


def polhode_circle(results, model, spec) -> None:
    """Lamb Art. 29: psi' = omega sin(beta)/sin(alpha), alpha the obliquity, omega ~ n: the polhode's radius."""
    beta = np.arcsin(model.secular_rate() * np.sin(model.obliquity) / model.n)
    radius = spec["earth_radius_cm"]
    results.number("earth_radius_cm", radius, "cm", note=spec["source"])
    results.number("polhode_cone_angle_mas", beta / earth.MAS, "mas",
                   note="$\\beta$: $\\sin\\beta = \\dot\\psi\\sin\\varepsilon/n$, the secular rate of this scene "
                        "(Lamb Art. 29)")
    results.number("polhode_circle_radius_cm", radius * np.sin(beta), "cm",
                   note="where the polhode cone meets the Earth's surface: $R\\sin\\beta$")


def moon_line_offset(results, spec, polhode=None) -> None:
    """Lamb Ex. VI.5: couple/force of the Moon on the Earth, in Earth radii (units: E = a = gamma M = 1)."""
    rho, delta = spec["moon_distance_radii"], np.radians(spec["declination_deg"])
    C_minus_A = spec["C_minus_A_over_Ea2"]
    # torque_body returns N/C with H = (C - A)/C; C = 1 (in E a^2) makes H = C - A, and N = that output
    p = np.zeros(prec.N_PARAMS)
    p[prec.H_] = C_minus_A
    p[prec.MOON], p[prec.MOON_K] = 1.0, 3.0 / rho**3          # 3 gamma M / rho^3, circular orbit: (a/r)^3 = 1
    p[prec.MOON_L0] = np.pi / 2                               # the Moon at ecliptic longitude 90 deg ...
    # ... and the figure axis tilted by delta toward it (a turn by -delta about x): declination delta
    q = np.array([np.cos(delta / 2), -np.sin(delta / 2), 0.0, 0.0])
    torque = np.empty(3)
    prec.torque_body(0.0, q, p, torque)
    couple, force = float(np.linalg.norm(torque)), 1.0 / rho**2
    offset = couple / force
    results.number("moon_line_offset_radii", offset, "1",
                   note=f"Lamb Ex. VI.5: couple/force of the Moon at {spec['moon_distance_radii']:g} radii and "
                        f"declination {spec['declination_deg']:g}°, $C - A$ = {spec['C_minus_A_over_Ea2']:g} "
                        "$Ea^2$ (the couple from the full rung's torque routine)")
    results.number("moon_line_offset_closed_form_radii",
                   3.0 * C_minus_A * np.sin(delta) * np.cos(delta) / rho, "1",
                   note="$3(C - A)\\sin\\delta\\cos\\delta/(E\\rho)$")
    if polhode is not None:
        results.number("moon_line_offset_ft", offset * polhode["earth_radius_cm"] / CM_PER_FT, "ft",
                       note="the same on Lamb's radius of Art. 29, 30.48 cm to the foot")


def gyroscope_couple(results, spec) -> None:
    """Lamb Ex. XI.1: the pitching couple of a rotary engine and propeller on an aeroplane turning in a circle."""
    g = spec["g_ft_per_s2"]
    C = sum(w * k**2 for w, k in zip(spec["weights_lb"], spec["radii_of_gyration_ft"])) / g     # slug ft^2
    A = spec["transverse_over_axial"] * C
    I = np.array([A, A, C])
    n = 2.0 * np.pi * spec["spin_rev_per_s"]
    Omega = 2.0 * np.pi / spec["turn_period_s"]
    coefficients = rb.euler_coefficients(I)
    worst = 0.0
    for phase in np.linspace(0.0, 2.0 * np.pi, 7)[:-1]:
        # body frame: spin axis e3 horizontal; the vertical (the turning axis) at angle -phase about e3
        z_body = np.array([np.cos(phase), -np.sin(phase), 0.0])
        omega = Omega * z_body + np.array([0.0, 0.0, n])
        omega_dot = -n * Omega * np.cross([0.0, 0.0, 1.0], z_body)   # the vertical turns at -n in the body
        free = np.empty(3)
        rb.euler_free(0.0, omega, coefficients, free)
        couple = I * (omega_dot - free)
        worst = max(worst, float(np.linalg.norm(couple)))
    results.number("gyroscope_axial_moment_slug_ft2", C, "1",
                   note="$C = \\sum Wk^2/g$ in slug ft$^2$ (Lamb Ex. XI.1; $g$ = "
                        f"{g:g} ft s$^{{-2}}$)")
    results.number("gyroscope_couple_ft_lb", worst, "ft-lb",
                   note="the couple that keeps the rotor turning with the aeroplane, from Euler's equations "
                        "(largest over the rotor's turn; the transverse moment does not enter)")
    results.number("gyroscope_couple_closed_form_ft_lb", C * n * Omega, "ft-lb", note="$Cn\\dot\\psi$")
