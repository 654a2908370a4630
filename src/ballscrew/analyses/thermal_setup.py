"""Case → :class:`~ballscrew.thermal.problem.ThermalProblem`: what the thermal model is given.

Geometry of the shaft, nut(s) and spacer, the friction heat of the balls and the bearings
(Q2–Q4), the convection coefficients (Q5, Q6), the smeared ball contact of each nut from the TCR
chain (A1–A4) and, for the 3-D model, the helical ball patches (theory manual: *Thermal*).
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, replace
from functools import partial
from typing import Any

import numpy as np

from ballscrew.analyses.case_cache import CaseCache, Fields
from ballscrew.analyses.kinematics import computed_drag_torque
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.screw_tcr import ScrewTCR, screw_tcr
from ballscrew.analyses.tcr_film import conductivities, heat_paths
from ballscrew.analyses.tcr_models import PATCH
from ballscrew.analyses.thermal_cooling import (
    bore_coefficient,
    nut_coolant_flux,
    shaft_coolant,
    table_mass,
)
from ballscrew.budget import check_memory
from ballscrew.case import Case, with_overrides
from ballscrew.case.thermal_spec import ThermalSpec
from ballscrew.contact_resistance import parallel_resistance
from ballscrew.errors import InputError
from ballscrew.loads import DRAG_TORQUE_MODELS, DragTorqueInputs
from ballscrew.thermal.boundary import fixed_point, mounting_coefficient
from ballscrew.thermal.convection import (
    Air,
    flat_plate_laminar,
    horizontal_cylinder_natural,
    rotating_cylinder,
)
from ballscrew.thermal.heat_sources import friction_heat, nut_heat_shares, palmgren_torque
from ballscrew.thermal.network import build_network
from ballscrew.thermal.problem import (
    BandHeat,
    Convection,
    RingPart,
    Sensor,
    Solid,
    ThermalProblem,
)
from ballscrew.thermal.simulate import Solution, simulate

__all__ = [
    "ConvectionCoefficient",
    "HeatSource",
    "NutInterface",
    "ball_patches",
    "build_problem",
    "check_mesh",
    "thermal_spec",
]


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
    """Micro TCR of all its balls, R_sbn/n_b (A2–A3), of the headline model (``[tcr]
    headline``) or of ``[thermal.contact] tcr_model``; R″/A for a given R″ [K/W]."""
    constriction_resistance: float
    """Macro-constriction of the Hertz patches into balls and raceways, all balls [K/W]."""
    resistance_per_area: float
    """R″ = R·S of the TCR chain (A4) for this nut [m² K/W] (NaN for a given value)."""
    bore_area: float
    """Nominal bore area 2πR·L_nut the balls are smeared over [m²]."""
    path_resistance: float | None = None
    """With ``[tcr] film_path``: the balls' resistance with the film around each contact in
    parallel (P3), which replaces micro + constriction; None without [K/W]."""

    @property
    def resistance(self) -> float:
        """Total screw-to-nut resistance of the nut's balls [K/W]."""
        if self.path_resistance is not None:
            return self.path_resistance
        return self.micro_resistance + self.constriction_resistance

    @property
    def conductance_per_area(self) -> float:
        """Smeared interface conductance h = 1/(R·A_bore) [W/(m² K)] (∞ → 0 if lifted off)."""
        r = self.resistance
        return 0.0 if not math.isfinite(r) else 1.0 / (r * self.bore_area)


def thermal_spec(case: Case) -> ThermalSpec:
    """The case's ``[thermal]`` section (one-line error without one)."""
    if case.thermal is None:
        raise InputError(
            "thermal",
            None,
            "a [thermal] section in the case file (every key has a default, so an empty "
            "[thermal] table works)",
        )
    return case.thermal


#: Sections :func:`screw_tcr` never reads (without ``[operating] coupled``).
_NOT_TCR: Fields = dict.fromkeys(
    ("name", "description", "thermal", "wear", "friction", "duty", "duty_repeat"), True
)


def _not_tcr(case: Case) -> Fields:
    """The case fields :func:`screw_tcr` of ``case`` does not read.

    Coupled, it solves the operating point, which reads every section. Without ``[tcr]
    film_path`` it reads neither the speed nor the oil's viscosity (the contacts take the ball
    loads, roughness, materials and the medium's conductivity), so the operating point at a
    new speed or contact temperature reuses the contacts; the meniscus film path reads both.
    """
    if case.operating.coupled:
        return {"name": True, "description": True}
    if case.tcr.film_path != "none":
        return _NOT_TCR
    return _NOT_TCR | {"operating": {"speed"}, "medium": {"viscosity", "pressure_viscosity"}}


_cached_tcr = CaseCache(screw_tcr, 32, exclude=_not_tcr)
""":func:`screw_tcr` of the case's headline, cached on every field it reads (through
:class:`ScrewParameters` and the ball loads: also ``loads``, ``design``, ``kinematics``,
``lubrication``). Cases that differ only in fields it does not read share one result, whose
``case`` is the first of them solved."""


def model_nut_resistances(case: Case, tcr: ScrewTCR, name: str) -> dict[int, float]:
    """R of each loaded nut by the TCR model ``name`` of :func:`screw_tcr`'s models [K/W].

    ``tcr`` serves when it holds the model; else the case's TCR is solved with ``name`` added
    to ``[tcr] models``. A correlation left out of the contact (p/H ≥ 0.5) is an error.
    """
    if name not in tcr.models:
        base = name.removesuffix(PATCH)
        if base not in case.tcr.models:
            case = with_overrides(case, {"tcr.models": [*case.tcr.models, base]})
        tcr = _cached_tcr(case)
    if name not in tcr.models:
        raise InputError(
            "thermal.contact.tcr_model",
            name,
            f"a model valid on this contact: {', '.join(tcr.models)} ({name} was left out: "
            "its range ends below the contact's peak p/H)",
        )
    return tcr.models[name].nut_resistances


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
    spec = thermal_spec(case)
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
    model = DRAG_TORQUE_MODELS.entry(dt.source)
    torque = model.model(
        DragTorqueInputs(
            op.preload,
            lead,
            geometry.lead_angle,
            given=dt.torque,
            ball_model=partial(computed_drag_torque, case),
        )
    )
    method = f"{model.name}: {model.description}"
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

    # convection (Q5, Q6), the table (Q8), a cooled nut (Q10)
    nuts_count = screw.nuts
    spacer_len = spec.spacer_length if nuts_count == 2 else 0.0
    surfaces = Surfaces(shaft_d, nut_d, spacer_d, nut_len, spacer_len, nuts_count, omega, feed)

    # the balls: TCR chain (A1–A4) + macro-constriction, or a given R″
    radius = 0.5 * shaft_d
    bore_area = 2 * math.pi * radius * nut_len
    interfaces = []
    contact = spec.contact
    if contact.source == "tcr":
        tcr = tcr if tcr is not None else _cached_tcr(case)
        by_index = {n.index: n for n in tcr.nuts}
        micro = {n.index: n.resistance for n in tcr.nuts}
        if contact.tcr_model is not None:
            micro = model_nut_resistances(case, tcr, contact.tcr_model)
        # constriction and film path of every nut: one computation (tcr_film.heat_paths)
        lam = conductivities(case)
        paths = {
            p.index: p for p in heat_paths(tcr.nuts, tcr.films, lam, micro, contact.constriction)
        }
    mats = case.materials
    for k in range(nuts_count):
        name = f"nut {k + 1}"
        if contact.source == "given":
            r_pp = float(contact.resistance_per_area)
            interfaces.append(NutInterface(name, r_pp / bore_area, 0.0, float("nan"), bore_area))
            continue
        flanks = _body_flanks(k + 1, nuts_count)
        films = [paths[i].resistance for i in flanks if i in paths] if tcr.films else []
        with_film = _parallel(films) if films else None
        loaded = [by_index[i] for i in flanks if i in by_index]
        if not loaded:  # lifted off: nothing, or its balls' films
            interfaces.append(NutInterface(name, math.inf, 0.0, math.inf, bore_area, with_film))
            continue
        r = _parallel([micro[n.index] for n in loaded])
        if len(loaded) == 1:  # one flank: its own split, bit for bit
            cons = paths[loaded[0].index].constriction
        else:  # both flanks of a single nut: what the constriction adds to their parallel R
            cons = _parallel([micro[n.index] + paths[n.index].constriction for n in loaded]) - r
        area = sum(n.apparent_area for n in loaded)
        interfaces.append(NutInterface(name, r, cons, r * area, bore_area, with_film))

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
        convection=Convection(0.0, 0.0, 0.0, 0.0),
        bearings=tuple(bands),
        stroke=spec.stroke.length,
        expansion=mats.screw.thermal_expansion,
        sensors=tuple(Sensor(s.name, s.body, s.r, s.z, s.theta) for s in spec.sensors),
        shaft_coolant=shaft_coolant(spec),
        nut_coolant_flux=nut_coolant_flux(spec, surfaces.outer_area),
        table=table_mass(spec, surfaces.outer_area),
    )
    problem, coefficients = _cooled(spec, surfaces, problem)
    return problem, tuple(sources), coefficients, tuple(interfaces), feed


@dataclass(frozen=True)
class Surfaces:
    """What the convection coefficients of a case depend on besides the temperatures (SI)."""

    shaft_diameter: float
    nut_diameter: float
    spacer_diameter: float
    nut_length: float
    spacer_length: float
    nuts: int
    speed: float
    """Screw speed ω [rad/s]."""
    feed: float
    """Nut speed [m/s]."""

    @property
    def ring_length(self) -> float:
        """Length of the nut assembly [m]."""
        return self.nuts * self.nut_length + self.spacer_length

    @property
    def outer_area(self) -> float:
        """Outer (cylindrical) area of the nut assembly A_od [m²]."""
        return math.pi * (
            self.nuts * self.nut_diameter * self.nut_length
            + self.spacer_diameter * self.spacer_length
        )


MIN_RISE = 0.01
"""Smallest surface ΔT at which natural convection is evaluated [K] (Nu → 0.36 below)."""


def _coefficients(
    spec: ThermalSpec, surfaces: Surfaces, rise_screw: float, rise_nut: float
) -> tuple[Convection, tuple[ConvectionCoefficient, ...]]:
    """Coefficients of every surface with natural convection at the given rises (Q5–Q10)."""
    cs = spec.convection
    coefficients: list[ConvectionCoefficient] = []

    def air(rise: float) -> Air:
        film = spec.ambient_temperature + 0.5 * rise
        return Air(cs.air_kinematic_viscosity, cs.air_conductivity, cs.air_prandtl, film)

    def natural(diameter: float, rise: float) -> tuple[str, float]:
        dt = max(rise, MIN_RISE)
        how = ", iterated" if _iterated(spec) else ""
        label = f"Churchill–Chu natural, ΔT = {dt:.4g} K (Q6{how})"
        return label, horizontal_cylinder_natural(diameter, dt, air(dt))

    def pick(name: str, override: float | None, options: dict[str, float]) -> float:
        if override is not None:
            coefficients.append(ConvectionCoefficient(name, float(override), "override"))
            return float(override)
        label, value = max(options.items(), key=lambda kv: kv[1])
        coefficients.append(ConvectionCoefficient(name, value, label))
        return value

    d_s, w = surfaces.shaft_diameter, surfaces.speed
    h_screw = pick(
        "screw",
        cs.screw,
        {
            "Kreith rotating cylinder (Q5)": rotating_cylinder(d_s, w, air(rise_screw)),
            **dict([natural(d_s, rise_screw)]),
        },
    )
    h_screw_ends = pick("screw ends", cs.screw_ends, {"= screw": h_screw})
    nut_options = dict([natural(surfaces.nut_diameter, rise_nut)])
    if spec.stroke.length > 0 and surfaces.feed > 0:
        nut_options["laminar flat plate at the feed speed (Q6)"] = flat_plate_laminar(
            surfaces.ring_length, surfaces.feed, air(rise_nut)
        )
    h_nut = pick("nut", cs.nut, nut_options)
    h_nut_ends = pick("nut ends", cs.nut_ends, {"= nut": h_nut})
    h_extra = 0.0
    mounting = spec.mounting
    if mounting.kind == "table" and mounting.table_heat_capacity is None:
        area = surfaces.outer_area
        contact = mounting.contact_area
        contact = mounting.contact_fraction * area if contact is None else contact
        h_mount = mounting_coefficient(
            mounting.contact_conductance, contact, area, mounting.table_conductance
        )
        table = "at ambient" if mounting.table_area is None else "a sink to ambient"
        coefficients.append(
            ConvectionCoefficient(
                "nut mounting", h_mount, f"table joint h_c A_c in series with {table} (Q8)"
            )
        )
        h_extra += h_mount
    coolant = spec.coolant
    if coolant.nut_coefficient > 0 and coolant.nut_channel_area > 0:
        h_cool = coolant.nut_coefficient * coolant.nut_channel_area / surfaces.outer_area
        coefficients.append(
            ConvectionCoefficient("nut coolant", h_cool, "given h over the channel area (Q10)")
        )
        h_extra += h_cool
    bore = bore_coefficient(spec)
    if bore is not None:
        coefficients.append(ConvectionCoefficient("shaft bore coolant", *bore))
    return Convection(h_screw, h_screw_ends, h_nut + h_extra, h_nut_ends), tuple(coefficients)


def _iterated(spec: ThermalSpec) -> bool:
    cs = spec.convection
    return cs.natural == "iterated" and None in (cs.screw, cs.nut)


def _cooled(
    spec: ThermalSpec, surfaces: Surfaces, problem: ThermalProblem
) -> tuple[ThermalProblem, tuple[ConvectionCoefficient, ...]]:
    """``problem`` with its coefficients; natural convection at the computed surface rises.

    The fixed point runs on the network model (milliseconds; its surface rises agree with the
    FE models' to about 1 %), started from ``convection.temperature_difference``; the network
    is built once and every iteration re-binds its coefficients.
    """
    cs = spec.convection
    start = (cs.temperature_difference, cs.temperature_difference)
    if _iterated(spec):
        check_mesh(spec, problem, "network")
        probes = _nut_probes(problem)
        probed = replace(problem, sensors=probes)
        network = build_network(probed, spec.mesh.network_cell)

        def update(rises: tuple[float, ...]) -> tuple[float, float]:
            conv, _ = _coefficients(spec, surfaces, *rises)
            trial = replace(probed, convection=conv)
            disc = network.rebound(trial) or build_network(trial, spec.mesh.network_cell)
            return _surface_rises(simulate(disc, None), probes)

        start, _ = fixed_point(update, start, cs.tolerance, cs.max_iterations)
    conv, coefficients = _coefficients(spec, surfaces, *start)
    return replace(problem, convection=conv), coefficients


def _nut_probes(problem: ThermalProblem) -> tuple[Sensor, ...]:
    """A sensor on the outer surface at the centre of every part of the nut assembly."""
    z = problem.ring_centre - 0.5 * problem.ring_length
    probes = []
    for k, part in enumerate(problem.parts):
        probes.append(Sensor(f"od{k}", "nut", part.outer_radius, z + 0.5 * part.length))
        z += part.length
    return tuple(probes)


def _surface_rises(solution: Solution, probes: tuple[Sensor, ...]) -> tuple[float, float]:
    """(length-mean rise of the shaft, rise of the nut assembly's outer surface) [K].

    The nut's is the mean of the probes at the centre of each part, weighted by its outer area.
    """
    disc = solution.discretisation
    z, axis = disc.axis_z, solution.axis
    screw = float(np.trapezoid(axis, z) / (z[-1] - z[0])) if z.size > 1 else float(axis[0])
    weights = np.array([p.outer_radius * p.length for p in disc.problem.parts])
    nut = float(weights @ solution.sensors[: len(probes)] / weights.sum())
    return screw, nut


@contextmanager
def bearings_named_by_key(spec: ThermalSpec) -> Iterator[None]:
    """Re-raise an :class:`InputError` of the thermal package about a bearing band, which names
    it ``bearings.NAME.width``, under its case key ``thermal.bearings.K.width``."""
    try:
        yield
    except InputError as exc:
        names = [b.name for b in spec.bearings]
        match = re.fullmatch(r"bearings\.(.+)\.(\w+)", exc.field)
        if match is None or match[1] not in names:
            raise
        key = f"thermal.bearings.{names.index(match[1])}.{match[2]}"
        raise InputError(key, exc.value, exc.allowed) from None


def check_mesh(spec: ThermalSpec, problem: ThermalProblem, model: str) -> None:
    """Refuse (naming the mesh key) a mesh whose matrices would not fit the memory budget, and
    (naming the bearing) a bearing band narrower than an axial cell of the network or 2-D mesh.

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
    if model == "3d":  # its band loads refuse a band that holds no facet (bearing_loads)
        return
    cell = f"at least one axial cell of the {model} model's mesh ({value:g} m, {field})"
    for k, bearing in enumerate(spec.bearings):
        if not bearing.width >= value:  # a narrower band may hold no cell length or node
            raise InputError(f"thermal.bearings.{k}.width", bearing.width, cell)


def _parallel(resistances: list[float]) -> float:
    """1/Σ(1/R_i) [K/W]; one resistance is returned unchanged (bit for bit)."""
    return resistances[0] if len(resistances) == 1 else float(parallel_resistance(resistances))


def _body_flanks(body: int, nuts: int) -> tuple[int, ...]:
    """The loaded flanks (rows of the TCR chain) whose balls touch nut body ``body``: its own
    flank for a double nut, both flanks of a preloaded single nut (their paths in parallel)."""
    return (body,) if nuts == 2 else (1, 2)


def ball_patches(case: Case, problem: ThermalProblem, tcr: ScrewTCR | None = None) -> tuple:
    """:class:`~ballscrew.thermal.threed.BallPatches` of each part of ``problem`` (3-D model).

    Loaded balls and Hertz semi-axes of the screw contact from the TCR chain (a, along the
    rolling direction; b·cos β across the groove projected on the cylinder); with a given R″
    the balls per nut of the case and mesh-sized patches. Spacers: None. A preloaded single nut
    takes the balls of both flanks (a four-point ball once) and the patch of the more loaded
    flank 1.
    """
    from ballscrew.thermal.threed import BallPatches

    screw = case.screw
    params = ScrewParameters.from_case(case)
    beta = params.geometry.contact_angle
    by_index = {}
    if thermal_spec(case).contact.source == "tcr":
        tcr = tcr if tcr is not None else _cached_tcr(case)
        by_index = {n.index: n for n in tcr.nuts}
    out: list = []
    k = 0
    for part in problem.parts:
        if not part.balls:
            out.append(None)
            continue
        k += 1
        loaded = [by_index[i] for i in _body_flanks(k, screw.nuts) if i in by_index]
        if not loaded:
            out.append(BallPatches(screw.balls_per_nut, screw.lead))
            continue
        balls = loaded[0].balls if params.flanks.shared else sum(n.balls for n in loaded)
        h = loaded[0].screw.contact.hertz
        out.append(BallPatches(balls, screw.lead, (h.a, h.b * math.cos(beta))))
    return tuple(out)


def _solid(material: Any) -> Solid:
    return Solid(material.thermal_conductivity, material.density, material.specific_heat)
