"""Rating life of a ball screw from its dynamic load rating, as the makers publish it.

* Nominal life L = (C_a/(f_w F_m))³ · 10⁶ revolutions (THK General Catalog A-704, eq. 27; HIWIN
  *Ballscrews & Accessories* F 3.10), in hours L_h = L/(60 n_m) and in travel L_s = L·P_h.
* Cube-mean load F_m = (Σ F_i³ n_i / Σ n_i)^(1/3) over the revolutions n_i (or travel) of each
  load level, one value per load direction: a level of the other sign counts as zero load
  (THK A-705/A-706; HIWIN F 3.8/3.9).
* Preloaded double nut: below the lift-off load F_lim = 2^(3/2) F_pr the loaded nut half carries
  F_b = (1 + F/(2^(3/2) F_pr))^(3/2) F_pr and the other half F_b − F (HIWIN F 3.5–3.7); the two
  halves' lives combine as L = (L₁^(−10/9) + L₂^(−10/9))^(−9/10) (HIWIN F 3.12).
* Reliability factor a₁ for 90–99 % survival (HIWIN Table 3.17).

ISO 3408-5, on which the makers base these forms, was not read; its own text may differ.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError
from ballscrew.validation import nonnegative, nonnegative_array, positive, real_array, same_shape

__all__ = [
    "LIFT_OFF_FACTOR",
    "RELIABILITY_FACTORS",
    "combined_life",
    "cube_mean_loads",
    "life_hours",
    "life_travel",
    "preloaded_half_loads",
    "rating_life",
    "reliability_factor",
    "static_safety_factor",
]

LIFT_OFF_FACTOR = 2.0**1.5
"""External load at which the second half of a preloaded double nut lifts off, / preload."""

RELIABILITY_FACTORS: dict[int, float] = {90: 1.0, 95: 0.63, 96: 0.53, 97: 0.44, 98: 0.33, 99: 0.21}
"""Life factor a₁ by reliability in percent (HIWIN Table 3.17)."""


def reliability_factor(reliability: float) -> float:
    """Life factor a₁ of a reliability in percent (one of :data:`RELIABILITY_FACTORS`)."""
    key = round(float(reliability))
    if key != reliability or key not in RELIABILITY_FACTORS:
        allowed = ", ".join(str(k) for k in RELIABILITY_FACTORS) + " (percent)"
        raise InputError("reliability", reliability, allowed)
    return RELIABILITY_FACTORS[key]


def rating_life(
    dynamic_load_rating: float,
    mean_load: ArrayLike,
    load_factor: float = 1.0,
    reliability: float = 90,
) -> NDArray[np.float64]:
    """Rating life a₁ (C_a/(f_w F_m))³ · 10⁶ in revolutions (inf where F_m = 0).

    Example (THK A-733): C_a = 5400 N, f_w = 1.5, F_m = 225 N → 4.096e9 rev.
    """
    ca = positive("dynamic_load_rating", dynamic_load_rating, "N")
    fw = positive("load_factor", load_factor)
    if fw < 1.0:
        raise InputError("load_factor", load_factor, "a number >= 1 (f_w, 1 = no shocks)")
    fm = nonnegative_array("mean_load", mean_load, "N")
    with np.errstate(divide="ignore"):
        ratio = np.where(fm > 0.0, ca / (fw * np.where(fm > 0.0, fm, 1.0)), np.inf)
    return reliability_factor(reliability) * ratio**3 * 1.0e6


def cube_mean_loads(loads: ArrayLike, shares: ArrayLike) -> tuple[float, float]:
    """Cube-mean loads (F_m+, F_m−) of a load spectrum, one per load direction, N.

    ``loads`` are signed axial loads; ``shares`` their revolutions, travel or time × speed
    (≥ 0, not all 0). Each direction's mean runs over the whole spectrum, the levels of the
    other sign counting as zero load (THK A-706: loads 10, 50, −40, −10 N over 10, 50, 10,
    70 mm give 35.5 N and 17.2 N).
    """
    f = real_array("loads", loads, "N")
    w = nonnegative_array("shares", shares)
    same_shape("loads, shares", f, w)
    total = float(w.sum())
    if not total > 0.0:
        raise InputError("shares", w.tolist(), "revolutions or travel >= 0, not all 0")
    positive_part = np.maximum(f, 0.0)
    negative_part = np.maximum(-f, 0.0)
    return (
        float(np.sum(positive_part**3 * w) / total) ** (1.0 / 3.0),
        float(np.sum(negative_part**3 * w) / total) ** (1.0 / 3.0),
    )


def preloaded_half_loads(axial_load: ArrayLike, preload: float) -> tuple[NDArray, NDArray]:
    """Equivalent loads (F_b1, F_b2) of the two halves of a preloaded double nut, N.

    F_b1 = (1 + F/(2^(3/2) F_pr))^(3/2) F_pr and F_b2 = F_b1 − F below lift-off
    (F < 2^(3/2) F_pr); F_b1 = F and F_b2 = 0 above it (HIWIN F 3.5–3.7).
    """
    f = nonnegative_array("axial_load", axial_load, "N")
    fp = positive("preload", preload, "N")
    below = f < LIFT_OFF_FACTOR * fp
    f1 = np.where(below, (1.0 + f / (LIFT_OFF_FACTOR * fp)) ** 1.5 * fp, f)
    return f1, np.where(below, f1 - f, 0.0)


def combined_life(lives: Sequence[float]) -> float:
    """Life of a nut of several loaded halves, (Σ L_i^(−10/9))^(−9/10) (HIWIN F 3.12)."""
    terms = [float(life) for life in lives]
    if not terms or not all(t > 0.0 for t in terms):  # inf (an unloaded half) is allowed
        raise InputError("lives", list(lives), "one or more lives > 0 rev (inf: unloaded)")
    inverse = sum(0.0 if math.isinf(t) else t ** (-10.0 / 9.0) for t in terms)
    return math.inf if inverse == 0.0 else inverse ** (-9.0 / 10.0)


def life_hours(revolutions: float, mean_speed: float) -> float:
    """Life in hours L/(60 n_m) at the mean screw speed ``mean_speed`` [rad/s]."""
    speed = positive("mean_speed", mean_speed, "rad/s")
    return nonnegative("revolutions", revolutions) / (speed / (2.0 * math.pi)) / 3600.0


def life_travel(revolutions: float, lead: float) -> float:
    """Life as the nut's travel L·P_h, m."""
    return nonnegative("revolutions", revolutions) * positive("lead", lead, "m")


def static_safety_factor(static_load_rating: float, max_axial_load: float) -> float:
    """Static safety factor f_s = C_0a / F_a,max (THK A-703 eq. 26; inf without load)."""
    c0 = positive("static_load_rating", static_load_rating, "N")
    f = nonnegative("max_axial_load", max_axial_load, "N")
    return math.inf if f == 0.0 else c0 / f
