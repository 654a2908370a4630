"""Case-level entry points: ball kinematics, drag torques and curves versus speed.

The Python API other code relies on:

* :func:`ball_kinematics` ``(case, speed=None, level=0)`` → :class:`BallState` with
  ``ball_speed``, ``orbital_speed``, ``spin_screw``, ``spin_nut``, ``load_screw``, ``load_nut``,
  ``angle_screw``, ``angle_nut``;
* :func:`drag_torque` ``(case, preload=None)`` → catalogue preload drag torque (E9.1), N m;
* :func:`computed_drag_torque` ``(case, speed=None)`` → drag torque of the ball model (E3.7),
  N m, at the case's balance level; the heat it makes is T·ω_s (used by the thermal model).

Inputs are checked before any work: speed < 0, an unknown level, level 2 without lubricant data
are :class:`~ballscrew.errors.InputError`; a speed above the whirling or d·n limit is a
:class:`~ballscrew.kinematics.limits.SpeedLimitWarning`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ballscrew.errors import InputError
from ballscrew.geometry import ScrewGeometry
from ballscrew.kinematics.balance import LEVELS, BallState, solve_ball
from ballscrew.kinematics.limits import check_speed_limits, dn_value
from ballscrew.kinematics.model import BallModel, ball_model
from ballscrew.kinematics.torque import ball_drag
from ballscrew.loads import nut_forces, preload_drag_torque
from ballscrew.validation import case_with

__all__ = [
    "SpeedSweep",
    "ball_kinematics",
    "computed_drag_torque",
    "curve_speeds",
    "drag_torque",
    "nut_loads",
    "prepare",
    "speed_sweep",
]

FloatArray = NDArray[np.float64]


def _speed(case: Any, speed: float | None) -> float:
    case_with(case, "screw", "operating", "materials")
    value = case.operating.speed if speed is None else speed
    try:
        omega = float(value)
    except (TypeError, ValueError):
        raise InputError("speed", value, "a screw speed >= 0 rad/s") from None
    if not (math.isfinite(omega) and omega >= 0.0):
        raise InputError("speed", value, "a screw speed >= 0 rad/s")
    return omega


def _level(case: Any, level: int | None) -> int:
    value = case.kinematics.level if level is None else level
    if isinstance(value, bool) or value not in LEVELS:
        raise InputError("level", value, "0 (static), 1 (centrifugal + groove) or 2 (full)")
    return int(value)


def prepare(
    case: Any, speeds: float | FloatArray | list[float], level: int | None
) -> tuple[BallModel, int]:
    """Validate speeds and level, warn about speed limits, and build the ball model.

    Every check runs before any computation (level 2 needs lubricant data).
    """
    values = [_speed(case, float(s)) for s in np.atleast_1d(np.asarray(speeds, dtype=float))]
    lvl = _level(case, level)
    model = ball_model(case)
    if lvl == 2 and not model.lubricated:
        raise InputError(
            "medium.viscosity",
            case.medium.viscosity,
            "lubricant data for level 2: viscosity and pressure_viscosity in [medium], or "
            "[kinematics] lubricant",
        )
    if values:
        check_speed_limits(case, max(values), stacklevel=4)
    return model, lvl


def nut_loads(case: Any, preload: float | None = None) -> list[tuple[int, float, int]]:
    """(nut number, axial force, flank) of each nut: (P1)–(P3)/(E1.10) for a double nut.

    Nut 1 carries F_1 on flank s = +1 and nut 2 carries F_2 on s = −1; a single nut carries
    F_p + F_a on s = +1. ``preload`` overrides the case's.
    """
    op = case.operating
    fp = op.preload if preload is None else float(preload)
    if not (math.isfinite(fp) and fp >= 0.0):
        raise InputError("preload", preload, "a force >= 0 N")
    if case.screw.nuts == 2:
        if fp <= 0.0:
            raise InputError("preload", fp, "a preload > 0 N for a double nut")
        f1, f2 = nut_forces(fp, op.axial_load)
        return [(1, float(f1), 1), (2, float(f2), -1)]
    return [(1, fp + op.axial_load, 1)]


def ball_kinematics(
    case: Any, speed: float | None = None, level: int | None = 0, *, nut: int = 1
) -> BallState:
    """Kinematics and loads of a ball of ``nut`` (1 = loaded nut) at screw speed ``speed``.

    ``speed`` [rad/s] defaults to ``operating.speed``; ``level`` 0, 1 or 2 (None = the case's
    ``[kinematics] level``). The result has ``ball_speed`` (m/s, ball centre relative to the nut),
    ``orbital_speed`` (rad/s), ``spin_screw`` / ``spin_nut`` (rad/s, relative spin about the
    contact normals Z_A, Z_B pointing into the ball), ``load_screw`` / ``load_nut`` (N) and
    ``angle_screw`` / ``angle_nut`` (rad).
    """
    omega = _speed(case, speed)
    model, lvl = prepare(case, omega, level)
    loads = {number: (force, flank) for number, force, flank in nut_loads(case)}
    if nut not in loads:
        raise InputError("nut", nut, f"one of {sorted(loads)} for this screw")
    force, flank = loads[nut]
    return solve_ball(model, omega, force, flank, lvl)


def drag_torque(case: Any, preload: float | None = None) -> float:
    """Catalogue preload drag torque T_p = K F_p L/(2π), K = 0.05/√tanλ, (E9.1), N m.

    ``preload`` [N] defaults to the case's. REF (F_p = 1500 N): 0.4231 N m (T9.2).
    """
    case_with(case, "screw", "operating")
    fp = case.operating.preload if preload is None else preload
    geometry = ScrewGeometry.from_spec(case.screw)
    return preload_drag_torque(fp, geometry.lead, geometry.lead_angle)


def _model_torque(
    model: BallModel, case: Any, omega: float, level: int, preload: float | None = None
) -> float:
    total = 0.0
    for _, force, flank in nut_loads(case, preload):
        if force > 0.0:
            state = solve_ball(model, omega, force, flank, level)
            total += model.balls * ball_drag(model, state).dissipation_torque
    return total


def computed_drag_torque(
    case: Any, speed: float | None = None, *, level: int | None = None, preload: float | None = None
) -> float:
    """Drag torque of the screw from the ball model, N m (heat: T·ω_s).

    Sum over the loaded balls of every nut of the power dissipated by sliding at A (traction
    E3.3, JGP share E6.4) and by EHL rolling resistance at A and B (E3.4), over ω_s. With the
    full balance (level 2) this is exactly the torque (E3.7) of the ball forces on the screw at
    fixed nut force; at levels 0/1 the traction is not part of the balance and the dissipation is
    the consistent measure. ``speed`` defaults to ``operating.speed`` (0 gives the ω → 0⁺ limit,
    the dry breakaway value), ``level`` to ``[kinematics] level``, ``preload`` to the case's.
    The external load's reversible torque F_a L/2π is not included.
    """
    omega = _speed(case, speed)
    model, lvl = prepare(case, omega, level)
    return _model_torque(model, case, omega, lvl, preload)


def curve_speeds(case: Any) -> FloatArray:
    """Speeds of the curves vs speed: ``[kinematics] speed_range`` or 0 … max(case, d·n limit)."""
    spec = case.kinematics
    if spec.speed_range is not None:
        low, high = spec.speed_range
    else:
        geometry = ScrewGeometry.from_spec(case.screw)
        dn_speed = spec.dn_limit / dn_value(geometry.pitch_diameter, 1.0)
        low, high = 0.0, max(case.operating.speed, dn_speed)
    return np.linspace(low, high, spec.speed_points)


@dataclass(frozen=True)
class SpeedSweep:
    """Loads, angles, speeds and torques of a ball of nut 1 versus screw speed."""

    speed: FloatArray
    """Screw speeds ω_s [rad/s]."""
    level: int
    load_screw: FloatArray
    load_nut: FloatArray
    angle_screw: FloatArray
    angle_nut: FloatArray
    ball_speed: FloatArray
    orbital_speed: FloatArray
    spin_screw: FloatArray
    asperity_share: FloatArray
    """ψ at A (1 without lubricant)."""
    film_thickness: FloatArray
    """h_c at A at the film-borne load [m] (NaN without lubricant)."""
    model_torque: FloatArray
    """Ball-model drag torque (all nuts) [N m]."""
    catalogue_torque: float
    """E9.1 at the case's preload [N m]."""


def speed_sweep(
    case: Any, speeds: FloatArray | None = None, level: int | None = None
) -> SpeedSweep:
    """Ball of nut 1 and the drag torque at each speed (default :func:`curve_speeds`)."""
    omegas = curve_speeds(case) if speeds is None else np.asarray(speeds, dtype=float)
    model, lvl = prepare(case, omegas, level)
    _, force, flank = nut_loads(case)[0]
    rows = []
    for omega in omegas:  # one quasi-static solve per speed
        state = solve_ball(model, float(omega), force, flank, lvl)
        sharing = state.sharing or model.sharing(state.load_screw, abs(state.ball_speed))
        rows.append(
            (
                state.load_screw,
                state.load_nut,
                state.angle_screw,
                state.angle_nut,
                state.ball_speed,
                state.orbital_speed,
                state.spin_screw,
                sharing.psi,
                sharing.separation if sharing.film is not None else math.nan,
                _model_torque(model, case, float(omega), lvl),
            )
        )
    cols = np.array(rows, dtype=float).T
    return SpeedSweep(omegas, lvl, *cols, catalogue_torque=drag_torque(case))
