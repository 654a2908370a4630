"""Catalogue preload drag torque of a preloaded ball screw."""

from __future__ import annotations

import math

from ballscrew.errors import InputError


def preload_drag_torque(preload: float, lead: float, lead_angle: float) -> float:
    """No-load (preload) drag torque of a preloaded nut, N·m.

        T_p = K · F_p · L / (2π),   K = 0.05 / √(tan α)

    with the preload F_p [N], the lead L [m] and the lead angle α [rad]. This is the catalogue
    formula of THK, HIWIN and NSK (ISO 3408 practice); theory manual
    ``docs/theory/loads.md`` (E9.1). Example: F_p = 1500 N, L = 10 mm, d_m = 40 mm → K = 0.17725,
    T_p = 0.42314 N·m.
    """
    if not preload >= 0.0:
        raise InputError("preload", preload, "a force ≥ 0 N")
    if not lead > 0.0:
        raise InputError("lead", lead, "a length > 0 m")
    if not 0.0 < lead_angle < math.pi / 2:
        raise InputError("lead_angle", lead_angle, "an angle in (0, π/2) rad")
    coefficient = 0.05 / math.sqrt(math.tan(lead_angle))
    return coefficient * preload * lead / (2.0 * math.pi)
