"""Traction of the ball–screw contact A from the sliding field in mixed lubrication.

``docs/theory/kinematics.md`` (E3.3) [reconstructed]: on each cell of the pressure grid the shear
stress on the ball opposes the local sliding Δv (ball relative to screw),

    τ = −[ μ_b ψ p + (1 − ψ) min( η(p) ‖Δv‖/h_c , Λ p ) ] · Δv/‖Δv‖,

the asperity-borne pressure ψ p with boundary friction μ_b, the film-borne part with a viscous
shear stress capped at the limiting shear stress τ_L = Λ p (Bair & Winer 1979; Λ ≈ 0.07).
The effective viscosity is the Barus viscosity η(p) = η₀ exp(α_p p) at the local pressure
(the document leaves η_e open; with it the film term reaches τ_L at these slide speeds).
F_T = Σ τ ΔA, and the moment about the ball centre Σ (P − c) × τ ΔA (E3.3).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ballscrew.kinematics.motion import BallMotion

__all__ = ["ContactTraction", "contact_traction", "hertz_pressure_grid", "shear_stress"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class ContactTraction:
    """Resultants of the traction on the ball at A."""

    force: FloatArray
    """F_T,A on the ball [N] (global components)."""
    moment: FloatArray
    """Σ (P − c) × τ ΔA about the ball centre [N m]."""
    power_loss: float
    """Dissipated power −Σ τ·Δv ΔA ≥ 0 [W]."""
    screw_power: float
    """Power the screw supplies against the traction, Σ τ·v_screw ΔA [W]."""


def hertz_pressure_grid(
    semi_x: float, semi_y: float, load: float, cells: int
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Cell-centred grid over the Hertz ellipse and its pressure, normalised to Σ p ΔA = Q.

    ``cells`` per axis; returns (x, y, p) with p of shape (cells, cells) [m, m, Pa].
    """
    x = (np.arange(cells) + 0.5 - 0.5 * cells) * (2.0 * semi_x / cells)
    y = (np.arange(cells) + 0.5 - 0.5 * cells) * (2.0 * semi_y / cells)
    shape = 1.0 - (x[:, None] / semi_x) ** 2 - (y[None, :] / semi_y) ** 2
    p = np.sqrt(np.maximum(shape, 0.0))
    cell_area = (2.0 * semi_x / cells) * (2.0 * semi_y / cells)
    return x, y, p * (load / (p.sum() * cell_area))


def shear_stress(
    pressure: FloatArray,
    slip: FloatArray,
    *,
    psi: float,
    film_thickness: float,
    viscosity: float | None,
    pressure_viscosity: float | None,
    boundary_friction: float,
    limiting_shear: float,
) -> FloatArray:
    """|τ| = μ_b ψ p + (1 − ψ) min(η(p) |Δv|/h, Λ p) of (E3.3) on cells of pressure p, slip |Δv|.

    η(p) = η₀ exp(α_p p) (Barus); without a lubricant (no viscosity) only the boundary term
    μ_b ψ p acts. A lubricated contact whose film carries nothing (``film_thickness`` 0: the
    load sharing found none) shears the (1 − ψ) part at its cap Λ p, the limit h → 0 of the
    viscous stress; it matters only where ψ is a law's weight other than the JGP share (the
    ``skf`` law's φ_bl) [Pa].
    """
    shear = boundary_friction * psi * pressure
    if psi < 1.0 and viscosity is not None:
        cap = limiting_shear * pressure
        if film_thickness <= 0.0:
            return shear + (1.0 - psi) * cap
        alpha = pressure_viscosity or 0.0
        with np.errstate(divide="ignore"):
            log_viscous = (
                math.log(viscosity)
                + np.minimum(alpha * pressure, 700.0)
                + np.log(slip / film_thickness)
            )
            viscous = np.exp(np.minimum(log_viscous, 700.0))
        shear = shear + (1.0 - psi) * np.minimum(viscous, cap)
    return shear


def contact_traction(
    motion: BallMotion,
    x: FloatArray,
    y: FloatArray,
    pressure: FloatArray,
    *,
    psi: float,
    film_thickness: float,
    viscosity: float | None,
    pressure_viscosity: float | None,
    boundary_friction: float,
    limiting_shear: float,
    deformed_radius: float,
) -> ContactTraction:
    """Traction resultants at A over the grid (x, y) with the cell pressures ``pressure``, (E3.3).

    Vectorised over the grid; P = A + x X_A + y Y_A − y²/(2R_d) e_A; the cells' shear of
    :func:`shear_stress` (without a lubricant only the boundary term, with ψ as given).
    """
    axes = motion.screw_contact
    cell_area = (x[1] - x[0]) * (y[1] - y[0]) if x.size > 1 and y.size > 1 else 0.0
    xx, yy = np.meshgrid(x, y, indexing="ij")
    points = axes.point(xx, yy, -(yy**2) / (2.0 * deformed_radius))
    dv = motion.sliding_velocity(points)
    dv = dv - (dv @ axes.z)[..., None] * axes.z  # tangential part
    speed = np.linalg.norm(dv, axis=-1)
    reference = max(abs(motion.screw_speed) * motion.frame.ball_radius, 1e-30)
    direction = dv / np.sqrt(speed**2 + (1e-12 * reference) ** 2)[..., None]
    shear = shear_stress(
        np.asarray(pressure, dtype=float),
        speed,
        psi=psi,
        film_thickness=film_thickness,
        viscosity=viscosity,
        pressure_viscosity=pressure_viscosity,
        boundary_friction=boundary_friction,
        limiting_shear=limiting_shear,
    )
    tau = -shear[..., None] * direction
    force = tau.sum(axis=(0, 1)) * cell_area
    moment = np.cross(points - motion.frame.centre, tau).sum(axis=(0, 1)) * cell_area
    power = -float(np.sum(tau * dv)) * cell_area
    screw_power = float(np.sum(tau * motion.screw_velocity(points))) * cell_area
    return ContactTraction(force=force, moment=moment, power_loss=power, screw_power=screw_power)
