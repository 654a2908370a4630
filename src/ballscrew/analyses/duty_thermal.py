"""Temperatures and thermal elongation over a duty cycle (a working day of thermal error).

Each ``[[duty]]`` segment runs at its steady coupled operating point
(:func:`~ballscrew.analyses.operating_point.operating_point`: friction torque and heat with the
lubricant at the segment's temperature), averaged over the segment's strokes and dwells
(:mod:`~ballscrew.analyses.duty`): the heat is f·Q(ω) at the mean speed f·ω. The thermal model
of the case is assembled once per segment (same mesh, the segment's heat and convection) and
marched by implicit Euler through the schedule, the factorisation of each segment reused
(theory manual, *Operating point*). The lubricant's viscosity of a segment is that of its steady
operating point: it does not yet follow the temperature within the day.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import ModuleType
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from ballscrew.analyses import duty_thermal_report
from ballscrew.analyses.duty import DutyPhase, duty_schedule
from ballscrew.analyses.operating_point import heat_overrides, operating_point
from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.analyses.thermal import _mesh_options
from ballscrew.analyses.thermal_setup import build_problem, check_mesh, thermal_spec
from ballscrew.case import Case, with_overrides
from ballscrew.errors import InputError
from ballscrew.thermal.models import THERMAL_MODELS, build_model
from ballscrew.thermal.simulate import check_transient
from ballscrew.thermal.timestepping import StepSystem, implicit_euler

__all__ = ["DutyThermal", "thermal_duty"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class DutyThermal(Presented):
    """Temperatures and elongation of the screw over the duty cycle (SI; temperatures in K)."""

    case: Case
    model: str
    ambient_temperature: float
    phases: tuple[DutyPhase, ...]
    segment_heat: tuple[float, ...]
    """Time-mean friction heat of each ``[[duty]]`` segment, f·Q(ω) [W]."""
    time: FloatArray
    """Times of the record [s]."""
    max_temperature: FloatArray
    """Largest temperature of the model [K]."""
    elongation: FloatArray
    """Thermal elongation of the screw shaft α∫ΔT̄ dz [m]."""
    sensors: FloatArray
    """Sensor temperatures [K], shape (time, sensor)."""
    sensor_names: tuple[str, ...]
    heat_in: float
    """Heat that entered over the day [J]."""
    heat_balance_error: float
    """|heat in − stored − lost| / heat in over the day [-]."""
    warnings: tuple[str, ...] = ()

    analysis: ClassVar[str] = "duty"
    presentation: ClassVar[ModuleType] = duty_thermal_report

    @property
    def title(self) -> str:
        return f"Duty cycle: temperatures and thermal elongation of {self.case.name}"


def _segment_case(case: Case, phase: DutyPhase) -> tuple[Case, float]:
    """The case of one segment at its time-mean heat and speed, and that mean heat [W]."""
    base = with_overrides(
        case, {"operating.speed": phase.speed, "operating.axial_load": phase.axial_load}
    )
    heat, to_screw = 0.0, 0.0
    if phase.mean_speed > 0.0:
        point = operating_point(base, model="network")
        heat = phase.moving_fraction * point.heat
        to_screw = phase.moving_fraction * point.heat_to_screw
    overrides = {
        "operating.speed": phase.mean_speed,
        **heat_overrides(heat, to_screw, phase.mean_speed),
    }
    return with_overrides(base, overrides), heat


def thermal_duty(case: Case, model: str | None = None) -> DutyThermal:
    """Temperatures and elongation of ``case`` over its ``[[duty]]`` cycle.

    ``model``: the thermal model (None: the case's ``[thermal] model``). The time step is
    ``[thermal.transient] time_step``; the duration is the whole schedule.
    """
    spec = thermal_spec(case)
    model = THERMAL_MODELS.check(spec.model if model is None else model)
    phases = duty_schedule(case)
    if not phases:
        raise InputError("duty", [], "a [[duty]] list of segments for a duty-cycle run")
    total = phases[-1].end
    check_transient(None, total, spec.transient.time_step)
    steps = max(1, math.ceil(total / spec.transient.time_step))
    dt = total / steps
    with recorded_warnings() as messages:
        systems, heats = [], []
        for k in range(len(case.duty)):
            segment, heat = _segment_case(case, phases[k])
            problem, *_ = build_problem(segment)
            check_mesh(spec, problem, model)
            disc = build_model(model, problem, _mesh_options(spec))
            systems.append((disc, *disc.assemble(disc.grid.weights)))
            heats.append(heat)
        first = systems[0][0]
        check_transient(first, total, dt)
        starts = np.array([p.start for p in phases])
        segment_of = [
            (int(np.searchsorted(starts, (n - 0.5) * dt, side="right")) - 1) % len(case.duty)
            for n in range(steps + 1)
        ]
        time = dt * np.arange(steps + 1)
        max_rise = np.zeros(steps + 1)
        elongation = np.zeros(steps + 1)
        sensors = np.zeros((steps + 1, first.sensors.shape[0]))

        def system(n: int) -> StepSystem:
            _, conductance, load = systems[segment_of[n]]
            return StepSystem(segment_of[n], conductance, load)

        def observe(n: int, theta: FloatArray, loss: float) -> None:
            max_rise[n] = theta.max()
            elongation[n] = first.elongation @ theta
            sensors[n] = first.sensors @ theta

        final, heat_in, lost = implicit_euler(
            first.capacity,
            dt,
            steps,
            system,
            observe,
            cache_size=len(systems) + 1,
            direct_limit=first.direct_limit,
        )
    stored = float(np.asarray(first.capacity.sum(axis=0)).ravel() @ final)
    amb = spec.ambient_temperature
    return DutyThermal(
        case=case,
        model=model,
        ambient_temperature=amb,
        phases=phases,
        segment_heat=tuple(heats),
        time=time,
        max_temperature=amb + max_rise,
        elongation=elongation,
        sensors=amb + sensors,
        sensor_names=tuple(s.name for s in first.problem.sensors),
        heat_in=heat_in,
        heat_balance_error=abs(heat_in - stored - lost) / heat_in if heat_in > 0 else 0.0,
        warnings=tuple(messages),
    )
