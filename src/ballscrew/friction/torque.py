"""Friction torque of the nut: its parts, the rival total models and the heat it makes.

The screw torque at speed ω_s against the axial load F_a is

    T = F_a L/(2π) + T_load + T_preload + n_s T_seal + T_recirculation,

the work F_a L/(2π) on the load plus friction parts; the heat is everything not delivered as
work, Q = T ω_s − F_a v = (T − F_a L/2π) ω_s ≥ 0 with v = L ω_s/(2π). T_load = F_a L/(2π)(1/η − 1)
is the makers' efficiency form (:mod:`ballscrew.friction.efficiency`). The preload part is the
makers' catalogue torque (``"catalogue"``) or the ball losses of
:mod:`ballscrew.friction.ball_losses` at the preload (``"ball_model"``: traction, Heathcote
slip at the nut contact, EHL rolling, hysteresis, ball–ball friction, drag in the lubricant and
the ball-return loss). A seal's torque
is a parameter (its default is set by the case); ``recirculation_torque`` is a given ball-return
torque added to the modelled one (the catalogue model has only the given one, default 0).

Heat split: the catalogue preload and load parts are not located; half of each is ASSUMED at
the screw contact A (shared equally by screw and ball), half at the nut contact B. A seal rubs
on the screw and is held by the nut: half each (ASSUMED). Recirculation heats the nut.
At ω_s = 0 the torque is the static (breakaway) value and the heat 0.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from ballscrew.errors import InputError
from ballscrew.friction.ball_losses import DEFAULT_HYSTERESIS, BallLosses
from ballscrew.friction.efficiency import (
    CATALOGUE_ROLLING_FRICTION,
    backdriving_efficiency,
    driving_efficiency,
    load_friction_torque,
)
from ballscrew.loads import DRAG_TORQUE_MODELS, DragTorqueInputs
from ballscrew.lubrication import regime
from ballscrew.registry import Registry
from ballscrew.validation import nonnegative

__all__ = ["FRICTION_MODELS", "FrictionInputs", "FrictionTorque", "nut_friction_torque"]

#: Share of an unlocated ball-screw loss that heats the screw: half at A, split equally there.
UNLOCATED_SCREW_SHARE = 0.25


@dataclass(frozen=True)
class FrictionInputs:
    """What the friction models need (SI)."""

    lead: float
    """L [m]."""
    lead_angle: float
    """λ [rad]."""
    preload: float
    """F_p [N]."""
    axial_load: float = 0.0
    """Working load F_a [N]."""
    speed: float = 0.0
    """Screw speed ω_s ≥ 0 [rad/s]."""
    rolling_friction: float = CATALOGUE_ROLLING_FRICTION
    """Effective μ of the efficiency formulas."""
    seals: int = 0
    """Number of contacting seals or wipers."""
    seal_torque: float = 0.0
    """Torque of one seal [N m]."""
    recirculation_torque: float = 0.0
    """Given ball-return loss [N m], added to the modelled one of ``ball_model`` (default 0)."""
    hysteresis: float = DEFAULT_HYSTERESIS
    """Hysteresis loss fraction α of the Hertz contacts (ball model)."""
    ball_losses: Callable[[float], BallLosses] | None = None
    """Ball losses at the preload for a screw speed (the composer builds it), for ``ball_model``."""


@dataclass(frozen=True)
class FrictionTorque:
    """Screw torque of the nut, its parts, the efficiencies and the heat."""

    total: float
    """Screw torque T [N m] (work on the load included)."""
    parts: dict[str, float]
    """Its parts [N m]: ``work``, ``load``, ``preload`` or the ball losses (``sliding``,
    ``groove_slip``, ``ehl_rolling``, ``hysteresis``, ``ball_ball``, ``drag``), ``seals``,
    ``recirculation``."""
    efficiency_driving: float
    """η = tan λ/tan(λ + ρ′)."""
    efficiency_backdriving: float
    """η′ = tan(λ − ρ′)/tan λ (≤ 0: self-locking)."""
    heat: float
    """Q = T ω_s − F_a v [W]."""
    heat_to_screw: float
    """Part of Q that goes into the screw shaft [W]."""
    heat_to_nut: float
    """Part of Q that goes into the nut (balls included) [W]."""
    model: str = "catalogue"
    film_parameter: float | None = None
    """Film parameter Λ = h_c/σ_Λ (E6.6) at the screw contact A of the loaded nut: the central
    film of its whole ball load over the raceway's composite roughness, as the operating point
    reports it (ball model)."""
    regime: str | None = None
    """boundary, mixed or EHL from Λ (ball model)."""
    asperity_share: float | None = None
    """JGP asperity share ψ(Λ) at the same contact, the boundary weight of the ``film``
    traction law (ball model)."""
    speed: float = 0.0
    """ω_s [rad/s]."""
    traction_coefficient: float | None = None
    """μ of the traction law at the screw contact of the loaded nut, s μ_b + (1 − s) μ_f
    (ball model; the coefficient of a cell whose film shear has reached its cap)."""

    @property
    def friction(self) -> float:
        """T − F_a L/(2π): the torque that becomes heat [N m]."""
        return self.total - self.parts["work"]


def _check(inputs: FrictionInputs) -> None:
    nonnegative("speed", inputs.speed, "rad/s")
    nonnegative("axial_load", inputs.axial_load, "N")
    for name in ("seal_torque", "recirculation_torque", "hysteresis"):
        nonnegative(f"friction.{name}", getattr(inputs, name))
    if inputs.seals < 0:
        raise InputError("friction.seals", inputs.seals, "a count >= 0")


def _result(
    inputs: FrictionInputs,
    model: str,
    friction: dict[str, float],
    screw_torque: float,
    losses: BallLosses | None = None,
    recirculation: float = 0.0,
) -> FrictionTorque:
    """Assemble the result from the friction parts and the torque whose heat goes to the screw;
    ``recirculation`` is the modelled ball-return torque added to the given one."""
    work = inputs.axial_load * inputs.lead / (2.0 * math.pi)
    seals = inputs.seals * inputs.seal_torque
    returns = inputs.recirculation_torque + recirculation
    parts = {"work": work, **friction, "seals": seals, "recirculation": returns}
    omega = inputs.speed
    heat = (sum(parts.values()) - work) * omega
    to_screw = (screw_torque + 0.5 * seals) * omega
    film = losses.film_parameter if losses is not None else None
    return FrictionTorque(
        total=sum(parts.values()),
        parts=parts,
        efficiency_driving=driving_efficiency(inputs.lead_angle, inputs.rolling_friction),
        efficiency_backdriving=backdriving_efficiency(inputs.lead_angle, inputs.rolling_friction),
        heat=heat,
        heat_to_screw=to_screw,
        heat_to_nut=heat - to_screw,
        model=model,
        film_parameter=film,
        regime=regime(film) if film is not None else None,
        asperity_share=losses.asperity_share if losses is not None else None,
        traction_coefficient=losses.traction_coefficient if losses is not None else None,
        speed=omega,
    )


FRICTION_MODELS: Registry[Callable[[FrictionInputs], FrictionTorque]] = Registry(
    "friction model", "friction.model"
)
"""Rival models of the nut's friction torque, name → :class:`FrictionTorque`."""


def _load_part(inputs: FrictionInputs) -> float:
    return load_friction_torque(
        inputs.axial_load, inputs.lead, inputs.lead_angle, inputs.rolling_friction
    )


@FRICTION_MODELS.register(
    "catalogue", "makers' preload torque K F_p L/(2π) + load torque F_a L/(2π η) + seals"
)
def catalogue_friction(inputs: FrictionInputs) -> FrictionTorque:
    """Catalogue preload torque (E9.1), efficiency load torque, seals and recirculation."""
    preload = DRAG_TORQUE_MODELS["catalogue"](
        DragTorqueInputs(inputs.preload, inputs.lead, inputs.lead_angle)
    )
    load = _load_part(inputs)
    screw = UNLOCATED_SCREW_SHARE * (preload + load)
    return _result(inputs, "catalogue", {"load": load, "preload": preload}, screw)


@FRICTION_MODELS.register(
    "ball_model",
    "ball losses at the preload (traction, EHL rolling, hysteresis, ball–ball friction, drag, "
    "ball returns) + load torque + seals",
)
def ball_model_friction(inputs: FrictionInputs) -> FrictionTorque:
    """Physics ball losses at the preload, efficiency load torque, seals and recirculation."""
    if inputs.ball_losses is None:
        raise InputError("friction.model", "ball_model", "a case with a ball model")
    losses = inputs.ball_losses(inputs.speed)
    load = _load_part(inputs)
    parts = {
        "load": load,
        "sliding": losses.sliding,
        "groove_slip": losses.groove_slip,
        "ehl_rolling": losses.ehl_rolling,
        "hysteresis": losses.hysteresis,
        "ball_ball": losses.ball_ball,
        "drag": losses.drag,
    }
    screw = losses.screw_share + UNLOCATED_SCREW_SHARE * load
    return _result(inputs, "ball_model", parts, screw, losses, losses.recirculation)


def nut_friction_torque(inputs: FrictionInputs, model: str = "catalogue") -> FrictionTorque:
    """Friction torque of the nut by the registered ``model`` (see :data:`FRICTION_MODELS`)."""
    _check(inputs)
    return FRICTION_MODELS.entry(model).model(inputs)
