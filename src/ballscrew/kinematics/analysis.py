"""The ``kinematics`` analysis of one case: ball state, contact fields, curves and torques.

Composes :mod:`ballscrew.kinematics`, the contact solver and :mod:`ballscrew.lubrication` for
the results folder of ``ballscrew kinematics``: the ball of each nut at the case speed, the
pressure at A (Polonsky–Keer on the exact gap at the ball's β_A) with the sliding field and the
asperity pressure on the same grid (E2.6, E6.5), the sliding field at a low and a high speed,
Q and β versus speed, and the drag torque versus speed and preload next to the catalogue value.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ballscrew.kinematics.api import (
    SpeedSweep,
    _model_torque,
    curve_speeds,
    drag_torque,
    nut_loads,
    prepare,
    speed_sweep,
)
from ballscrew.kinematics.balance import BallState, solve_ball
from ballscrew.kinematics.model import BallModel
from ballscrew.kinematics.sliding import SlidingField, sliding_field, sliding_field_closed_form
from ballscrew.kinematics.torque import BallDrag, ball_drag
from ballscrew.lubrication import LoadSharing, asperity_pressure

__all__ = ["ContactFields", "KinematicsRun", "contact_fields", "run_kinematics"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class ContactFields:
    """Fields over the contact A of one ball at one speed, on the contact-solver grid."""

    state: BallState
    contact: Any
    """:class:`ballscrew.analyses.ball_contact.RacewayContact` at Q_A, β_A."""
    sliding: SlidingField
    """Exact sliding field (E2.6) of the state's motion."""
    closed_form: SlidingField
    """Closed form (E2.7) of the Level-0 motion, for comparison."""
    sharing: LoadSharing
    asperity_pressure: FloatArray
    """ψ p (E6.5) [Pa]."""


def contact_fields(case: Any, model: BallModel, state: BallState) -> ContactFields:
    """Pressure, sliding and asperity pressure at A for ``state`` (one contact solve)."""
    from ballscrew.analyses.ball_contact import solve_raceway_contact

    geometry = dataclasses.replace(model.geometry, contact_angle=state.angle_screw)
    contact = solve_raceway_contact(
        geometry, "screw", state.load_screw, model.e_star_screw, case.numerics, flank=state.flank
    )
    x, y = np.asarray(contact.x), np.asarray(contact.y)
    sliding = sliding_field(state.motion, x, y, radius=model.deformed_radius("screw"))
    closed = sliding_field_closed_form(
        model.geometry, state.screw_speed, x, y, state.flank, curvature=True
    )
    sharing = state.sharing or model.sharing(state.load_screw, abs(state.ball_speed))
    pressure = np.asarray(contact.solution.pressure)
    return ContactFields(
        state, contact, sliding, closed, sharing, asperity_pressure(pressure, sharing.psi)
    )


@dataclass(frozen=True)
class KinematicsRun:
    """Everything the ``kinematics`` results folder shows."""

    case_name: str
    level: int
    speed: float
    """Case speed ω_s [rad/s]."""
    states: dict[int, BallState]
    """Ball of each loaded nut at the case speed."""
    drags: dict[int, BallDrag]
    fields: ContactFields
    """Nut 1 at the case speed."""
    low: ContactFields
    high: ContactFields
    sweep: SpeedSweep
    """Nut 1 versus speed, at the operating loads."""
    drag_speeds: FloatArray
    no_load_torque: FloatArray
    """Ball-model drag torque at F_a = 0 versus speed [N m]."""
    preloads: FloatArray
    preload_catalogue: FloatArray
    preload_model: FloatArray
    """Ball-model drag torque at F_a = 0 and the case speed versus preload [N m]."""
    catalogue_torque: float
    model_torque: float
    """Ball-model drag torque at the operating point [N m]."""
    lubricated: bool
    warnings: list[str]


def _no_load(case: Any) -> Any:
    return case.model_copy(
        update={"operating": case.operating.model_copy(update={"axial_load": 0.0})}
    )


def run_kinematics(
    case: Any, level: int | None = None, speed: float | None = None
) -> KinematicsRun:
    """Run the analysis (all checks first, see :func:`ballscrew.kinematics.api.prepare`)."""
    import warnings

    from ballscrew.kinematics.limits import speed_limit_messages

    omega = case.operating.speed if speed is None else float(speed)
    speeds = curve_speeds(case)
    model, lvl = prepare(case, np.append(speeds, omega), level)
    messages = speed_limit_messages(case, float(max(omega, speeds.max())))
    with warnings.catch_warnings():
        from ballscrew.kinematics.limits import SpeedLimitWarning

        warnings.simplefilter("ignore", SpeedLimitWarning)
        states, drags = {}, {}
        for number, force, flank in nut_loads(case):
            if force > 0.0:
                states[number] = solve_ball(model, omega, force, flank, lvl)
                drags[number] = ball_drag(model, states[number])
        fields = contact_fields(case, model, states[1])
        positive = speeds[speeds > 0]
        low_speed = omega if omega > 0 else float(positive.min()) if positive.size else 1.0
        high_speed = float(max(speeds.max(), low_speed))
        _, f1, s1 = nut_loads(case)[0]

        def nut1_fields(speed: float) -> ContactFields:
            """Nut 1 at ``speed``: the case-speed solution when it is the same problem."""
            if speed == omega:
                return fields
            return contact_fields(case, model, solve_ball(model, speed, f1, s1, lvl))

        low, high = nut1_fields(low_speed), nut1_fields(high_speed)
        sweep = speed_sweep(case, speeds, lvl)
        free = _no_load(case)
        no_load = np.array([_model_torque(model, free, float(w), lvl) for w in speeds])
        preloads = case.operating.preload * np.linspace(0.25, 2.0, 8)
        preload_model = np.array(
            [_model_torque(model, free, omega, lvl, preload=float(fp)) for fp in preloads]
        )
    model_torque = sum(model.balls * d.dissipation_torque for d in drags.values())
    return KinematicsRun(
        case_name=case.name,
        level=lvl,
        speed=omega,
        states=states,
        drags=drags,
        fields=fields,
        low=low,
        high=high,
        sweep=sweep,
        drag_speeds=speeds,
        no_load_torque=no_load,
        preloads=preloads,
        preload_catalogue=np.array([drag_torque(case, float(fp)) for fp in preloads]),
        preload_model=preload_model,
        catalogue_torque=drag_torque(case),
        model_torque=float(model_torque),
        lubricated=model.lubricated,
        warnings=messages,
    )
