"""The design check an engineer runs first: life, static safety, speed, buckling, stiffness.

case → :class:`ScrewParameters` and ``[design]`` → the load spectrum (the ``[[duty]]`` segments,
weighted by their revolutions, else the ``[operating]`` point; signed loads, F_a < 0 the reverse
direction on nut 2 / flank 2) → the makers' formulas of
:mod:`ballscrew.design` and the preloaded nut with Hertz contacts and elastic bodies
(:mod:`ballscrew.loads.distribution`) → values with margins.

The load ratings C_a and C_0a are the catalogue's when ``[design]`` gives them; otherwise they
are computed from the geometry (:mod:`ballscrew.design.ratings`) and the check says so in a
warning and in the report.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Collection
from dataclasses import dataclass, field
from functools import cached_property, partial
from types import ModuleType
from typing import ClassVar, Literal

import numpy as np
import xarray as xr

from ballscrew import design
from ballscrew.analyses import design_check_report
from ballscrew.analyses.ball_loads import elastic_distribution, elastic_lift_off
from ballscrew.analyses.duty import moving_fraction, operating_excess
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.case import Case
from ballscrew.case.design_spec import DesignSpec
from ballscrew.errors import InputError
from ballscrew.kinematics.limits import critical_speed, dn_value, groove_root_diameter
from ballscrew.loads import preload_drag_torque
from ballscrew.loads.distribution import LIFT_OFF_SEARCH, Distribution
from ballscrew.units import format_number, format_quantity, in_display_units
from ballscrew.validation import case_with

__all__ = [
    "AMBER_BAND",
    "BODY_SOFTENING_LIMIT",
    "DesignCheck",
    "DesignWarning",
    "LoadSpectrum",
    "Margin",
    "design_check",
    "design_scalars",
    "load_spectrum",
]

AMBER_BAND = 0.25
"""A margin is amber when the capacity exceeds the demand by less than this share."""

PRELOAD_SHARE = design.MAX_PRELOAD_SHARE
"""Largest preload / C_a by nut count (HIWIN §3.6.2; THK A-687: 0.1 C_a)."""

DRAG_TORQUE_BAND = 0.30
"""± share of the real preload torque about the formula [ASSUMED: the makers' tolerance of the
preload torque (THK A-689) depends on the torque, the accuracy grade and the thread length;
±30 % is a middle value of that table]."""

BODY_SOFTENING_LIMIT = 0.5
"""GUESS: the nut stiffness with the elastic bodies below this share of the Hertz contacts'
alone is warned about as implausible (the bodies soften a nut by tens of per cent)."""

_HINTS = {
    "lift_off": (
        "above it the second {part} carries no load and the nut runs with backlash; a preload "
        "of at least the largest load / 2^1.5 keeps both {part}s loaded"
    ),
    "pretension": (
        "the shaft pretensioned for the temperature rise would be loaded above its permissible "
        "tension; a smaller temperature rise (cooling) or a larger shaft is needed"
    ),
}
"""What a red margin means, added to its warning ({part}: nut or flank)."""

_ASSUMED_DUTY = (
    "the [[duty]] is listed in [assumed]: an illustrative cycle, not sized to this screw"
    "{required}; write the machine's duty before reading this margin"
)
"""Added to a red life margin's warning when the duty is an assumed one."""

Status = Literal["green", "amber", "red"]


class DesignWarning(UserWarning):
    """A design value outside the makers' limits."""


@dataclass(frozen=True)
class Margin:
    """One design value against its allowed value."""

    name: str
    label: str
    demand: float
    """What the case asks for (load, speed, preload, required life), SI."""
    capacity: float
    """What the screw allows, SI."""
    unit: str

    @property
    def ratio(self) -> float:
        """capacity / demand (inf without demand)."""
        return math.inf if self.demand == 0.0 else self.capacity / self.demand

    @property
    def status(self) -> Status:
        """green: ≥ (1 + AMBER_BAND) × the demand; amber: ≥ the demand; red: below it."""
        if self.ratio >= 1.0 + AMBER_BAND:
            return "green"
        return "amber" if self.ratio >= 1.0 else "red"


@dataclass(frozen=True)
class LoadSpectrum:
    """Axial load levels and the revolutions share of each (sum 1)."""

    loads: tuple[float, ...]
    """Axial load F_a of each level [N], signed: ≥ 0 loads nut 1 (flank 1), < 0 nut 2."""
    shares: tuple[float, ...]
    """Share of the screw revolutions at each level [-]."""
    mean_speed: float
    """Time-mean screw speed over the cycle [rad/s] (0: no running time known)."""
    max_speed: float
    """Highest screw speed [rad/s]."""
    source: str
    """'duty' or 'operating'."""

    @property
    def max_load(self) -> float:
        """Largest |F_a| of the spectrum, either direction [N]."""
        return max(abs(f) for f in self.loads)


@dataclass(frozen=True)
class DesignCheck(Presented):
    """Design values of the screw with their margins (SI)."""

    case: Case
    spectrum: LoadSpectrum
    flanks: int
    """Loaded flanks: 2 for a preloaded nut (spacer, oversized balls, offset lead), 1 for a
    single nut without preload."""
    dynamic_load_rating: float | None
    """C_a [N] (catalogue, else computed from the geometry × f_H f_ac)."""
    static_load_rating: float | None
    """C_0a [N] (catalogue, else computed from the geometry × f_H f_ac)."""
    equivalent_loads: tuple[float, float]
    """Cube-mean equivalent loads F_bm of flank 1 and 2 [N] (without preload flank 2 carries
    the reverse loads alone: 0 for a one-direction spectrum)."""
    rating_life: float | None
    """L10 (× a₁) in revolutions [-]; None without C_a."""
    life_hours: float | None
    """Rating life in hours of the cycle [h]; None without C_a or without running time."""
    life_travel: float | None
    """Rating life as travel [m]."""
    static_safety_factor: float | None
    """f_s = C_0a / |F_a|,max [-] (the largest load of either direction); None without C_0a."""
    root_diameter: float
    """d_r [m]."""
    critical_speed: float
    """First whirling speed of the shaft, Euler beam [rad/s] (the makers allow 0.8×)."""
    buckling_load: float
    """Euler buckling load of the shaft [N] (the makers allow 0.5×)."""
    permissible_tension: float
    """σ_perm A of the shaft [N]."""
    dn: float
    """d·n at the highest speed [mm·rpm]."""
    compliance: float
    """Hertz compliance C, δ = C F^(2/3) per loaded flank (nut half) [m N^(-2/3)]."""
    contact_stiffness: float
    """Hertz contacts only (rigid bodies) of the preloaded nut at the case's loads [N/m]."""
    nut_stiffness: float
    """Preloaded nut at the case's preload and axial load: Hertz contacts of every ball with
    the elastic shaft under the nut and nut body (``[loads]``) [N/m]."""
    catalogue_nut_stiffness: float | None
    """0.8 K (F_p/0.1 C_a)^(1/3) from the catalogue rigidity [N/m]; None without it."""
    shaft_stiffness: float
    """Shaft between the fixed bearing and the nut [N/m]."""
    axial_stiffness: float
    """The nut (``nut_stiffness``) in series with the shaft, the supports rigid [N/m]."""
    drive_stiffness: float | None
    """``axial_stiffness`` with the support bearings in series [N/m]; None without
    ``[design] bearing_stiffness``."""
    preload_drag_torque: float
    """Catalogue preload drag torque [N·m]."""
    nut_radial_force: float | None
    """|F_r| of the balls' net radial force on a guided nut under the largest |F_a| of the
    spectrum, which its housing takes [N] (``loads.nut_support = "guided"``; else None)."""
    nut_tilting_moment: float | None
    """|M| of the balls' net tilting moment about the guided nut's centre, same load [N·m]."""
    nut_radial_displacement: float | None
    """|u| of a free nut's radial displacement relative to the screw at its centre under the
    largest |F_a| [m] (``loads.nut_support = "free"``; else None)."""
    nut_tilt: float | None
    """|γ| of a free nut's tilt relative to the screw, same load [rad]."""
    lost_motion: float
    """Lost motion at a reversal of the largest |F_a| = F of the spectrum,
    2 (x_nut(F) + F/K_shaft [+ F/K_bearings]) [m]: x_nut the nut's displacement under F with
    contacts and bodies; a nut without preload adds its axial play (not an input)."""
    thermal_elongation: float | None
    """Free elongation of the unsupported length at the temperature rise [m]."""
    thermal_pretension: float | None
    """Pretension E A α ΔT that takes it up [N]."""
    margins: tuple[Margin, ...]
    warnings: tuple[str, ...] = ()
    computed_ratings: tuple[str, ...] = ()
    """Names of the load ratings computed from the geometry (not given in ``[design]``)."""
    largest_distribution: Distribution | None = field(default=None, repr=False, compare=False)
    """Elastic load of every ball (contacts and bodies) under the spectrum's largest |F_a|, the
    nut values above come from (None: no loaded ball)."""
    unloaded_distribution: Distribution | None = field(default=None, repr=False, compare=False)
    """The same under F_a = 0: the preloaded nut, whose spacer interference the stiffness curve
    keeps (None without preload)."""

    analysis: ClassVar[str] = "check"
    presentation: ClassVar[ModuleType] = design_check_report

    @property
    def title(self) -> str:
        return f"Design check: {self.case.name}"

    @property
    def spec(self) -> DesignSpec:
        """The case's ``[design]`` section."""
        return self.case.design  # type: ignore[return-value]

    @property
    def part(self) -> str:
        """What a loaded flank is called: :func:`loaded_part` of the case."""
        return loaded_part(self.case)

    @cached_property
    def stiffness_curve(self) -> xr.Dataset:
        """:func:`design_check_report.stiffness_curve` of the result, built once: the data file
        and the stiffness figure both read it (its body curve is 40+ elastic solves)."""
        return design_check_report.stiffness_curve(self)

    @property
    def preload_drag_torque_min(self) -> float:
        """Lower end of the makers' band of the preload torque, (1 − DRAG_TORQUE_BAND) T [N·m]."""
        return (1.0 - DRAG_TORQUE_BAND) * self.preload_drag_torque

    @property
    def preload_drag_torque_max(self) -> float:
        """Upper end of the band, (1 + DRAG_TORQUE_BAND) T [N·m]."""
        return (1.0 + DRAG_TORQUE_BAND) * self.preload_drag_torque


def loaded_part(case: Case) -> str:
    """'nut' for the loaded flanks of a double nut (its two nuts), 'flank' for a single nut's."""
    return "flank" if case.screw.nuts == 1 else "nut"


def load_spectrum(case: Case) -> LoadSpectrum:
    """Load levels weighted by revolutions: the ``[[duty]]`` segments, else ``[operating]``."""
    op = case.operating
    if not case.duty:
        speed = op.speed
        return LoadSpectrum((op.axial_load,), (1.0,), speed, speed, "operating")
    lead = case.screw.lead
    revs, loads, time = [], [], 0.0
    for seg in case.duty:
        fraction = moving_fraction(seg.speed, lead, seg.stroke, seg.dwell)
        revs.append(fraction * seg.speed * seg.duration)
        loads.append(seg.axial_load)
        time += seg.duration
    total = sum(revs)
    if not total > 0.0:
        raise InputError(
            "duty", "no segment turns the screw", "one [[duty]] segment with speed > 0"
        )
    return LoadSpectrum(
        tuple(loads),
        tuple(r / total for r in revs),
        total / time,
        max(seg.speed for seg in case.duty),
        "duty",
    )


def _equivalent_loads(spectrum: LoadSpectrum, preload: float, flanks: int) -> tuple[float, float]:
    """Cube-mean load of each loaded flank over the spectrum (a double nut's two nuts, or the
    two flanks of a single nut preloaded by oversized balls or an offset lead).

    Preloaded: each level's half loads (F_b1, F_b2) of |F_a| (HIWIN F 3.5–3.7), a reverse
    level (F_a < 0) with the halves swapped (nut 2 the loaded one). Without preload the
    forward levels load flank 1 and the reverse levels flank 2, each counting as zero on the
    other flank (THK A-706: one cube mean per direction)."""
    loads = np.asarray(spectrum.loads)
    if flanks != 2:
        return design.cube_mean_loads(loads, spectrum.shares)
    loaded, other = design.preloaded_half_loads(np.abs(loads), preload)
    reverse = loads < 0.0
    halves = (np.where(reverse, other, loaded), np.where(reverse, loaded, other))
    return tuple(design.cube_mean_loads(h, spectrum.shares)[0] for h in halves)  # type: ignore[return-value]


def rating_factor(case: Case, params: ScrewParameters) -> float:
    """f_H f_ac: hardness factor of the softer of screw and nut raceway times the accuracy factor
    of ``[design] accuracy_grade`` (NBS catalogue, :mod:`ballscrew.design.rating_factors`)."""
    raceway = min(params.material(side).hardness for side in ("screw", "nut"))
    grade = case.design.accuracy_grade if case.design else 5
    return design.hardness_factor(raceway) * design.accuracy_factor(grade)


def load_ratings(case: Case, params: ScrewParameters) -> tuple[float, float, tuple[str, ...]]:
    """(C_a, C_0a, names of those computed): ``[design]``'s values, else from the geometry
    times :func:`rating_factor` (C_0a by ``[design] static_rating_model``).

    A maker's ratings are taken as printed (they hold for the hardness and class of his product).
    """
    spec = case.design
    given = (spec.dynamic_load_rating, spec.static_load_rating) if spec else (None, None)
    balls = params.flanks.balls
    factor = rating_factor(case, params) if None in given else 1.0
    ca = given[0] or factor * design.dynamic_load_rating(params.geometry, balls)
    c0a = given[1] or factor * design.static_load_rating(
        params.geometry,
        balls,
        (params.contact_modulus("screw"), params.contact_modulus("nut")),
        model=spec.static_rating_model if spec else "iso76",
    )
    names = ("dynamic_load_rating", "static_load_rating")
    return ca, c0a, tuple(n for n, g in zip(names, given, strict=True) if g is None)


def _life(ca: float, spec: DesignSpec, equivalent: tuple[float, float]) -> float:
    lives = [
        float(design.rating_life(ca, f, spec.load_factor, spec.reliability))
        for f in equivalent
        if f > 0.0
    ]
    return design.combined_life(lives) if lives else math.inf


def _margins(check: dict, spec: DesignSpec, case: Case) -> tuple[Margin, ...]:
    s = check["spectrum"]
    f_max = s.max_load
    out = [
        Margin(
            "speed",
            "speed vs 0.8 × critical speed",
            s.max_speed,
            design.SPEED_SAFETY * check["critical_speed"],
            "rad/s",
        ),
        Margin("dn", "d·n vs its limit", check["dn"], spec.dn_limit, "mm·rpm"),
        Margin(
            "buckling",
            "axial load vs 0.5 × buckling load",
            f_max,
            design.BUCKLING_SAFETY * check["buckling_load"],
            "N",
        ),
        Margin(
            "tension",
            "axial load vs permissible tension/compression",
            f_max,
            check["permissible_tension"],
            "N",
        ),
    ]
    if check["flanks"] == 2:
        out.append(
            Margin(
                "lift_off",
                "max axial load vs lift-off load 2^1.5 F_p",
                f_max,
                design.LIFT_OFF_FACTOR * case.operating.preload,
                "N",
            )
        )
    pretension = check["thermal_pretension"]
    if pretension is not None and spec.mounting == "fixed-fixed":
        out.append(
            Margin(
                "pretension",
                "pretension + axial load vs permissible tension",
                pretension + f_max,
                check["permissible_tension"],
                "N",
            )
        )
    if check["static_safety_factor"] is not None:
        out.append(
            Margin(
                "static_safety",
                "f_s vs its minimum",
                spec.min_static_safety,
                check["static_safety_factor"],
                "",
            )
        )
    if check["dynamic_load_rating"] is not None:
        share = spec.max_preload_share or PRELOAD_SHARE[case.screw.nuts]
        out.append(
            Margin(
                "preload",
                f"preload vs its largest share of C_a ({share:.0%})",
                case.operating.preload,
                share * check["dynamic_load_rating"],
                "N",
            )
        )
        if spec.required_life is not None and check["life_hours"] is not None:
            out.append(
                Margin(
                    "life",
                    "required life vs rating life",
                    spec.required_life / 3600.0,
                    check["life_hours"],
                    "h",
                )
            )
    return tuple(out)


def _elastic_nut(
    params: ScrewParameters, case: Case, root: float, largest: float
) -> tuple[float, float, Distribution | None, Distribution | None]:
    """(stiffness at the case's axial load, travel x(F) − x(0) under the largest load F, the
    distributions under F and under F_a = 0) of the nut with contacts and bodies [N/m, m]. A
    preloaded nut keeps the spacer interference of F_a = 0 (one solve, shared); without preload
    x(0) = 0, the unloaded contacts (no distribution under F_a = 0)."""
    run = partial(elastic_distribution, params, case.loads, root, numerics=case.numerics)
    solved: dict[float, Distribution] = {}
    interference = None
    if params.preload > 0.0:
        solved[0.0] = run(axial_load=0.0)
        interference = solved[0.0].interference

    def at(load: float) -> Distribution:
        if load not in solved:
            solved[load] = run(axial_load=load, interference=interference)
        return solved[load]

    stiffness = at(params.axial_load).stiffness
    if largest == 0.0:
        return stiffness, 0.0, solved.get(0.0), solved.get(0.0)
    rest = solved[0.0].displacement if 0.0 in solved else 0.0
    return stiffness, at(largest).displacement - rest, at(largest), solved.get(0.0)


def _nut_rigid_body(dist: Distribution | None, support: str) -> dict[str, float | None]:
    """|F_r| [N] and |M| [N·m] of the balls on a guided nut (what its housing takes), or a free
    nut's radial displacement |u| [m] and tilt |γ| [rad], from ``dist``; None where they do not
    apply (the other support, no loaded ball)."""
    names = ("nut_radial_force", "nut_tilting_moment", "nut_radial_displacement", "nut_tilt")
    if dist is None:
        return dict.fromkeys(names)
    resultant = dist.resultant
    pairs = (resultant[1:3], resultant[3:], dist.radial_displacement, dist.tilt)
    shown = (support == "guided",) * 2 + (support == "free",) * 2
    return {
        name: float(np.hypot(*pair)) if used else None
        for name, pair, used in zip(names, pairs, shown, strict=True)
    }


def _warn(
    margins: tuple[Margin, ...],
    values: dict,
    computed: tuple[str, ...],
    spec: DesignSpec,
    part: str,
    assumed: Collection[str] = (),
) -> None:
    """Warn of the computed ratings, every red margin (with what it means; a red life on an
    ``assumed`` duty says so) and nut bodies much softer than the contacts."""
    methods = {
        "dynamic_load_rating": "Lundberg-Palmgren",
        "static_load_rating": design.STATIC_RATING_MODELS.entry(
            spec.static_rating_model
        ).description,
    }
    for name in computed:
        warnings.warn(
            f"design.{name} not given: {values[name] * 1e-3:.4g} kN computed from the geometry "
            f"({methods[name]}); give the maker's value when known",
            DesignWarning,
            stacklevel=3,
        )
    for m in margins:
        if m.status == "red":
            shown, unit = in_display_units((m.demand, m.capacity), m.unit)
            demand, capacity = (f"{format_number(v)} {unit}".rstrip() for v in shown)
            hint = f"; {_HINTS[m.name].format(part=part)}" if m.name in _HINTS else ""
            if m.name == "life" and "duty" in assumed:
                required = ", and the required life is assumed too"
                hint += "; " + _ASSUMED_DUTY.format(
                    required=required if "design.required_life" in assumed else ""
                )
            warnings.warn(
                f"{m.label}: {demand} against {capacity}{hint}",
                DesignWarning,
                stacklevel=3,
            )
    nut_k, contact_k = values["nut_stiffness"], values["contact_stiffness"]
    if nut_k < BODY_SOFTENING_LIMIT * contact_k:
        warnings.warn(
            f"nut stiffness with the elastic bodies {format_quantity(nut_k, 'N/m')} is below "
            f"{BODY_SOFTENING_LIMIT:.0%} of the Hertz contacts' alone "
            f"{format_quantity(contact_k, 'N/m')}; check [loads] (nut_outer_diameter, "
            "lead_error, ball_diameter_error) and design.root_diameter",
            DesignWarning,
            stacklevel=3,
        )


def _warn_external_loads(case: Case, loaded: Distribution | None) -> None:
    """Warn that the makers' life and static safety leave out a free nut's external radial
    force and tilting moment, which its ball loads (``loaded``, the largest |F_a|) balance."""
    spec = case.loads
    if loaded is None or not (spec.nut_radial_load or spec.nut_tilting_moment):
        return
    warnings.warn(
        "loads.nut_radial_load and nut_tilting_moment load the free nut's balls (largest ball "
        f"load {float(loaded.loads.max()):.4g} N under the largest axial load), but the rating "
        "life and static safety are the makers' formulas of the axial load alone",
        DesignWarning,
        stacklevel=3,
    )


def _warn_lift_off(case: Case, params: ScrewParameters, root: float) -> None:
    """Warn that the lift-off margin's 2^1.5 F_p leaves out the case's lead and ball-diameter
    errors and a free nut's external radial load and moment, naming the lift-off of the
    distribution with them, the contacts and the bodies (:func:`elastic_lift_off`)."""
    spec = case.loads
    keys = ("lead_error", "ball_diameter_error", "nut_radial_load", "nut_tilting_moment")
    given = [f"loads.{key}" for key in keys if getattr(spec, key)]
    if params.flanks.count != 2 or not given:
        return
    lift = elastic_lift_off(params, spec, root, case.numerics)
    part = loaded_part(case)
    at = (
        f"none below {format_quantity(LIFT_OFF_SEARCH * params.preload, 'N')}"
        if math.isinf(lift)
        else f"at {format_quantity(lift, 'N')}"
    )
    rigid = format_quantity(design.LIFT_OFF_FACTOR * params.preload, "N")
    warnings.warn(
        f"the lift-off margin's 2^1.5 F_p = {rigid} is that of a rigid nut without "
        f"{', '.join(given)}; with them, the contacts and the bodies the last ball of the "
        f"second {part} lifts off {at}",
        DesignWarning,
        stacklevel=3,
    )


def _warn_operating_outside_duty(case: Case, spectrum: LoadSpectrum) -> None:
    """Warn when ``[operating]`` runs harder than every ``[[duty]]`` segment: the life and the
    margins take the duty's loads and speeds, so that point (a ``--set operating.…`` too) is
    not checked; only the contact stiffness is taken at ``[operating] axial_load``."""
    if spectrum.source != "duty":
        return
    over = operating_excess(case, spectrum.max_load, spectrum.max_speed, "duty")
    if over:
        warnings.warn(
            f"[operating] {' and '.join(over)}: the life, static safety, speed, lift-off and "
            "lost-motion values take the [[duty]] loads and speeds, not this point; add it to "
            "[[duty]] to check it",
            DesignWarning,
            stacklevel=3,
        )


def design_check(case: Case) -> DesignCheck:
    """Every design value of the case's screw with its margin (needs ``[design]``)."""
    spec = case_with(case, "screw", "operating", "design").design  # type: ignore[attr-defined]
    if spec is None:
        raise InputError("design", None, "a [design] section (at least unsupported_length)")
    params = ScrewParameters.from_case(case)
    geometry, screw = params.geometry, params.screw
    spectrum = load_spectrum(case)
    preload, flanks = case.operating.preload, params.flanks.count
    root = spec.root_diameter or groove_root_diameter(geometry)
    length = spec.unsupported_length
    equivalent = _equivalent_loads(spectrum, preload, flanks)
    ca, c0a, computed = load_ratings(case, params)
    life = _life(ca, spec, equivalent)
    running = math.isfinite(life) and spectrum.mean_speed > 0.0
    compliance = params.nut_compliance
    contact_k = design.nut_stiffness(case.operating.axial_load, preload, compliance, flanks)
    f_max = spectrum.max_load
    with recorded_warnings() as distribution_messages:
        nut_k, travel, loaded, unloaded = _elastic_nut(params, case, root, f_max)
    shaft_k = design.shaft_axial_stiffness(
        root, length, screw.youngs_modulus, spec.mounting, spec.nut_distance
    )
    axial_k = design.series_stiffness(nut_k, shaft_k)
    catalogue_k = None
    if spec.catalogue_rigidity is not None and preload:
        catalogue_k = design.catalogue_nut_rigidity(spec.catalogue_rigidity, preload, 0.1 * ca)
    rise = spec.temperature_rise
    values = {
        "spectrum": spectrum,
        "flanks": flanks,
        "dynamic_load_rating": ca,
        "static_load_rating": c0a,
        "equivalent_loads": equivalent,
        "rating_life": life,
        "life_hours": design.life_hours(life, spectrum.mean_speed) if running else None,
        "life_travel": design.life_travel(life, geometry.lead),
        "static_safety_factor": design.static_safety_factor(c0a, f_max),
        "root_diameter": root,
        "critical_speed": critical_speed(
            root, length, screw.youngs_modulus, screw.density, spec.mounting
        ),
        "buckling_load": design.buckling_load(root, length, screw.youngs_modulus, spec.mounting),
        "permissible_tension": design.permissible_tension(root),
        "dn": dn_value(geometry.pitch_diameter, spectrum.max_speed),
        "compliance": compliance,
        "contact_stiffness": contact_k,
        "nut_stiffness": nut_k,
        "catalogue_nut_stiffness": catalogue_k,
        "shaft_stiffness": shaft_k,
        "axial_stiffness": axial_k,
        "drive_stiffness": None
        if spec.bearing_stiffness is None
        else design.series_stiffness(axial_k, spec.bearing_stiffness),
        "preload_drag_torque": preload_drag_torque(preload, geometry.lead, geometry.lead_angle),
        "lost_motion": design.lost_motion(
            travel, f_max, shaft_k, *filter(None, (spec.bearing_stiffness,))
        ),
        **_nut_rigid_body(loaded, case.loads.nut_support),
        "thermal_elongation": None
        if rise is None
        else design.thermal_elongation(length, screw.thermal_expansion, rise),
        "thermal_pretension": None
        if rise is None
        else design.thermal_pretension(root, screw.youngs_modulus, screw.thermal_expansion, rise),
    }
    margins = _margins(values, spec, case)
    with recorded_warnings() as messages:
        assumed = case.assumed if case.duty else ()
        _warn(margins, values, computed, spec, loaded_part(case), assumed)
        _warn_external_loads(case, loaded)
        _warn_lift_off(case, params, root)
        _warn_operating_outside_duty(case, spectrum)
    return DesignCheck(
        case=case,
        margins=margins,
        warnings=tuple(dict.fromkeys((*distribution_messages, *messages))),
        computed_ratings=computed,
        largest_distribution=loaded,
        unloaded_distribution=unloaded,
        **values,
    )


def design_scalars(case: Case) -> dict[str, tuple[float, str]]:
    """Sweepable scalars of :func:`design_check` (those the case defines), with units."""
    result = design_check(case)
    names = {
        "rating_life": "",
        "life_hours": "h",
        "static_safety_factor": "",
        "critical_speed": "rad/s",
        "buckling_load": "N",
        "axial_stiffness": "N/m",
        "nut_stiffness": "N/m",
        "contact_stiffness": "N/m",
        "preload_drag_torque": "N*m",
        "lost_motion": "m",
    }
    return {
        name: (float(getattr(result, name)), unit)
        for name, unit in names.items()
        if getattr(result, name) is not None
    }
