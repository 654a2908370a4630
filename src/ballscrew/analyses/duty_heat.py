"""The friction heat of one duty segment as a function of the contact temperature.

While the screw warms up, the lubricant thins and the friction heat of a segment changes:

    Q(T_c) = f · Q_friction(ω, F_a, η(T_c)),

with f the segment's moving fraction (:mod:`~ballscrew.analyses.duty`) and η(T_c) the
lubricant's viscosity at the contact temperature. Q is tabulated on nodes every
:data:`NODE_SPACING` from ambient and at the segment's steady contact temperature T*, where it
equals the steady operating point's heat exactly, and interpolated linearly between nodes; a
temperature outside the table adds nodes (no clamp). A friction model that does not see the
viscosity (the catalogue model, or a lubricant of constant viscosity) gives a constant Q.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.operating_point import OperatingPoint, medium_law
from ballscrew.case import Case

__all__ = ["NODE_SPACING", "SegmentHeat"]

NODE_SPACING = 5.0
"""Spacing of the temperature nodes [K]: the viscosity of mineral oils falls by about 15 % per
5 K near 40 °C, so the linear interpolation of Q between nodes is within about 0.1 %."""


@dataclass
class SegmentHeat:
    """Q(T_c) of one segment turning at ``point.speed`` for the ``fraction`` f of its time."""

    case: Case
    """The segment's case (its speed and axial load)."""
    point: OperatingPoint
    """The segment's steady coupled operating point."""
    fraction: float
    ambient: float
    """Ambient temperature [K], the origin of the node grid."""
    _nodes: dict[float, float] = field(default_factory=dict, repr=False)
    _viscosity: Callable[[float], float | None] = field(init=False, repr=False)
    _constant: bool = field(init=False, repr=False)
    _table: np.ndarray = field(init=False, repr=False)
    """(node temperatures, heats), sorted."""

    def __post_init__(self) -> None:
        self._viscosity = lambda t: medium_law(self.case)(t)[0]
        self._nodes[self.point.contact_temperature] = self.steady_heat
        self._table = np.array(sorted(self._nodes.items())).T
        self._constant = math.isclose(
            self._friction_heat(self.ambient), self.steady_heat, rel_tol=1e-12, abs_tol=1e-12
        )

    @property
    def steady_heat(self) -> float:
        """f·Q at the steady operating point [W]."""
        return self.fraction * self.point.heat

    def _friction_heat(self, temperature: float) -> float:
        eta = self._viscosity(temperature)
        return self.fraction * friction_torque(self.case, viscosity=eta).heat

    def _cover(self, temperature: float) -> None:
        """Add the grid nodes from the table to ``temperature`` and refresh the arrays."""
        steps = [(t - self.ambient) / NODE_SPACING for t in (temperature, *self._nodes)]
        for j in range(math.floor(min(steps)), math.ceil(max(steps)) + 1):
            node = self.ambient + j * NODE_SPACING
            if node not in self._nodes:
                self._nodes[node] = self._friction_heat(node)
        self._table = np.array(sorted(self._nodes.items())).T

    def heat(self, temperature: float) -> float:
        """Time-mean friction heat f·Q(T_c) of the segment at contact temperature T_c [W]."""
        if self._constant:
            return self.steady_heat
        if not self._table[0, 0] <= temperature <= self._table[0, -1]:
            self._cover(temperature)
        return float(np.interp(temperature, self._table[0], self._table[1]))
