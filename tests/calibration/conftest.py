"""A closed-form stand-in for the wear model, so the calibration tests never run the real one.

Step-stress history in the shape of the reference run of examples/wear_step_stress.toml: three
levels of 4.8e5 rev, wear depth linear in K within each level, h(N) = K · c(N), with the
per-level depth increments of that run at K_REF = 1.3041e-4 (0.968 / 0.693 / 0.769 µm). Preload
from (E1.13) with the reference nut (F_p0 = 1500 N, C_a = 3.749e-8 m N^-2/3, β = 45°), friction
torque from (E9.1) times a torque scale.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pytest

from ballscrew.loads import preload_after_wear, preload_drag_torque

K_REF = 1.3041e-4
LEVEL_REVOLUTIONS = 4.8e5
LEVEL_DEPTHS = (0.968e-6, 0.693e-6, 0.769e-6)  # at K_REF
PRELOAD0 = 1500.0
C_A = 3.749e-8
BETA = math.pi / 4
LEAD = 0.010
LAMBDA = math.atan(LEAD / (math.pi * 0.040))
MEASURED_AT = np.arange(0.0, 1.44e6 + 1.0, 4.8e4)  # the bench's sampling, 31 points


@dataclass(frozen=True)
class History:
    revolutions: np.ndarray
    max_wear_depth: np.ndarray
    preload: np.ndarray
    friction_torque: np.ndarray


def exact(k: float, revolutions: np.ndarray, torque_scale: float = 1.0) -> History:
    """The closed-form history at any revolutions (used to make the 'measured' data)."""
    n = np.asarray(revolutions, dtype=float)
    depth = np.zeros_like(n)
    for level, dh in enumerate(LEVEL_DEPTHS):
        in_level = np.clip(n - level * LEVEL_REVOLUTIONS, 0.0, LEVEL_REVOLUTIONS)
        depth += (k / K_REF) * dh * in_level / LEVEL_REVOLUTIONS
    preload = preload_after_wear(PRELOAD0, C_A, depth, BETA, LAMBDA)
    torque = torque_scale * preload_drag_torque(1.0, LEAD, LAMBDA) * preload
    return History(n, depth, preload, torque)


class SyntheticModel:
    """``simulate(K)``: the closed form on its own non-uniform grid; counts its runs."""

    def __init__(self, torque_scale: float = 1.0) -> None:
        self.torque_scale = torque_scale
        self.runs = 0
        # 0.1 µm-like steps: denser early, not aligned with the 4.8e4 rev sampling
        self.grid = np.unique(np.r_[np.linspace(0.0, 1.44e6, 91), np.geomspace(1e3, 1e5, 15)])

    def __call__(self, k: float) -> History:
        self.runs += 1
        return exact(k, self.grid, self.torque_scale)


@pytest.fixture
def synthetic_model() -> type[SyntheticModel]:
    return SyntheticModel
