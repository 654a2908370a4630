"""Normal load and contact angle of every ball of every nut: ``ballscrew.ball_loads(case)``.

``loads.distribution = "uniform"`` (default): every loaded ball of a nut carries
Q = F/(Z sinβ cosα) at the nominal contact angle β (rigid bodies, no lead error).
``"elastic"``: Hertz contacts with the elastic screw shaft and nut body, the nut ring's
expansion, lead error and ball-diameter variation, contact angle under load
(:mod:`ballscrew.loads.distribution`; theory manual, *Loads*). Uniform is its rigid limit.
With ``loads.contact = "numerical"`` every ball's contacts follow the contact solver's
load–approach law on the raceway gap (:mod:`ballscrew.analyses.contact_law`) instead of Hertz.
``loads.nut_support = "free"`` balances the nut on its balls in radial displacement and tilt too
(:mod:`ballscrew.loads.rigid_nut`); ``"guided"`` (default) leaves the radial force and tilting
moment to the housing.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ballscrew.analyses.contact_law import numerical_contact, warn_above_table
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.case import Case, NumericsSpec
from ballscrew.case.loads_spec import LoadsSpec
from ballscrew.kinematics.limits import groove_root_diameter
from ballscrew.loads.contact_law import TabulatedContact
from ballscrew.loads.distribution import (
    BallLayout,
    Distribution,
    NutBodies,
    ball_layout,
    body_properties,
    lift_off_load,
    loaded_contact_angle,
    solve_distribution,
)
from ballscrew.validation import as_case_fields

__all__ = [
    "NUT_DIAMETER_BALLS",
    "BallLoads",
    "NutBallLoad",
    "ball_contact_law",
    "ball_loads",
    "chain_ball_loads",
    "elastic_distribution",
    "elastic_lift_off",
    "nut_model",
]

NUT_DIAMETER_BALLS = 5.0
"""GUESS: nut outer diameter d_m + 5 D_b when the case gives none (close to DIN 69051 flanged
nuts of 6.35 mm balls on 32–63 mm screws)."""

_FIELDS = {
    "nut_outer_diameter": "loads.nut_outer_diameter",
    "lead_error": "loads.lead_error",
    "ball_excess": "loads.ball_diameter_error",
    "root_diameter": "design.root_diameter",
    "nut_support": "loads.nut_support",
    "radial_load": "loads.nut_radial_load",
    "tilting_moment": "loads.nut_tilting_moment",
}


@dataclass(frozen=True)
class BallLoads:
    """Per-ball loads and angles, one row per loaded flank (the nuts of a double nut, nut 1
    first; the two contact pairs of a four-point nut), one column per ball (SI).

    Columns run from each nut's end nearest the loaded end of the shaft.
    """

    loads: NDArray[np.float64]
    """Normal ball load Q [N], shape (nuts, balls per nut); 0 for a lifted-off ball."""
    angles: NDArray[np.float64]
    """Contact angle β [rad], same shape."""
    axial_forces: NDArray[np.float64]
    """Axial force of each nut's balls, Σ Q sinβ₀ cosα [N] (equals the nut force)."""
    distribution: str = "uniform"
    positions: NDArray[np.float64] | None = None
    """Axial position of each ball [m] (elastic only), same shape as ``loads``."""
    radial_force: NDArray[np.float64] | None = None
    """Net radial force (2) of the balls on the nut [N] (elastic only): a guided nut's housing
    takes it, a free nut's external radial load balances it."""
    tilting_moment: NDArray[np.float64] | None = None
    """Net tilting moment (2) of the balls on the nut about its centre [N·m] (elastic only)."""
    radial_displacement: NDArray[np.float64] | None = None
    """Radial displacement (2) of the nut relative to the screw at its centre [m] (elastic
    only; 0 for a guided nut)."""
    tilt: NDArray[np.float64] | None = None
    """Tilt (2) of the nut relative to the screw [rad] (elastic only; 0 for a guided nut)."""

    @property
    def max_load(self) -> float:
        """The most loaded ball's normal load [N]."""
        return float(self.loads.max())

    @property
    def spread(self) -> float:
        """Largest over mean load of the balls of nut 1 [-] (1 for uniform)."""
        return float(self.loads[0].max() / self.loads[0].mean())


def nut_model(
    params: ScrewParameters, spec: LoadsSpec, root_diameter: float | None = None
) -> tuple[BallLayout, NutBodies]:
    """Ball positions and elastic bodies of the case's nut(s), one row of balls per loaded
    flank (an offset-lead nut: its two halves, the lead-shift zone as ``spec.spacer``)."""
    g = params.geometry
    root = groove_root_diameter(g) if root_diameter is None else root_diameter
    outer = spec.nut_outer_diameter or g.pitch_diameter + NUT_DIAMETER_BALLS * g.ball_diameter
    flanks = params.flanks
    layout = ball_layout(
        flanks.balls,
        flanks.count,
        g.lead,
        g.pitch_diameter,
        g.ball_diameter,
        g.lead_angle,
        spec.spacer or g.lead,
        shared=flanks.shared,
    )
    with as_case_fields(_FIELDS):
        bodies = body_properties(
            g.pitch_diameter,
            g.ball_diameter,
            g.contact_angle,
            root,
            outer,
            (params.screw.youngs_modulus, params.screw.poissons_ratio),
            (params.nut.youngs_modulus, params.nut.poissons_ratio),
            spec.flange == "loaded_end",
        )
    return layout, bodies


def ball_contact_law(
    params: ScrewParameters, spec: LoadsSpec, numerics: NumericsSpec | None = None
) -> TabulatedContact | None:
    """The tabulated law of ``spec.contact = "numerical"`` (``numerics`` None: the defaults of
    ``[numerics]``); None for Hertz contacts."""
    if spec.contact != "numerical":
        return None
    return numerical_contact(params, numerics or NumericsSpec())


def elastic_distribution(
    params: ScrewParameters,
    spec: LoadsSpec,
    root_diameter: float | None = None,
    axial_load: float | None = None,
    interference: float | None = None,
    errors: bool = True,
    numerics: NumericsSpec | None = None,
    start: Distribution | None = None,
) -> Distribution:
    """The elastic distribution of the case's screw at ``axial_load`` (None: the case's);
    ``start``: a solution at a neighbouring load for Newton to start from (long nuts,
    :func:`~ballscrew.loads.distribution.solve_distribution`).

    ``spec.contact = "numerical"`` tabulates the contact law with ``numerics`` (None: the
    defaults of ``[numerics]``) once per screw and load range (cached), and warns
    (:class:`~ballscrew.analyses.contact_law.ContactLawWarning`) when a ball's load is above the
    table.
    """
    layout, bodies = nut_model(params, spec, root_diameter)
    g = params.geometry
    contact = ball_contact_law(params, spec, numerics)
    with as_case_fields(_FIELDS):
        dist = solve_distribution(
            layout,
            sum(params.hertz_constants),
            g.contact_angle,
            g.lead_angle,
            params.axial_load if axial_load is None else axial_load,
            params.preload,
            bodies,
            lead_error=spec.lead_error or None if errors else None,
            ball_excess=spec.ball_diameter_error or None if errors else None,
            interference=interference,
            contact=contact,
            support=spec.nut_support,
            radial_load=spec.nut_radial_load,
            tilting_moment=spec.nut_tilting_moment,
            start=start,
        )
    if contact is not None:
        warn_above_table(contact, float(dist.loads.max()))
    return dist


def elastic_lift_off(
    params: ScrewParameters,
    spec: LoadsSpec,
    root_diameter: float | None = None,
    numerics: NumericsSpec | None = None,
    rtol: float = 1e-4,
) -> float:
    """Axial load [N] at which the last ball of the second loaded flank lifts off in the
    distribution :func:`elastic_distribution` solves (contacts and bodies, the nut support, lead
    and ball-diameter errors, a free nut's external radial load and moment); 0 with one loaded
    flank, inf where none lifts off below ``LIFT_OFF_SEARCH`` × F_p
    (:func:`~ballscrew.loads.distribution.lift_off_load`)."""
    if params.flanks.count != 2:
        return 0.0
    layout, bodies = nut_model(params, spec, root_diameter)
    g = params.geometry
    with as_case_fields(_FIELDS):
        return lift_off_load(
            layout,
            sum(params.hertz_constants),
            g.contact_angle,
            g.lead_angle,
            params.preload,
            bodies,
            rtol,
            contact=ball_contact_law(params, spec, numerics),
            support=spec.nut_support,
            lead_error=spec.lead_error or None,
            ball_excess=spec.ball_diameter_error or None,
            radial_load=spec.nut_radial_load,
            tilting_moment=spec.nut_tilting_moment,
        )


def _root(case: Case) -> float | None:
    return None if case.design is None else case.design.root_diameter


def ball_loads(case: Case, axial_load: float | None = None) -> BallLoads:
    """Normal load and contact angle of every ball of every nut of ``case`` at ``axial_load``
    [N] (None: the case's)."""
    params = ScrewParameters.from_case(case)
    g = params.geometry
    if case.loads.distribution == "uniform":
        z = params.flanks.balls
        nuts = params.with_loads(axial_load=axial_load).flank_loads
        loads = np.array([np.full(z, nut.ball_load) for nut in nuts])
        angles = np.full_like(loads, g.contact_angle)
        return BallLoads(loads, angles, loads.sum(axis=1) * params.axial_projection)
    dist = elastic_distribution(
        params, case.loads, _root(case), axial_load=axial_load, numerics=case.numerics
    )
    gap = (g.screw_conformity + g.nut_conformity - 1.0) * g.ball_diameter
    angles = loaded_contact_angle(dist.approach, g.contact_angle, gap)
    return BallLoads(
        dist.per_nut(dist.loads),
        dist.per_nut(angles),
        dist.nut_forces,
        "elastic",
        dist.per_nut(dist.layout.z),
        dist.resultant[1:3],
        dist.resultant[3:],
        dist.radial_displacement,
        dist.tilt,
    )


@dataclass(frozen=True)
class NutBallLoad:
    """What the contact and TCR chains take of one nut's distribution."""

    force: float
    """Axial force of the nut [N]."""
    ball_load: float
    """Uniform: every ball's load; elastic: the most loaded ball's [N]."""
    spread: float
    """Largest over mean ball load of the nut [-] (1 uniform or lifted off)."""


def chain_ball_loads(case: Case, params: ScrewParameters) -> tuple[NutBallLoad, ...]:
    """Per loaded flank (flank 1 first: the nuts of a double nut, the two contact pairs of a
    four-point nut, the two halves of an offset-lead nut) the force and ball load the contact
    and TCR chains use."""
    if case.loads.distribution == "uniform":
        return tuple(NutBallLoad(n.force, n.ball_load, 1.0) for n in params.flank_loads)
    result = ball_loads(case)
    return tuple(
        NutBallLoad(float(force), float(q.max()), float(q.max() / q.mean()) if q.max() > 0 else 1.0)
        for force, q in zip(result.axial_forces, result.loads, strict=True)
    )
