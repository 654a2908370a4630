"""Ball-load classes: a few representative balls of an uneven per-ball load distribution.

Every ball of a nut runs over every point of the raceway it loads (the balls circulate), so the
raceway depth rate is the mean over the Z balls of each ball's rate,
ḣ = (1/Z) Σ_i ḣ(Q_i) = Σ_k w_k ḣ(r_k Q̄) (theory manual, *Wear*, per-ball wear). The balls are
sorted by load and split into n classes of (nearly) equal count; class k stands for its balls by
their mean load ratio r_k = mean(Q_i)/Q̄ and its share w_k = Z_k/Z. Equal-count classes keep the
nut force, Σ_k w_k r_k = 1, and converge to the per-ball sum as n → Z (quantile binning of the
load distribution, as in the load-class life sums of Lundberg and Palmgren, 1947).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["UNIFORM", "LoadClasses", "load_classes"]


@dataclass(frozen=True)
class LoadClasses:
    """Load ratio r_k = Q_k/Q̄ and ball share w_k of each class (Σ w_k = 1, Σ w_k r_k = 1)."""

    ratios: tuple[float, ...]
    weights: tuple[float, ...]

    def __post_init__(self) -> None:
        if len(self.ratios) != len(self.weights) or not self.ratios:
            raise ValueError("one weight per load ratio, at least one class")


UNIFORM = LoadClasses((1.0,), (1.0,))
"""Every ball carries the mean load (the uniform distribution)."""


def load_classes(loads: ArrayLike, classes: int) -> LoadClasses:
    """``classes`` equal-count classes of the per-ball loads of one nut (sorted by load).

    A nut without load, or one whose balls carry the same load, is :data:`UNIFORM`.
    """
    q = np.sort(np.asarray(loads, dtype=float).ravel())
    if classes < 1:
        raise ValueError(f"classes = {classes} must be ≥ 1")
    mean = float(q.mean()) if q.size else 0.0
    if mean <= 0.0 or float(q[-1] - q[0]) <= 1e-12 * mean:
        return UNIFORM
    groups = np.array_split(q / mean, min(classes, q.size))
    return LoadClasses(
        tuple(float(g.mean()) for g in groups), tuple(g.size / q.size for g in groups)
    )
