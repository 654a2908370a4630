"""The kinematics analysis of one case: ball state, drag torques, contact fields and curves.

Composes :mod:`ballscrew.kinematics`, the contact solver and :mod:`ballscrew.lubrication`
(theory manual: *Kinematics*, *Lubrication*). The Python API other code relies on:

* :func:`ball_kinematics` ``(case, speed=None, level=None)`` → :class:`BallState` with
  ``ball_speed``, ``orbital_speed``, ``spin_screw``, ``spin_nut``, ``load_screw``, ``load_nut``,
  ``angle_screw``, ``angle_nut``; ``None`` takes the case's speed and ``[kinematics] level``;
* :func:`drag_torque` ``(case, preload=None)`` → catalogue preload drag torque, N m;
* :func:`computed_drag_torque` ``(case, speed=None)`` → drag torque of the ball model, N m, at
  the case's balance level; the heat it makes is T·ω_s (used by the thermal model);
* :func:`run_kinematics` ``(case, speed=None, level=None)`` → everything the ``ballscrew
  kinematics`` results folder shows.

Inputs are checked before any work: speed < 0, an unknown level, level 2 without lubricant data
are :class:`~ballscrew.errors.InputError`; a speed above the whirling or d·n limit is a
:class:`~ballscrew.kinematics.limits.SpeedLimitWarning`.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass, replace
from types import ModuleType
from typing import Any, ClassVar

import numpy as np
from numpy.typing import NDArray

from ballscrew.analyses import kinematics_report
from ballscrew.analyses.ball_contact import solve_raceway_contact
from ballscrew.analyses.parameters import (
    ScrewParameters,
    film_model,
    library_entry,
    lubricant_state,
)
from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.analyses.roughness import roughness_input
from ballscrew.case import Case
from ballscrew.case.base import MAX_SPEED
from ballscrew.case.plausibility import speed_hint
from ballscrew.errors import InputError
from ballscrew.fractal.yan_komvopoulos import surface_dimension
from ballscrew.kinematics.balance import LEVELS, BallState, solve_ball
from ballscrew.kinematics.limits import (
    SpeedLimitWarning,
    critical_speed,
    dn_value,
    groove_root_diameter,
)
from ballscrew.kinematics.model import BallModel
from ballscrew.kinematics.sliding import SlidingField, sliding_field, sliding_field_closed_form
from ballscrew.kinematics.torque import BallDrag, ball_drag
from ballscrew.loads import preload_drag_torque
from ballscrew.lubrication import (
    AsperitySurface,
    FilmThickness,
    LoadSharing,
    asperity_pressure,
    film_parameter,
)
from ballscrew.units import format_quantity, to_si
from ballscrew.validation import case_with, positive

__all__ = [
    "ContactFields",
    "KinematicsRun",
    "SpeedSweep",
    "ball_kinematics",
    "ball_model",
    "check_speed_limits",
    "computed_drag_torque",
    "contact_fields",
    "curve_speeds",
    "drag_torque",
    "nut_loads",
    "prepare",
    "run_kinematics",
    "speed_limit_messages",
    "speed_sweep",
    "whirl_shaft",
]

FloatArray = NDArray[np.float64]


_SPEED_RANGE = f"a screw speed in [0, {MAX_SPEED:g}] rad/s (the range of operating.speed)"


def _speed(case: Case, speed: float | str | None) -> float:
    case_with(case, "screw", "operating", "materials")
    value = case.operating.speed if speed is None else speed
    try:  # a number is rad/s; a string may carry its unit ("1500 rpm"), as operating_point's
        omega = to_si(value, "angular_velocity")
    except ValueError as exc:
        raise InputError("speed", value, f"{exc}; {_SPEED_RANGE}") from None
    if not (math.isfinite(omega) and 0.0 <= omega <= MAX_SPEED):
        raise InputError("speed", value, _SPEED_RANGE)
    return omega


def at_operating_temperature(case: Case, speed: float | None = None) -> Case:
    """``case`` with ``[operating] coupled = true``: its lubricant at the temperature of the
    coupled operating point at ``speed`` [rad/s]; any other case as it is."""
    if not case.operating.coupled:
        return case
    # imported here: the operating point uses the ball model of this module
    from ballscrew.analyses.operating_point import at_operating_point

    return at_operating_point(case, speed)[0]


def film_viscosity_source(case: Case) -> str:
    """Where the viscosity of the kinematics' film and traction comes from (``case`` as given,
    before :func:`at_operating_temperature`), in words."""
    if case.medium.viscosity is not None:
        return "medium.viscosity, fixed at every temperature"
    entry = library_entry(case)
    if entry is None:
        return "no lubricant data: dry contacts"
    name = case.medium.lubricant or case.kinematics.lubricant or "of [medium] viscosity_40/100"
    if case.operating.coupled:
        return f"lubricant {name}, at the contact temperature of the coupled operating point"
    return (
        f"lubricant {name}, at [lubrication] temperature = "
        f"{case.lubrication.temperature - 273.15:.4g} °C, not at the contact temperature that "
        "the operating point computes (set [operating] coupled = true for it)"
    )


def _level(case: Case, level: int | None) -> int:
    value = case.kinematics.level if level is None else level
    if isinstance(value, bool) or value not in LEVELS:
        raise InputError("level", value, "0 (static), 1 (centrifugal + groove) or 2 (full)")
    return int(value)


def prepare(
    case: Case,
    speeds: float | FloatArray | list[float],
    level: int | None,
    warn_at: float | None = None,
) -> tuple[BallModel, int]:
    """Validate speeds and level, warn about the speed limits of ``warn_at`` [rad/s] (default
    the largest speed), and build the ball model.

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
        check_speed_limits(case, max(values) if warn_at is None else warn_at, stacklevel=4)
    return model, lvl


def nut_loads(case: Case, preload: float | None = None) -> list[tuple[int, float, int]]:
    """(nut number, axial force, flank) of each loaded flank, from :class:`ScrewParameters`.

    Nut 1 carries F_1 on flank s = +1 and nut 2 carries F_2 on s = −1. A single nut preloaded
    on both flanks (P1) gives both: F_1 on s = +1 as number 1 and F_2 on s = −1 as number 2 (the
    two contact pairs of a four-point ball, or the two halves of an offset-lead nut, each with
    ``params.flanks.balls`` balls); without preload its one flank, F_a on s = +1. ``preload``
    overrides the case's.
    """
    return [(n.index, n.force, n.flank) for n in _loaded(case, preload).flank_loads]


def _loaded(case: Case, preload: float | None) -> ScrewParameters:
    """The case's parameters at ``preload`` [N] (None: the case's), checked."""
    fp = case.operating.preload if preload is None else float(preload)
    if not (math.isfinite(fp) and fp >= 0.0):
        raise InputError("preload", preload, "a force >= 0 N")
    if case.screw.nuts == 2 and fp <= 0.0:
        raise InputError("preload", fp, "a preload > 0 N for a double nut")
    return ScrewParameters.from_case(case).with_loads(preload=fp)


def ball_kinematics(
    case: Case, speed: float | str | None = None, level: int | None = None, *, nut: int = 1
) -> BallState:
    """Kinematics and loads of a ball of ``nut`` (1 = loaded nut) at screw speed ``speed``.

    ``speed`` [rad/s, or a string with its unit such as "1500 rpm"] defaults to
    ``operating.speed``; ``level`` 0, 1 or 2 defaults to the case's ``[kinematics] level``. The
    result has ``ball_speed`` (m/s, ball centre relative to the nut), ``orbital_speed``
    (rad/s), ``spin_screw`` / ``spin_nut`` (rad/s, relative spin about the contact normals Z_A,
    Z_B pointing into the ball), ``load_screw`` / ``load_nut`` (N) and ``angle_screw`` /
    ``angle_nut`` (rad). With ``[operating] coupled = true`` the lubricant is that of the
    coupled operating point at ``speed``.
    """
    omega = _speed(case, speed)
    case = at_operating_temperature(case, omega)
    model, lvl = prepare(case, omega, level)
    loads = {number: (force, flank) for number, force, flank in nut_loads(case)}
    if nut not in loads:
        raise InputError("nut", nut, f"one of {sorted(loads)} for this screw")
    force, flank = loads[nut]
    return solve_ball(model, omega, force, flank, lvl)


def drag_torque(case: Case, preload: float | None = None) -> float:
    """Catalogue preload drag torque T_p = K F_p L/(2π), K = 0.05/√tanλ, N m.

    ``preload`` [N] defaults to the case's. The 40 × 10 reference screw at F_p = 1500 N:
    0.4231 N m.
    """
    case_with(case, "screw", "operating")
    fp = case.operating.preload if preload is None else preload
    geometry = ScrewParameters.from_case(case).geometry
    return preload_drag_torque(fp, geometry.lead, geometry.lead_angle)


def _model_torque(
    model: BallModel, case: Case, omega: float, level: int, preload: float | None = None
) -> float:
    params = _loaded(case, preload)
    if preload is not None:  # a single nut's flanks (and balls per flank) follow the preload
        model = replace(model, balls=params.flanks.balls)
    states = [
        solve_ball(model, omega, n.force, n.flank, level) for n in params.flank_loads if n.force > 0
    ]
    return _flanks_torque(model, states)


def _flanks_torque(model: BallModel, states: list[BallState]) -> float:
    """Ball-model drag torque Σ Z T_d of the loaded flanks' ball ``states`` [N m]."""
    return sum((model.balls * ball_drag(model, state).dissipation_torque for state in states), 0.0)


def computed_drag_torque(
    case: Case,
    speed: float | str | None = None,
    *,
    level: int | None = None,
    preload: float | None = None,
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


def curve_speeds(case: Case) -> FloatArray:
    """Speeds of the curves vs speed: ``[kinematics] speed_range`` or 0 … max(case, d·n limit)."""
    spec = case.kinematics
    if spec.speed_range is not None:
        low, high = spec.speed_range
    else:
        geometry = ScrewParameters.from_case(case).geometry
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
    separation: FloatArray
    """Mean-plane separation h at A under the JGP share, h_c of the film-borne load (E6.2) [m]
    (NaN without lubricant)."""
    model_torque: FloatArray
    """Ball-model drag torque (all nuts) [N m]."""
    catalogue_torque: float
    """E9.1 at the case's preload [N m]."""


def speed_sweep(
    case: Case, speeds: FloatArray | None = None, level: int | None = None
) -> SpeedSweep:
    """Ball of nut 1 and the drag torque at each speed (default :func:`curve_speeds`)."""
    omegas = curve_speeds(case) if speeds is None else np.asarray(speeds, dtype=float)
    model, lvl = prepare(case, omegas, level)
    (_, force, flank), *others = nut_loads(case)
    rows = []
    for omega in omegas:  # one quasi-static solve per speed and loaded flank
        state = solve_ball(model, float(omega), force, flank, lvl)
        loaded = [state] if force > 0.0 else []
        loaded += [solve_ball(model, float(omega), f, s, lvl) for _, f, s in others if f > 0.0]
        sharing = state.sharing or model.sharing(
            state.load_screw, model.entrainment_speed(state.motion)
        )
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
                _flanks_torque(model, loaded),  # the ball-model torque of all nuts
            )
        )
    cols = np.array(rows, dtype=float).T
    return SpeedSweep(omegas, lvl, *cols, catalogue_torque=drag_torque(case))


def ball_model(case: Case, viscosity: float | None = None) -> BallModel:
    """The :class:`BallModel` of a validated case, the one of every analysis that solves balls.

    ``[kinematics]`` gives the surface, μ_b, Λ_L and the traction grid; ``[friction]`` the
    traction law (``friction.traction``) and, when set, μ_b (``friction.boundary_friction``); a
    named lubricant its density at ``[lubrication] temperature`` (870 kg/m³ without one). A
    given ``viscosity`` [Pa s] (a caller's contact temperature) replaces η and, for a named
    lubricant without ``[medium]`` viscosity, also sets α_p, the density and the film's inlet
    heating at the temperature where the lubricant has that viscosity.
    """
    params = ScrewParameters.from_case(case)
    spec = case.kinematics
    e_star = params.contact_modulus("screw")
    surface = AsperitySurface(
        Ds=surface_dimension(params.D),
        G=params.G_surface,
        e_star=e_star,
        hardness=params.screw.hardness,
        cell_area=spec.micro_contact_size**2,
        roughness=roughness_input(case),
    )
    state = lubricant_state(case, viscosity)
    model = BallModel(
        geometry=params.geometry,
        balls=params.flanks.balls,
        ball_density=params.ball.density,
        e_star_screw=e_star,
        e_star_nut=params.contact_modulus("nut"),
        surface=surface,
        viscosity=params.lubrication.viscosity,
        pressure_viscosity=params.lubrication.pressure_viscosity,
        film_model=params.lubrication.film_model,
        boundary_friction=(
            spec.boundary_friction
            if case.friction.boundary_friction is None
            else case.friction.boundary_friction
        ),
        limiting_shear=spec.limiting_shear,
        traction_cells=spec.traction_cells,
        traction_law=case.friction.traction,
        entrainment=spec.entrainment,
    )
    changes: dict[str, object] = {}
    if state is not None:
        changes["lubricant_density"] = state.density
    if viscosity is not None:
        changes["viscosity"] = positive("viscosity", viscosity, "Pa s")
        if state is not None and case.medium.viscosity is None:
            if case.medium.pressure_viscosity is None:
                changes["pressure_viscosity"] = state.pressure_viscosity
            changes["film_model"] = film_model(case, state)
    return dataclasses.replace(model, **changes)


def speed_limit_messages(case: Case, speed: float) -> list[str]:
    """Why ``speed`` [rad/s] is too high for the case's screw (empty when it is not)."""
    spec = case.kinematics
    params = ScrewParameters.from_case(case)
    geometry = params.geometry
    messages = []
    dn = dn_value(geometry.pitch_diameter, speed)
    if dn > spec.dn_limit:
        messages.append(
            f"speed {format_quantity(speed, 'rad/s')} gives d·n = {dn:.0f} mm·rpm above the limit "
            f"{spec.dn_limit:.0f} ([kinematics] dn_limit)"
            + speed_hint(speed, geometry.pitch_diameter)
        )
    shaft = whirl_shaft(case)
    if shaft is not None:
        length, mounting, root = shaft
        root = root or groove_root_diameter(geometry)
        material = params.screw
        allowed = spec.critical_speed_factor * critical_speed(
            root, length, material.youngs_modulus, material.density, mounting
        )
        if speed > allowed:
            messages.append(
                f"speed {format_quantity(speed, 'rad/s')} exceeds "
                f"{spec.critical_speed_factor:g} × the whirling speed of the screw shaft = "
                f"{format_quantity(allowed, 'rad/s')} ({mounting}, "
                f"l = {format_quantity(length, 'm')}, "
                f"d_r = {format_quantity(root, 'm')})"
            )
    return messages


def curve_limit_messages(case: Case, speed: float, curve: FloatArray) -> list[str]:
    """The speed limits that the curves versus speed pass and the case ``speed`` [rad/s] does
    not (one line, said of the curves; empty when none): their top is the d·n limit's speed
    or ``[kinematics] speed_range``, not a speed the screw runs at."""
    top = float(np.max(curve))
    if top <= speed:
        return []

    def kind(message: str) -> str:
        return "whirling" if "whirling" in message else "d·n"

    passed = {kind(m) for m in speed_limit_messages(case, speed)}
    beyond = [m for m in speed_limit_messages(case, top) if kind(m) not in passed]
    if not beyond:
        return []
    return [
        f"the curves versus speed run to {format_quantity(top, 'rad/s')}, above the case speed "
        f"{format_quantity(speed, 'rad/s')}: " + "; ".join(beyond)
    ]


def whirl_shaft(case: Case) -> tuple[float, str, float | None] | None:
    """(unsupported length [m], mounting, root diameter [m] or None = groove bottom) of the
    whirling check; None when neither ``[kinematics]`` nor ``[design]`` gives the length.

    Each of ``unsupported_length``, ``mounting`` and ``root_diameter`` is taken from
    ``[kinematics]`` where the case gives it there, else from ``[design]`` (which ``ballscrew
    init`` writes), else the ``[kinematics]`` default.
    """
    spec, design = case.kinematics, case.design
    given = spec.model_fields_set

    def pick(name: str) -> Any:
        if name in given or design is None:
            return getattr(spec, name)
        value = getattr(design, name)
        return getattr(spec, name) if value is None else value

    length = pick("unsupported_length")
    if length is None:
        return None
    return length, pick("mounting"), pick("root_diameter")


def check_speed_limits(case: Case, speed: float, *, stacklevel: int = 3) -> list[str]:
    """Warn (:class:`SpeedLimitWarning`) for each speed limit ``speed`` exceeds; return them.

    Silent when ``[kinematics] speed_warnings = false``.
    """
    messages = speed_limit_messages(case, speed)
    if case.kinematics.speed_warnings:
        for message in messages:
            warnings.warn(message, SpeedLimitWarning, stacklevel=stacklevel)
    return messages


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


def contact_fields(case: Case, model: BallModel, state: BallState) -> ContactFields:
    """Pressure, sliding and asperity pressure at A for ``state`` (one contact solve)."""
    geometry = dataclasses.replace(model.geometry, contact_angle=state.angle_screw)
    contact = solve_raceway_contact(
        geometry, "screw", state.load_screw, model.e_star_screw, case.numerics, flank=state.flank
    )
    x, y = np.asarray(contact.x), np.asarray(contact.y)
    sliding = sliding_field(state.motion, x, y, radius=model.deformed_radius("screw"))
    closed = sliding_field_closed_form(
        model.geometry, state.screw_speed, x, y, state.flank, curvature=True
    )
    sharing = state.sharing or model.sharing(
        state.load_screw, model.entrainment_speed(state.motion)
    )
    pressure = np.asarray(contact.solution.pressure)
    return ContactFields(
        state, contact, sliding, closed, sharing, asperity_pressure(pressure, sharing.psi)
    )


@dataclass(frozen=True)
class KinematicsRun(Presented):
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
    """Ball contacts' losses T_c at the case speed and load [N m]: sliding at A and EHL rolling
    resistance at A and B over ω_s (:func:`computed_drag_torque`); without the ball–ball
    friction, viscous drag, hysteresis, seals and returns that ``friction.model =
    "ball_model"`` adds (the name is kept for compatibility)."""
    lubricated: bool
    case: Case
    """The case that was solved."""
    warnings: tuple[str, ...] = ()
    """Speed-limit messages and warnings raised while solving (one line each)."""
    films: tuple[FilmThickness | None, FilmThickness | None] = (None, None)
    """Hamrock–Dowson films at A and B of nut 1 at their whole ball loads, the films of the
    film parameter Λ = h_c/σ_Λ (None dry or at rest); ``fields.sharing`` holds A's JGP share
    and separation."""
    entrainment: tuple[float, float] = (0.0, 0.0)
    """Entrainment speeds u_e at A and B of nut 1 at the case speed (E2.8) [m/s]."""
    roughness: float = math.nan
    """Composite RMS roughness σ_Λ of the screw raceway (E6.6) [m]: the σ of the film parameter
    and of the asperity heights of the JGP share."""
    viscosity: float = math.nan
    """Dynamic viscosity η₀ of the films and the traction [Pa s] (NaN dry)."""
    viscosity_source: str = ""
    """Where η₀ comes from (:func:`film_viscosity_source`)."""

    analysis: ClassVar[str] = "kinematics"
    presentation: ClassVar[ModuleType] = kinematics_report

    @property
    def film_parameter(self) -> float:
        """Λ = h_c/σ_Λ (E6.6) at A of nut 1 at its whole ball load (NaN dry or at rest)."""
        film = self.films[0]
        return math.nan if film is None else film_parameter(film.central, self.roughness)

    @property
    def title(self) -> str:
        return f"Ball kinematics, balance, lubrication and drag torque: {self.case.name}"


def _no_load(case: Case) -> Any:
    return case.model_copy(
        update={"operating": case.operating.model_copy(update={"axial_load": 0.0})}
    )


def run_kinematics(
    case: Case, speed: float | str | None = None, level: int | None = None
) -> KinematicsRun:
    """Run the analysis (all checks first, see :func:`prepare`)."""
    omega = _speed(case, speed)  # a number [rad/s] or a string with its unit, as ball_kinematics
    source = film_viscosity_source(case)
    case = at_operating_temperature(case, omega)
    speeds = curve_speeds(case)
    with recorded_warnings() as raised:
        model, lvl = prepare(case, np.append(speeds, omega), level, warn_at=omega)
        messages = speed_limit_messages(case, omega)
        for message in curve_limit_messages(case, omega, speeds):
            messages.append(message)
            if case.kinematics.speed_warnings:
                warnings.warn(message, SpeedLimitWarning, stacklevel=2)
        with warnings.catch_warnings():
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
    first = states[1]
    entrainment = (
        model.entrainment_speed(first.motion, "screw"),
        model.entrainment_speed(first.motion, "nut"),
    )
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
        case=case,
        warnings=tuple(dict.fromkeys(messages + raised)),
        films=(
            model.film(first.load_screw, entrainment[0], "screw"),
            model.film(first.load_nut, entrainment[1], "nut"),
        ),
        entrainment=entrainment,
        roughness=model.surface.film_roughness,
        viscosity=math.nan if model.viscosity is None else model.viscosity,
        viscosity_source=source,
    )
