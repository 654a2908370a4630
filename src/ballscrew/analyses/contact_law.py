"""The numerical (non-Hertzian) load–approach law of a ball's two contacts, for the distribution.

``[loads] contact = "numerical"``: every ball of the elastic distribution follows δ(Q) of the
contact solver on the case's raceway gap (the exact conforming groove with ``numerics.gap_model =
"exact"``) instead of Hertz. All balls share the groove geometry, so δ is tabulated at
:data:`TABLE_POINTS` loads, geometrically spaced over a span of :data:`TABLE_SPAN` up to the
tabulation top Q_top (the power of two at or above :data:`TOP_FACTOR` × the nominal ball load
F/(Z sinβ cosα), so nearby load cases share one table), with one batched solve for both raceways
(:func:`ballscrew.contact.solve_contacts`, each raceway one request at Q_top with the other loads
as its ``extra_loads``, on the cells of its own Q_top), and interpolated monotonically
(:class:`ballscrew.loads.contact_law.TabulatedContact`). The grid follows the Hertz ellipse of
Q_top (``numerics.cells_across`` cells across it, or ``numerics.cells``, box
``numerics.box_factor``) and is enlarged like a single solve until the pressure vanishes at its
edge; the smallest load then has about cells_across / TABLE_SPAN^(1/3) cells across, and a grid
leaving it fewer than :data:`MIN_CELLS` is refused (cells_across ≥ 41).

Ball-diameter errors enter the distribution as approach offsets; the law itself is that of the
nominal ball (a 1 µm larger ball changes the contact curvatures by ~1e-4, neglected).
"""

from __future__ import annotations

import math
import warnings
from functools import lru_cache
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ballscrew.analyses.parameters import SIDES, ScrewParameters, Side
from ballscrew.case import NumericsSpec
from ballscrew.contact import ContactRequest, HertzContact, grid_cells, hertz, solve_contacts
from ballscrew.contact.grid import GapFunction
from ballscrew.errors import BallscrewError, ConvergenceError, InputError
from ballscrew.geometry import RacewayCurvature, ScrewGeometry, gap_function, raceway_curvature
from ballscrew.loads.contact_law import TabulatedContact
from ballscrew.units import format_quantity

__all__ = [
    "MIN_CELLS",
    "TABLE_POINTS",
    "TABLE_SPAN",
    "TOP_FACTOR",
    "ContactLawWarning",
    "clear_cache",
    "inside_ball",
    "numerical_contact",
    "outside_ball",
    "raceway_approaches",
    "raceways_approaches",
    "table_loads",
    "warn_above_table",
]

TABLE_POINTS = 7
"""Tabulation loads (one batch entry each)."""
TABLE_SPAN = 128.0
"""Largest over smallest tabulation load."""
TOP_FACTOR = 6.0
"""GUESS: Q_top ≥ this × the nominal ball load, so that the most loaded ball of an uneven
distribution stays inside the table; beyond it the end exponent continues the law and
:func:`warn_above_table` says so."""
MIN_CELLS = 8
"""Fewest grid cells across the smallest tabulated load's contact (each axis)."""


class ContactLawWarning(UserWarning):
    """A ball load beyond the tabulated contact law: its approach is extrapolated."""


def warn_above_table(law: TabulatedContact, largest: float) -> None:
    """Warn (:class:`ContactLawWarning`) when the largest ball load ``largest`` [N] is above the
    table's top: there δ(Q) is the power law of the table's end exponent, whose error grows as
    the true log-slope moves away from it (theory manual, *Loads*)."""
    if largest > law.top:
        warnings.warn(
            f"the largest ball load, {format_quantity(largest, 'force')}, is above the top of "
            f"the tabulated contact law ({format_quantity(law.top, 'force')}, at least "
            f"{TOP_FACTOR:g} × the nominal ball load): its approach is extrapolated as δ ∝ Q^n "
            f"with the table's end exponent n = {law.exponents[1]:.3f}",
            ContactLawWarning,
            stacklevel=3,
        )


def outside_ball(exc: InputError, geometry: ScrewGeometry, side: Side, load: float) -> InputError:
    """The error to raise for ``exc`` from a contact solve: the case's ball is too small for
    the grid when the gap was asked at a point outside the ball (field "x, y"), else ``exc``."""
    if exc.field != "x, y":
        return exc
    allowed = (
        f"larger than the {side} contact of the ball load Q = {load:.4g} N (its grid reaches "
        "outside the ball): lower operating.preload / axial_load or numerics.box_factor"
    )
    return InputError("screw.ball_diameter", 2.0 * geometry.ball_radius, allowed)


def table_loads(ball_load: float) -> NDArray[np.float64]:
    """The tabulation loads for the nominal ball load ``ball_load`` [N]."""
    top = 2.0 ** math.ceil(math.log2(TOP_FACTOR * ball_load))
    return top * np.geomspace(1.0 / TABLE_SPAN, 1.0, TABLE_POINTS)


def raceway_approaches(
    geometry: ScrewGeometry,
    side: Side,
    e_star: float,
    loads: NDArray[np.float64],
    numerics: NumericsSpec,
) -> NDArray[np.float64]:
    """Approach δ(Q_k) of the ball against the ``side`` raceway at each of ``loads`` [m].

    All loads on the grid of the largest (sized, and enlarged while its contact carries pressure
    on the grid's edge, as :func:`ballscrew.contact.solve_contact` does), in one batched call.
    """
    return raceways_approaches(geometry, {side: e_star}, loads, numerics)[side]


def inside_ball(gap: GapFunction, geometry: ScrewGeometry, side: Side, load: float) -> GapFunction:
    """``gap`` whose "outside the ball" error names the case's ball (:func:`outside_ball`)."""

    def checked(x: NDArray[np.float64], y: NDArray[np.float64]) -> Any:
        try:
            return gap(x, y)
        except InputError as exc:
            raise outside_ball(exc, geometry, side, load) from None

    return checked


def raceways_approaches(
    geometry: ScrewGeometry,
    e_stars: dict[Side, float],
    loads: NDArray[np.float64],
    numerics: NumericsSpec,
) -> dict[Side, NDArray[np.float64]]:
    """:func:`raceway_approaches` of each raceway of ``e_stars`` (side → E* [Pa]).

    One :func:`~ballscrew.contact.solve_contacts` call: each raceway is one request at the
    largest load with the others as its extra loads (all on the grid of the largest); raceways
    whose grids have equal cell counts are solved in one batched call, each with its own cells
    and E*. A grid leaving fewer than :data:`MIN_CELLS` cells across the smallest load's Hertz
    contact is refused before any solve.
    """
    loads = np.asarray(loads, dtype=float)
    top = int(np.argmax(loads))
    others = np.delete(np.arange(loads.size), top)
    sides = sorted(e_stars, key=SIDES.index)
    requests = []
    for side in sides:
        c = raceway_curvature(geometry, side)
        _check_cells(c, e_stars[side], loads, numerics)
        gap = gap_function(geometry, side, model=numerics.gap_model)
        requests.append(
            ContactRequest(
                inside_ball(gap, geometry, side, float(loads[top])),
                c.rx, c.ry, e_stars[side], float(loads[top]),
                tuple(float(q) for q in loads[others]),
            )
        )  # fmt: skip
    try:
        solved = solve_contacts(
            requests, numerics.cells_across, numerics.box_factor, numerics.tolerance,
            cells=numerics.cells, max_iterations=numerics.max_iterations,
        )  # fmt: skip
    except BallscrewError as error:
        raise _named(error, sides, numerics) from None
    approaches = {}
    for side, result in zip(sides, solved, strict=True):
        delta = np.empty(loads.size)
        delta[top] = result.approach
        delta[others] = [s.approach for s in result.extra]
        approaches[side] = delta
    return approaches


def _named(error: BallscrewError, sides: list[Side], numerics: NumericsSpec) -> BallscrewError:
    """``error`` of the tabulation's :func:`~ballscrew.contact.solve_contacts` call with the
    raceway of each batch index and the case fields that control it."""
    which = ", ".join(f"contact {k} = the {side} raceway" for k, side in enumerate(sides))
    if isinstance(error, ConvergenceError):
        return ConvergenceError(
            f"{error.solver}, tabulating the contact law ({which}; numerics.max_iterations = "
            f"{numerics.max_iterations}, numerics.tolerance = {numerics.tolerance:g})",
            error.iterations, error.residual, error.tolerance,
        )  # fmt: skip
    if isinstance(error, InputError):
        return error
    return BallscrewError(
        f"{error} (tabulating the contact law, {which}: numerics.box_factor = "
        f"{numerics.box_factor!r} in the case)"
    )


def _check_cells(
    c: RacewayCurvature, e_star: float, loads: NDArray[np.float64], numerics: NumericsSpec
) -> None:
    """Refuse a grid of the largest of ``loads`` [N] (:func:`ballscrew.contact.grid_cells`)
    that leaves fewer than :data:`MIN_CELLS` cells across the smallest load's contact."""
    estimate = hertz(c.rx, c.ry, e_star, float(loads.max()))
    dx, dy, _, _ = grid_cells(estimate, numerics.cells_across, numerics.box_factor, numerics.cells)
    low = hertz(c.rx, c.ry, e_star, float(loads.min()))
    across = min(2.0 * low.a / dx, 2.0 * low.b / dy)
    if across < MIN_CELLS:
        raise _too_coarse(numerics, low, estimate, across)


def _too_coarse(
    numerics: NumericsSpec, low: HertzContact, top: HertzContact, across: float
) -> InputError:
    """The error for a grid with ``across`` < :data:`MIN_CELLS` cells across the smallest
    tabulated load's contact ``low`` (its δ is off by several % below that)."""
    scale = MIN_CELLS / across
    if numerics.cells is None:
        field, value = "numerics.cells_across", numerics.cells_across
        need = f"≥ {math.ceil(scale * value)}"
    else:
        field, value = "numerics.cells", list(numerics.cells)
        need = "≥ [{}, {}]".format(*(math.ceil(scale * n) for n in value))
    return InputError(
        field,
        value,
        f"{need} with loads.contact = 'numerical' ({MIN_CELLS} cells across the smallest "
        f"tabulated contact, Q = {low.load:.3g} N, on the grid of Q = {top.load:.3g} N; it has "
        f"{across:.1f})",
    )


@lru_cache(maxsize=16)
def _table(
    geometry: ScrewGeometry, e_stars: tuple[float, float], numerics: str, top: float
) -> TabulatedContact:
    spec = NumericsSpec.model_validate_json(numerics)
    loads = table_loads(top / TOP_FACTOR)
    both = raceways_approaches(geometry, dict(zip(SIDES, e_stars, strict=True)), loads, spec)
    return TabulatedContact(loads, both["screw"] + both["nut"])


def clear_cache() -> None:
    """Forget the tabulated laws (the next :func:`numerical_contact` solves again)."""
    _table.cache_clear()


def numerical_contact(params: ScrewParameters, numerics: NumericsSpec) -> TabulatedContact:
    """Q(δ) of a ball's screw and nut contacts in series from the contact solver (cached).

    The nominal ball load is that of the case's nut forces (the larger of F_p and F_a for a
    nut preloaded on both flanks, F_p + F_a for one flank, over Z sinβ cosα per flank). The
    law is cached; a distribution whose balls go above the table's top warns through
    :func:`warn_above_table`.
    """
    fp, fa = params.preload, params.axial_load
    flanks = params.flanks
    force = max(fp, fa) if flanks.count == 2 else fp + fa
    if not force > 0.0:
        raise InputError("operating.axial_load", fa, "> 0 N where the preload is 0 N")
    top = float(table_loads(force / (flanks.balls * params.axial_projection))[-1])
    e_stars = (params.contact_modulus("screw"), params.contact_modulus("nut"))
    return _table(params.geometry, e_stars, numerics.model_dump_json(), top)
