"""The history of a wear run: depth, preload and drag torque against revolutions."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ballscrew.wear.setup import FloatArray

__all__ = ["WearLife"]


@dataclass(frozen=True)
class WearLife:
    """History of a wear run; arrays have one entry per recorded step (index 0: N = 0)."""

    revolutions: FloatArray
    """Screw revolutions N [-]."""
    max_wear_depth: FloatArray
    """h_max(N), largest depth over both flanks [m]."""
    preload: FloatArray
    """F_p(N) (E1.13) [N]."""
    friction_torque: FloatArray
    """Drag torque T(N) (E9.1) [N m]."""
    nut_forces: FloatArray
    """(F_1, F_2) at each record, under the level then running [N]; shape (n, 2)."""
    level: NDArray[np.int64]
    """Index of the level each record belongs to (its end for boundaries)."""
    sampled: NDArray[np.bool_]
    """True at the torque-sampling revolutions (multiples of ``torque_sampling``, and N = 0)."""
    y: FloatArray
    """Grid positions across the groove [m]."""
    profiles: FloatArray
    """h_s(y) [m], shape (n, 2, ny): flank +1 then −1."""
    level_boundaries: FloatArray
    """Cumulative revolutions at the end of each level [-]."""
    level_loads: FloatArray
    """Axial load of each level [N]."""
    ellipse_major_axis: float = math.nan
    """Extent across the groove of the loaded cells under the loaded nut of the last level at
    the end of the run (worn groove, flank +1) [m] (E8.6)."""
    ellipse_major_axis_unworn: float = math.nan
    """The same on the unworn groove at the same load [m]."""
    worn_band_width: float = math.nan
    """Width of the band with h > 5 % of h_max on flank +1 at the end [m]."""
    final_pressure: FloatArray | None = None
    """Pressure under the loaded nut of the last level at the end (worn groove) [Pa]."""
    x: FloatArray | None = None
    contact_solves: int = 0
    steps: int = 0
    wall_time: float = 0.0
    complete: bool = True
    model: str = "A"
    coefficient: float = math.nan
    raceway_length: float = math.nan
    compliance: float = math.nan
    cell_area: float = math.nan
    initial_psi: dict[str, float] = field(default_factory=dict)

    @property
    def torque_samples(self) -> tuple[FloatArray, FloatArray]:
        """(N, T) at the torque-sampling revolutions."""
        return self.revolutions[self.sampled], self.friction_torque[self.sampled]
