"""Temperatures and thermal elongation over a duty cycle (a working day of thermal error).

Each ``[[duty]]`` segment is averaged over its strokes and dwells (:mod:`~ballscrew.analyses.
duty`): the heat is f·Q at the mean speed f·ω. The thermal model of the case is assembled once
per segment (same mesh; the segment's convection, set at its steady coupled operating point,
:func:`~ballscrew.analyses.operating_point.operating_point`) and marched by implicit Euler
through the schedule, the factorisation of each segment reused. The friction heat follows the
temperature in time: the heat of step n is Q(T_c(θₙ₋₁)) (:mod:`~ballscrew.analyses.duty_heat`,
the lubricant's viscosity at the contact temperature of the step before), split between screw
and nut as at the segment's steady point. A segment run long enough thus ends at its steady
coupled operating point (theory manual, *Operating point*). A reverse segment (F_a < 0) makes
the heat of its mirror image at |F_a| (ASSUMED mirror symmetry of the nut), and the two nuts of
a double nut, each in its place, swap their balls' heat and contact conductance: nut 2 is the
loaded one.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from types import ModuleType
from typing import ClassVar

import numpy as np
from numpy.typing import NDArray

from ballscrew.analyses import duty_thermal_report
from ballscrew.analyses.duty import DutyPhase, duty_schedule, mirrored_load
from ballscrew.analyses.duty_heat import SegmentHeat
from ballscrew.analyses.operating_point import (
    contact_readout,
    heat_overrides,
    medium_law,
    operating_point,
)
from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.analyses.thermal import _mesh_options
from ballscrew.analyses.thermal_setup import (
    bearings_named_by_key,
    build_problem,
    check_mesh,
    thermal_spec,
)
from ballscrew.backend import blas_single_thread
from ballscrew.budget import check_count
from ballscrew.case import Case, with_overrides
from ballscrew.errors import InputError
from ballscrew.thermal.discretisation import Discretisation, coolant_outlet_rise
from ballscrew.thermal.models import THERMAL_MODELS, build_model
from ballscrew.thermal.problem import ThermalProblem
from ballscrew.thermal.simulate import check_transient
from ballscrew.thermal.timestepping import StepSystem, implicit_euler

__all__ = ["DutyThermal", "checked_cycle", "duty_scalars", "thermal_duty"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class DutyThermal(Presented):
    """Temperatures and elongation of the screw over the duty cycle (SI; temperatures in K)."""

    case: Case
    model: str
    ambient_temperature: float
    phases: tuple[DutyPhase, ...]
    segment_heat: tuple[float, ...]
    """Time-mean friction heat of each ``[[duty]]`` segment at its steady operating point,
    f·Q(ω) [W]."""
    time: FloatArray
    """Times of the record [s]."""
    max_temperature: FloatArray
    """Largest temperature of the model [K]."""
    elongation: FloatArray
    """Thermal elongation of the screw shaft α∫ΔT̄ dz [m]."""
    sensors: FloatArray
    """Sensor temperatures [K], shape (time, sensor)."""
    sensor_names: tuple[str, ...]
    friction_heat: FloatArray
    """Time-mean friction heat of the balls in force over the step ending at each time [W]
    (index 0: that of the first step)."""
    contact_temperature: FloatArray
    """Contact temperature T_c (mean of nut and screw at the nut) [K]."""
    viscosity: FloatArray
    """Lubricant viscosity at the T_c the step's heat was taken at [Pa s] (NaN: dry)."""
    heat_in: float
    """Heat that entered over the day [J]."""
    heat_balance_error: float
    """|heat in − stored − lost| / heat in over the day [-]."""
    coolant_outlet_temperature: FloatArray | None = None
    """Outlet temperature of the hollow shaft's coolant [K] (None: a solid shaft)."""
    warnings: tuple[str, ...] = ()

    analysis: ClassVar[str] = "duty"
    presentation: ClassVar[ModuleType] = duty_thermal_report

    @property
    def title(self) -> str:
        return f"Duty cycle: temperatures and thermal elongation of {self.case.name}"


@dataclass(frozen=True)
class _Segment:
    """One segment's step system: C/Δt + A and the load f_b + (Q/Q*)·f_balls (SI)."""

    conductance: object
    bearings: FloatArray
    """Load of the support bearings [W]."""
    balls: FloatArray
    """Load of the balls at the steady heat Q* [W]."""
    heat: SegmentHeat | None
    """Q(T_c) of the segment (None: at rest)."""

    def load(self, temperature: float) -> tuple[FloatArray, float]:
        """(load vector, time-mean ball heat) at contact temperature ``temperature``."""
        if self.heat is None or self.heat.steady_heat <= 0.0:
            return self.bearings, 0.0
        q = self.heat.heat(temperature)
        return self.bearings + (q / self.heat.steady_heat) * self.balls, q


def _without_ball_heat(problem: ThermalProblem) -> ThermalProblem:
    parts = tuple(dataclasses.replace(p, screw_heat=0.0, nut_heat=0.0) for p in problem.parts)
    return dataclasses.replace(problem, parts=parts)


def _reversed(problem: ThermalProblem) -> ThermalProblem:
    """``problem`` (built at |F_a|, nut 1 the loaded nut) under the reverse load −F_a: the two
    nuts of a double nut swap their balls' heat and contact conductance, each nut staying in
    its place (nut 2 is the loaded one). One nut body (a single nut's two flanks) is unchanged.
    """
    parts = problem.parts
    if len(parts) < 2 or not (parts[0].balls and parts[-1].balls):
        return problem
    first, *middle, last = parts
    swapped = ("contact_conductance", "screw_heat", "nut_heat")
    one = dataclasses.replace(first, **{k: getattr(last, k) for k in swapped})
    two = dataclasses.replace(last, **{k: getattr(first, k) for k in swapped})
    return dataclasses.replace(problem, parts=(one, *middle, two))


def _segment(
    case: Case, index: int, phase: DutyPhase, model: str, reuse: Discretisation | None = None
) -> tuple[_Segment, Discretisation]:
    """The step system of segment ``index``, its heat at the steady operating point and its
    model (``reuse``'s mesh and matrices re-bound to the segment's loads when they fit)."""
    spec = thermal_spec(case)
    base = with_overrides(
        case,
        {
            "operating.speed": phase.speed,
            "operating.axial_load": mirrored_load(phase.axial_load),
            "operating.coupled": False,
        },
    )
    heat, to_screw, table = 0.0, 0.0, None
    if phase.mean_speed > 0.0:
        point = operating_point(base, model="network")
        table = SegmentHeat(base, point, phase.moving_fraction, spec.ambient_temperature)
        heat = table.steady_heat
        to_screw = phase.moving_fraction * point.heat_to_screw
    overrides = {
        "operating.speed": phase.mean_speed,
        **heat_overrides(heat, to_screw, phase.mean_speed),
    }
    problem, *_ = build_problem(with_overrides(base, overrides))
    if phase.axial_load < 0.0:
        problem = _reversed(problem)
    free = problem.shaft_length - problem.ring_length
    if phase.stroke > free:
        raise InputError(
            f"duty.{index}.stroke",
            phase.stroke,
            f"at most {free:g} m: the nut assembly ({problem.ring_length:g} m) stays on the "
            f"{problem.shaft_length:g} m shaft (thermal.shaft_length)",
        )
    check_mesh(spec, problem, model)
    options = _mesh_options(spec)
    with bearings_named_by_key(spec):
        disc = (reuse.rebound(problem) if reuse is not None else None) or build_model(
            model, problem, options
        )
    conductance, load = disc.assemble(disc.grid.weights)
    bearings = load
    if heat > 0.0:
        cold_problem = _without_ball_heat(problem)
        cold = disc.rebound(cold_problem) or build_model(model, cold_problem, options)
        bearings = cold.assemble(cold.grid.weights)[1]
    return _Segment(conductance, bearings, load - bearings, table), disc


def checked_cycle(case: Case) -> tuple[DutyPhase, ...]:
    """The phases of the case's ``[[duty]]`` cycle, refused before any solve when there are none
    or when ``[thermal.transient] time_step`` over the whole cycle (``duty_repeat`` times the
    list) makes more steps than the budget allows."""
    spec = thermal_spec(case)
    phases = duty_schedule(case)
    if not phases:
        raise InputError("duty", [], "a [[duty]] list of segments for a duty-cycle run")
    total, step = phases[-1].end, spec.transient.time_step
    what = f"time steps over the [[duty]] cycle of {total:g} s ({case.duty_repeat} × the list)"
    check_count("thermal.transient.time_step", step, total / step, what)
    return phases


def thermal_duty(case: Case, model: str | None = None) -> DutyThermal:
    """Temperatures and elongation of ``case`` over its ``[[duty]]`` cycle.

    ``model``: the thermal model (None: the case's ``[thermal] model``). The time step is
    ``[thermal.transient] time_step``; the duration is the whole schedule.
    """
    spec = thermal_spec(case)
    model = THERMAL_MODELS.check(spec.model if model is None else model)
    phases = checked_cycle(case)
    total = phases[-1].end
    steps = max(1, math.ceil(total / spec.transient.time_step))
    dt = total / steps
    amb = spec.ambient_temperature
    viscosity_at = medium_law(case)
    with recorded_warnings() as messages:
        built: list[tuple[_Segment, Discretisation]] = []
        for k in range(len(case.duty)):
            built.append(_segment(case, k, phases[k], model, built[-1][1] if built else None))
        segments = [b[0] for b in built]
        first = built[0][1]
        check_transient(first, total, dt)
        starts = np.array([p.start for p in phases])
        segment_of = [
            (int(np.searchsorted(starts, (n - 0.5) * dt, side="right")) - 1) % len(case.duty)
            for n in range(steps + 1)
        ]
        screw_row, nut_rise = contact_readout(first)
        time = dt * np.arange(steps + 1)
        max_rise = np.zeros(steps + 1)
        elongation = np.zeros(steps + 1)
        sensors = np.zeros((steps + 1, first.sensors.shape[0]))
        contact = np.full(steps + 1, amb)
        heat = np.zeros(steps + 1)
        viscosity = np.zeros(steps + 1)
        cooled = coolant_outlet_rise(first, np.zeros(first.unknowns)) is not None
        outlet = np.zeros(steps + 1) if cooled else None

        def system(n: int) -> StepSystem:
            k = segment_of[n]
            load, heat[n] = segments[k].load(contact[n - 1])
            eta = viscosity_at(contact[n - 1])[0]
            viscosity[n] = math.nan if eta is None else eta
            return StepSystem(k, segments[k].conductance, load)

        def observe(n: int, theta: FloatArray, loss: float) -> None:
            max_rise[n] = theta.max()
            elongation[n] = first.elongation @ theta
            sensors[n] = first.sensors @ theta
            contact[n] = amb + 0.5 * (nut_rise(theta) + float(screw_row @ theta))
            if outlet is not None:
                outlet[n] = coolant_outlet_rise(first, theta)

        # per step only triangular solves and vector products: BLAS threads just contend for
        # the cores (the 8-hour axisymmetric day: 46 s threaded, 12 s on one thread, 2 shared
        # cores; measured)
        with blas_single_thread():
            final, heat_in, lost = implicit_euler(
                first.capacity,
                dt,
                steps,
                system,
                observe,
                cache_size=len(segments) + 1,
                direct_limit=first.direct_limit,
            )
    heat[0], viscosity[0] = heat[1], viscosity[1]
    stored = float(np.asarray(first.capacity.sum(axis=0)).ravel() @ final)
    return DutyThermal(
        case=case,
        model=model,
        ambient_temperature=amb,
        phases=phases,
        segment_heat=tuple(s.heat.steady_heat if s.heat else 0.0 for s in segments),
        time=time,
        max_temperature=amb + max_rise,
        elongation=elongation,
        sensors=amb + sensors,
        sensor_names=tuple(s.name for s in first.problem.sensors),
        friction_heat=heat,
        contact_temperature=contact,
        viscosity=viscosity,
        heat_in=heat_in,
        heat_balance_error=abs(heat_in - stored - lost) / heat_in if heat_in > 0 else 0.0,
        coolant_outlet_temperature=None if outlet is None else amb + outlet,
        warnings=tuple(messages),
    )


def duty_scalars(case: Case) -> dict[str, tuple[float, str]]:
    """Sweepable scalars of :func:`thermal_duty` (the case's ``[thermal] model``) with their
    units: the peak and end-of-cycle elongation and largest temperature, the heat of the cycle
    and its balance error (``ballscrew sweep --analysis duty``)."""
    result = thermal_duty(case)
    return {
        "peak_elongation": (float(result.elongation.max()), "m"),
        "final_elongation": (float(result.elongation[-1]), "m"),
        "peak_temperature": (float(result.max_temperature.max()), "K"),
        "final_temperature": (float(result.max_temperature[-1]), "K"),
        "heat_in": (result.heat_in, "J"),
        "heat_balance_error": (result.heat_balance_error, ""),
    }
