"""Differential (Heathcote) slip of a ball rolling in a conforming groove.

The contact surface of a ball in a groove of conformity f = r_g/d_w is curved across the
rolling direction with the radius R_d = 2 r_g r_b/(r_g + r_b). A ball turning relative to the
raceway at the rate ω = ω·Y about the axis Y across the rolling direction (in the contact
plane, along the major axis; :func:`heathcote_rate`) has its surface at the lateral offset y a
distance y²/(2R_d) closer to that axis than the centre line, so the surfaces can roll without
slip on two lines y = ±c only; between them the ball slides forward, outside them backward, at

    Δv(y) = ω (y² − c²)/(2 R_d)                                   (Heathcote 1921)

(the same field the traction grid of the screw contact integrates). With a traction ∝ p
(boundary friction or a film at its limiting shear stress), the rolling lines sit where the
forward and backward friction forces balance: for the Hertz line load q(y) ∝ 1 − y²/b² this
is the load-halving line u_c = c/b with u_c − u_c³/3 = 1/3, u_c = 2 cos(4π/9) = 0.3473. The
dissipated power is then

    P_H = k_H μ Q ω b²/R_d,   k_H = (3/8) ∫₋₁¹ (1 − u²)|u² − u_c²| du = 0.0806,

i.e. a rolling resistance F_H = P_H/(ω r_b) = 0.0806 μ Q b²/(R_d r_b), the full-slip result
"F/W ≈ 0.08 μ (b/R)²" Johnson (1985, *Contact Mechanics*, ch. 8, Heathcote slip) quotes.
:func:`differential_slip_power` integrates the same slip field over the Hertz pressure grid
with a pressure- and speed-dependent traction (that of the screw contact, JGP share ψ).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from ballscrew.kinematics.frames import ContactAxes
from ballscrew.kinematics.traction import hertz_pressure_grid, shear_stress

__all__ = [
    "HEATHCOTE_COEFFICIENT",
    "HEATHCOTE_ROLLING_LINE",
    "differential_slip_power",
    "heathcote_power",
    "heathcote_rate",
]

#: u_c = c/b of the two rolling lines under full slip, root of u³ − 3u + 1 = 0 in (0, 1).
HEATHCOTE_ROLLING_LINE = 2.0 * math.cos(4.0 * math.pi / 9.0)


def _coefficient(uc: float) -> float:
    """k_H = (3/8) ∫₋₁¹ (1 − u²)|u² − u_c²| du in closed form (G(u) its antiderivative)."""

    def g(u: float) -> float:
        return -(u**5) / 5.0 + (1.0 + uc * uc) * u**3 / 3.0 - uc * uc * u

    return 3.0 / 8.0 * 2.0 * (g(1.0) - 2.0 * g(uc))


#: k_H of P_H = k_H μ Q ω b²/R_d (full slip, Hertz line load): 0.0806.
HEATHCOTE_COEFFICIENT = _coefficient(HEATHCOTE_ROLLING_LINE)


def heathcote_rate(relative_angular_velocity: ArrayLike, axes: ContactAxes) -> float:
    """ω_r = ω·Y [rad/s], the rolling rate that drives the differential slip of a contact.

    ``relative_angular_velocity`` ω is the ball's angular velocity relative to the raceway;
    ``axes`` the contact frame (X rolling direction, Y across it in the contact plane, the
    major axis of a conforming groove's contact, Z the normal). Only the turning about Y moves
    the ball surface at the lateral offset y by a distance y²/(2R_d) nearer the turning axis
    (Johnson 1985, ch. 8); ω·Z is spin (slip linear in the position) and ω·X a sideways slide
    ω·X r_b of the whole contact (theory manual, *Friction*, rolling rate of (F3b)).
    """
    return float(np.asarray(relative_angular_velocity, dtype=float) @ axes.y)


def heathcote_power(
    load: float, semi_across: float, deformed_radius: float, rolling_rate: float, friction: float
) -> float:
    """P_H = k_H μ Q |ω| b²/R_d [W] of one contact under full slip (closed form above).

    ``load`` Q [N]; ``semi_across`` b, the Hertz semi-axis across the rolling direction [m];
    ``deformed_radius`` R_d [m]; ``rolling_rate`` ω, the ball's angular velocity relative to
    the raceway about the axis across the rolling direction (:func:`heathcote_rate`) [rad/s];
    ``friction`` μ.
    """
    if load <= 0.0:
        return 0.0
    return (
        HEATHCOTE_COEFFICIENT
        * friction
        * load
        * abs(rolling_rate)
        * semi_across**2
        / (deformed_radius)
    )


def differential_slip_power(
    load: float,
    semi_along: float,
    semi_across: float,
    deformed_radius: float,
    rolling_rate: float,
    *,
    psi: float,
    boundary_friction: float,
    limiting_shear: float,
    film_thickness: float = 0.0,
    viscosity: float | None = None,
    pressure_viscosity: float | None = None,
    cells: int = 32,
) -> float:
    """Power [W] of the differential slip of one contact, integrated over the Hertz grid.

    Slip |Δv| = |ω| |y² − c²|/(2R_d) with c = u_c b; shear stress on each cell as at the screw
    contact (``docs/theory/kinematics.md`` (E3.3)): τ = μ_b ψ p + (1 − ψ) min(η(p)|Δv|/h,
    Λ_L p), η(p) = η₀ exp(α_p p) (Barus) (:func:`~ballscrew.kinematics.traction.shear_stress`;
    without a lubricant τ = μ_b ψ p). In the dry limit ψ = 1 it equals :func:`heathcote_power` with
    μ = μ_b (up to the grid's discretisation).
    """
    if load <= 0.0 or rolling_rate == 0.0:
        return 0.0
    x, y, p = hertz_pressure_grid(semi_along, semi_across, load, cells)
    c = HEATHCOTE_ROLLING_LINE * semi_across
    slip = abs(rolling_rate) * np.abs(y * y - c * c) / (2.0 * deformed_radius)
    slip = np.broadcast_to(slip[None, :], p.shape)
    shear = shear_stress(
        p,
        slip,
        psi=psi,
        film_thickness=film_thickness,
        viscosity=viscosity,
        pressure_viscosity=pressure_viscosity,
        boundary_friction=boundary_friction,
        limiting_shear=limiting_shear,
    )
    cell_area = (x[1] - x[0]) * (y[1] - y[0])
    return float(np.sum(shear * slip)) * cell_area
