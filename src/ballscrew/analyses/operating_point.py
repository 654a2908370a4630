"""The coupled operating point of the screw: temperature ↔ viscosity ↔ film ↔ friction ↔ heat.

The friction torque of the nut depends on the lubricant's viscosity, the viscosity on the
temperature of the contacts, and the temperature on the friction heat. The steady operating
point is the fixed point of

    T_c → η(T_c), α_p(T_c) → friction torque M(η) → heat M·ω − F_a·v → steady field → T_c,

with T_c the mean of the nut and screw temperatures at the nut, solved by fixed-point
iteration (damped whenever the residual does not shrink) to a residual of 0.01 K (theory manual,
*Thermal* and *Lubrication*). A case without a named lubricant keeps its ``[medium]``
viscosity at every temperature.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from types import ModuleType
from typing import Any, ClassVar

import numpy as np

from ballscrew.analyses import operating_point_report
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.kinematics import ball_model, speed_limit_messages
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.analyses.thermal import ThermalField, thermal_field
from ballscrew.case import Case, with_overrides
from ballscrew.errors import ConvergenceError
from ballscrew.friction.torque import FrictionTorque
from ballscrew.loads import preload_drag_torque
from ballscrew.lubrication.lubricant_library import LUBRICANT_LIBRARY
from ballscrew.wear.step import entrainment_speed

__all__ = [
    "OperatingPoint",
    "OperatingPointWarning",
    "heat_overrides",
    "operating_point",
    "operating_point_scalars",
]

TOLERANCE = 0.01
"""Change of the contact temperature [K] at which the fixed point is reached."""
MAX_ITERATIONS = 60
NUT_WARNING_TEMPERATURE = 333.15
"""Nut temperature above which the result warns [K] (60 °C; nuts on machine axes run 5–30 K
above ambient)."""


class OperatingPointWarning(UserWarning):
    """The operating point is outside what the screw or the models are made for."""


@dataclass(frozen=True)
class OperatingPoint(Presented):
    """The steady operating point of the screw at one speed and load (SI)."""

    case: Case
    speed: float
    """Screw speed ω [rad/s]."""
    axial_load: float
    """Axial load F_a [N]."""
    friction_torque: float
    """Friction torque of the nut(s) [N·m]."""
    heat: float
    """Friction heat of the nut(s) [W]."""
    heat_to_screw: float
    """Part of the heat that goes into the screw shaft [W]."""
    efficiency: float
    """Driving efficiency (work out / work in) [-]."""
    nut_temperature: float
    """Mean temperature of the nut at steady state [K]."""
    screw_temperature: float
    """Mean temperature of the screw shaft under the nut [K]."""
    viscosity: float
    """Dynamic viscosity of the lubricant at the contact temperature [Pa s]."""
    film_thickness: float
    """Central film thickness at the screw contact of nut 1 [m] (NaN when dry or at rest)."""
    iterations: int
    field: ThermalField
    warnings: tuple[str, ...] = ()

    analysis: ClassVar[str] = "operating-point"
    presentation: ClassVar[ModuleType] = operating_point_report

    @property
    def contact_temperature(self) -> float:
        """Mean of the nut and screw temperatures [K]."""
        return 0.5 * (self.nut_temperature + self.screw_temperature)

    @property
    def title(self) -> str:
        return f"Operating point: {self.case.name}"


def _viscosity_law(case: Case) -> Callable[[float], tuple[float | None, float | None]]:
    """T → (η, α_p) of the case's lubricant: the library's laws, or its constant values."""
    params = ScrewParameters.from_case(case)
    name = case.kinematics.lubricant
    if name is not None and name in LUBRICANT_LIBRARY and case.medium.viscosity is None:
        entry = LUBRICANT_LIBRARY[name]

        def law(temperature: float) -> tuple[float | None, float | None]:
            state = entry.at(temperature)
            return state.viscosity, state.pressure_viscosity

        return law
    constant = (params.lubrication.viscosity, params.lubrication.pressure_viscosity)
    return lambda _: constant


def _warnings(case: Case, omega: float, nut: float, friction: FrictionTorque) -> list[str]:
    """What the user must know about an operating point."""
    out = speed_limit_messages(case, omega) if omega > 0.0 else []
    if nut > NUT_WARNING_TEMPERATURE:
        out.append(
            f"the nut runs at {nut - 273.15:.0f} °C, above "
            f"{NUT_WARNING_TEMPERATURE - 273.15:.0f} °C: check its cooling and mounting"
        )
    film = friction.film_parameter
    if film is not None and film < 1.0:
        out.append(
            f"film parameter Λ = {film:.2g} < 1 at the screw contact: boundary lubrication, "
            "outside the range of the EHL film and traction models"
        )
    if friction.model != "catalogue" and omega > 0.0:
        params = ScrewParameters.from_case(case)
        g = params.geometry
        catalogue = preload_drag_torque(params.preload, g.lead, g.lead_angle)
        preload_part = friction.total - friction.parts.get("work", 0.0)
        if not 0.5 * catalogue <= preload_part <= 2.0 * catalogue:
            out.append(
                f"the {friction.model} friction torque without the work on the load, "
                f"{preload_part:.3g} N·m, is outside 0.5–2 × the catalogue preload torque "
                f"{catalogue:.3g} N·m"
            )
    return out


def heat_overrides(heat: float, to_screw: float, omega: float) -> dict[str, Any]:
    """Case overrides that feed ``heat`` [W] (``to_screw`` of it into the screw) at ``omega``
    [rad/s] to the thermal model: a given torque heat/ω and the screw share."""
    return {
        "thermal.drag_torque.source": "given",
        "thermal.drag_torque.torque": heat / omega if omega > 0.0 else 0.0,
        "thermal.screw_heat_fraction": to_screw / heat if heat > 0.0 else 0.5,
    }


def _nut_and_screw(field: ThermalField) -> tuple[float, float]:
    """Steady mean temperatures of the nut assembly and of the shaft under it [K]."""
    disc = field.solution.discretisation
    steady = field.solution.steady
    amb = field.ambient_temperature
    problem = disc.problem
    half = 0.5 * problem.ring_length
    axis = disc.axis @ steady
    under = np.abs(disc.axis_z - problem.ring_centre) <= half
    screw = float(axis[under].mean()) if under.any() else float(axis.max())
    ring = disc.extra.get("ring_mean")
    nut = float(steady[ring].mean()) if ring is not None else field.max_temperature_rise
    return amb + nut, amb + screw


def operating_point(
    case: Case,
    speed: float | None = None,
    axial_load: float | None = None,
    *,
    model: str = "network",
    start_temperature: float | None = None,
) -> OperatingPoint:
    """The steady coupled operating point of ``case`` at ``speed`` [rad/s] and ``axial_load``
    [N] (None: the case's ``[operating]`` values).

    ``model``: the thermal model (the 1-D network by default, milliseconds per iteration);
    ``start_temperature`` [K]: where the iteration starts (default: ambient); the answer does
    not depend on it.
    """
    op = case.operating
    omega = op.speed if speed is None else float(speed)
    load = op.axial_load if axial_load is None else float(axial_load)
    base = with_overrides(case, {"operating.speed": omega, "operating.axial_load": load})
    law = _viscosity_law(base)
    ambient = base.thermal.ambient_temperature if base.thermal is not None else 293.15
    contact = ambient if start_temperature is None else float(start_temperature)
    relaxation, residual, iterations = 1.0, math.inf, 0
    with recorded_warnings() as messages:
        while True:
            if iterations == MAX_ITERATIONS:
                raise ConvergenceError("coupled operating point", iterations, residual, TOLERANCE)
            iterations += 1
            eta, _ = law(contact)
            friction = friction_torque(base, viscosity=eta)
            overrides = heat_overrides(friction.heat, friction.heat_to_screw, omega)
            field = thermal_field(with_overrides(base, overrides), model, transient=False)
            nut, screw = _nut_and_screw(field)
            new = 0.5 * (nut + screw) - contact  # the fixed point's residual T(T_c) − T_c
            if abs(new) <= TOLERANCE:
                break
            if abs(new) >= residual:  # not contracting: damp the update
                relaxation *= 0.5
            residual = abs(new)
            contact += relaxation * new
        for text in _warnings(base, omega, nut, friction):
            warnings.warn(text, OperatingPointWarning, stacklevel=2)
    eta, alpha = law(contact)
    params = ScrewParameters.from_case(base)
    balls = ball_model(base)
    if eta is not None:
        balls = dataclasses.replace(balls, viscosity=eta, pressure_viscosity=alpha)
    film = balls.film(params.loaded_nut.ball_load, entrainment_speed(params.geometry, omega))
    return OperatingPoint(
        case=base,
        speed=omega,
        axial_load=load,
        friction_torque=friction.total,
        heat=friction.heat,
        heat_to_screw=friction.heat_to_screw,
        efficiency=friction.efficiency_driving,
        nut_temperature=nut,
        screw_temperature=screw,
        viscosity=math.nan if eta is None else eta,
        film_thickness=film.central if film is not None else math.nan,
        iterations=iterations,
        field=field,
        warnings=tuple(messages),
    )


def operating_point_scalars(case: Case) -> dict[str, tuple[float, str]]:
    """Sweepable scalars of :func:`operating_point` (curves against speed or load)."""
    point = operating_point(case)
    return {
        "friction_torque": (point.friction_torque, "N*m"),
        "heat": (point.heat, "W"),
        "efficiency": (point.efficiency, ""),
        "nut_temperature": (point.nut_temperature, "K"),
        "screw_temperature": (point.screw_temperature, "K"),
        "viscosity": (point.viscosity, "Pa*s"),
        "film_thickness": (point.film_thickness, "m"),
    }
