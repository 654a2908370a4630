"""The load programme and the options of a wear run, as plain SI values."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["WearLevel", "WearOptions"]


@dataclass(frozen=True)
class WearLevel:
    """One level of the programme: a constant axial load and speed for some revolutions."""

    axial_load: float
    """External axial load F_a [N]."""
    speed: float
    """Screw speed ω_s [rad/s]."""
    revolutions: float
    """Screw revolutions of the level [-]."""


@dataclass(frozen=True)
class WearOptions:
    """Wear law, load programme and integration settings of a wear run (SI)."""

    model: str
    """Registered wear law (``ballscrew.wear.WEAR_LAWS``)."""
    coefficient: float
    """Wear coefficient K [-]."""
    stroke: float
    """Reciprocating stroke S of the nut [m]."""
    max_depth_step: float
    """Largest growth of h_max per time step [m]."""
    torque_sampling: float
    """Screw revolutions between drag-torque samples [-]."""
    torque_scale: float
    """Factor on the catalogue drag-torque coefficient [-]."""
    initial_torque: float | None
    """Measured drag torque at N = 0 [N m]; None = use ``torque_scale``."""
    programme: tuple[WearLevel, ...]
    grid: tuple[int, int]
    """Contact-grid cells (along the rolling direction, across the groove)."""
    box_factor: float
    """Grid half-widths / Hertz semi-axes at the largest ball load [-]."""
    checkpoint_every: int
    """Time steps between checkpoint saves."""
