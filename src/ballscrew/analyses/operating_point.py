"""The coupled operating point of the screw: temperature ↔ viscosity ↔ film ↔ friction ↔ heat.

The friction torque of the nut depends on the lubricant's viscosity, the viscosity on the
temperature of the contacts, and the temperature on the friction heat. The steady operating
point is the fixed point of

    T_c → η(T_c), α_p(T_c) → friction torque M(η) → heat M·ω − F_a·v → steady field → T_c,

with T_c the mean of the nut and screw temperatures at the nut, solved by fixed-point
iteration (a secant step on the residual from the second iteration, damped whenever the residual
does not shrink) to a residual of 0.01 K, or as soon as
the heat at the new T_c equals the heat just solved (a friction model that does not see the
viscosity) (theory manual, *Operating point*). A case without a named lubricant keeps its
``[medium]`` viscosity at every temperature.

:func:`coupled_heat` hands the operating point's heat to :func:`~ballscrew.analyses.thermal.
thermal_field`; :func:`at_operating_point` gives the case with its lubricant at the operating
temperature, for the TCR and kinematics analyses of a case with ``[operating] coupled = true``.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from types import ModuleType
from typing import Any, ClassVar, NamedTuple

import numpy as np
from numpy.typing import NDArray

from ballscrew.analyses import operating_point_report
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.kinematics import ball_model, speed_limit_messages
from ballscrew.analyses.parameters import SIDES, ScrewParameters, library_entry
from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.analyses.thermal import HeatCoupling, ThermalField, solve_field
from ballscrew.case import Case, with_overrides
from ballscrew.errors import ConvergenceError, InputError
from ballscrew.friction.torque import FrictionTorque
from ballscrew.kinematics.motion import entrainment_speed
from ballscrew.loads import preload_drag_torque
from ballscrew.lubrication import BOUNDARY_FILM_PARAMETER, film_parameter
from ballscrew.lubrication.lubricant_library import LibraryLubricant
from ballscrew.thermal.discretisation import Discretisation, nut_mean_row
from ballscrew.validation import case_with

__all__ = [
    "OperatingPoint",
    "OperatingPointWarning",
    "SpeedCurve",
    "at_operating_point",
    "contact_readout",
    "coupled_heat",
    "heat_overrides",
    "medium_law",
    "operating_point",
    "operating_point_scalars",
    "speed_curve",
]

FloatArray = NDArray[np.float64]

TOLERANCE = 0.01
"""Change of the contact temperature [K] at which the fixed point is reached."""
MAX_ITERATIONS = 60
MIN_SECANT_SLOPE = 0.25
"""Smallest |r′| of the secant step on the residual r(T_c) = T(T_c) − T_c [-]: a step is at most
4 × the plain one."""
NUT_WARNING_TEMPERATURE = 333.15
"""Nut temperature above which the result warns [K] (60 °C; nuts on machine axes run 5–30 K
above ambient)."""


class OperatingPointWarning(UserWarning):
    """The operating point is outside what the screw or the models are made for."""


@dataclass(frozen=True)
class SpeedCurve:
    """The coupled operating point over a range of speeds at one axial load (SI arrays, one
    entry per speed; NaN where a quantity is undefined)."""

    speed: FloatArray
    """Screw speeds ω [rad/s], rising."""
    axial_load: float
    """F_a [N]."""
    friction_torque: FloatArray
    """Screw torque T, the work on the load included [N·m]."""
    friction_part: FloatArray
    """Friction torque T_f = heat/ω [N·m]."""
    heat: FloatArray
    """Friction heat [W]."""
    efficiency_overall: FloatArray
    """F_a L/(2π T) [-]."""
    nut_temperature: FloatArray
    """Mean nut temperature [K]."""
    screw_temperature: FloatArray
    """Mean screw temperature under the nut [K]."""
    viscosity: FloatArray
    """Lubricant viscosity at the contact temperature [Pa s]."""
    film_thickness: FloatArray
    """Central film h_c at the screw contact A [m]."""
    warnings: tuple[tuple[str, ...], ...]
    """The warnings of each point (speed limits, a hot nut, thin film, ...)."""


@dataclass(frozen=True)
class OperatingPoint(Presented):
    """The steady operating point of the screw at one speed and load (SI)."""

    case: Case
    speed: float
    """Screw speed ω [rad/s]."""
    axial_load: float
    """Axial load F_a [N]."""
    friction: FrictionTorque
    """The friction model's torque at the fixed point: its parts, heat, film parameter Λ and
    traction coefficient."""
    nut_temperature: float
    """Mean temperature of the nut assembly at steady state [K]: its volume mean on the FE
    models, the mean of its cells on the network."""
    screw_temperature: float
    """Mean temperature of the screw shaft under the nut [K]."""
    viscosity: float
    """Dynamic viscosity of the lubricant at the contact temperature [Pa s]."""
    film_thickness: float
    """Central EHL film thickness h_c at the screw contact A of a ball of the loaded nut (nut 1)
    at its whole ball load [m] (NaN when dry or at rest); the name is kept for compatibility."""
    iterations: int
    field: ThermalField
    warnings: tuple[str, ...] = ()
    film_thickness_minimum: float = math.nan
    """Minimum EHL film thickness h_min at the same contact A [m] (NaN when dry or at rest)."""
    film_thickness_nut: float = math.nan
    """Central EHL film thickness h_c at the nut contact B of the same ball [m]."""
    film_roughness: float = math.nan
    """Composite RMS roughness σ_Λ of the screw raceway for Λ = h_c/σ_Λ (E6.6) [m]."""
    viscosity_source: str = ""
    """Where :attr:`viscosity` comes from: the named lubricant's law at the contact temperature
    or the fixed ``medium.viscosity``."""
    film_thickness_per_nut: tuple[float, ...] = ()
    """Central film h_c at the screw contact A of each nut (each loaded flank of a preloaded
    single nut) at its own ball load, nut 1 first [m] (NaN lifted off, dry or at rest)."""
    curve: SpeedCurve | None = None
    """The operating point over a range of speeds at the same load (:func:`speed_curve`; the
    command line adds it), or None."""

    analysis: ClassVar[str] = "operating-point"
    presentation: ClassVar[ModuleType] = operating_point_report

    @property
    def film_parameter(self) -> float:
        """Film parameter Λ = h_c/σ_Λ (E6.6) at the screw contact A: :attr:`film_thickness` (the
        central film of the whole ball load) over :attr:`film_roughness`, whatever the friction
        model; NaN when dry or at rest. The ball model's traction reads its asperity share
        ψ(Λ) on the same σ_Λ (``friction.asperity_share``)."""
        return film_parameter(self.film_thickness, self.film_roughness)

    @property
    def friction_torque(self) -> float:
        """Screw torque T = T_f + F_a·L/2π of the nut(s) [N·m]: the friction torque T_f
        (:attr:`friction_part`) plus the work on the load; the name is kept for compatibility."""
        return self.friction.total

    @property
    def friction_part(self) -> float:
        """Friction torque T_f = heat/ω of the nut(s), without the work on the load [N·m]."""
        return self.friction.friction

    @property
    def heat(self) -> float:
        """Friction heat of the nut(s) [W]."""
        return self.friction.heat

    @property
    def heat_to_screw(self) -> float:
        """Part of the heat that goes into the screw shaft [W]."""
        return self.friction.heat_to_screw

    @property
    def efficiency(self) -> float:
        """Driving efficiency of the screw η = tan λ/tan(λ + ρ′) (makers' formula, the
        ``[friction] rolling_friction`` μ) [-]."""
        return self.friction.efficiency_driving

    @property
    def efficiency_backdriving(self) -> float:
        """Back-driving efficiency η′ = tan(λ − ρ′)/tan λ (load turning the screw; ≤ 0:
        self-locking) [-]."""
        return self.friction.efficiency_backdriving

    @property
    def efficiency_overall(self) -> float:
        """Efficiency of the nut at this operating point, work on the load over work in,
        F_a L/(2π T) [-]: the preload, seals and ball losses included; 0 without load, NaN at
        rest."""
        total = self.friction_torque
        return self.friction.parts["work"] / total if self.speed > 0.0 and total > 0.0 else math.nan

    @property
    def catalogue_preload_torque(self) -> float:
        """The makers' preload torque K F_p L/2π of the case (E9.1) [N·m]: the reference of a
        physics friction model's torque at the preload (warned outside 0.5–2 ×)."""
        return _catalogue_torque(self.case)

    @property
    def preload_torque(self) -> float:
        """The friction model's torque at the preload [N·m]: its parts without the work on the
        load, the working load's friction and the seals (the part the band compares)."""
        return sum(v for k, v in self.friction.parts.items() if k not in _NOT_PRELOAD)

    @property
    def max_temperature(self) -> float:
        """Largest temperature of the steady field [K] (at the balls, above the nut's mean)."""
        return self.field.max_temperature

    @property
    def contact_temperature(self) -> float:
        """Mean of the nut and screw temperatures [K]."""
        return 0.5 * (self.nut_temperature + self.screw_temperature)

    @property
    def title(self) -> str:
        return f"Operating point: {self.case.name}"


def _library_lubricant(case: Case) -> LibraryLubricant | None:
    """The case's lubricant whose laws against temperature apply (None: the constant
    ``[medium]`` values, which a given ``[medium] viscosity`` selects)."""
    return library_entry(case) if case.medium.viscosity is None else None


def medium_law(case: Case) -> Callable[[float], tuple[float | None, float | None, float]]:
    """T → (η, α_p, λ_f) of the case's lubricant: the library's laws of a named lubricant when
    ``[medium] viscosity`` is not given, else the constant ``[medium]`` values."""
    entry = _library_lubricant(case)
    if entry is not None:

        def law(temperature: float) -> tuple[float | None, float | None, float]:
            state = entry.at(temperature)
            return state.viscosity, state.pressure_viscosity, state.conductivity

        return law
    lub = ScrewParameters.from_case(case).lubrication
    constant = (lub.viscosity, lub.pressure_viscosity, lub.thermal_conductivity)
    return lambda _: constant


def _viscosity_law(case: Case) -> Callable[[float], tuple[float | None, float | None]]:
    """T → (η, α_p) of the case's lubricant (:func:`medium_law`)."""
    law = medium_law(case)
    return lambda temperature: law(temperature)[:2]


def viscosity_source(case: Case) -> tuple[str, str | None]:
    """(where the operating point's viscosity comes from, a warning or None): the fixed
    ``medium.viscosity`` wins over a named lubricant, which is then used for nothing else."""
    medium = case.medium
    named = medium.lubricant or case.kinematics.lubricant
    if medium.viscosity is None:
        if _library_lubricant(case) is None:
            return "no lubricant data", None
        return (
            f"lubricant {named or 'of [medium] viscosity_40/100'}, at the contact temperature",
            None,
        )
    given = "medium.viscosity, fixed at every temperature"
    if named is None and medium.viscosity_40 is None:
        return given, None
    key = "medium.viscosity_40/100" if named is None else f"lubricant = {named!r}"
    return given, (
        f"medium.viscosity = {medium.viscosity:g} Pa s is given beside {key}: it wins and stays "
        "fixed at every temperature; leave medium.viscosity out to follow the lubricant's "
        "viscosity against temperature"
    )


def _warnings(
    case: Case, omega: float, nut: float, friction: FrictionTorque, lam: float
) -> list[str]:
    """What the user must know about an operating point (``lam``: Λ at A, NaN when dry)."""
    out = speed_limit_messages(case, omega) if omega > 0.0 else []
    if nut > NUT_WARNING_TEMPERATURE:
        out.append(
            f"the nut runs at {nut - 273.15:.0f} °C, above "
            f"{NUT_WARNING_TEMPERATURE - 273.15:.0f} °C: check its cooling and mounting"
        )
    if lam < BOUNDARY_FILM_PARAMETER:
        out.append(
            f"film parameter Λ = h_c/σ = {lam:.3g} < {BOUNDARY_FILM_PARAMETER:g} at the screw "
            "contact: boundary lubrication, outside the range of the EHL film and traction models"
        )
    note = viscosity_source(case)[1]
    if note is not None:
        out.append(note)
    if friction.model != "catalogue" and omega > 0.0:
        catalogue = _catalogue_torque(case)
        preload_part = sum(v for k, v in friction.parts.items() if k not in _NOT_PRELOAD)
        if catalogue > 0.0 and not 0.5 * catalogue <= preload_part <= 2.0 * catalogue:
            out.append(
                f"the {friction.model} torque at the preload (without the work on the load, "
                f"its friction and the seals), {preload_part:.3g} N·m, is outside 0.5–2 × the "
                f"catalogue preload torque {catalogue:.3g} N·m"
            )
    return out


def _catalogue_torque(case: Case) -> float:
    """K F_p L/2π of ``case`` (E9.1) [N·m]."""
    params = ScrewParameters.from_case(case)
    g = params.geometry
    return preload_drag_torque(params.preload, g.lead, g.lead_angle)


#: Torque parts outside the band of the makers' preload torque K F_p L/2π: the work on the load,
#: the friction of the working load (the efficiency's) and the seals (a part of their own here).
_NOT_PRELOAD = frozenset({"work", "load", "seals"})


def heat_overrides(heat: float, to_screw: float, omega: float) -> dict[str, Any]:
    """Case overrides that feed ``heat`` [W] (``to_screw`` of it into the screw) at ``omega``
    [rad/s] to the thermal model: a given torque heat/ω and the screw share."""
    return {
        "thermal.drag_torque.source": "operating_point",
        "thermal.drag_torque.torque": heat / omega if omega > 0.0 else 0.0,
        "thermal.screw_heat_fraction": to_screw / heat if heat > 0.0 else 0.5,
    }


def contact_readout(disc: Discretisation) -> tuple[FloatArray, Callable[[FloatArray], float]]:
    """(row r, nut) with the screw's mean rise under the nut = r·θ and the nut's rise nut(θ).

    The nut's is the mean over the nut assembly: of its cells' mean rises (network model) or
    its volume mean (1/V)∫θ dV (FE models); the screw's the cross-section mean of the shaft
    averaged over the nut's length.
    """
    problem = disc.problem
    distance = np.abs(disc.axis_z - problem.ring_centre)
    under = np.nonzero(distance <= 0.5 * problem.ring_length)[0]
    rows = under if under.size else np.array([int(np.argmin(distance))])
    screw = np.asarray(disc.axis[rows].mean(axis=0)).ravel()
    nut = nut_mean_row(disc)
    return screw, lambda theta: float(nut @ theta)


def _nut_and_screw(field: ThermalField) -> tuple[float, float]:
    """Steady mean temperatures of the nut assembly and of the shaft under it [K]."""
    screw, nut = contact_readout(field.solution.discretisation)
    steady = field.solution.steady
    amb = field.ambient_temperature
    return amb + nut(steady), amb + float(screw @ steady)


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
    op = case_with(case, "screw", "operating").operating  # type: ignore[attr-defined]
    given = {
        "operating.speed": op.speed if speed is None else speed,
        "operating.axial_load": op.axial_load if axial_load is None else axial_load,
    }
    base = with_overrides(case, {**given, "operating.coupled": False})
    omega, load = base.operating.speed, base.operating.axial_load
    law = _viscosity_law(base)
    ambient = base.thermal.ambient_temperature if base.thermal is not None else 293.15
    contact = ambient if start_temperature is None else float(start_temperature)
    relaxation, residual, iterations = 1.0, math.inf, 0
    disc: Discretisation | None = None  # meshed and assembled once, re-bound to every heat
    last: tuple[float, float] | None = None  # (T_c, residual) of the previous field

    def friction_at(temperature: float) -> FrictionTorque:
        return friction_torque(base, viscosity=law(temperature)[0])

    friction = friction_at(contact)
    with recorded_warnings() as messages:
        while True:
            if iterations == MAX_ITERATIONS:
                raise ConvergenceError("coupled operating point", iterations, residual, TOLERANCE)
            iterations += 1
            overrides = heat_overrides(friction.heat, friction.heat_to_screw, omega)
            field = solve_field(
                with_overrides(base, overrides),
                model,
                transient=False,
                reuse=disc,
                thermoelastic=False,
            )
            disc = field.solution.discretisation
            nut, screw = _nut_and_screw(field)
            new = 0.5 * (nut + screw) - contact  # the fixed point's residual T(T_c) − T_c
            if abs(new) <= TOLERANCE:
                break
            if abs(new) >= residual:  # not contracting: damp the update
                relaxation *= 0.5
            residual = abs(new)
            step = relaxation * new
            if relaxation == 1.0 and last is not None:  # secant on r(T_c) = T(T_c) − T_c
                slope = (new - last[1]) / (contact - last[0])
                if slope < 0.0:
                    step = new / max(-slope, MIN_SECANT_SLOPE)
            last = (contact, new)
            trial = friction_at(contact + step)
            if relaxation == 1.0 and _same_heat(trial, friction):  # T(T_c) is the fixed point
                contact += new
                break
            contact += step
            friction = trial
        eta, alpha = law(contact)
        films = _films(base, omega, eta, alpha)
        lam = film_parameter(films.central, films.roughness)
        for text in _warnings(base, omega, nut, friction, lam):
            warnings.warn(text, OperatingPointWarning, stacklevel=2)
    return OperatingPoint(
        case=base,
        speed=omega,
        axial_load=load,
        friction=friction,
        nut_temperature=nut,
        screw_temperature=screw,
        viscosity=math.nan if eta is None else eta,
        film_thickness=films.central,
        iterations=iterations,
        field=field,
        warnings=tuple(messages),
        film_thickness_minimum=films.minimum,
        film_thickness_nut=films.nut,
        film_roughness=films.roughness,
        film_thickness_per_nut=films.per_nut,
        viscosity_source=viscosity_source(base)[0],
    )


class _Films(NamedTuple):
    """The films of a ball of the loaded nut at its whole ball load [m] (NaN dry or at rest)."""

    central: float
    """h_c at the screw contact A."""
    minimum: float
    """h_min at A."""
    nut: float
    """h_c at the nut contact B."""
    roughness: float
    """σ_Λ of the film parameter (E6.6)."""
    per_nut: tuple[float, ...]
    """h_c at A of each nut (flank) at its own ball load."""


def _films(case: Case, omega: float, eta: float | None, alpha: float | None) -> _Films:
    """:class:`_Films` at the Level-0 motion and the lubricant (η, α_p)."""
    params = ScrewParameters.from_case(case)
    balls = ball_model(case)
    if eta is not None:
        balls = dataclasses.replace(balls, viscosity=eta, pressure_viscosity=alpha)
    load = params.loaded_nut.ball_load
    speed = {s: entrainment_speed(params.geometry, omega, balls.entrainment, s) for s in SIDES}
    a, b = (balls.film(load, speed[side], side) for side in SIDES)
    nan = math.nan
    per_nut = []
    for nut in params.flank_loads:  # one or two nuts (flanks)
        film = balls.film(nut.ball_load, speed["screw"], "screw") if nut.loaded else None
        per_nut.append(film.central if film is not None else nan)
    return _Films(
        central=a.central if a is not None else nan,
        minimum=a.minimum if a is not None else nan,
        nut=b.central if b is not None else nan,
        roughness=balls.surface.film_roughness,
        per_nut=tuple(per_nut),
    )


def _same_heat(a: FrictionTorque, b: FrictionTorque) -> bool:
    """Equal heat and screw share (to rounding): the field just solved is the fixed point."""
    return math.isclose(a.heat, b.heat, rel_tol=1e-12, abs_tol=1e-12) and math.isclose(
        a.heat_to_screw, b.heat_to_screw, rel_tol=1e-12, abs_tol=1e-12
    )


def coupled_heat(case: Case, model: str) -> tuple[Case, HeatCoupling, ThermalField]:
    """The case with the balls' heat of its coupled operating point, that point and its steady
    field on ``model``.

    The fixed point is solved on the network model (milliseconds) and, for the FE models,
    continued on ``model`` from the network's contact temperature (one FE solve when the heat
    does not depend on the viscosity, a few otherwise).
    """
    point = operating_point(case, model="network")
    if model != "network":
        point = operating_point(case, model=model, start_temperature=point.contact_temperature)
    overrides = heat_overrides(point.heat, point.heat_to_screw, point.speed)
    resolved = with_overrides(case, {**overrides, "operating.coupled": False})
    coupling = HeatCoupling(
        friction_model=case.friction.model,
        friction_torque=point.friction_torque,
        heat=point.heat,
        heat_to_screw=point.heat_to_screw,
        contact_temperature=point.contact_temperature,
        viscosity=point.viscosity,
        iterations=point.iterations,
    )
    return resolved, coupling, point.field


def at_operating_point(case: Case, speed: float | None = None) -> tuple[Case, OperatingPoint]:
    """``case`` with its lubricant at the contact temperature T_c of its coupled operating point
    at ``speed`` [rad/s] (None: the case's), and that point (network model).

    A named library lubricant gets η(T_c), α_p(T_c) and λ_f(T_c) into ``[medium]``; constant
    ``[medium]`` values stay as they are.
    """
    point = operating_point(case, speed)
    overrides: dict[str, Any] = {"operating.coupled": False}
    if _library_lubricant(case) is not None:
        _, alpha, conductivity = medium_law(case)(point.contact_temperature)
        overrides |= {
            "medium.viscosity": point.viscosity,
            "medium.pressure_viscosity": alpha,
            "medium.thermal_conductivity": conductivity,
        }
    return with_overrides(case, overrides), point


#: Quantities of a :class:`SpeedCurve`, read from each :class:`OperatingPoint`.
CURVE_QUANTITIES = (
    "friction_torque",
    "friction_part",
    "heat",
    "efficiency_overall",
    "nut_temperature",
    "screw_temperature",
    "viscosity",
    "film_thickness",
)


def speed_curve(
    case: Case, speeds: FloatArray | list[float], axial_load: float | None = None
) -> SpeedCurve:
    """The coupled steady operating point of ``case`` (network model) at each of ``speeds``
    [rad/s, each > 0] and ``axial_load`` [N] (None: the case's): torque, heat, efficiency,
    temperatures, viscosity and film against speed. The warnings of each point are kept with
    it, not raised."""
    omega = np.sort(np.asarray(speeds, dtype=float).ravel())
    if omega.size == 0 or not np.all(np.isfinite(omega)) or omega[0] <= 0.0:
        raise InputError("speeds", speeds, "one or more finite speeds > 0 rad/s")
    points = []
    for w in omega:  # one coupled fixed point per speed: each is its own iteration
        with warnings.catch_warnings():  # each point keeps its warnings (p.warnings), and
            warnings.simplefilter("ignore")  # the case's own speed is warned about once
            points.append(operating_point(case, float(w), axial_load))
    values = {k: np.array([getattr(p, k) for p in points]) for k in CURVE_QUANTITIES}
    return SpeedCurve(
        speed=omega,
        axial_load=points[0].axial_load,
        warnings=tuple(p.warnings for p in points),
        **values,
    )


def operating_point_scalars(case: Case) -> dict[str, tuple[float, str]]:
    """Sweepable scalars of :func:`operating_point` (curves against speed or load)."""
    point = operating_point(case)
    return {
        "friction_torque": (point.friction_torque, "N*m"),
        "friction_part": (point.friction_part, "N*m"),
        "heat": (point.heat, "W"),
        "efficiency": (point.efficiency, ""),
        "nut_temperature": (point.nut_temperature, "K"),
        "screw_temperature": (point.screw_temperature, "K"),
        "viscosity": (point.viscosity, "Pa*s"),
        "film_thickness": (point.film_thickness, "m"),
    }
