"""Many normal contacts on one grid in one call: the preconditioned CG along a leading batch axis.

B contacts (the balls of a nut, the flanks, the steps of a wear run) that share the cell sizes and
E* are solved together: every array is a (B, nx, ny) stack, each contact has its own gap, load,
step length, conjugacy and stop, and a converged contact leaves the stack
(:func:`ballscrew.contact.preconditioned.solve_batch`). Each result equals the one
:func:`~ballscrew.contact.solve_normal` gives for that contact alone.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ballscrew.backend import array_module
from ballscrew.contact._validation import finite_grid, integer_at_least, positive
from ballscrew.contact.convolution import DCFFTOperator
from ballscrew.contact.polonsky_keer import (
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


def _loads(loads: Any, batch: int) -> np.ndarray:
    """One load per contact [N] (a scalar applies to all), each finite and > 0."""
    values = np.asarray(loads, dtype=np.float64)
    if values.ndim > 1 or values.size not in (1, batch):
        raise InputError("loads", f"array of shape {values.shape}", f"a scalar or shape ({batch},)")
    values = np.broadcast_to(values, (batch,)).copy()
    for value in values:
        positive("loads", float(value), "N")
    return values


def solve_normal_batch(
    gaps: Any,
    dx: float,
    dy: float,
    e_star: float,
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
    run on all contacts at once; the convolutions of the stack are batched FFTs.

    Parameters
    ----------
    gaps
        Initial gaps h [m], a (B, nx, ny) NumPy or CuPy array; ``gaps[b, i, j]`` at (x_i, y_j).
    dx, dy
        Cell sizes [m], common to all contacts.
    e_star
        Composite modulus E* [Pa], common to all contacts.
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
    h = finite_grid("gaps", gaps, xp, ndim=3)
    batch, nx, ny = h.shape
    dx, dy, e_star = positive("dx", dx, "m"), positive("dy", dy, "m"), positive("e_star", e_star)
    tol = positive("tol", tol)
    max_iterations = integer_at_least("max_iterations", max_iterations, 1)
    if precision not in PRECISIONS:
        raise InputError("precision", precision, f"one of {', '.join(PRECISIONS)}")
    total = _loads(loads, batch) / (dx * dy)
    p = None
    if initial is not None:
        p = finite_grid("initial", initial, xp, ndim=3)
        if p.shape != h.shape:
            raise InputError("initial", f"array of shape {p.shape}", f"shape {h.shape}")
        if bool((p < 0.0).any()) or not bool((p.sum(axis=(1, 2)) > 0.0).all()):
            raise InputError("initial", "array", "pressures ≥ 0 with a positive sum per contact")
    operator = DCFFTOperator.for_grid((nx, ny), dx, dy, e_star, xp)
    state = solve_batch(
        h, dx, dy, e_star, total, tol, max_iterations,
        initial=p, nested=nested, dtype=PRECISIONS[precision], operator=operator,
    )  # fmt: skip
    results = []
    for b in range(batch):
        problem = _Problem(h[b], dx, dy, tol, max_iterations, operator)
        iterate = _Iterate(
            state.pressure[b],
            int(state.iterations[b]),
            float(state.residual[b]),
            bool(state.converged[b]),
            float(state.coarse_work[b]),
        )
        if not iterate.converged and raise_on_failure:
            raise ConvergenceError(
                f"{SOLVER} (contact {b} of the batch)", iterate.iterations, iterate.residual, tol
            )
        results.append(_finish(iterate, problem, raise_on_failure))
    return tuple(results)
