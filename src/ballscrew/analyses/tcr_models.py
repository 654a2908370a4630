"""Every thermal-contact-resistance model on the same solved contacts, and their spread.

The fractal element variants (V2, MT, V1) are re-evaluated on the pressure fields the headline
model used; the Gaussian correlations (CMY, Mikic, each with the liquid gap) integrate their
conductance h(p) over the same fields. All of them are then assembled like the headline result:
the screw and nut contact of a ball in series, the balls of a nut and the nuts in parallel, and
R″ = R·S with the headline's apparent area S, so the models differ only in their micro-physics.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

from ballscrew.analyses.parameters import ScrewParameters, Side
from ballscrew.case import TCRSpec
from ballscrew.contact_resistance import (
    ELEMENT_MODELS,
    FractalTCRModel,
    contact_tcr,
    parallel_resistance,
)
from ballscrew.contact_resistance.correlations import (
    CORRELATIONS,
    GaussianJoint,
    correlation_conductance,
    fractal_roughness,
)
from ballscrew.contact_resistance.element import harmonic_mean_conductivity

if TYPE_CHECKING:
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


ContactResistance = Callable[["RacewayTCR", Side], float]


def _element_resistance(
    models: dict[Side, FractalTCRModel], options: TCRSpec, variant: str, patch: bool
) -> ContactResistance:
    def resistance(raceway: RacewayTCR, side: Side) -> float:
        sol = raceway.contact.solution
        if patch:  # one cell that holds the whole grid: MB on the real contact
            nx, ny = sol.pressure.shape
            cell: float | None = 1.01 * max(nx * sol.dx, ny * sol.dy)
        else:
            cell = options.cell_size if options.rebin else None
        return contact_tcr(
            sol.pressure,
            sol.dx,
            sol.dy,
            replace(models[side], variant=variant),
            cell_size=cell,
            load_threshold=options.load_threshold,
            partial_cells="contact_area",
        ).resistance

    return resistance


PATCH = "/patch"
"""Suffix of an element variant evaluated on the whole Hertz patch instead of fractal cells."""


def _correlation_resistance(joints: dict[Side, GaussianJoint], name: str) -> ContactResistance:
    def resistance(raceway: RacewayTCR, side: Side) -> float:
        sol = raceway.contact.solution
        return 1.0 / correlation_conductance(sol.pressure, sol.dx, sol.dy, joints[side], name)

    return resistance


def _peak_relative_pressure(nuts: Sequence[NutTCR], joints: dict[Side, GaussianJoint]) -> str:
    """The largest p/H of the contacts and where, as text; '' when all are below 0.5."""
    peaks = {
        (n.index, side): float(getattr(n, side).contact.solution.pressure.max())
        / joints[side].hardness
        for n in nuts
        for side in joints
    }
    (nut, side), peak = max(peaks.items(), key=lambda item: item[1])
    if peak < _MAX_RELATIVE_PRESSURE:
        return ""
    return f"p/H = {peak:.2f} at the {side} contact of nut {nut} (the correlations need < 0.5)"


def _nut_resistances(nuts: Sequence[NutTCR], contact: ContactResistance) -> dict[int, float]:
    """(A2)–(A3) per nut with ``contact`` evaluated once per solved contact: nuts of equal ball
    load share their :class:`RacewayTCR` objects (one solve serves both)."""
    done: dict[int, float] = {}

    def once(raceway: RacewayTCR, side: Side) -> float:
        if id(raceway) not in done:
            done[id(raceway)] = contact(raceway, side)
        return done[id(raceway)]

    return {n.index: (once(n.screw, "screw") + once(n.nut, "nut")) / n.balls for n in nuts}


def _expanded(names: Sequence[str]) -> list[str]:
    """The models with each element variant also evaluated on the whole patch."""
    element = [n for n in names if n in ELEMENT_MODELS]
    return [*names, *(n + PATCH for n in element)]


def compare_models(
    params: ScrewParameters,
    options: TCRSpec,
    element_models: dict[Side, FractalTCRModel],
    nuts: Sequence[NutTCR],
    apparent_area: float,
) -> tuple[dict[str, ModelTCR], ModelSpread | None]:
    """Each model of ``options.models`` on the solved contacts of ``nuts``, and their spread.

    The correlations are left out when a contact lies outside their range (p/H ≥ 0.5) with a
    :class:`ModelRangeWarning`; the spread is None when fewer than two models remain.
    """
    joints = {side: gaussian_joint(params, options, side) for side in element_models}
    out_of_range = _peak_relative_pressure(nuts, joints)
    results: dict[str, ModelTCR] = {}
    for name in _expanded(options.models):
        if name.endswith(PATCH):
            variant = name.removesuffix(PATCH)
            contact = _element_resistance(element_models, options, variant, patch=True)
            description = f"{variant} on the whole Hertz patch (no fractal cell size)"
        elif name in ELEMENT_MODELS:
            contact = _element_resistance(element_models, options, name, patch=False)
            description = ELEMENT_MODELS.entry(name).description
        else:
            contact = _correlation_resistance(joints, name)
            description = CORRELATIONS.entry(name).description
        if name in CORRELATIONS and out_of_range:
            warnings.warn(f"TCR model {name} left out: {out_of_range}", ModelRangeWarning, 2)
            continue
        per_nut = _nut_resistances(nuts, contact)
        r = float(parallel_resistance(list(per_nut.values())))
        results[name] = ModelTCR(name, description, r, r * apparent_area, per_nut)
    values = [m.resistance_per_area for m in results.values() if math.isfinite(m.resistance)]
    if len(values) < 2:
        return results, None
    return results, ModelSpread(min(values), max(values), tuple(results))
