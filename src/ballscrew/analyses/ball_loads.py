"""Normal load and contact angle of every ball of every nut: ``ballscrew.ball_loads(case)``.

The distribution is uniform: every loaded ball of a nut carries Q = F/(Z sinβ cosα) at the
nominal contact angle β (rigid screw and nut bodies, no lead error; theory manual, *Loads*).
The elastic distribution along the nut (body compliance, lead error, ball-diameter variation,
the change of the contact angle under load) is not built yet; uniform is its rigid limit.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.case import Case

__all__ = ["BallLoads", "ball_loads"]


@dataclass(frozen=True)
class BallLoads:
    """Per-ball loads and angles, one row per nut (nut 1 first), one column per ball (SI)."""

    loads: NDArray[np.float64]
    """Normal ball load Q [N], shape (nuts, balls per nut); 0 for a lifted-off nut."""
    angles: NDArray[np.float64]
    """Contact angle β [rad], same shape."""
    axial_forces: NDArray[np.float64]
    """Axial force of each nut's balls, Σ Q sinβ cosα [N] (equals the nut force)."""
    distribution: str = "uniform"


def ball_loads(case: Case) -> BallLoads:
    """Normal load and contact angle of every ball of every nut of ``case`` (uniform)."""
    params = ScrewParameters.from_case(case)
    z = params.balls_per_nut
    loads = np.array([np.full(z, nut.ball_load) for nut in params.nuts])
    angles = np.full_like(loads, params.geometry.contact_angle)
    return BallLoads(loads, angles, loads.sum(axis=1) * params.axial_projection)
