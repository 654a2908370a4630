"""``thermal_field(case)``: temperature field and thermal elongation of the ball screw.

After Gao, Wang & Liu (2019), §5: screw shaft, nut(s) and spacer, heated by the support bearings
and the ball screw's friction, cooled by convection, with the thermal contact resistance of the
TCR chain on the balls; steady state, the transient from ambient, and the elongation
ΔL = α∫ΔT dz (theory manual: *Thermal*).

Models: ``"axisymmetric"`` (default; 2-D scikit-fem), ``"network"`` (1-D axial, milliseconds)
and ``"3d"`` (hexahedra, helical contact patches; :mod:`~ballscrew.thermal.threed`).
"""

from __future__ import annotations

import math
import time as _time
from dataclasses import dataclass
from typing import Any

import numpy as np
import xarray as xr

from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.screw_tcr import ScrewTCR, screw_tcr
from ballscrew.budget import check_memory
from ballscrew.case import Case
from ballscrew.case.thermal_spec import ThermalSpec
from ballscrew.contact_resistance.constriction import ball_contact_constriction
from ballscrew.errors import InputError
from ballscrew.loads import preload_drag_torque
from ballscrew.thermal.convection import (
    Air,
    flat_plate_laminar,
    horizontal_cylinder_natural,
    rotating_cylinder,
)
from ballscrew.thermal.elongation import displacement_profile, thermoelastic_elongation
from ballscrew.thermal.heat_sources import friction_heat, nut_heat_shares, palmgren_torque
from ballscrew.thermal.models import THERMAL_MODELS, MeshOptions, build_model
from ballscrew.thermal.problem import (
    BandHeat,
    Convection,
    RingPart,
    Sensor,
    Solid,
    ThermalProblem,
)
from ballscrew.thermal.simulate import Solution, check_transient, simulate, time_to_fraction
from ballscrew.validation import case_with


@dataclass(frozen=True)
class HeatSource:
    """One friction heat source (Q2–Q4)."""

    name: str
    method: str
    """How the torque was obtained."""
    torque: float
    """Friction torque [N·m]."""
    heat: float
    """Heat generated, M·ω [W]."""
    into_screw: float
    """Part entering the screw model [W]."""
    into_nut: float
    """Part entering the nut model [W] (bearings: 0, the rest leaves through the housing)."""


@dataclass(frozen=True)
class ConvectionCoefficient:
    """A heat-transfer coefficient and where it came from (Q5, Q6)."""

    surface: str
    value: float
    """h [W/(m² K)]."""
    correlation: str
    """Correlation used, or 'override'."""


@dataclass(frozen=True)
class NutInterface:
    """The smeared ball contact of one nut."""

    name: str
    micro_resistance: float
    """Fractal TCR of all its balls, R_sbn/n_b (A2–A3), or R″/A for a given R″ [K/W]."""
    constriction_resistance: float
    """Macro-constriction of the Hertz patches into balls and raceways, all balls [K/W]."""
    resistance_per_area: float
    """R″ = R·S of the TCR chain (A4) for this nut [m² K/W] (NaN for a given value)."""
    bore_area: float
    """Nominal bore area 2πR·L_nut the balls are smeared over [m²]."""

    @property
    def resistance(self) -> float:
        """Total screw-to-nut resistance of the nut's balls [K/W]."""
        return self.micro_resistance + self.constriction_resistance

    @property
    def conductance_per_area(self) -> float:
        """Smeared interface conductance h = 1/(R·A_bore) [W/(m² K)] (∞ → 0 if lifted off)."""
        r = self.resistance
        return 0.0 if not math.isfinite(r) else 1.0 / (r * self.bore_area)


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
class ThermalField:
    """Temperature field and thermal elongation of the ball screw (issue #4 contract).

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
    def elongation(self) -> float:
        """Steady thermal elongation of the screw shaft ΔL = α∫ΔT̄ dz (Q7) [m]."""
        return self.solution.elongation

    @property
    def heat_input(self) -> float:
        """Heat entering the model [W]."""
        return self.solution.heat_input

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

    def to_xarray(self) -> xr.Dataset:
        """Fields and histories with units (temperatures in K)."""
        return field_dataset(self)


def thermal_field(
    case: Case,
    model: str | None = None,
    *,
    tcr: ScrewTCR | None = None,
    transient: bool = True,
) -> ThermalField:
    """Temperature field and thermal elongation of the ball screw of ``case``.

    ``model``: "axisymmetric" (2-D FE), "network" (1-D, fast) or "3d" (3-D FE with the balls as
    helical contact patches, ``[thermal.mesh]`` ``*_3d`` keys); ``None`` takes the case's
    ``[thermal] model``. ``tcr``: a precomputed :func:`screw_tcr` of the same case (else
    computed, and cached per contact input). ``transient=False`` skips the transient.
    """
    started = _time.perf_counter()
    case_with(case, "screw", "operating", "materials", "thermal")
    spec = _spec(case)
    model = THERMAL_MODELS.check(spec.model if model is None else model)
    if transient:  # the step count before any work; the history's memory once the mesh is known
        check_transient(None, spec.transient.duration, spec.transient.time_step)
    problem, sources, convection, interfaces, speed = build_problem(case, tcr)
    _check_mesh(spec, problem, model)
    ms = spec.mesh
    mesh = MeshOptions(
        size=ms.size,
        order=ms.order,
        network_cell=ms.network_cell,
        size_3d=ms.size_3d,
        far_size_3d=ms.far_size_3d,
        divisions_3d=ms.divisions_3d,
        layers_3d=ms.layers_3d,
    )
    patches = ball_patches(case, problem, tcr) if model == "3d" and ms.helical_patches else None
    disc = build_model(model, problem, mesh, patches)
    tr = spec.transient
    solution = simulate(
        disc,
        tr.duration if transient else None,
        tr.time_step,
        tr.snapshots,
        spec.stroke.mode,
        speed,
    )
    thermoelastic = None
    if model == "axisymmetric" and spec.thermoelastic_check:
        screw = case.materials.screw
        thermoelastic = thermoelastic_elongation(
            disc, solution.steady, screw.youngs_modulus, screw.poissons_ratio
        )
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
        elongation_thermoelastic=thermoelastic,
        seconds=_time.perf_counter() - started,
    )


def _check_mesh(spec: ThermalSpec, problem: ThermalProblem, model: str) -> None:
    """Refuse (naming the mesh key) a mesh whose matrices would not fit the memory budget.

    Unknowns: the shaft length and the largest outer radius over the element size (times the
    element order) for the axisymmetric model, axial planes × divisions × (layers + 6) for the
    3-D model, one per cell for the network; about 2 KiB (2-D, network) or 4 KiB (3-D) per
    unknown for the sparse matrices and a direct factorisation.
    """
    ms = spec.mesh
    length = problem.shaft_length
    if model == "network":
        field, value, per = "thermal.mesh.network_cell", ms.network_cell, 2048.0
        unknowns = length / ms.network_cell + 1.0
    elif model == "3d":
        field, value, per = "thermal.mesh.size_3d", ms.size_3d, 4096.0
        planes = (problem.ring_length + problem.stroke) / ms.size_3d + length / ms.far_size_3d
        unknowns = (planes + 1.0) * ms.divisions_3d * (ms.layers_3d + 6.0)
    else:
        field, value, per = "thermal.mesh.size", ms.size, 2048.0
        radius = max(part.outer_radius for part in problem.parts)
        unknowns = (ms.order * length / ms.size + 1.0) * (ms.order * radius / ms.size + 1.0)
    check_memory(field, value, unknowns * per, f"a {model} mesh of about {unknowns:.3g} unknowns")


def _spec(case: Case) -> ThermalSpec:
    if case.thermal is None:
        raise InputError(
            "thermal",
            None,
            "a [thermal] section in the case file (every key has a default, so an empty "
            "[thermal] table works)",
        )
    return case.thermal


_TCR_CACHE: dict[str, ScrewTCR] = {}
_TCR_KEYS = {"screw", "materials", "surface", "medium", "operating", "numerics", "tcr"}


def _cached_tcr(case: Case) -> ScrewTCR:
    """:func:`screw_tcr` of the case's variant, cached on the inputs it depends on."""
    key = case.model_dump_json(include=_TCR_KEYS)
    if key not in _TCR_CACHE:
        if len(_TCR_CACHE) >= 32:
            _TCR_CACHE.pop(next(iter(_TCR_CACHE)))
        _TCR_CACHE[key] = screw_tcr(case)
    return _TCR_CACHE[key]


def build_problem(
    case: Case, tcr: ScrewTCR | None = None
) -> tuple[
    ThermalProblem,
    tuple[HeatSource, ...],
    tuple[ConvectionCoefficient, ...],
    tuple[NutInterface, ...],
    float,
]:
    """Translate ``case`` into the SI :class:`ThermalProblem` and its reported inputs.

    Returns (problem, heat sources, convection coefficients, nut interfaces, feed speed).
    """
    spec = _spec(case)
    screw, op = case.screw, case.operating
    d_m = screw.pitch_diameter
    shaft_d = spec.shaft_diameter or d_m
    nut_d = spec.nut_outer_diameter or 1.75 * d_m
    nut_len = spec.nut_length or 2.5 * d_m
    spacer_d = spec.spacer_outer_diameter or nut_d
    for name, value in (("nut_outer_diameter", nut_d), ("spacer_outer_diameter", spacer_d)):
        if not value > shaft_d:
            raise InputError(f"thermal.{name}", value, f"a diameter > the shaft's {shaft_d:g} m")
    omega = op.speed
    params = ScrewParameters.from_case(case)
    geometry = params.geometry
    lead = screw.lead
    feed = spec.stroke.feed_speed
    feed = abs(omega) * lead / (2 * math.pi) if feed is None else feed
    length = spec.shaft_length

    # heat of the ball screw, split between the nuts by their forces
    forces = tuple(n.force for n in params.nuts)
    dt = spec.drag_torque
    if dt.source == "kinematics":
        from ballscrew.analyses.kinematics import computed_drag_torque

        torque, method = float(computed_drag_torque(case)), "kinematics model (ball drag)"
    elif dt.source == "given":
        torque, method = float(dt.torque), "given"
    else:
        torque = preload_drag_torque(op.preload, lead, geometry.lead_angle)
        method = "catalogue preload torque K·F_p·L/(2π), K = 0.05/√tan α"
    drag_heat = friction_heat(torque, omega)
    s = spec.screw_heat_fraction
    sources = [
        HeatSource(
            f"nut {k + 1} balls",
            method,
            torque * fraction,
            drag_heat * fraction,
            s * drag_heat * fraction,
            (1 - s) * drag_heat * fraction,
        )
        for k, fraction in enumerate(nut_heat_shares(1.0, forces))
    ]

    # bearings (Q2, Q3)
    bands = []
    for b in spec.bearings:
        if b.torque is not None:
            m_be, how = b.torque, "catalogue torque"
        else:
            pt = palmgren_torque(
                omega,
                b.f0,
                b.viscosity,
                b.mean_diameter,
                b.axial_load,
                b.static_load_rating,
                b.radial_load,
                b.f1,
            )
            m_be = pt.total
            how = f"Palmgren M0 + M1 = {pt.load_independent:.4g} + {pt.load_dependent:.4g} N·m"
        q = friction_heat(m_be, omega)
        sources.append(HeatSource(b.name, how, m_be, q, b.shaft_fraction * q, 0.0))
        bands.append(BandHeat(b.name, b.position, b.width, b.shaft_fraction * q))

    # convection (Q5, Q6)
    cs = spec.convection
    dT = cs.temperature_difference
    air = Air(
        cs.air_kinematic_viscosity,
        cs.air_conductivity,
        cs.air_prandtl,
        spec.ambient_temperature + 0.5 * dT,
    )
    nuts_count = screw.nuts
    spacer_len = spec.spacer_length if nuts_count == 2 else 0.0
    ring_length = nuts_count * nut_len + spacer_len
    coefficients: list[ConvectionCoefficient] = []

    def pick(name: str, override: float | None, options: dict[str, float]) -> float:
        if override is not None:
            coefficients.append(ConvectionCoefficient(name, float(override), "override"))
            return float(override)
        label, value = max(options.items(), key=lambda kv: kv[1])
        coefficients.append(ConvectionCoefficient(name, value, label))
        return value

    h_screw = pick(
        "screw",
        cs.screw,
        {
            "Kreith rotating cylinder (Q5)": rotating_cylinder(shaft_d, omega, air),
            f"Churchill–Chu natural, ΔT = {dT:g} K (Q6)": horizontal_cylinder_natural(
                shaft_d, dT, air
            ),
        },
    )
    h_screw_ends = pick("screw ends", cs.screw_ends, {"= screw": h_screw})
    nut_options = {
        f"Churchill–Chu natural, ΔT = {dT:g} K (Q6)": horizontal_cylinder_natural(nut_d, dT, air)
    }
    if spec.stroke.length > 0 and feed > 0:
        nut_options["laminar flat plate at the feed speed (Q6)"] = flat_plate_laminar(
            ring_length, feed, air
        )
    h_nut = pick("nut", cs.nut, nut_options)
    h_nut_ends = pick("nut ends", cs.nut_ends, {"= nut": h_nut})

    # the balls: TCR chain (A1–A4) + macro-constriction, or a given R″
    radius = 0.5 * shaft_d
    bore_area = 2 * math.pi * radius * nut_len
    interfaces = []
    contact = spec.contact
    if contact.source == "tcr":
        tcr = tcr if tcr is not None else _cached_tcr(case)
        by_index = {n.index: n for n in tcr.nuts}
    mats = case.materials
    for k in range(nuts_count):
        name = f"nut {k + 1}"
        if contact.source == "given":
            r_pp = float(contact.resistance_per_area)
            interfaces.append(NutInterface(name, r_pp / bore_area, 0.0, float("nan"), bore_area))
            continue
        nut = by_index.get(k + 1)
        if nut is None:  # lifted off
            interfaces.append(NutInterface(name, math.inf, 0.0, math.inf, bore_area))
            continue
        constriction = 0.0
        if contact.constriction:
            per_ball = ball_contact_constriction(
                (nut.screw.contact.hertz.a, nut.screw.contact.hertz.b),
                mats.ball.thermal_conductivity,
                mats.screw.thermal_conductivity,
            ) + ball_contact_constriction(
                (nut.nut.contact.hertz.a, nut.nut.contact.hertz.b),
                mats.ball.thermal_conductivity,
                mats.nut.thermal_conductivity,
            )
            constriction = per_ball / nut.balls
        interfaces.append(
            NutInterface(
                name, nut.resistance, constriction, nut.resistance * nut.apparent_area, bore_area
            )
        )

    nut_parts = [
        RingPart(
            f"nut {k + 1}",
            nut_len,
            0.5 * nut_d,
            True,
            0.0 if not math.isfinite(i.resistance) else 1.0 / i.resistance,
            sources[k].into_screw,
            sources[k].into_nut,
        )
        for k, i in enumerate(interfaces)
    ]
    parts = nut_parts[:1]
    if nuts_count == 2:
        if spacer_len > 0:
            parts.append(RingPart("spacer", spacer_len, 0.5 * spacer_d, balls=False))
        parts.append(nut_parts[1])
    problem = ThermalProblem(
        shaft_radius=radius,
        shaft_length=length,
        shaft=_solid(mats.screw),
        ring=_solid(mats.nut),
        parts=tuple(parts),
        ring_centre=spec.nut_position if spec.nut_position is not None else 0.5 * length,
        convection=Convection(h_screw, h_screw_ends, h_nut, h_nut_ends),
        bearings=tuple(bands),
        stroke=spec.stroke.length,
        expansion=mats.screw.thermal_expansion,
        sensors=tuple(Sensor(s.name, s.body, s.r, s.z, s.theta) for s in spec.sensors),
    )
    return problem, tuple(sources), tuple(coefficients), tuple(interfaces), feed


def ball_patches(case: Case, problem: ThermalProblem, tcr: ScrewTCR | None = None) -> tuple:
    """:class:`~ballscrew.thermal.threed.BallPatches` of each part of ``problem`` (3-D model).

    Loaded balls and Hertz semi-axes of the screw contact from the TCR chain (a, along the
    rolling direction; b·cos β across the groove projected on the cylinder); with a given R″
    the balls per nut of the case and mesh-sized patches. Spacers: None.
    """
    from ballscrew.thermal.threed import BallPatches

    screw = case.screw
    beta = ScrewParameters.from_case(case).geometry.contact_angle
    by_index = {}
    if _spec(case).contact.source == "tcr":
        tcr = tcr if tcr is not None else _cached_tcr(case)
        by_index = {n.index: n for n in tcr.nuts}
    out: list = []
    k = 0
    for part in problem.parts:
        if not part.balls:
            out.append(None)
            continue
        k += 1
        nut = by_index.get(k)
        if nut is None:
            out.append(BallPatches(screw.balls_per_nut, screw.lead))
            continue
        h = nut.screw.contact.hertz
        out.append(BallPatches(nut.balls, screw.lead, (h.a, h.b * math.cos(beta))))
    return tuple(out)


def _solid(material: Any) -> Solid:
    return Solid(material.thermal_conductivity, material.density, material.specific_heat)


def field_dataset(result: ThermalField) -> xr.Dataset:
    """The results of :func:`thermal_field` as an xarray Dataset with units."""
    sol = result.solution
    disc = sol.discretisation
    problem = result.problem
    amb = result.ambient_temperature

    def kelvin(long_name: str) -> dict[str, str]:
        return {"units": "K", "long_name": long_name}

    alpha = problem.expansion
    data: dict[str, Any] = {
        "axis_temperature": (
            "axis_z",
            amb + sol.axis,
            kelvin("steady cross-section mean temperature of the screw"),
        ),
        "axis_displacement": (
            "axis_z",
            displacement_profile(disc.axis_z, sol.axis, alpha),
            {"units": "m", "long_name": "steady axial thermal displacement α∫ΔT̄ dz from z = 0"},
        ),
        "sensor_temperature_steady": (
            "sensor",
            amb + sol.sensors,
            kelvin("steady sensor temperature"),
        ),
        "sensor_r": ("sensor", [s.r for s in problem.sensors], {"units": "m"}),
        "sensor_z": ("sensor", [s.z for s in problem.sensors], {"units": "m"}),
        "sensor_body": ("sensor", [s.body for s in problem.sensors]),
    }
    coords: dict[str, Any] = {
        "axis_z": ("axis_z", disc.axis_z, {"units": "m", "long_name": "axial position"}),
        "sensor": ("sensor", [s.name for s in problem.sensors]),
    }
    t = sol.transient
    if t is not None:
        coords["time"] = ("time", t.time, {"units": "s", "long_name": "time"})
        coords["snapshot_time"] = ("snapshot_time", t.snapshot_times, {"units": "s"})
        data.update(
            max_temperature=("time", amb + t.max_rise, kelvin("largest temperature")),
            elongation=(
                "time",
                t.elongation,
                {"units": "m", "long_name": "thermal elongation α∫ΔT̄ dz of the screw"},
            ),
            sensor_temperature=(("time", "sensor"), amb + t.sensors, kelvin("sensor temperature")),
            axis_temperature_history=(
                ("time", "axis_z"),
                amb + t.axis,
                kelvin("cross-section mean temperature of the screw"),
            ),
            nut_offset=(
                "time",
                t.offset * disc.grid.dz,
                {"units": "m", "long_name": "nut stroke offset (resolved stroke)"},
            ),
        )
    if disc.model in ("axisymmetric", "3d"):
        fe_mesh = disc.extra["mesh"]
        nodal = disc.extra["basis"].nodal_dofs[0]
        node_axes = (
            (("node_r", "radius"), ("node_z", "axial position"))
            if disc.model == "axisymmetric"
            else (("node_x", "x"), ("node_y", "y"), ("node_z", "axial position"))
        )
        coords["node"] = ("node", np.arange(fe_mesh.mesh.p.shape[1]))
        for row, (name, long_name) in enumerate(node_axes):
            data[name] = ("node", fe_mesh.mesh.p[row], {"units": "m", "long_name": long_name})
        data.update(
            element_nodes=(("element", "corner"), fe_mesh.mesh.t.T),
            element_body=(
                "element",
                fe_mesh.body,
                {"long_name": "0 = screw shaft, 1 = nut assembly"},
            ),
            temperature_steady=("node", amb + sol.steady[nodal], kelvin("steady temperature")),
        )
        if t is not None:
            data["temperature"] = (
                ("snapshot_time", "node"),
                amb + t.snapshots[:, nodal],
                kelvin("temperature"),
            )
    else:
        ex = disc.extra
        coords["ring_z"] = ("ring_z", ex["ring_z"], {"units": "m", "long_name": "nut cell centre"})
        for key, label in (
            ("ring_mean", "nut assembly mean"),
            ("ring_bore", "nut bore"),
            ("ring_outer", "nut outer surface"),
        ):
            data[f"{key}_temperature_steady"] = (
                "ring_z",
                amb + sol.steady[ex[key]],
                kelvin(f"steady {label} temperature"),
            )
        data["shaft_surface_temperature_steady"] = (
            "axis_z",
            amb + sol.steady[ex["shaft_surface"]],
            kelvin("steady screw surface temperature"),
        )
        if t is not None:
            data["ring_mean_temperature"] = (
                ("snapshot_time", "ring_z"),
                amb + t.snapshots[:, ex["ring_mean"]],
                kelvin("nut assembly mean temperature"),
            )
    return xr.Dataset(
        data,
        coords=coords,
        attrs={
            "case": result.case_name,
            "model": result.model,
            "ambient_temperature_K": amb,
            "heat_input_W": result.heat_input,
            "max_temperature_rise_K": result.max_temperature_rise,
            "elongation_m": result.elongation,
            "unknowns": result.unknowns,
        },
    )


def thermal_scalars(case: Case, model: str | None = None) -> dict[str, tuple[float, str]]:
    """Sweepable steady-state scalars of :func:`thermal_field` with their units.

    ``model`` defaults to the case's ``[thermal] model`` (``ballscrew sweep --analysis
    thermal``); :func:`thermal_network_scalars` takes the 1-D network (milliseconds per point,
    thousands of points in a minute) and :func:`thermal_fe_scalars` the axisymmetric model.
    """
    result = thermal_field(case, model, transient=False)
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
