"""A closed-form wear history that responds to K, the film supply factor φ and the running-in
depth h_r, so the calibration of each parameter subset can be tested without the real model.

Three levels of 4.8e5 rev with the reference depth increments at K_REF (conftest), each scaled by
an asperity share ψ_l(φ) = 1/(1 + (c_l/φ)²) that falls with the level's film c_l (a faster level
has a thicker film), and a running-in factor 1 + A e^(−h/h_r) on the rate:

    dh/dN = a_l (1 + A e^(−h/h_r))  →  h = h_r ln((e^(h₀/h_r) + A) e^(a_l ΔN/h_r) − A)

Preload (E1.13) and torque (E9.1) as in the conftest stand-in.
"""

from __future__ import annotations

import math

import numpy as np

from ballscrew.loads import preload_after_wear, preload_drag_torque

from .conftest import BETA, C_A, K_REF, LAMBDA, LEAD, LEVEL_DEPTHS, LEVEL_REVOLUTIONS, History

FILM = (0.3, 0.8, 1.5)
RUNNING_IN = 3.0
TRUE = {
    "wear_coefficient": 2.0e-4,
    "film_factor": 0.5,
    "running_in_depth": 0.3e-6,
    "torque_scale": 1.2,
}
START = {"wear_coefficient": 1.0e-4, "film_factor": 1.0, "running_in_depth": 1.0e-6}
GRID = np.unique(np.r_[np.linspace(0.0, 1.44e6, 145), np.geomspace(1e2, 1e5, 31)])
MEASURED_AT = np.linspace(0.0, 1.44e6, 61)


def _depth(values: dict[str, float], revolutions: np.ndarray) -> np.ndarray:
    k, phi = values["wear_coefficient"], values.get("film_factor", 1.0)
    h_r = values.get("running_in_depth", 1.0)
    amplitude = RUNNING_IN if "running_in_depth" in values else 0.0
    out = np.zeros_like(revolutions)
    h0 = 0.0
    for level, (dh, c) in enumerate(zip(LEVEL_DEPTHS, FILM, strict=True)):
        a = (k / K_REF) * dh / LEVEL_REVOLUTIONS / (1.0 + (c / phi) ** 2)
        dn = np.clip(revolutions - level * LEVEL_REVOLUTIONS, 0.0, LEVEL_REVOLUTIONS)
        start = level * LEVEL_REVOLUTIONS
        inside = revolutions > start
        log_y = np.logaddexp(h0 / h_r, math.log(amplitude) if amplitude else -np.inf)
        big = log_y + a * dn / h_r
        h = h_r * (big + np.log1p(-amplitude * np.exp(-big)))
        out = np.where(inside, h, out)
        end = log_y + a * LEVEL_REVOLUTIONS / h_r
        h0 = h_r * (end + math.log1p(-amplitude * math.exp(-end)))
    return out


def history(values: dict[str, float], revolutions: np.ndarray, scale: float = 1.0) -> History:
    depth = _depth(values, np.asarray(revolutions, dtype=float))
    preload = preload_after_wear(1500.0, C_A, depth, BETA, LAMBDA)
    torque = scale * preload_drag_torque(1.0, LEAD, LAMBDA) * preload
    return History(np.asarray(revolutions, dtype=float), depth, preload, torque)


class MultiModel:
    """``simulate(values)`` on its own grid; counts its runs."""

    def __init__(self, fixed: dict[str, float] | None = None) -> None:
        self.fixed = fixed or {}
        self.runs = 0

    def __call__(self, values) -> History:
        self.runs += 1
        return history({**self.fixed, **values}, GRID)
