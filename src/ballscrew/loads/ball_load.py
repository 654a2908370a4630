"""Normal ball load from the axial force carried by one nut.

Theory manual: ``docs/theory/loads.md``, ball load (Q1).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError
from ballscrew.validation import nonnegative_array

__all__ = ["ball_load", "validate_angles", "validate_balls"]


def validate_angles(contact_angle: float, lead_angle: float) -> tuple[float, float]:
    """Return (β, α) as floats after checking 0 < β < π/2 and 0 ≤ α < π/2 (radians).

    Raises:
        InputError: if either angle is outside its range.
    """
    beta = float(contact_angle)
    alpha = float(lead_angle)
    if not (math.isfinite(beta) and 0.0 < beta < 0.5 * math.pi):
        raise InputError("contact_angle", contact_angle, "0 < β < π/2 rad")
    if not (math.isfinite(alpha) and 0.0 <= alpha < 0.5 * math.pi):
        raise InputError("lead_angle", lead_angle, "0 <= α < π/2 rad")
    return beta, alpha


def validate_balls(balls: int) -> int:
    """Return the number of loaded balls per nut after checking it is an integer >= 1.

    Raises:
        InputError: if ``balls`` is not a positive integer.
    """
    if isinstance(balls, bool) or int(balls) != balls or balls < 1:
        raise InputError("balls", balls, "an integer >= 1 (loaded balls per nut)")
    return int(balls)


def ball_load(
    axial_force: ArrayLike, balls: int, contact_angle: float, lead_angle: float
) -> NDArray[np.float64]:
    """Normal ball load Q = F / (n_b sinβ cosα), equation (Q1) (paper Eq. (20)).

    Every loaded ball of the nut carries the same load; friction is neglected. The axial
    component of a ball's contact normal is sinβ·cosα (``docs/theory/geometry.md``).

    Args:
        axial_force: axial force F carried by the nut (>= 0), N; any shape.
        balls: number of loaded balls n_b of that nut.
        contact_angle: contact angle β in the normal plane, rad (0 < β < π/2).
        lead_angle: lead angle α of the ball-centre helix, rad (0 <= α < π/2).

    Returns:
        Q in N, same shape as ``axial_force``; e.g. 39.40790 N for F = 1500 N, n_b = 54,
        β = 45°, α = 4.549865°.

    Raises:
        InputError: for negative or non-finite forces, or invalid balls or angles.
    """
    beta, alpha = validate_angles(contact_angle, lead_angle)
    n_b = validate_balls(balls)
    force = nonnegative_array("axial_force", axial_force, "N")
    return force / (n_b * math.sin(beta) * math.cos(alpha))
