"""The friction torque of the nut of one case: inputs from the case, physics from
:mod:`ballscrew.friction` (theory manual: *Friction*).

:func:`friction_torque` ``(case, speed=None, axial_load=None, viscosity=None)`` →
:class:`~ballscrew.friction.FrictionTorque`; ``None`` takes the case's speed, axial load and
inlet viscosity (the viscosity at the operating temperature is passed by the caller).
"""

from __future__ import annotations

import warnings
from functools import partial

from ballscrew.analyses.ball_loads import ball_loads, nut_model
from ballscrew.analyses.case_cache import CaseCache
from ballscrew.analyses.kinematics import _level, _speed, ball_model
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.case import Case
from ballscrew.case.base import MAX_FORCE
from ballscrew.errors import InputError
from ballscrew.friction import (
    FrictionInputs,
    FrictionTorque,
    NutLossParameters,
    ball_losses,
    nut_friction_torque,
)
from ballscrew.friction.speed_spread import NutBalls
from ballscrew.loads import preload_flanks
from ballscrew.loads.distribution import expand_errors
from ballscrew.validation import nonnegative, positive

__all__ = [
    "FourPointContactWarning",
    "friction_torque",
    "nut_balls",
    "nut_loss_parameters",
    "seal_torque",
]


class FourPointContactWarning(UserWarning):
    """The ball model runs a single nut preloaded by oversized balls as two flanks of the same
    balls; the extra spin and sliding of a ball touching four points are not modelled."""


#: Largest axial load accepted [N]: the upper end of ``operating.axial_load``.
_LOAD_RANGE = f"a force in [0, {MAX_FORCE:g}] N (the range of operating.axial_load)"


def seal_torque(case: Case) -> float:
    """Torque of one seal: ``friction.seal_torque`` or ``seal_force`` × d_m/2 [N m]."""
    spec = case.friction
    if spec.seal_torque is not None:
        return spec.seal_torque
    return spec.seal_force * 0.5 * case.screw.pitch_diameter


def nut_loss_parameters(case: Case) -> NutLossParameters:
    """Ball–ball, drag and ball-return parameters of ``[friction]`` per loaded flank (the
    lubricant's density is the ball model's, see
    :func:`~ballscrew.analyses.kinematics.ball_model`). The two halves of a preloaded
    offset-lead nut are run as two flanks, each with half of the nut's ``friction.circuits``;
    without preload its one flank has all balls and circuits."""
    spec, screw = case.friction, case.screw
    circuits = spec.circuits
    method = screw.resolved_preload_method
    flanks = preload_flanks(method, screw.nuts, screw.balls_per_nut, case.operating.preload)
    if flanks.balls < screw.balls_per_nut:  # the halves of one nut share its circuits
        if circuits % 2:
            raise InputError(
                "friction.circuits",
                circuits,
                'an even number with screw.preload_method = "offset_lead" (each half of the '
                "nut has its own circuits)",
            )
        circuits //= 2
    return NutLossParameters(
        ball_ball_load_ratio=spec.ball_ball_load_ratio,
        ball_ball_friction=spec.ball_ball_friction,
        lubricant_fill=spec.lubricant_fill,
        circuits=circuits,
        ball_train=spec.ball_train,
        return_friction=spec.return_friction,
        return_fraction=spec.return_fraction,
    )


def nut_balls(case: Case, params: ScrewParameters | None = None) -> tuple[NutBalls, ...] | None:
    """Per nut the loads, contact angles and diameter excesses of its balls under the preload
    alone, for ``friction.ball_train = "speed_spread"`` with ``loads.distribution = "elastic"``
    (None otherwise: identical balls). Cached: a coupled operating point asks for the same
    case at every temperature it tries. ``params`` is accepted for the callers of the earlier
    ``nut_balls(case, params)``; the states follow from ``case`` alone (the cache's key)."""
    if case.friction.ball_train != "speed_spread" or case.loads.distribution != "elastic":
        return None
    return _NUT_BALLS(case)


def _elastic_nut_balls(case: Case) -> tuple[NutBalls, ...]:
    loads = ball_loads(case, axial_load=0.0)
    layout, _ = nut_model(ScrewParameters.from_case(case), case.loads)
    errors = case.loads.ball_diameter_error or None
    excess = expand_errors("loads.ball_diameter_error", errors, layout).reshape(layout.nuts, -1)
    return tuple(
        NutBalls(q, beta, e) for q, beta, e in zip(loads.loads, loads.angles, excess, strict=True)
    )


#: The per-ball states by the case fields they depend on (all but these, which they never read).
_NUT_BALLS = CaseCache(
    _elastic_nut_balls,
    size=8,
    exclude={"name", "description", "thermal", "wear", "duty", "duty_repeat", "assumed"},
)


def friction_torque(
    case: Case,
    speed: float | None = None,
    axial_load: float | None = None,
    viscosity: float | None = None,
) -> FrictionTorque:
    """Friction torque of the nut, its parts, efficiencies and heat at one operating point.

    ``speed`` [rad/s], ``axial_load`` [N] and ``viscosity`` [Pa s] default to the case's
    ``operating.speed``, ``operating.axial_load`` and inlet viscosity; the model and its
    parameters come from ``[friction]``. With a named lubricant (and no ``[medium]``
    viscosity) a given ``viscosity`` also sets α_p, the density and the inlet heating of the
    film at the temperature where the lubricant has that viscosity. The ball model runs at
    ``[kinematics] level`` on the nut forces of the preload alone (the working load enters
    through the efficiency).
    """
    omega = _speed(case, speed)
    force = nonnegative(
        "axial_load", case.operating.axial_load if axial_load is None else axial_load, "N"
    )
    if force > MAX_FORCE:
        raise InputError("axial_load", axial_load, _LOAD_RANGE)
    if viscosity is not None:  # checked even where the model does not use it
        positive("viscosity", viscosity, "Pa s")
    spec = case.friction
    params = ScrewParameters.from_case(case)
    geometry = params.geometry
    losses = None
    if spec.model == "ball_model":
        model = ball_model(case, viscosity)
        level = _level(case, None)
        nuts = tuple((n.force, n.flank) for n in params.with_loads(axial_load=0.0).flank_loads)
        if params.flanks.shared:
            warnings.warn(
                "screw.preload_method = oversized_balls: the ball model adds the contact losses "
                "of both flanks and counts the ball train once, but not the extra spin and "
                "sliding of a ball touching four points, so its torque is a lower estimate",
                FourPointContactWarning,
                stacklevel=2,
            )
        losses = partial(
            ball_losses,
            model,
            nuts=nuts,
            level=level,
            hysteresis=spec.hysteresis,
            nut=nut_loss_parameters(case),
            balls=nut_balls(case),
            shared=params.flanks.shared,
        )
    inputs = FrictionInputs(
        lead=geometry.lead,
        lead_angle=geometry.lead_angle,
        preload=params.preload,
        axial_load=force,
        speed=omega,
        rolling_friction=spec.rolling_friction,
        seals=spec.seals,
        seal_torque=seal_torque(case),
        recirculation_torque=spec.recirculation_torque,
        hysteresis=spec.hysteresis,
        ball_losses=losses,
    )
    return nut_friction_torque(inputs, spec.model)
