"""Contact of one ball with the screw raceway (A) and the nut raceway (B).

case → :class:`ScrewParameters` → axial force on the loaded nut → ball load Q → exact (or
quadratic) raceway gap → Polonsky–Keer on DC-FFT, with the exact elliptical Hertz and
Hamrock–Brewe solutions alongside for comparison (theory manual: *Geometry*, *Contact*).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from types import ModuleType
from typing import Any, ClassVar

import numpy as np

from ballscrew.analyses import contact_report
from ballscrew.analyses.ball_loads import chain_ball_loads
from ballscrew.analyses.contact_law import inside_ball
from ballscrew.analyses.parameters import SIDES, ScrewParameters, Side
from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.case import Case, NumericsSpec
from ballscrew.contact import ContactRequest, hamrock_brewe, hertz, solve_contacts
from ballscrew.contact.hertz import HertzContact
from ballscrew.geometry import RacewayCurvature, ScrewGeometry, gap_function, raceway_curvature


@dataclass(frozen=True)
class RacewayContact:
    """Solved contact of a ball with one raceway."""

    side: Side
    """'screw' (contact A) or 'nut' (contact B)."""
    load: float
    """Normal ball load Q [N]."""
    e_star: float
    """Composite modulus of ball and raceway [Pa]."""
    curvature: RacewayCurvature
    """Exact gap curvatures (G15)–(G17) at the contact point."""
    hertz: HertzContact
    """Exact elliptical Hertz solution on the quadratic gap (H2)–(H4)."""
    hamrock_brewe: HertzContact
    """Hamrock–Brewe approximation (H5)–(H7)."""
    x: np.ndarray
    """Cell centres along the rolling direction t [m]."""
    y: np.ndarray
    """Cell centres across the groove [m]."""
    gap: np.ndarray
    """Initial gap h(x, y) [m] (exact or quadratic, as the case's ``numerics.gap_model``)."""
    solution: Any
    """The converged :class:`ballscrew.contact.ContactResult`."""

    @property
    def semi_axes(self) -> tuple[float, float]:
        """Half-widths of the contact along x and y, edges interpolated between cells [m]
        (:attr:`ballscrew.contact.ContactResult.semi_axes`)."""
        return self.solution.semi_axes


@dataclass(frozen=True)
class BallContacts(Presented):
    """Both contacts of one ball of the loaded nut."""

    case: Case
    geometry: ScrewGeometry
    nut_force: float
    """Axial force carried by the loaded nut [N]."""
    ball_load: float
    """Normal load on each of its balls, Q = F/(n_b sinβ cosα) [N]."""
    screw: RacewayContact
    nut: RacewayContact
    warnings: tuple[str, ...] = ()
    """Warnings raised while solving (one line each)."""
    load_spread: float = 1.0
    """Largest over mean ball load of the nut (``loads.distribution = "elastic"``: the ball
    solved is the most loaded one) [-]."""

    analysis: ClassVar[str] = "contact"
    presentation: ClassVar[ModuleType] = contact_report

    def contact(self, side: Side) -> RacewayContact:
        """The contact on ``side``."""
        return self.screw if side == "screw" else self.nut

    @property
    def title(self) -> str:
        return f"Ball–raceway contact: {self.case.name}"


def solve_raceway_contact(
    geometry: ScrewGeometry,
    side: Side,
    load: float,
    e_star: float,
    numerics: NumericsSpec,
    flank: int = 1,
) -> RacewayContact:
    """Solve one ball–raceway contact on an automatically sized grid.

    The grid follows the Hertz ellipse of the quadratic gap (``numerics.cells_across`` cells
    across it on each axis, box ``numerics.box_factor`` × the semi-axes, enlarged until the
    pressure vanishes at its edge); the gap itself is exact or quadratic per
    ``numerics.gap_model``.
    """
    return solve_raceway_contacts(geometry, [(side, load, e_star, flank)], numerics)[0]


def solve_raceway_contacts(
    geometry: ScrewGeometry,
    contacts: Sequence[tuple[Side, float, float, int]],
    numerics: NumericsSpec,
) -> tuple[RacewayContact, ...]:
    """:func:`solve_raceway_contact` of each (side, load Q [N], E* [Pa], flank) of ``contacts``.

    Those whose grids have equal cell counts (each follows its own Hertz ellipse) are solved in
    one batched call (:func:`ballscrew.contact.solve_contacts`).
    """
    requests, curvatures = [], []
    for side, load, e_star, flank in contacts:
        curvatures.append(curvature := raceway_curvature(geometry, side))
        gap = inside_ball(
            gap_function(geometry, side, flank=flank, model=numerics.gap_model),
            geometry, side, load,
        )  # fmt: skip
        requests.append(ContactRequest(gap, curvature.rx, curvature.ry, e_star, load))
    outcomes = solve_contacts(
        requests,
        cells_across=numerics.cells_across,
        box_factor=numerics.box_factor,
        tol=numerics.tolerance,
        cells=numerics.cells,
        max_iterations=numerics.max_iterations,
    )
    return tuple(
        RacewayContact(
            side=side,
            load=load,
            e_star=e_star,
            curvature=c,
            hertz=hertz(c.rx, c.ry, e_star, load),
            hamrock_brewe=hamrock_brewe(c.rx, c.ry, e_star, load),
            x=np.asarray(outcome.x),
            y=np.asarray(outcome.y),
            gap=np.asarray(outcome.gap),
            solution=outcome.solution,
        )
        for (side, load, e_star, _), c, outcome in zip(contacts, curvatures, outcomes, strict=True)
    )


def solve_ball_contacts(case: Case) -> BallContacts:
    """Screw-side and nut-side contact of a ball of the loaded nut under the case's loads (one
    batched solve where both grids have the same cell counts)."""
    params = ScrewParameters.from_case(case)
    with recorded_warnings() as messages:
        nut = chain_ball_loads(case, params)[0]
        solved = solve_raceway_contacts(
            params.geometry,
            [(side, nut.ball_load, params.contact_modulus(side), 1) for side in SIDES],
            case.numerics,
        )
        contacts = dict(zip(SIDES, solved, strict=True))
    return BallContacts(
        case,
        params.geometry,
        nut.force,
        nut.ball_load,
        contacts["screw"],
        contacts["nut"],
        tuple(messages),
        nut.spread,
    )


def contact_scalars(case: Case) -> dict[str, tuple[float, str]]:
    """Sweepable scalars of :func:`solve_ball_contacts`: loads and peak pressures with units."""
    result = solve_ball_contacts(case)
    scalars = {
        "nut_force": (result.nut_force, "N"),
        "ball_load": (result.ball_load, "N"),
    }
    if case.loads.distribution == "elastic":
        scalars["ball_load_spread"] = (result.load_spread, "")
    for side in SIDES:
        c = result.contact(side)
        scalars[f"{side}_peak_pressure"] = (c.solution.peak_pressure, "Pa")
        scalars[f"{side}_hertz_peak_pressure"] = (c.hertz.p0, "Pa")
        scalars[f"{side}_approach"] = (c.solution.approach, "m")
        scalars[f"{side}_contact_area"] = (c.solution.contact_area, "m^2")
    return scalars
