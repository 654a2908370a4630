"""Normal contact on the elastic half-space: the Polonsky & Keer conjugate-gradient solver.

Polonsky & Keer (1999), Wear 231:206, "A numerical method for solving rough contact problems based
on the multi-level multi-summation and conjugate gradient techniques", with the convolutions done
by DC-FFT (Liu, Wang & Liu 2000). Unknowns: cell pressures p ≥ 0 and the approach δ, such that

(C1) s = h + u − δ = 0 where p > 0 and s ≥ 0 where p = 0, u = K ∗ p  (K5);
(C2) dx·dy·Σp = W  (load control, δ is its Lagrange multiplier), or δ given (displacement control).

Each iteration costs one convolution (of the search direction); the displacement u = K ∗ p is
updated from it as u ← scale·(u − τ r) when the step neither clips a pressure nor re-admits a cell,
and recomputed by a second convolution otherwise. All array work is written against the array module
of the gap, so the same code runs on NumPy and CuPy arrays.

The solver is chosen by name from :data:`NORMAL_SOLVERS`: ``"pcg"`` (default), the same iteration
with the spectral preconditioner and the nested-grid start of
:mod:`ballscrew.contact.preconditioned`, or ``"pk"``, the plain Polonsky & Keer CG of this module.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from dataclasses import dataclass
from types import ModuleType
from typing import Any

import numpy as np

from ballscrew.backend import array_module, blas_single_thread
from ballscrew.contact._validation import (
    composite_modulus_checked,
    gap_grid,
    integer_at_least,
    positive,
)
from ballscrew.contact.convolution import DCFFTOperator
from ballscrew.contact.preconditioned import solve_batch
from ballscrew.contact.result import ContactResult
from ballscrew.errors import ConvergenceError, InputError
from ballscrew.registry import Registry

__all__ = [
    "DEFAULT_METHOD",
    "NORMAL_SOLVERS",
    "PRECISIONS",
    "solve_normal",
    "solve_normal_displacement",
]

SOLVER = "Polonsky-Keer conjugate gradient"
PCG_HINT = 'try method="pk" (the plain Polonsky-Keer CG) or a larger max_iterations'
"""What a :class:`~ballscrew.errors.ConvergenceError` of the preconditioned solver suggests."""
BATCH_HINT = (
    'try a larger max_iterations, or the contact alone by solve_normal(..., method="pk") '
    "(the plain Polonsky-Keer CG)"
)
""":data:`PCG_HINT` where the caller (a batch, a grid-sized solve) has no ``method``."""
DEFAULT_METHOD = "pcg"
"""Solver of :func:`solve_normal` (a name of :data:`NORMAL_SOLVERS`)."""
PRECISIONS = {"float64": np.float64, "mixed": np.float32}
"""``precision`` → FFT precision of the iterations; ``"mixed"`` finishes in float64 (pcg only)."""
DEFAULT_MAX_ITERATIONS = 2000
"""CG iterations before a solve is a :class:`~ballscrew.errors.ConvergenceError`."""
DEFAULT_TOLERANCE = 1e-8
"""Relative pressure change at which the CG stops."""


@dataclass
class _Iterate:
    """State handed back by :func:`_conjugate_gradient`."""

    pressure: Any
    iterations: int
    residual: float
    converged: bool
    coarse_work: float = 0.0
    displacement: Any = None
    """u = K ∗ p of the final pressure if the solver computed it exactly, else None."""


def _reductions_context(xp: ModuleType) -> contextlib.AbstractContextManager[None]:
    return blas_single_thread() if xp is np else contextlib.nullcontext()


def _row_span(mask: Any) -> tuple[int, int]:
    """First and one-past-last row of ``mask`` holding a True value ((0, 0) if none)."""
    xp = array_module(mask)
    rows = xp.flatnonzero(mask.any(axis=1))
    return (int(rows[0]), int(rows[-1]) + 1) if rows.size else (0, 0)


def _min_outside(a: Any, lo: int, hi: int) -> float:
    """Smallest value of ``a`` outside rows lo:hi (+inf if there is none)."""
    parts = [part.min() for part in (a[:lo], a[hi:]) if part.size]
    return min((float(v) for v in parts), default=np.inf)


def _conjugate_gradient(
    h: Any,
    p: Any,
    u: Any,
    operator: DCFFTOperator,
    tol: float,
    max_iterations: int,
    total: float | None,
) -> _Iterate:
    """Polonsky & Keer (1999) CG, load control or displacement control (``docs/theory/contact.md``).

    ``h`` is the gap (load control) or h − δ (displacement control, ``total`` None); ``p`` the
    initial pressures (modified in place) and ``u`` = K ∗ p (modified in place). Load control keeps
    Σp = ``total`` = W/(dx·dy): the gap and the conjugate response are taken relative to their means
    over the contact set (Eqs. 24-26 and 30-32) and p is rescaled after each step (Eqs. 38-39).

    Bookkeeping: p and t vanish outside the band of rows lo:hi that holds the contact set, so the
    contact-set arithmetic runs on that (contiguous) band only; the gap g = u + h − ḡ is still
    checked on every cell for penetration (Eq. 37), and the band grows when a cell outside it
    re-enters.
    """
    xp = array_module(h)
    load_control = total is not None
    q, t, r, p_old, contact, step, work = (xp.empty_like(h) for _ in range(7))
    t.fill(0.0)
    empty, penetrating = xp.empty(h.shape, dtype=bool), xp.empty(h.shape, dtype=bool)
    lo, hi = _row_span(p > 0.0)
    conjugate, g_norm_old, residual = False, 1.0, np.inf
    for iteration in range(1, max_iterations + 1):
        # Step 3: q = u + h, contact set I_c = {p > 0}, gap g = q − ḡ on I_c (in `s`).
        xp.add(u, h, out=q)
        pb, tb, qb = p[lo:hi], t[lo:hi], q[lo:hi]
        c, s, w = contact[lo:hi], step[lo:hi], work[lo:hi]
        xp.greater(pb, 0.0, out=c)
        n_contact = float(c.sum())
        xp.multiply(qb, c, out=s)
        g_mean = float(s.sum()) / n_contact if load_control else 0.0
        if load_control:
            xp.subtract(qb, g_mean, out=s)
            xp.multiply(s, c, out=s)
        # Step 4: new conjugate direction t on I_c (Eqs. 27-29).
        g_norm = float(xp.vdot(s, s))
        if g_norm > 0.0:
            if conjugate:
                xp.multiply(tb, g_norm / g_norm_old, out=tb)
                xp.multiply(tb, c, out=tb)
                xp.add(tb, s, out=tb)
            else:
                xp.copyto(tb, s)
            g_norm_old = g_norm
            # Step 5: r = K ∗ t and the step length τ (Eqs. 30-33).
            operator.apply(t, out=r)
            rb = r[lo:hi]
            curvature = float(xp.vdot(rb, tb))
            if load_control:
                curvature -= float(xp.vdot(rb, c)) / n_contact * float(tb.sum())
            if not curvature > 0.0:  # breakdown: no descent along t
                return _Iterate(p, iteration, residual, False)
            tau = float(xp.vdot(s, tb)) / curvature
        else:  # g is uniform on I_c (one cell, say): no CG step; only Eq. 37 can move p, with
            # the step of a lone cell, τ = 1/K(0, 0).
            t.fill(0.0)
            r.fill(0.0)
            tau = 1.0 / operator.self_coefficient
        # Steps 6-7: p ← max(p − τ t, 0) (Eqs. 34-36).
        xp.copyto(p_old[lo:hi], pb)
        xp.multiply(tb, tau, out=w)
        xp.subtract(pb, w, out=pb)
        clipped = float(pb.min()) < 0.0
        if clipped:
            xp.maximum(pb, 0.0, out=pb)
        # Step 8: cells with p = 0 and g < 0 re-enter the contact (Eq. 37); conjugacy is reset.
        if _min_outside(q, lo, hi) < g_mean:
            new_lo, new_hi = _row_span(q < g_mean)
            new_lo, new_hi = min(lo, new_lo), max(hi, new_hi)
            p_old[new_lo:lo] = 0.0
            p_old[hi:new_hi] = 0.0
            lo, hi = new_lo, new_hi
            pb, qb, w = p[lo:hi], q[lo:hi], work[lo:hi]
        zero, enter = empty[lo:hi], penetrating[lo:hi]
        xp.less_equal(pb, 0.0, out=zero)
        xp.less(qb, g_mean, out=enter)
        xp.logical_and(zero, enter, out=enter)
        readmitted = bool(enter.any())
        if readmitted:
            xp.subtract(qb, g_mean, out=w)
            xp.multiply(w, enter, out=w)
            xp.multiply(w, tau, out=w)
            xp.subtract(pb, w, out=pb)
        conjugate = not readmitted
        # Step 9: load balance (Eqs. 38-39).
        current = float(pb.sum())
        if not current > 0.0:
            return _Iterate(p, iteration, np.inf, False)
        scale = total / current if load_control else 1.0
        if load_control:
            xp.multiply(pb, scale, out=pb)
        # Step 10: ε = Σ|p − p_old| / Σp (Eq. 40).
        xp.subtract(pb, p_old[lo:hi], out=w)
        xp.abs(w, out=w)
        residual = float(w.sum()) / (total if load_control else current)
        if clipped or readmitted:
            operator.apply(p, out=u)
        else:  # p = scale·(p_old − τ t) exactly, so u = scale·(u_old − τ r).
            xp.multiply(r, tau, out=step)
            xp.subtract(u, step, out=u)
            if load_control:
                xp.multiply(u, scale, out=u)
        if residual < tol:
            return _Iterate(p, iteration, residual, True)
        # Shrink the band to the rows that still carry pressure; t must vanish outside it.
        first, last = _row_span(pb > 0.0)
        t[lo : lo + first] = 0.0
        t[lo + last : hi] = 0.0
        lo, hi = lo + first, lo + last
    return _Iterate(p, max_iterations, residual, False)


Solver = Callable[[Any, Any, DCFFTOperator, float, int, Any, bool, type], _Iterate]
NORMAL_SOLVERS: Registry[Solver] = Registry("normal contact solver", "method")
"""Iterations of the normal contact solvers: f(h, p, operator, tol, max_iterations, total,
nested, dtype) → state; ``p`` None asks for the solver's own start, ``total`` None for
displacement control."""


@NORMAL_SOLVERS.register(
    "pcg",
    "Polonsky & Keer CG with the spectral preconditioner of Vollebregt (2014) and a nested-grid "
    "start (iteration count nearly independent of the grid)",
)
def _preconditioned(
    h: Any,
    p: Any,
    operator: DCFFTOperator,
    tol: float,
    max_iterations: int,
    total: float | None,
    nested: bool,
    dtype: type,
) -> _Iterate:
    """One contact through :func:`~ballscrew.contact.preconditioned.solve_batch` (batch of 1)."""
    state = solve_batch(
        h[None], operator.dx, operator.dy, operator.e_star,
        None if total is None else np.array([total]), tol, max_iterations,
        initial=None if p is None else p[None], nested=nested, dtype=dtype, operator=operator,
    )  # fmt: skip
    return _Iterate(
        state.pressure[0],
        int(state.iterations[0]),
        float(state.residual[0]),
        bool(state.converged[0]),
        float(state.coarse_work[0]),
        None if state.displacement is None else state.displacement[0],
    )


@NORMAL_SOLVERS.register("pk", "Polonsky & Keer (1999) CG, unpreconditioned, uniform start")
def _plain(
    h: Any,
    p: Any,
    operator: DCFFTOperator,
    tol: float,
    max_iterations: int,
    total: float | None,
    nested: bool,
    dtype: type,
) -> _Iterate:
    """:func:`_conjugate_gradient` from ``p`` (uniform if None); ``nested`` is ignored."""
    xp = array_module(h)
    if dtype is not np.float64:
        raise InputError("precision", "mixed", "float64 with method 'pk' (mixed needs 'pcg')")
    if p is None:
        p = xp.full(h.shape, total / h.size)
    with _reductions_context(xp):
        return _conjugate_gradient(h, p, operator.apply(p), operator, tol, max_iterations, total)


def _solver(method: str, precision: str) -> tuple[Solver, type]:
    """The registered solver ``method`` and the FFT precision named ``precision``."""
    if precision not in PRECISIONS:
        raise InputError("precision", precision, f"one of {', '.join(PRECISIONS)}")
    return NORMAL_SOLVERS[method], PRECISIONS[precision]


@dataclass(frozen=True)
class _Problem:
    """Checked inputs shared by both solvers."""

    h: Any
    dx: float
    dy: float
    tol: float
    max_iterations: int
    operator: DCFFTOperator

    @property
    def xp(self) -> ModuleType:
        return array_module(self.h)


def _problem(
    gap: Any,
    dx: float,
    dy: float,
    e_star: float,
    tol: float,
    max_iterations: int,
    operator: DCFFTOperator | None,
) -> _Problem:
    """Check the inputs (InputError naming the argument; the memory budget before anything is
    allocated) and find the grid's DC-FFT operator."""
    xp = array_module(gap)
    h = gap_grid("gap", gap, xp)
    dx, dy = positive("dx", dx), positive("dy", dy)
    e_star = composite_modulus_checked("e_star", e_star, stacklevel=4)
    tol = positive("tol", tol)
    max_iterations = integer_at_least("max_iterations", max_iterations, 1)
    if operator is None:
        operator = DCFFTOperator.for_grid(h.shape, dx, dy, e_star, xp)
    elif not operator.matches(h.shape, dx, dy, e_star):
        raise InputError(
            "operator",
            f"DCFFTOperator(shape={operator.shape}, dx={operator.dx}, dy={operator.dy}, "
            f"e_star={operator.e_star})",
            f"the operator of this grid: shape={h.shape}, dx={dx}, dy={dy}, e_star={e_star}",
        )
    return _Problem(h, dx, dy, tol, max_iterations, operator)


def _initial_pressure(initial: Any, h: Any, xp: ModuleType) -> Any:
    """``initial`` as a new float64 array, checked: shape of the gap, finite, ≥ 0, positive sum."""
    p = xp.array(initial, dtype=xp.float64, copy=True)
    if p.shape != h.shape:
        raise InputError("initial", f"array of shape {p.shape}", f"an array of shape {h.shape}")
    if not bool(xp.isfinite(p).all()) or bool((p < 0.0).any()) or not float(p.sum()) > 0.0:
        raise InputError("initial", "array", "finite pressures ≥ 0 with a positive sum")
    return p


def _finish(
    state: _Iterate,
    problem: _Problem,
    raise_on_failure: bool,
    approach: float | None = None,
    method: str = DEFAULT_METHOD,
) -> ContactResult:
    """Check convergence (the error of ``method`` "pcg" suggests "pk"), recompute u = K ∗ p
    exactly, and collect the result."""
    if not state.converged and raise_on_failure:
        hint = PCG_HINT if method == "pcg" else ""
        raise ConvergenceError(SOLVER, state.iterations, state.residual, problem.tol, hint)
    h, p = problem.h, state.pressure
    u = problem.operator.apply(p) if state.displacement is None else state.displacement
    contact = p > 0.0
    n_contact = int(contact.sum())
    if approach is None:  # δ = mean of u + h over the contact set (Polonsky & Keer 1999).
        approach = float(problem.xp.where(contact, u + h, 0.0).sum()) / max(n_contact, 1)
    cell_area = problem.dx * problem.dy
    return ContactResult(
        pressure=p,
        displacement=u,
        approach=approach,
        load=float(p.sum()) * cell_area,
        contact_area=n_contact * cell_area,
        iterations=state.iterations,
        residual=state.residual,
        converged=state.converged,
        dx=problem.dx,
        dy=problem.dy,
        coarse_work=state.coarse_work,
    )


def solve_normal(
    gap: Any,
    dx: float,
    dy: float,
    e_star: float,
    load: float,
    tol: float = DEFAULT_TOLERANCE,
    *,
    max_iterations: int = DEFAULT_MAX_ITERATIONS,
    initial: Any = None,
    operator: DCFFTOperator | None = None,
    raise_on_failure: bool = True,
    method: str = DEFAULT_METHOD,
    precision: str = "float64",
    nested: bool = True,
) -> ContactResult:
    """Pressure under the normal load W between two bodies with the initial gap ``gap``.

    Load-controlled conjugate gradients of Polonsky & Keer (1999) on the discrete problem
    (C1)-(C2) with Love's cell coefficients (K4) and DC-FFT convolution (Liu, Wang & Liu 2000).

    Parameters
    ----------
    gap
        Initial separation h [m] at the cell centres, a 2-D NumPy or CuPy array; ``gap[i, j]`` is
        at (x_i, y_j), axis 0 along x.
    dx, dy
        Cell sizes along x and y [m].
    e_star
        Composite modulus E* [Pa] (K1).
    load
        Normal load W [N].
    tol
        Stop when Σ|p − p_old| / Σp < tol (Polonsky & Keer, Eq. 40).
    max_iterations
        Iterations allowed before :class:`~ballscrew.errors.ConvergenceError` is raised.
    initial
        Warm-start pressures (≥ 0, shape of ``gap``); rescaled to the load. Default: the nested-grid
        start (``method="pcg"`` with ``nested``), else uniform.
    operator
        A :class:`DCFFTOperator` of this grid to reuse; default: the cached one of the grid.
    raise_on_failure
        If False, return the last iterate with ``converged=False`` instead of raising.
    method
        A name of :data:`NORMAL_SOLVERS`: ``"pcg"`` (preconditioned, default) or ``"pk"``.
    precision
        ``"float64"``, or ``"mixed"``: float32 FFTs down to Σ|Δp|/Σp = 1e-5, then float64 to
        ``tol`` (``"pcg"`` only).
    nested
        Start from the solution on the grids coarsened 2 × 2 (``"pcg"`` without ``initial``).

    Returns
    -------
    ContactResult
        Pressure [Pa], displacement [m], approach δ = mean of u + h over the contact set [m], ...

    The grid must hold the whole contact patch: the half-space outside it carries no pressure.
    :func:`ballscrew.contact.solve_contact` sizes the grid and checks its edge.
    """
    load = positive("load", load)
    solver, dtype = _solver(method, precision)
    problem = _problem(gap, dx, dy, e_star, tol, max_iterations, operator)
    h, xp, op = problem.h, problem.xp, problem.operator
    total = load / (problem.dx * problem.dy)
    p = None
    if initial is not None:
        p = _initial_pressure(initial, h, xp)
        p *= total / float(p.sum())
    state = solver(h, p, op, problem.tol, problem.max_iterations, total, bool(nested), dtype)
    return _finish(state, problem, raise_on_failure, method=method)


def solve_normal_displacement(
    gap: Any,
    dx: float,
    dy: float,
    e_star: float,
    approach: float,
    tol: float = DEFAULT_TOLERANCE,
    *,
    max_iterations: int = DEFAULT_MAX_ITERATIONS,
    initial: Any = None,
    operator: DCFFTOperator | None = None,
    raise_on_failure: bool = True,
    method: str = DEFAULT_METHOD,
    precision: str = "float64",
) -> ContactResult:
    """Pressure and load for a given rigid-body approach δ (displacement control).

    Polonsky & Keer (1999) CG with g = u + h − δ and neither the mean subtraction nor the load
    rescaling; stops when Σ|p − p_old| / Σp < tol. The initial guess is p ∝ (δ − h)⁺ scaled to
    minimise the complementary energy (C3) along it, unless ``initial`` (pressures [Pa], used as
    given) is. The load W = dx·dy·Σp is an output. Parameters as :func:`solve_normal`, with
    ``approach`` δ [m] (> 0) in place of the load (no nested-grid start).
    """
    approach = positive("approach", approach)
    solver, dtype = _solver(method, precision)
    problem = _problem(gap, dx, dy, e_star, tol, max_iterations, operator)
    h, xp, op = problem.h, problem.xp, problem.operator
    h_shifted = h - approach
    p = xp.maximum(-h_shifted, 0.0) if initial is None else _initial_pressure(initial, h, xp)
    if not float(p.sum()) > 0.0:  # No interference anywhere: the bodies do not touch.
        return _finish(_Iterate(p, 0, 0.0, True), problem, raise_on_failure, approach, method)
    if initial is None:
        with _reductions_context(xp):
            p *= -float(xp.vdot(p, h_shifted)) / float(xp.vdot(p, op.apply(p)))
    state = solver(h_shifted, p, op, problem.tol, problem.max_iterations, None, False, dtype)
    return _finish(state, problem, raise_on_failure, approach, method)
