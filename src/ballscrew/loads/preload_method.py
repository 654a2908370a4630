"""How a nut is preloaded, and which flanks of the groove its balls load.

A preloaded nut always has two loaded flanks pressed against each other; what differs is which
balls sit on each flank:

* ``spacer`` — double nut: two nuts with a spacer between them, each nut's balls on one flank.
* ``oversized_balls`` — single nut with balls larger than the groove gap: every ball touches both
  flanks (four-point contact, two contact pairs per ball), so each flank carries *all* balls of
  the nut and the two "halves" lie at the same axial positions.
* ``offset_lead`` — single nut whose lead is shifted by the preload offset between its two
  halves of turns: a double nut in one body, half of the balls on each flank.

Axially each is the double nut of (P1)–(P3): F1^(2/3) + F2^(2/3) = 2 F_p^(2/3), F1 − F2 = F_a,
lift-off of the unloaded flank at F_a = 2^(3/2) F_p (rigid bodies, Hertz). A single nut without
preload has one loaded flank carrying F_a. Theory manual, *Loads* (four-point contact).
"""

from __future__ import annotations

from dataclasses import dataclass

from ballscrew.errors import InputError
from ballscrew.loads.ball_load import validate_balls
from ballscrew.loads.double_nut import NutForces, nut_forces

__all__ = ["PRELOAD_METHODS", "Flanks", "flank_forces", "preload_flanks", "preload_methods"]

PRELOAD_METHODS = ("spacer", "oversized_balls", "offset_lead")
"""Names of the preload methods (``screw.preload_method``)."""


def preload_methods(nuts: int) -> tuple[str, ...]:
    """The preload methods a nut assembly of ``nuts`` nuts allows, its default first: a double
    nut the spacer, a single nut oversized balls or an offset lead; () for another count."""
    return {1: PRELOAD_METHODS[1:], 2: PRELOAD_METHODS[:1]}.get(nuts, ())


@dataclass(frozen=True)
class Flanks:
    """The loaded flanks of a nut assembly."""

    count: int
    """1 (single nut without preload) or 2 (preloaded: both flanks loaded)."""
    balls: int
    """Balls on each flank."""
    shared: bool
    """True: the two flanks are the two contact pairs of the same balls (four-point contact)."""


def preload_flanks(method: str, nuts: int, balls_per_nut: int, preload: float) -> Flanks:
    """The flanks of ``nuts`` nuts of ``balls_per_nut`` balls preloaded by ``method``.

    A double nut needs ``spacer``; a single nut takes ``oversized_balls`` or ``offset_lead``
    (an even ball count: two equal halves) and has one flank when ``preload`` is 0.
    """
    balls = validate_balls(balls_per_nut)
    allowed = preload_methods(nuts)
    if not allowed:
        raise InputError("nuts", nuts, "1 or 2")
    if method not in allowed:
        raise InputError("preload_method", method, f"{' or '.join(allowed)} for nuts = {nuts}")
    if nuts == 2:
        return Flanks(2, balls, False)
    if preload <= 0.0:
        return Flanks(1, balls, False)
    if method == "oversized_balls":
        return Flanks(2, balls, True)
    if balls % 2:
        raise InputError("balls_per_nut", balls, "an even number for an offset-lead nut")
    return Flanks(2, balls // 2, False)


def flank_forces(preload: float, axial_load: float, flanks: int) -> NutForces:
    """Axial forces (F1, F2) of the loaded and the unloaded flank, N.

    Two flanks: :func:`~ballscrew.loads.nut_forces` (P1)–(P3); one flank: (F_p + F_a, 0).
    """
    if flanks == 2:
        return nut_forces(preload, axial_load)
    if flanks == 1:
        return NutForces(float(preload) + float(axial_load), 0.0)
    raise InputError("flanks", flanks, "1 or 2")
