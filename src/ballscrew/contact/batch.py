"""Many normal contacts on one grid in one call: the preconditioned CG along a leading batch axis.

B contacts (the balls of a nut, the flanks, the steps of a wear run, the raceways of a screw) on
grids of the same cell counts are solved together: every array is a (B, nx, ny) stack, each contact
has its own gap, load, step length, conjugacy and stop (and, if given per contact, its own cell
sizes and E*, so its own influence kernel), and a converged contact leaves the stack
(:func:`ballscrew.contact.preconditioned.solve_batch`). Each result equals the one
:func:`~ballscrew.contact.solve_normal` gives for that contact alone.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ballscrew.backend import array_module
from ballscrew.contact._validation import (
    PLAUSIBLE_E_STAR,
    composite_modulus_checked,
    finite_grid,
    gap_grid,
    integer_at_least,
    positive,
)
from ballscrew.contact.convolution import DCFFTOperator, DCFFTStack
from ballscrew.contact.polonsky_keer import (
    BATCH_HINT,
    DEFAULT_MAX_ITERATIONS,
    DEFAULT_TOLERANCE,
    PRECISIONS,
    SOLVER,
    _finish,
    _Iterate,
    _Problem,
)
from ballscrew.contact.preconditioned import solve_batch
from ballscrew.contact.result import ContactResult
from ballscrew.errors import ConvergenceError, InputError

__all__ = ["solve_normal_batch"]


def _per_contact(field: str, values: Any, batch: int, unit: str) -> np.ndarray:
    """One value per contact (a scalar applies to all), each finite and > 0."""
    values = np.asarray(values, dtype=np.float64)
    if values.ndim > 1 or values.size not in (1, batch):
        raise InputError(field, f"array of shape {values.shape}", f"a scalar or shape ({batch},)")
    values = np.broadcast_to(values, (batch,)).copy()
    for value in values:
        positive(field, float(value), unit)
    return values


def _cells(dx: Any, dy: Any, e_star: Any, batch: int) -> tuple[Any, Any, Any]:
    """dx, dy [m] and E* [Pa] as three floats if all contacts share them, else three (B,) arrays."""
    if all(np.ndim(v) == 0 for v in (dx, dy, e_star)):
        e_star = composite_modulus_checked("e_star", e_star, stacklevel=4)
        return positive("dx", dx, "m"), positive("dy", dy, "m"), e_star
    cells = [
        _per_contact(field, value, batch, unit)
        for field, value, unit in (("dx", dx, "m"), ("dy", dy, "m"), ("e_star", e_star, "Pa"))
    ]
    low, high = PLAUSIBLE_E_STAR  # one warning for the batch, of its first implausible E*
    odd = cells[2][(cells[2] < low) | (cells[2] > high)]
    composite_modulus_checked("e_star", (odd if odd.size else cells[2])[0], stacklevel=4)
    if all(bool((v == v[0]).all()) for v in cells):  # one operator serves all
        return float(cells[0][0]), float(cells[1][0]), float(cells[2][0])
    return cells[0], cells[1], cells[2]


def solve_normal_batch(
    gaps: Any,
    dx: Any,
    dy: Any,
    e_star: Any,
    loads: Any,
    tol: float = DEFAULT_TOLERANCE,
    *,
    max_iterations: int = DEFAULT_MAX_ITERATIONS,
    initial: Any = None,
    precision: str = "float64",
    nested: bool = True,
    raise_on_failure: bool = True,
) -> tuple[ContactResult, ...]:
    """Pressures of B contacts on one grid, each under its own load and gap (load control).

    The preconditioned Polonsky & Keer CG (method ``"pcg"`` of
    :func:`~ballscrew.contact.solve_normal`, Vollebregt 2014 preconditioner, nested-grid start)
    run on all contacts at once; the convolutions of the stack are batched FFTs. Contacts with
    their own cell sizes or modulus each keep the exact kernel spectrum of their cells (Love's
    coefficients do not scale as one kernel when dx/dy differs), so each result equals that of
    :func:`~ballscrew.contact.solve_normal` on its own grid.

    Parameters
    ----------
    gaps
        Initial gaps h [m], a (B, nx, ny) NumPy or CuPy array; ``gaps[b, i, j]`` at (x_i, y_j).
    dx, dy
        Cell sizes [m], common to all contacts (scalars) or one per contact (shape (B,)).
    e_star
        Composite modulus E* [Pa], common to all contacts or one per contact (shape (B,)).
    loads
        Normal loads W [N], shape (B,) (or one scalar for all).
    tol, max_iterations, precision, nested
        As in :func:`~ballscrew.contact.solve_normal`, for every contact.
    initial
        Warm-start pressures, a (B, nx, ny) array (≥ 0, positive sum per contact).
    raise_on_failure
        If False, unconverged contacts come back with ``converged=False``; otherwise the first
        one raises :class:`~ballscrew.errors.ConvergenceError`.

    Returns
    -------
    tuple[ContactResult, ...]
        One result per contact, in the order of the stack.
    """
    xp = array_module(gaps)
    h = gap_grid("gaps", gaps, xp, ndim=3)
    batch, nx, ny = h.shape
    dx, dy, e_star = _cells(dx, dy, e_star, batch)
    tol = positive("tol", tol)
    max_iterations = integer_at_least("max_iterations", max_iterations, 1)
    if precision not in PRECISIONS:
        raise InputError("precision", precision, f"one of {', '.join(PRECISIONS)}")
    total = _per_contact("loads", loads, batch, "N") / (dx * dy)
    p = None
    if initial is not None:
        p = finite_grid("initial", initial, xp, ndim=3)
        if p.shape != h.shape:
            raise InputError("initial", f"array of shape {p.shape}", f"shape {h.shape}")
        if bool((p < 0.0).any()) or not bool((p.sum(axis=(1, 2)) > 0.0).all()):
            raise InputError("initial", "array", "pressures ≥ 0 with a positive sum per contact")
    shared = np.ndim(dx) == 0
    operator = (DCFFTOperator.for_grid if shared else DCFFTStack.for_grids)(
        (nx, ny), dx, dy, e_star, xp
    )
    state = solve_batch(
        h, dx, dy, e_star, total, tol, max_iterations,
        initial=p, nested=nested, dtype=PRECISIONS[precision], operator=operator,
    )  # fmt: skip
    results = []
    for b in range(batch):
        problem = (
            _Problem(h[b], dx, dy, tol, max_iterations, operator)
            if shared
            else _Problem(h[b], dx[b], dy[b], tol, max_iterations, operator.operators[b])
        )
        iterate = _Iterate(
            state.pressure[b],
            int(state.iterations[b]),
            float(state.residual[b]),
            bool(state.converged[b]),
            float(state.coarse_work[b]),
            None if state.displacement is None else state.displacement[b],
        )
        if not iterate.converged and raise_on_failure:
            raise ConvergenceError(
                f"{SOLVER} (contact {b} of the batch)", iterate.iterations, iterate.residual, tol,
                BATCH_HINT,
            )  # fmt: skip
        results.append(_finish(iterate, problem, raise_on_failure))
    return tuple(results)
