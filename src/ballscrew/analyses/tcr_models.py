"""Every thermal-contact-resistance model on the same solved contacts, and their spread.

The fractal element variants (V2, MT, V1) are evaluated on the Δ_f cells of Gao et al. and on
the whole Hertz patch (``V2/patch``, no cell size); the Gaussian correlations (CMY, Mikic, each
with the liquid gap) integrate their conductance h(p) over the same fields. The headline
(``[tcr] headline``, CMY by default) is one of them. All of them are assembled alike: the screw
and nut contact of a ball in series, the balls of a nut and the nuts in parallel, and R″ = R·S
with the headline's apparent area S, so the models differ only in their micro-physics.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np

from ballscrew.analyses.parameters import ScrewParameters, Side
from ballscrew.case import TCRSpec
from ballscrew.contact_resistance import (
    ELEMENT_MODELS,
    FractalTCRModel,
    contact_tcr,
    parallel_resistance,
    patch_tcr,
)
from ballscrew.contact_resistance.correlations import (
    CORRELATIONS,
    GaussianJoint,
    correlation_conductance,
    fractal_roughness,
)
from ballscrew.contact_resistance.element import harmonic_mean_conductivity

if TYPE_CHECKING:
    from ballscrew.analyses.ball_contact import RacewayContact
    from ballscrew.analyses.screw_tcr import NutTCR, RacewayTCR


_MAX_RELATIVE_PRESSURE = 0.5
"""p/H from which the Gaussian surfaces touch everywhere (the correlations' range ends)."""


class ModelRangeWarning(UserWarning):
    """A rival TCR model was left out because the contact lies outside its range."""


@dataclass(frozen=True)
class ModelTCR:
    """One model's thermal contact resistance of the whole screw."""

    name: str
    description: str
    resistance: float
    """R of the screw, every loaded ball of every nut in parallel [K/W]."""
    resistance_per_area: float
    """R″ = R·S with the headline model's apparent area S [m² K/W]."""
    nut_resistances: dict[int, float] = field(default_factory=dict)
    """R of each loaded nut, all its balls in parallel (A3): nut index → R [K/W]."""


@dataclass(frozen=True)
class ModelSpread:
    """Spread of R″ over the models: the modelling uncertainty of the TCR."""

    low: float
    """Smallest R″ of the models [m² K/W]."""
    high: float
    """Largest R″ of the models [m² K/W]."""
    models: tuple[str, ...]
    """The models the spread is taken over."""

    @property
    def ratio(self) -> float:
        """high/low: a factor of uncertainty."""
        return self.high / self.low


def gaussian_joint(params: ScrewParameters, options: TCRSpec, side: Side) -> GaussianJoint:
    """(σ, m) and the materials of the ball against the ``side`` raceway for the correlations.

    σ and m are the case's measured values when given, else those of the raceway's fractal
    profile over the wavelength band [``cutoff_length``, ``sampling_length``] (the ball is
    smooth).
    """
    if options.rms_roughness is not None and options.rms_slope is not None:
        sigma, slope = options.rms_roughness, options.rms_slope
    else:
        sigma, slope = fractal_roughness(
            params.D, params.G, options.sampling_length, options.cutoff_length
        )
    return GaussianJoint(
        sigma=sigma,
        slope=slope,
        lambda_s=harmonic_mean_conductivity(
            params.ball.thermal_conductivity, params.material(side).thermal_conductivity
        ),
        lambda_f=params.lubrication.thermal_conductivity,
        hardness=params.hardness(side),
        E_star=params.contact_modulus(side),
        rarefaction=params.lubrication.rarefaction,
    )


ContactResistance = Callable[["RacewayContact", Side], float]
"""R_c of one solved ball–raceway contact by one model [K/W]."""

PATCH = "/patch"
"""Suffix of an element variant evaluated on the whole Hertz patch instead of fractal cells."""


def solved_contact_area(contact: RacewayContact) -> float:
    """S_c = N(p > 0)·dx·dy, the solved contact area of ``contact`` (A4 without cells) [m²]."""
    sol = contact.solution
    return float(np.count_nonzero(sol.pressure > 0.0)) * sol.dx * sol.dy


def _element_resistance(
    models: dict[Side, FractalTCRModel], options: TCRSpec, variant: str, patch: bool
) -> ContactResistance:
    def resistance(contact: RacewayContact, side: Side) -> float:
        sol = contact.solution
        model = replace(models[side], variant=variant)
        if patch:  # the MB population of the whole solved patch: no cell size (A1p)
            return patch_tcr(sol.pressure, sol.dx, sol.dy, model).resistance
        return contact_tcr(
            sol.pressure,
            sol.dx,
            sol.dy,
            model,
            cell_size=options.cell_size if options.rebin else None,
            load_threshold=options.load_threshold,
            partial_cells="contact_area",
        ).resistance

    return resistance


def _correlation_resistance(joints: dict[Side, GaussianJoint], name: str) -> ContactResistance:
    def resistance(contact: RacewayContact, side: Side) -> float:
        sol = contact.solution
        return 1.0 / correlation_conductance(sol.pressure, sol.dx, sol.dy, joints[side], name)

    return resistance


def contact_model(
    name: str,
    params: ScrewParameters,
    options: TCRSpec,
    element_models: dict[Side, FractalTCRModel],
) -> tuple[ContactResistance, str]:
    """The model ``name`` of :func:`~ballscrew.case.thermal_spec.tcr_model_names` as a function
    of a solved contact, with its description: an element variant on the Δ_f cells (the paper's
    cell model) or on the whole patch (``V2/patch``), or a correlation integrated over the field."""
    if name.endswith(PATCH):
        variant = name.removesuffix(PATCH)
        description = f"{variant} on the whole Hertz patch, no fractal cell size"
        return _element_resistance(element_models, options, variant, patch=True), description
    if name in ELEMENT_MODELS:
        description = f"{ELEMENT_MODELS.entry(name).description}, on Δ_f cells (Gao et al.)"
        return _element_resistance(element_models, options, name, patch=False), description
    joints = {side: gaussian_joint(params, options, side) for side in element_models}
    return _correlation_resistance(joints, name), CORRELATIONS.entry(name).description


def out_of_range(
    contacts: Iterable[tuple[str, Side, RacewayContact]], hardness: Mapping[Side, float]
) -> str:
    """The largest p/H of ``contacts`` (label, side, contact) and where, as text; '' when all
    are below 0.5, the end of the correlations' range. ``hardness``: H of each side's pair."""
    peak, label, side = max(
        (
            (float(c.solution.pressure.max()) / hardness[side], label, side)
            for label, side, c in contacts
        ),
        key=lambda item: item[0],
    )
    if peak < _MAX_RELATIVE_PRESSURE:
        return ""
    return f"p/H = {peak:.2f} at the {side} contact of {label} (the correlations need < 0.5)"


def _nut_resistances(nuts: Sequence[NutTCR], contact: ContactResistance) -> dict[int, float]:
    """(A2)–(A3) per nut with ``contact`` evaluated once per solved contact: nuts of equal ball
    load share their :class:`RacewayTCR` objects (one solve serves both)."""
    done: dict[int, float] = {}

    def once(raceway: RacewayTCR, side: Side) -> float:
        if id(raceway) not in done:
            done[id(raceway)] = contact(raceway.contact, side)
        return done[id(raceway)]

    return {n.index: float(once(n.screw, "screw") + once(n.nut, "nut")) / n.balls for n in nuts}


def _expanded(names: Sequence[str], headline: str) -> list[str]:
    """The models with each element variant also evaluated on the whole patch, and the
    headline."""
    element = [n for n in names if n in ELEMENT_MODELS]
    out = [*names, *(n + PATCH for n in element)]
    return out if headline in out else [*out, headline]


def compare_models(
    params: ScrewParameters,
    options: TCRSpec,
    element_models: dict[Side, FractalTCRModel],
    nuts: Sequence[NutTCR],
    apparent_area: float,
    headline: str,
) -> tuple[dict[str, ModelTCR], ModelSpread | None]:
    """Each model of ``options.models`` and the ``headline`` on the solved contacts of
    ``nuts``, and their spread; a correlation headline is the nuts' own resistance (an element
    headline's cells may differ from the comparison's ``partial_cells``).

    The correlations are left out when a contact lies outside their range (p/H ≥ 0.5) with a
    :class:`ModelRangeWarning`; the spread is None when fewer than two models remain.
    """
    outside = out_of_range(
        ((f"nut {n.index}", s, getattr(n, s).contact) for n in nuts for s in element_models),
        {side: params.hardness(side) for side in element_models},
    )
    results: dict[str, ModelTCR] = {}
    for name in _expanded(options.models, headline):
        if name in CORRELATIONS and outside:
            warnings.warn(f"TCR model {name} left out: {outside}", ModelRangeWarning, 2)
            continue
        contact, description = contact_model(name, params, options, element_models)
        if name == headline and name in CORRELATIONS:  # the nuts' R: this model, solved once
            per_nut = {n.index: n.resistance for n in nuts}
        else:
            per_nut = _nut_resistances(nuts, contact)
        r = float(parallel_resistance(list(per_nut.values())))
        results[name] = ModelTCR(name, description, r, r * float(apparent_area), per_nut)
    values = [m.resistance_per_area for m in results.values() if math.isfinite(m.resistance)]
    if len(values) < 2:
        return results, None
    return results, ModelSpread(min(values), max(values), tuple(results))
