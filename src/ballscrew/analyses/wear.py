"""The wear life of a case: wear profile, preload and drag torque over the load programme.

Composes :mod:`ballscrew.wear` (time integration, wear laws, strips), the contact solver and
the lubrication model for the ``[wear]`` section of a case (theory manual: *Wear*).
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import warnings
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any, ClassVar

import numpy as np

from ballscrew.analyses import wear_report
from ballscrew.analyses.ball_loads import ball_contact_law, elastic_distribution
from ballscrew.analyses.duty import operating_excess
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.analyses.roughness import (
    ball_roughness,
    measurement_band,
    roughness_input,
    surface_roughness,
)
from ballscrew.analyses.wear_duty import duty_programme, warn_outside_range
from ballscrew.analyses.wear_film import PartFilm, part_films, warn_full_film
from ballscrew.budget import check_memory, contact_grid_bytes
from ballscrew.case import Case
from ballscrew.case.wear_spec import WearSpec
from ballscrew.contact import cell_centres, hertz
from ballscrew.errors import InputError
from ballscrew.fractal.yan_komvopoulos import surface_dimension
from ballscrew.geometry import gap_function, raceway_curvature
from ballscrew.loads import ball_load, preload_drag_torque
from ballscrew.lubrication import AsperitySurface
from ballscrew.validation import case_with
from ballscrew.wear.history import WearLife
from ballscrew.wear.life import check_wear_work, integrate_wear
from ballscrew.wear.load_classes import LoadClasses, load_classes
from ballscrew.wear.programme import RunningIn, WearLevel, WearOptions
from ballscrew.wear.setup import FLANKS, FilmRoughness, WearSetup, nut_force_pair
from ballscrew.wear.strips import working_raceway_length

__all__ = [
    "OperatingOutsideWarning",
    "WearResult",
    "fingerprint",
    "wear_life",
    "wear_options",
    "wear_setup",
]


class OperatingOutsideWarning(UserWarning):
    """``[operating]`` runs harder than every level of the wear programme, which the run
    follows instead."""


@dataclass(frozen=True)
class WearResult(Presented):
    """The wear life of a case: its :class:`~ballscrew.wear.WearLife` history (every attribute
    of which it answers too: ``revolutions``, ``preload``, ``torque_samples``, …) with the case."""

    case: Case
    life: WearLife
    warnings: tuple[str, ...] = ()
    """Warnings raised during the run (one line each)."""
    films: tuple[PartFilm, ...] = ()
    """Film parameter Λ and asperity share ψ of each programme part the run reached, at the start
    of its level (the wear engine's own, :func:`~ballscrew.analyses.wear_film.part_films`)."""

    analysis: ClassVar[str] = "wear"
    presentation: ClassVar[ModuleType] = wear_report
    dataset_name: ClassVar[str] = "history"

    def __getattr__(self, name: str) -> Any:
        life = vars(self).get("life")
        if life is None or name.startswith("__"):
            raise AttributeError(name)
        return getattr(life, name)

    @property
    def title(self) -> str:
        return f"Wear life: {self.case.name}"


def wear_options(case: Case) -> WearOptions:
    """The ``[wear]`` section of ``case`` (its defaults when absent) as plain SI values."""
    spec = case.wear if case.wear is not None else WearSpec()
    programme = _programme(case, spec)
    running = spec.running_in
    return WearOptions(
        model=spec.model,
        coefficient=spec.wear_coefficient,
        stroke=spec.stroke,
        max_depth_step=spec.max_depth_step,
        torque_sampling=spec.torque_sampling,
        torque_scale=spec.torque_scale,
        initial_torque=spec.initial_torque,
        programme=programme,
        grid=tuple(spec.grid),
        box_factor=spec.box_factor,
        checkpoint_every=spec.checkpoint_every,
        film_factor=spec.film_factor,
        running_in=(
            None
            if running is None
            else RunningIn(running.D, surface_roughness(case, running.D, running.G), running.depth)
        ),
        load_classes=spec.load_classes,
        torque_offset=spec.torque_offset,
        asperity_roughness=spec.asperity_roughness,
        preload_contact=spec.preload_contact,
    )


def _programme(case: Case, spec: WearSpec) -> tuple[WearLevel, ...]:
    """``[[wear.programme]]``, or the case's ``[[duty]]`` at its operating points (then the
    programme must be left at its default)."""
    if not case.duty:
        return tuple(WearLevel(lv.axial_load, lv.speed, lv.revolutions) for lv in spec.programme)
    if spec.programme != WearSpec().programme:  # a programme of its own besides the duty
        raise InputError(
            "wear.programme",
            f"{len(spec.programme)} levels",
            "either [[wear.programme]] or the case's [[duty]] list, not both",
        )
    programme = duty_programme(case)
    if not programme:
        raise InputError("duty", "no turning segment", "a [[duty]] segment with speed > 0")
    return programme


def wear_setup(case: Case) -> WearSetup:
    """Fixed grid, gaps, fractal surface, C_a, L_w and torque factor of a case with ``[wear]``.

    A preloaded nut: a double nut, or a single nut preloaded by oversized balls (four-point
    contact: both flanks carry all its balls) or by an offset lead (half the balls per flank);
    the engine wears its two loaded flanks as the two nuts of a double nut. A single nut without
    preload is refused (one loaded flank: backlash, not preload loss).
    """
    case_with(case, "screw", "operating")
    spec = wear_options(case)
    if case.screw.nuts == 1 and not case.operating.preload > 0.0:
        raise InputError(
            "operating.preload",
            case.operating.preload,
            "> 0 N for screw.nuts = 1 (the wear life follows the loss of preload; a single nut "
            "without preload wears into backlash, which is not modelled)",
        )
    params = ScrewParameters.from_case(case)
    geometry = params.geometry
    balls = params.flanks.balls  # per loaded flank: a nut, a four-point nut's pairs, a half
    e_star = params.contact_modulus("screw")
    hardness = case.materials.screw.hardness
    ca = raceway_curvature(geometry, "screw")
    compliance = params.nut_compliance
    preload = case.operating.preload
    if not preload > 0.0:
        raise InputError("operating.preload", preload, "an initial preload > 0 N")
    q_max = max(
        float(
            ball_load(
                max(nut_force_pair(preload, part.axial_load)),
                balls,
                geometry.contact_angle,
                geometry.lead_angle,
            )
        )
        for lv in spec.programme
        for _, part in lv.parts()
    )
    classes = _ball_classes(case, params, spec)
    widest = max((c.ratios[-1] for _, pair in classes for c in pair), default=1.0)
    hz = hertz(
        ca.rx, ca.ry, e_star, max(widest, 1.0) * q_max
    )  # a along x (rolling), b along y (across)
    nx, ny = spec.grid
    grid_bytes = contact_grid_bytes(nx, ny) + 8.0 * nx * ny * 16  # + warm starts, gaps, rates
    check_memory("wear.grid", list(spec.grid), grid_bytes, f"the {nx} × {ny} wear grid")
    check_wear_work(spec, 0, 0.0, 0)
    dx, dy = 2.0 * spec.box_factor * hz.a / nx, 2.0 * spec.box_factor * hz.b / ny
    x, y = cell_centres(nx, dx), cell_centres(ny, dy)
    model = case.numerics.gap_model
    gaps = {
        s: np.asarray(
            gap_function(geometry, "screw", flank=s, model=model)(x[:, None], y[None, :]),
            dtype=float,
        )
        for s in FLANKS
    }
    eta, alpha = params.lubrication.viscosity, params.lubrication.pressure_viscosity
    surface = AsperitySurface(
        Ds=surface_dimension(params.D),
        G=params.G_surface,
        e_star=e_star,
        hardness=hardness,
        cell_area=dx * dy,
        roughness=roughness_input(case),
    )
    length = working_raceway_length(
        spec.stroke,
        geometry.lead,
        geometry.pitch_radius,
        geometry.ball_radius,
        geometry.contact_angle,
    )
    catalogue = preload_drag_torque(preload, geometry.lead, geometry.lead_angle)
    if spec.initial_torque is None:
        factor = spec.torque_scale
    elif spec.initial_torque > spec.torque_offset:
        factor = (spec.initial_torque - spec.torque_offset) / catalogue
    else:
        raise InputError(
            "wear.initial_torque",
            spec.initial_torque,
            f"more than wear.torque_offset = {spec.torque_offset:g} N·m",
        )
    return WearSetup(
        geometry=geometry,
        spec=spec,
        balls=balls,
        e_star=e_star,
        hardness=hardness,
        surface=surface,
        viscosity=eta,
        pressure_viscosity=alpha,
        rx=ca.rx,
        ry=ca.ry,
        x=x,
        y=y,
        dx=dx,
        dy=dy,
        nominal_gap=gaps,
        compliance=compliance,
        raceway_length=length,
        initial_preload=preload,
        torque_factor=factor,
        tolerance=case.numerics.tolerance,
        max_iterations=case.numerics.max_iterations,
        film_roughness=_film_roughness(case),
        body_compliance=_preload_loop_compliance(case, params),
        film_model=params.lubrication.film_model,
        entrainment=case.kinematics.entrainment,
        ball_classes=classes,
        torque_offset=spec.torque_offset,
    )


def _film_roughness(case: Case) -> FilmRoughness:
    """σ_Λ of the case's raceway as it runs in: the band of ``[tcr]``, a rough ball's σ over it
    (``surface.ball``) and ``tcr.rms_roughness`` when measured (theory manual, *Wear*,
    running-in)."""
    return FilmRoughness(measurement_band(case), ball_roughness(case), case.tcr.rms_roughness)


def _ball_classes(
    case: Case, params: ScrewParameters, spec: WearOptions
) -> tuple[tuple[float, tuple[LoadClasses, LoadClasses]], ...]:
    """Per axial load of the programme the ball-load classes of both loaded flanks (the nuts of
    a double nut, the contact pairs or halves of a preloaded single nut): the elastic
    distribution (with the case's lead and ball-diameter errors) at the initial preload, split
    into ``spec.load_classes`` equal-count classes; empty for ``loads.distribution =
    "uniform"``. The class ratios stay fixed as the preload falls (ASSUMED). A reverse load
    −F takes the classes of +F with the nuts swapped (ASSUMED mirror symmetry: the shaft's load
    path and the flange side make the real nut slightly asymmetric)."""
    if case.loads.distribution == "uniform":
        return ()
    loads = sorted({part.axial_load for lv in spec.programme for _, part in lv.parts()})
    root = None if case.design is None else case.design.root_diameter
    solved: dict[float, tuple[LoadClasses, LoadClasses]] = {}
    out = []
    for load in loads:
        size = abs(load)
        if size not in solved:
            dist = elastic_distribution(
                params.with_loads(axial_load=size), case.loads, root, numerics=case.numerics
            )
            q = dist.per_nut(dist.loads)
            n = spec.load_classes
            solved[size] = (load_classes(q[0], n), load_classes(q[1], n))
        pair = solved[size]
        out.append((load, pair if load >= 0.0 else pair[::-1]))
    return tuple(out)


def _preload_loop_compliance(case: Case, params: ScrewParameters) -> float:
    """c_b per loaded flank: the preload interference of the elastic distribution (a double
    nut's spacer, a four-point nut's ball oversize, an offset-lead nut's lead shift) at the
    preload beyond the contacts' approach, over F_p [m/N]; 0 for ``loads.distribution =
    "uniform"``. The approach is C_a F_p^(2/3) (Hertz) or, for ``loads.contact =
    "numerical"``, δ(Q)/(sinβ cosα) of the tabulated law at the flank's ball load
    Q = F_p/(n_b sinβ cosα), n_b its balls. A four-point nut's bars carry no net force at
    F_a = 0, so its c_b is the ring's alone, 2 cos²β c_r n_t/(L n_b s²) (theory manual, *Wear*)."""
    if case.loads.distribution == "uniform":
        return 0.0
    fp = params.preload
    preloaded = params.with_loads(axial_load=0.0)
    g = elastic_distribution(preloaded, case.loads, errors=False, numerics=case.numerics)
    law = ball_contact_law(preloaded, case.loads, case.numerics)
    if law is None:
        approach = params.nut_compliance * fp ** (2.0 / 3.0)
    else:
        projection = params.axial_projection
        approach = law.approach(fp / (params.flanks.balls * projection)) / projection
    return max(g.interference - approach, 0.0) / fp


def fingerprint(case: Case, setup: WearSetup) -> str:
    """Hash of every input of the wear run (a checkpoint must come from the same inputs)."""
    surface = case.surface.model_dump(mode="json")
    # the 3-D G the wear law reads: a "surface" case keeps the fingerprint of earlier versions
    surface.update(G=setup.surface.G)
    del surface["G_convention"]
    data = {
        "wear": dataclasses.asdict(setup.spec),
        "screw": case.screw.model_dump(mode="json"),
        "surface": surface,
        "preload": case.operating.preload,
        "numerics": case.numerics.model_dump(mode="json"),
        "viscosity": setup.viscosity,
        "pressure_viscosity": setup.pressure_viscosity,
        "hardness": setup.hardness,
        "e_star": setup.e_star,
    }
    if setup.body_compliance:
        data["body_compliance"] = setup.body_compliance
    if setup.ball_classes:
        data["loads"] = case.loads.model_dump(mode="json")
    else:  # the uniform distribution: the checkpoints of earlier versions stay valid
        del data["wear"]["load_classes"]
    if not data["wear"]["torque_offset"]:  # no offset: earlier checkpoints stay valid
        del data["wear"]["torque_offset"]
    if data["wear"]["asperity_roughness"] == "cell":  # earlier checkpoints stay valid
        del data["wear"]["asperity_roughness"]
    if data["wear"]["preload_contact"] == "hertz":  # earlier checkpoints stay valid
        del data["wear"]["preload_contact"]
    if not isinstance(setup.film_model, str):  # a starved or heated inlet
        data["lubrication"] = case.lubrication.model_dump(mode="json")
    if setup.film_model != "hamrock_dowson":
        data["film_model"] = case.medium.film_model
    if setup.spec.asperity_roughness == "film":  # σ_Λ, of the profile G since G_convention
        data["film_roughness"] = setup.surface.film_roughness
    return hashlib.sha256(json.dumps(data, sort_keys=True, default=str).encode()).hexdigest()


def _warn_operating_outside(case: Case, programme: tuple[WearLevel, ...]) -> None:
    """Warn when ``[operating]`` runs harder than every level of the wear programme, which
    the run follows instead (of ``[operating]`` it takes only the preload)."""
    parts = [part for level in programme for _, part in level.parts()]
    levels = "[[duty]]" if case.duty else "[wear] programme"
    over = operating_excess(
        case, max(abs(p.axial_load) for p in parts), max(p.speed for p in parts), levels
    )
    if over:
        warnings.warn(
            f"[operating] {' and '.join(over)}: the wear runs the {levels} levels, not this "
            f"point (of [operating] it takes the preload only); add it to the {levels} to wear "
            "at it",
            OperatingOutsideWarning,
            stacklevel=3,
        )


def wear_life(
    case: Case,
    *,
    checkpoint: str | Path | None = None,
    resume: bool = False,
    max_steps: int | None = None,
) -> WearResult:
    """Wear, preload and drag torque over the load programme of ``case.wear``.

    Args:
        case: a validated case; ``case.wear`` (None = the defaults of the ``[wear]`` section:
            the three-level step-stress programme with the calibrated wear coefficient).
        checkpoint: file (``.npz``) to save the state to after every ``checkpoint_every`` steps.
        resume: continue from ``checkpoint`` if it exists (it must come from the same case).
        max_steps: stop after this many time steps of this call (the result then has
            ``complete = False``; resume it later from the checkpoint).

    Returns:
        :class:`WearResult` (the :class:`~ballscrew.wear.WearLife` history with the case). The
        step-stress example
        (examples/wear_step_stress.toml, K = 1.304e-4) gives h_max = 2.43 µm and F_p = 244 N at
        1.44e6 rev. A preloaded single nut (``screw.nuts = 1``, ``screw.preload_method``) runs
        through the same engine, its two loaded flanks in place of the two nuts.
    """
    case_with(case, "screw", "operating")
    with recorded_warnings() as messages:
        setup = wear_setup(case)
        warn_outside_range(case.wear or WearSpec(), setup.spec.programme)
        _warn_operating_outside(case, setup.spec.programme)
        life = integrate_wear(
            setup,
            fingerprint(case, setup),
            checkpoint=checkpoint,
            resume=resume,
            max_steps=max_steps,
        )
        films = part_films(setup, setup.spec.programme, life)
        warn_full_film(films)
    return WearResult(case, life, tuple(messages), films)
