"""``thermal_field(case)``: temperature field and thermal elongation of the ball screw.

After Gao, Wang & Liu (2019), section 5: screw shaft, nut(s) and spacer, heated by the support
bearings and the ball screw's friction, cooled by convection, with the thermal contact
resistance of the TCR chain on the balls; steady state, the transient from ambient, and the
elongation ΔL = α∫ΔT dz (theory manual: *Thermal*).

A case with a ``[[duty]]`` cycle is also followed through it on the same model
(:func:`~ballscrew.analyses.duty_thermal.thermal_duty`, ``duty`` of the result): the field
above is that of the single ``[operating]`` point, the duty part the elongation and
temperatures over the cycle.

Models: ``"axisymmetric"`` (default; 2-D scikit-fem), ``"network"`` (1-D axial, milliseconds)
and ``"3d"`` (hexahedra, helical contact patches; :mod:`~ballscrew.thermal.threed`).

The friction heat of the balls is by default that of the coupled operating point
(:mod:`~ballscrew.analyses.operating_point`): the friction torque with the lubricant's viscosity
at the temperature the model computes; a case that names another
``[thermal.drag_torque] source`` (catalogue, given, kinematics) gets that fixed heat.
"""

from __future__ import annotations

import dataclasses
import time as _time
from dataclasses import dataclass
from types import ModuleType
from typing import TYPE_CHECKING, ClassVar

import numpy as np
from numpy.typing import NDArray

from ballscrew.analyses import thermal_report
from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.analyses.screw_tcr import ScrewTCR
from ballscrew.analyses.thermal_setup import (
    ConvectionCoefficient,
    HeatSource,
    NutInterface,
    ball_patches,
    bearings_named_by_key,
    build_problem,
    check_mesh,
    thermal_spec,
)
from ballscrew.backend import blas_single_thread
from ballscrew.case import Case
from ballscrew.case.thermal_spec import ThermalSpec
from ballscrew.thermal.discretisation import Discretisation, coolant_outlet_rise, nut_mean_row
from ballscrew.thermal.elongation import thermoelastic_elongation
from ballscrew.thermal.models import THERMAL_MODELS, MeshOptions, build_model
from ballscrew.thermal.problem import ThermalProblem
from ballscrew.thermal.simulate import Solution, check_transient, simulate, time_to_fraction
from ballscrew.validation import case_with

if TYPE_CHECKING:
    from ballscrew.analyses.duty_thermal import DutyThermal

__all__ = [
    "ConvectionCoefficient",
    "HeatCoupling",
    "HeatSource",
    "NutInterface",
    "SensorReading",
    "ThermalField",
    "ball_patches",
    "build_problem",
    "field_dataset",
    "solve_field",
    "thermal_fe_scalars",
    "thermal_field",
    "thermal_network_scalars",
    "thermal_scalars",
]


@dataclass(frozen=True)
class SensorReading:
    """Temperatures at a sensor point."""

    name: str
    body: str
    r: float
    """[m]"""
    z: float
    """[m]"""
    steady: float
    """Steady temperature [K]."""
    final: float
    """Temperature at the end of the transient [K] (NaN without transient)."""
    time_to_95: float
    """Time to 95 % of the steady rise [s] (NaN if not reached)."""


@dataclass(frozen=True)
class HeatCoupling:
    """The coupled operating point that gave the friction heat of the balls (SI)."""

    friction_model: str
    friction_torque: float
    """Friction torque of the nut(s) [N·m]."""
    heat: float
    """Friction heat of the nut(s) [W]."""
    heat_to_screw: float
    """Part of it entering the screw [W]."""
    contact_temperature: float
    """Mean of the nut and screw temperatures at the fixed point [K]."""
    viscosity: float
    """Lubricant viscosity at that temperature [Pa s] (NaN for a dry case)."""
    iterations: int
    """Fixed-point iterations of the model that was solved."""


@dataclass(frozen=True)
class ThermalField(Presented):
    """Temperature field and thermal elongation of the ball screw (attribute names are public).

    Temperatures in K, rises in K, lengths in m, heat in W, times in s.
    """

    case_name: str
    model: str
    ambient_temperature: float
    """Ambient and initial temperature [K]."""
    solution: Solution
    sources: tuple[HeatSource, ...]
    convection: tuple[ConvectionCoefficient, ...]
    interfaces: tuple[NutInterface, ...]
    feed_speed: float
    """Nut speed along the screw [m/s]."""
    stroke_mode: str
    elongation_thermoelastic: float | None
    """Thermo-elastic mean end displacement (axisymmetric FE) [m]; None if not computed."""
    seconds: float
    """Wall-clock time of the whole analysis [s]."""
    case: Case
    """The case that was solved."""
    warnings: tuple[str, ...] = ()
    """Warnings raised while solving (one line each)."""
    coupling: HeatCoupling | None = None
    """The operating point behind the balls' heat (None: a fixed heat of the case)."""
    duty: DutyThermal | None = None
    """The case's ``[[duty]]`` cycle on the same model (None: no duty list, or not asked)."""

    analysis: ClassVar[str] = "thermal"
    presentation: ClassVar[ModuleType] = thermal_report

    @property
    def problem(self) -> ThermalProblem:
        """The SI problem the model solved."""
        return self.solution.discretisation.problem

    @property
    def max_temperature_rise(self) -> float:
        """Largest steady temperature rise [K]."""
        return self.solution.max_temperature_rise

    @property
    def max_temperature(self) -> float:
        """Largest steady temperature [K]."""
        return self.ambient_temperature + self.max_temperature_rise

    @property
    def nut_temperature(self) -> float:
        """Steady mean temperature of the nut assembly [K] (volume mean on the FE models)."""
        return self.ambient_temperature + float(
            nut_mean_row(self.solution.discretisation) @ self.solution.steady
        )

    @property
    def coolant_outlet_temperature(self) -> float | None:
        """Steady outlet temperature of the hollow shaft's coolant [K]; None for a solid shaft."""
        rise = coolant_outlet_rise(self.solution.discretisation, self.solution.steady)
        return None if rise is None else self.ambient_temperature + rise

    @property
    def elongation(self) -> float:
        """Steady thermal elongation of the screw shaft ΔL = α∫ΔT̄ dz (Q7) [m]."""
        return self.solution.elongation

    @property
    def heat_input(self) -> float:
        """Friction heat entering the model [W] (a coolant's inlet enthalpy is not counted)."""
        return self.problem.heat_input

    @property
    def heat_balance_error(self) -> float:
        """Steady |in − out|/in [-]."""
        return self.solution.heat_balance_error

    @property
    def transient_heat_balance_error(self) -> float:
        """|∫Q dt − stored − convected| / ∫Q dt over the transient [-] (NaN without one)."""
        t = self.solution.transient
        return float("nan") if t is None else t.heat_balance_error

    @property
    def unknowns(self) -> int:
        """Unknowns of the discrete model."""
        return self.solution.discretisation.unknowns

    @property
    def time_to_95(self) -> float:
        """Time for the largest rise to reach 95 % of its steady value [s]."""
        t = self.solution.transient
        if t is None:
            return float("nan")
        return time_to_fraction(t.time, t.max_rise, self.max_temperature_rise)

    @property
    def elongation_time_to_95(self) -> float:
        """Time for the elongation to reach 95 % of its steady value [s]."""
        t = self.solution.transient
        if t is None:
            return float("nan")
        return time_to_fraction(t.time, t.elongation, self.elongation)

    @property
    def sensors(self) -> tuple[SensorReading, ...]:
        """Steady and final temperature at every sensor point."""
        t = self.solution.transient
        steady = self.solution.sensors
        out = []
        for k, s in enumerate(self.problem.sensors):
            final = float("nan") if t is None else float(t.sensors[-1, k])
            t95 = (
                float("nan") if t is None else time_to_fraction(t.time, t.sensors[:, k], steady[k])
            )
            out.append(
                SensorReading(
                    s.name,
                    s.body,
                    s.r,
                    s.z,
                    self.ambient_temperature + float(steady[k]),
                    self.ambient_temperature + final,
                    t95,
                )
            )
        return tuple(out)

    @property
    def title(self) -> str:
        cycle = "" if self.duty is None else " at the operating point and over the duty cycle"
        return f"Temperature field and thermal elongation{cycle}: {self.case_name}"


field_dataset = thermal_report.fields
"""The results of :func:`thermal_field` as an xarray Dataset with units."""


def thermal_field(
    case: Case,
    model: str | None = None,
    *,
    tcr: ScrewTCR | None = None,
    transient: bool = True,
    duty: bool = True,
) -> ThermalField:
    """Temperature field and thermal elongation of the ball screw of ``case``.

    ``model``: "axisymmetric" (2-D FE), "network" (1-D, fast) or "3d" (3-D FE with the balls as
    helical contact patches, ``[thermal.mesh]`` ``*_3d`` keys); ``None`` takes the case's
    ``[thermal] model``. ``tcr``: a precomputed :func:`screw_tcr` of the same case (else
    computed, and cached per contact input). ``transient=False`` skips the transient.

    With ``[thermal.drag_torque] source = "operating_point"`` (the default) the balls' heat is
    that of the coupled operating point, its fixed point solved on the network model and then
    on ``model`` (``coupling`` of the result); the transient runs from ambient at that heat.

    A case with a ``[[duty]]`` list is also run through its cycle on ``model``, the run of
    :func:`~ballscrew.analyses.duty_thermal.thermal_duty` (``duty`` of the result);
    ``duty=False`` keeps to the single operating point.
    """
    _checked(case, model, transient)
    if not (duty and case.duty):
        return _point_field(case, model, tcr, transient)
    # imported here: the duty cycle builds its segments with this module
    from ballscrew.analyses.duty_thermal import checked_cycle, thermal_duty

    checked_cycle(case)  # a cycle refused for its step count is refused before the point's solve
    field = _point_field(case, model, tcr, transient)
    started = _time.perf_counter()
    cycle = thermal_duty(case, field.model)
    return dataclasses.replace(
        field,
        duty=cycle,
        seconds=field.seconds + _time.perf_counter() - started,
        warnings=tuple(dict.fromkeys((*field.warnings, *cycle.warnings))),
    )


def _point_field(
    case: Case, model: str | None, tcr: ScrewTCR | None, transient: bool
) -> ThermalField:
    """:func:`thermal_field` at the case's single operating point."""
    spec, model = _checked(case, model, transient)
    if spec.drag_torque.source != "operating_point":
        return solve_field(case, model, tcr=tcr, transient=transient)
    # imported here: the operating point solves its fields with this module
    from ballscrew.analyses.operating_point import coupled_heat

    started = _time.perf_counter()
    with recorded_warnings() as messages:
        resolved, coupling, steady = coupled_heat(case, model)
    if transient and tcr is not None:  # the point was solved with the case's own TCR
        field = solve_field(resolved, model, tcr=tcr, steady=steady.solution)
    else:  # the last iteration solved the resolved case: its inputs, mesh and steady field
        with recorded_warnings() as marched:
            solution = steady.solution
            if transient:
                disc = solution.discretisation
                solution = _simulate(disc, spec, True, steady.feed_speed, solution.steady)
            elastic = _thermoelastic(case, spec, solution)  # the iterations skipped it
        field = dataclasses.replace(
            steady,
            solution=solution,
            elongation_thermoelastic=elastic,
            warnings=(*steady.warnings, *marched),
        )
    return dataclasses.replace(
        field,
        case=case,
        coupling=coupling,
        seconds=_time.perf_counter() - started,
        warnings=tuple(dict.fromkeys((*messages, *field.warnings))),
    )


def _checked(case: Case, model: str | None, transient: bool) -> tuple[ThermalSpec, str]:
    """The case's ``[thermal]`` and the model name, checked before any work."""
    case_with(case, "screw", "operating", "materials", "thermal")
    spec = thermal_spec(case)
    model = THERMAL_MODELS.check(spec.model if model is None else model)
    if transient:  # the step count before any work; the history's memory once the mesh is known
        check_transient(None, spec.transient.duration, spec.transient.time_step)
    return spec, model


def solve_field(
    case: Case,
    model: str | None = None,
    *,
    tcr: ScrewTCR | None = None,
    transient: bool = True,
    reuse: Discretisation | None = None,
    thermoelastic: bool = True,
    steady: Solution | None = None,
) -> ThermalField:
    """:func:`thermal_field` with the heat the case gives, its drag torque taken as it stands
    (a resolved ``operating_point`` torque is ``thermal.drag_torque.torque``).

    ``reuse``: a discretisation of the same screw on ``model`` (another heat, other convection
    coefficients): its mesh and matrices are bound to this case's loads instead of meshing and
    assembling again, when :func:`~ballscrew.thermal.problem.same_mesh` and the 3-D model's ball
    patches allow (the result is the same to rounding). ``thermoelastic=False`` skips the
    ``thermoelastic_check`` (fixed-point iterations). ``steady``: a steady solution on
    ``model`` (the coupled operating point's last field): when it solved this very problem, its
    discretisation and steady field are taken as they are and only the transient is solved;
    otherwise its discretisation is a ``reuse``.
    """
    started = _time.perf_counter()
    spec, model = _checked(case, model, transient)
    with recorded_warnings() as messages:
        problem, sources, convection, interfaces, speed = build_problem(case, tcr)
        check_mesh(spec, problem, model)
        helical = model == "3d" and spec.mesh.helical_patches
        patches = ball_patches(case, problem, tcr) if helical else None
        mesh = _mesh_options(spec)
        known = _solved(steady, model, problem, patches, mesh)
        if known is not None:
            disc = known.discretisation
        else:
            if reuse is None and steady is not None:
                reuse = steady.discretisation
            with bearings_named_by_key(spec):
                disc = _rebound(reuse, model, problem, patches, mesh) or build_model(
                    model, problem, mesh, patches
                )
        disc.extra["patches"], disc.extra["mesh_options"] = patches, mesh
        solution = _simulate(disc, spec, transient, speed, None if known is None else known.steady)
        elastic = _thermoelastic(case, spec, solution) if thermoelastic else None
    return ThermalField(
        case_name=case.name,
        model=model,
        ambient_temperature=spec.ambient_temperature,
        solution=solution,
        sources=sources,
        convection=convection,
        interfaces=interfaces,
        feed_speed=speed,
        stroke_mode=spec.stroke.mode,
        elongation_thermoelastic=elastic,
        seconds=_time.perf_counter() - started,
        case=case,
        warnings=tuple(messages),
    )


def _simulate(
    disc: Discretisation,
    spec: ThermalSpec,
    transient: bool,
    speed: float,
    steady: NDArray[np.float64] | None = None,
) -> Solution:
    """:func:`~ballscrew.thermal.simulate.simulate` of ``disc`` with the case's transient and
    stroke settings (``steady``: its steady field, already solved)."""
    tr = spec.transient
    with blas_single_thread():  # triangular solves and vector products (see thermal_duty)
        return simulate(
            disc,
            tr.duration if transient else None,
            tr.time_step,
            tr.snapshots,
            spec.stroke.mode,
            speed,
            steady=steady,
        )


def _thermoelastic(case: Case, spec: ThermalSpec, solution: Solution) -> float | None:
    """The thermo-elastic end displacement when the case asks for it (axisymmetric model)."""
    disc = solution.discretisation
    if disc.model != "axisymmetric" or not spec.thermoelastic_check:
        return None
    screw = case.materials.screw
    return thermoelastic_elongation(
        disc, solution.steady, screw.youngs_modulus, screw.poissons_ratio
    )


def _fits(disc: Discretisation, model: str, patches: tuple | None, mesh: MeshOptions) -> bool:
    """Whether ``disc`` is a ``model`` mesh with these ball patches and mesh options."""
    extra = disc.extra
    return (
        disc.model == model
        and extra.get("patches") == patches
        and extra.get("mesh_options") == mesh
    )


def _rebound(
    reuse: Discretisation | None,
    model: str,
    problem: ThermalProblem,
    patches: tuple | None,
    mesh: MeshOptions,
) -> Discretisation | None:
    """``reuse`` bound to ``problem`` when it is a ``model`` mesh of it with the same patches
    and mesh options."""
    if reuse is None or not _fits(reuse, model, patches, mesh):
        return None
    return reuse.rebound(problem)


def _solved(
    steady: Solution | None,
    model: str,
    problem: ThermalProblem,
    patches: tuple | None,
    mesh: MeshOptions,
) -> Solution | None:
    """``steady`` when it is the steady state of ``problem`` on this ``model`` mesh."""
    if steady is None or not _fits(steady.discretisation, model, patches, mesh):
        return None
    return steady if steady.discretisation.problem == problem else None


def _mesh_options(spec: ThermalSpec) -> MeshOptions:
    ms = spec.mesh
    return MeshOptions(
        size=ms.size,
        order=ms.order,
        network_cell=ms.network_cell,
        size_3d=ms.size_3d,
        far_size_3d=ms.far_size_3d,
        divisions_3d=ms.divisions_3d,
        layers_3d=ms.layers_3d,
    )


def thermal_scalars(case: Case, model: str | None = None) -> dict[str, tuple[float, str]]:
    """Sweepable steady-state scalars of :func:`thermal_field` at the operating point (the
    ``[[duty]]`` cycle is not run) with their units.

    ``model`` defaults to the case's ``[thermal] model`` (``ballscrew sweep --analysis
    thermal``); :func:`thermal_network_scalars` takes the 1-D network (milliseconds per point,
    thousands of points in a minute) and :func:`thermal_fe_scalars` the axisymmetric model.
    """
    result = thermal_field(case, model, transient=False, duty=False)
    return {
        "max_temperature_rise": (result.max_temperature_rise, "K"),
        "elongation": (result.elongation, "m"),
        "heat_input": (result.heat_input, "W"),
        "heat_balance_error": (result.heat_balance_error, ""),
    }


def thermal_network_scalars(case: Case) -> dict[str, tuple[float, str]]:
    """:func:`thermal_scalars` of the 1-D network model."""
    return thermal_scalars(case, "network")


def thermal_fe_scalars(case: Case) -> dict[str, tuple[float, str]]:
    """:func:`thermal_scalars` of the axisymmetric FE model."""
    return thermal_scalars(case, "axisymmetric")
