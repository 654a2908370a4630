"""The numerical (non-Hertzian) load–approach law of a ball's two contacts, for the distribution.

``[loads] contact = "numerical"``: every ball of the elastic distribution follows δ(Q) of the
contact solver on the case's raceway gap (the exact conforming groove with ``numerics.gap_model =
"exact"``) instead of Hertz. All balls share the groove geometry, so δ is tabulated at
:data:`TABLE_POINTS` loads, geometrically spaced over a span of :data:`TABLE_SPAN` up to the
tabulation top Q_top (the power of two at or above :data:`TOP_FACTOR` × the nominal ball load
F/(Z sinβ cosα), so nearby load cases share one table), with one batched solve for both raceways
(:func:`ballscrew.contact.solve_normal_batch`, each raceway on the cells of its own largest load),
and interpolated monotonically (:class:`ballscrew.loads.contact_law.TabulatedContact`). The grid
follows the Hertz ellipse of Q_top (``numerics.cells_across`` cells across it, or
``numerics.cells``, box ``numerics.box_factor``) and is enlarged like a single solve until the
pressure of Q_top vanishes
at its edge; the smallest load then has about cells_across / TABLE_SPAN^(1/3) cells across,
and a grid leaving it fewer than :data:`MIN_CELLS` is refused (cells_across ≥ 41).

Ball-diameter errors enter the distribution as approach offsets; the law itself is that of the
nominal ball (a 1 µm larger ball changes the contact curvatures by ~1e-4, neglected).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np
import scipy.fft
from numpy.typing import NDArray

from ballscrew.analyses.parameters import SIDES, ScrewParameters, Side
from ballscrew.budget import check_memory, contact_grid_bytes
from ballscrew.case import NumericsSpec
from ballscrew.contact import HertzContact, cell_centres, hertz, solve_normal_batch
from ballscrew.errors import BallscrewError, InputError
from ballscrew.geometry import ScrewGeometry, gap_function, raceway_curvature
from ballscrew.loads.contact_law import TabulatedContact

__all__ = [
    "MIN_CELLS",
    "TABLE_POINTS",
    "TABLE_SPAN",
    "TOP_FACTOR",
    "clear_cache",
    "numerical_contact",
    "outside_ball",
    "raceway_approaches",
    "raceways_approaches",
    "table_loads",
]

TABLE_POINTS = 7
"""Tabulation loads (one batch entry each)."""
TABLE_SPAN = 128.0
"""Largest over smallest tabulation load."""
TOP_FACTOR = 6.0
"""Q_top ≥ this × the nominal ball load: the most loaded ball of an uneven distribution stays
inside the table (beyond it the end exponent continues the law)."""
MIN_CELLS = 8
"""Fewest grid cells across the smallest tabulated load's contact (each axis)."""
_EDGE = 1e-6
"""Edge pressure over peak pressure from which the grid is enlarged (as a single solve)."""
_GROWTH, _ENLARGEMENTS = 1.5, 4


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

    One :func:`~ballscrew.contact.solve_normal_batch` call on the grid of the largest load
    (sized as :func:`ballscrew.contact.solve_contact` sizes it), enlarged while the largest
    contact carries pressure on the grid's edge.
    """
    return raceways_approaches(geometry, {side: e_star}, loads, numerics)[side]


@dataclass
class _Table:
    """The tabulation grid of one raceway: its gap function, cells and cell counts."""

    gap: Any
    dx: float
    dy: float
    nx: int
    ny: int


def _table_grid(
    geometry: ScrewGeometry,
    side: Side,
    e_star: float,
    loads: NDArray[np.float64],
    numerics: NumericsSpec,
) -> _Table:
    """The grid of the largest of ``loads`` [N] on the ``side`` raceway (as solve_contact's);
    refused when it leaves fewer than :data:`MIN_CELLS` cells across the smallest load."""
    c = raceway_curvature(geometry, side)
    estimate = hertz(c.rx, c.ry, e_star, float(loads[-1]))
    fx, fy = (numerics.box_factor,) * 2 if np.isscalar(numerics.box_factor) else numerics.box_factor
    if numerics.cells is None:
        n = numerics.cells_across
        dx, dy = 2.0 * estimate.a / n, 2.0 * estimate.b / n
        nx, ny = (scipy.fft.next_fast_len(math.ceil(f * n), real=True) for f in (fx, fy))
    else:
        nx, ny = numerics.cells
        dx, dy = 2.0 * fx * estimate.a / nx, 2.0 * fy * estimate.b / ny
    low = hertz(c.rx, c.ry, e_star, float(loads[0]))
    across = min(2.0 * low.a / dx, 2.0 * low.b / dy)
    if across < MIN_CELLS:
        raise _too_coarse(numerics, low, estimate, across)
    return _Table(gap_function(geometry, side, model=numerics.gap_model), dx, dy, nx, ny)


def raceways_approaches(
    geometry: ScrewGeometry,
    e_stars: dict[Side, float],
    loads: NDArray[np.float64],
    numerics: NumericsSpec,
) -> dict[Side, NDArray[np.float64]]:
    """:func:`raceway_approaches` of each raceway of ``e_stars`` (side → E* [Pa]).

    The raceways whose grids have equal cell counts (each follows the Hertz ellipse of its own
    largest load) are solved in one :func:`~ballscrew.contact.solve_normal_batch` call, each
    with its own cells and E*; a raceway whose largest contact reaches the grid's edge is
    enlarged and solved again in the next round.
    """
    top = float(loads[-1])
    grids = {side: _table_grid(geometry, side, e, loads, numerics) for side, e in e_stars.items()}
    field, value = (
        ("numerics.cells_across", numerics.cells_across)
        if numerics.cells is None
        else ("numerics.cells", list(numerics.cells))
    )
    approaches: dict[Side, NDArray[np.float64]] = {}
    for _ in range(_ENLARGEMENTS + 1):
        rounds: dict[tuple[int, int], list[Side]] = {}
        for side in grids.keys() - approaches.keys():
            rounds.setdefault((grids[side].nx, grids[side].ny), []).append(side)
        for (nx, ny), sides in rounds.items():
            sides.sort(key=SIDES.index)
            size = len(sides) * loads.size
            what = f"the {size} × {nx} × {ny} batch of tabulation contacts"
            check_memory(field, value, size * contact_grid_bytes(nx, ny), what)
            gaps = []
            for side in sides:
                g = grids[side]
                x, y = cell_centres(nx, g.dx), cell_centres(ny, g.dy)
                try:
                    h = np.asarray(g.gap(x[:, None], y[None, :]), dtype=float)
                except InputError as exc:
                    raise outside_ball(exc, geometry, side, top) from None
                gaps.append(np.broadcast_to(h, (loads.size, nx, ny)))
            results = solve_normal_batch(
                np.concatenate(gaps),
                np.repeat([grids[side].dx for side in sides], loads.size),
                np.repeat([grids[side].dy for side in sides], loads.size),
                np.repeat([e_stars[side] for side in sides], loads.size),
                np.tile(loads, len(sides)), numerics.tolerance,
                max_iterations=numerics.max_iterations,
            )  # fmt: skip
            for k, side in enumerate(sides):
                mine = results[k * loads.size : (k + 1) * loads.size]
                p = np.asarray(mine[-1].pressure)
                peak = float(p.max())
                x_edge = max(float(p[0].max()), float(p[-1].max())) > _EDGE * peak
                y_edge = max(float(p[:, 0].max()), float(p[:, -1].max())) > _EDGE * peak
                if not (x_edge or y_edge):
                    approaches[side] = np.array([r.approach for r in mine])
                    continue
                g = grids[side]
                g.nx = scipy.fft.next_fast_len(math.ceil(_GROWTH * nx), real=True) if x_edge else nx
                g.ny = scipy.fft.next_fast_len(math.ceil(_GROWTH * ny), real=True) if y_edge else ny
        if len(approaches) == len(grids):
            return approaches
    side = next(side for side in SIDES if side in grids.keys() - approaches.keys())
    raise BallscrewError(
        f"the {side} contact of the tabulation load {top:.4g} N still reaches the "
        f"edge of its grid after {_ENLARGEMENTS} enlargements: raise numerics.box_factor"
    )


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
    double nut, F_p + F_a for one nut, over Z sinβ cosα).
    """
    fp, fa = params.preload, params.axial_load
    force = max(fp, fa) if params.nut_count == 2 else fp + fa
    if not force > 0.0:
        raise InputError("operating.axial_load", fa, "> 0 N where the preload is 0 N")
    top = float(table_loads(force / (params.balls_per_nut * params.axial_projection))[-1])
    e_stars = (params.contact_modulus("screw"), params.contact_modulus("nut"))
    return _table(params.geometry, e_stars, numerics.model_dump_json(), top)
