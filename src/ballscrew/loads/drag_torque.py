"""Catalogue preload drag torque of a preloaded ball screw."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from ballscrew.errors import InputError
from ballscrew.registry import Registry


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


@dataclass(frozen=True)
class DragTorqueInputs:
    """What the drag-torque models of :data:`DRAG_TORQUE_MODELS` may need (SI)."""

    preload: float
    """Preload F_p [N]."""
    lead: float
    """Lead L [m]."""
    lead_angle: float
    """Lead angle α [rad]."""
    given: float | None = None
    """A measured torque [N·m], for the ``given`` model."""
    ball_model: Callable[[], float] | None = None
    """Computes the ball model's torque [N·m] on demand, for the ``kinematics`` model."""


DRAG_TORQUE_MODELS: Registry[Callable[[DragTorqueInputs], float]] = Registry(
    "drag torque model", "thermal.drag_torque.source"
)
"""Rival models of the friction (drag) torque of the ball screw, name → torque [N·m]."""


@DRAG_TORQUE_MODELS.register("catalogue", "makers' preload torque K·F_p·L/(2π), K = 0.05/√tanα")
def catalogue_drag_torque(inputs: DragTorqueInputs) -> float:
    """:func:`preload_drag_torque` of the inputs."""
    return preload_drag_torque(inputs.preload, inputs.lead, inputs.lead_angle)


@DRAG_TORQUE_MODELS.register("given", "a torque measured on the screw")
def given_drag_torque(inputs: DragTorqueInputs) -> float:
    """The measured torque."""
    if inputs.given is None:
        raise InputError("thermal.drag_torque.torque", None, "a torque ≥ 0 N·m for 'given'")
    return float(inputs.given)


@DRAG_TORQUE_MODELS.register(
    "kinematics", "ball model: sliding and EHL rolling losses of the balls"
)
def ball_model_drag_torque(inputs: DragTorqueInputs) -> float:
    """The ball model's torque (the composer supplies how to compute it)."""
    if inputs.ball_model is None:
        raise InputError("thermal.drag_torque.source", "kinematics", "a case with a ball model")
    return float(inputs.ball_model())


@DRAG_TORQUE_MODELS.register(
    "operating_point",
    "coupled operating point: friction torque at the lubricant's viscosity at the computed "
    "temperature",
)
def operating_point_drag_torque(inputs: DragTorqueInputs) -> float:
    """The torque of the coupled operating point (the composer solves it and passes it as
    ``given``)."""
    if inputs.given is None:
        raise InputError(
            "thermal.drag_torque.source", "operating_point", "a torque solved by the composer"
        )
    return float(inputs.given)
