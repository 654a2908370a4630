"""Boundary conditions of the screw–nut model beyond still air (Q8–Q10).

The nut seated in a table (a contact conductance in series with the table as a heat sink),
forced convection of a coolant in a pipe or channel, and the fixed-point iteration that evaluates
natural convection at the computed surface temperature. SI throughout; theory manual
``docs/theory/thermal.md``, *Boundary conditions*.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ballscrew.errors import ConvergenceError
from ballscrew.validation import nonnegative, positive


def mounting_coefficient(
    contact_conductance: float,
    contact_area: float,
    outer_area: float,
    table_conductance: float | None = None,
) -> float:
    """h over the nut assembly's outer surface of its path into the table (Q8) [W/(m² K)].

        1/G = 1/(h_c A_c) + 1/G_t,   h_mount = G / A_od

    ``contact_conductance`` h_c of the joint [W/(m² K)] over ``contact_area`` A_c [m²], the table
    with ``table_conductance`` G_t [W/K] to ambient (None: a table held at ambient), smeared
    over the outer area A_od [m²]. Exact for an isothermal nut outer surface (Biot number
    h_mount·r/λ ≪ 1); the table is quasi-steady (its heat capacity is not modelled).
    """
    nonnegative("contact_conductance", contact_conductance, "W/(m² K)")
    nonnegative("contact_area", contact_area, "m²")
    positive("outer_area", outer_area, "m²")
    joint = contact_conductance * contact_area
    if table_conductance is not None:
        nonnegative("table_conductance", table_conductance, "W/K")
        if joint == 0.0 or table_conductance == 0.0:
            return 0.0
        joint = 1.0 / (1.0 / joint + 1.0 / table_conductance)
    return joint / outer_area


def gnielinski(reynolds: float, prandtl: float) -> float:
    """Nusselt number of turbulent pipe flow, Gnielinski (1976) (Q9).

        Nu = (f/8)(Re − 1000) Pr / [1 + 12.7 (f/8)^{1/2} (Pr^{2/3} − 1)],
        f = (0.790 ln Re − 1.64)^{−2}   (Petukhov)

    (Gnielinski, Int. Chem. Eng. 16 (1976) 359; Incropera & DeWitt Eq. 8.62; valid
    3000 ≤ Re ≤ 5·10⁶, 0.5 ≤ Pr ≤ 2000). At Pr = 1 the denominator is 1.
    """
    positive("reynolds", reynolds)
    positive("prandtl", prandtl)
    f = (0.790 * math.log(reynolds) - 1.64) ** -2
    return (
        (f / 8.0)
        * (reynolds - 1000.0)
        * prandtl
        / (1.0 + 12.7 * math.sqrt(f / 8.0) * (prandtl ** (2.0 / 3.0) - 1.0))
    )


def dittus_boelter(reynolds: float, prandtl: float, heating: bool = True) -> float:
    """Nusselt number of turbulent pipe flow, Dittus–Boelter (Q9).

        Nu = 0.023 Re^{4/5} Pr^n,   n = 0.4 (fluid heated), 0.3 (fluid cooled)

    (Dittus & Boelter 1930; Incropera & DeWitt Eq. 8.60; Re ≥ 10⁴, 0.6 ≤ Pr ≤ 160, L/D ≥ 10).
    """
    positive("reynolds", reynolds)
    positive("prandtl", prandtl)
    return 0.023 * reynolds**0.8 * prandtl ** (0.4 if heating else 0.3)


def pipe_coefficient(
    diameter: float,
    velocity: float,
    kinematic_viscosity: float,
    conductivity: float,
    prandtl: float,
) -> float:
    """h of a coolant flowing at ``velocity`` through a bore of ``diameter`` (Q9) [W/(m² K)].

    Gnielinski for Re ≥ 3000, the fully developed laminar value Nu = 3.66 (uniform wall
    temperature) below 2300, linear in Re between (a plain blend over the transition).
    """
    positive("diameter", diameter, "m")
    nonnegative("velocity", velocity, "m/s")
    re = velocity * diameter / positive("kinematic_viscosity", kinematic_viscosity, "m²/s")
    laminar, low, high = 3.66, 2300.0, 3000.0
    if re <= low:
        nu = laminar
    elif re >= high:
        nu = gnielinski(re, prandtl)
    else:
        t = (re - low) / (high - low)
        nu = (1.0 - t) * laminar + t * gnielinski(high, prandtl)
    return nu * positive("conductivity", conductivity, "W/(m K)") / diameter


def fixed_point(
    update: Callable[[tuple[float, ...]], tuple[float, ...]],
    start: tuple[float, ...],
    tolerance: float = 1e-6,
    max_iterations: int = 50,
    solver: str = "natural-convection iteration",
) -> tuple[tuple[float, ...], int]:
    """Iterate x ← update(x) until max |Δx|/max(|x|, 1) ≤ ``tolerance``.

    Returns (x, iterations); :class:`~ballscrew.errors.ConvergenceError` with the last residual
    otherwise. ``update`` maps surface temperature rises to the rises they produce (Q6 iterated).
    """
    x = tuple(float(v) for v in start)
    residual = math.inf
    for k in range(1, max_iterations + 1):
        new = tuple(float(v) for v in update(x))
        residual = max(abs(a - b) / max(abs(a), 1.0) for a, b in zip(new, x, strict=True))
        x = new
        if residual <= tolerance:
            return x, k
    raise ConvergenceError(solver, max_iterations, residual, tolerance)
