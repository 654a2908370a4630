"""Preconditioned, nested-grid and batched conjugate gradients for the normal contact problem.

The constrained CG of Polonsky & Keer (1999) with three additions (``docs/theory/contact.md``):

1. A spectral preconditioner (after Vollebregt 2014, J. Comput. Phys. 257:333, "A new solver for
   the elastic normal contact problem using conjugate gradients, deflation, and an FFT-based
   preconditioner"): the projected gap g on the contact set I_c is multiplied by the inverse
   symbol of the half-space, M̂(k) = (E*/2)·|κ| ≈ 1/K̂(k), on the periodic nx × ny grid, and the
   result is restricted to I_c and made mean-free there, z = P (M ∗ g). P M P is symmetric and
   positive definite on the mean-free functions of I_c, so the projected CG stays a CG.
2. A nested-grid start (as in full multigrid, Brandt 1977; ASPHER): the problem is solved first on
   grids coarsened by 2 × 2 (gap averaged over the four cells), down to :data:`COARSEST` cells
   below the problem's grid and :data:`HERTZ_COARSEST` below a coarse one, each to
   :data:`COARSE_TOLERANCE`, the coarsest from a Hertz pressure, and the pressure is interpolated
   bilinearly to the next grid as its initial guess.
3. A window: each contact iterates on the rows and columns around its start's pressure, with a
   margin (:data:`WINDOW_MARGIN`), when they hold at most :data:`WINDOW_MAX_FRACTION` of the grid.
   DC-FFT on the window is the exact displacement there of a pressure that vanishes outside it;
   the preconditioner is periodic on the window. A whole-grid u = K ∗ p at the end checks that
   no cell outside penetrates (else that contact's CG goes on on its whole grid).

Every array carries a leading batch axis: B contacts on grids of the same cell counts, each with its
own gap and load, step length, conjugacy and stop, and either one operator for all (shared dx, dy,
E*) or one per contact (:class:`~ballscrew.contact.convolution.DCFFTStack`, with a stack of
preconditioner symbols). A contact that has converged leaves the batch.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache
from types import ModuleType
from typing import Any

import numpy as np
import scipy.fft

from ballscrew.backend import array_module, fft_threads, map_chunks
from ballscrew.budget import check_chunk
from ballscrew.contact.convolution import DCFFTOperator, DCFFTStack

__all__ = [
    "COARSEST",
    "COARSE_TOLERANCE",
    "HERTZ_COARSEST",
    "MIXED_SWITCH",
    "WINDOW_MARGIN",
    "WINDOW_MAX_FRACTION",
    "WINDOW_MIN_MARGIN",
    "BatchIterate",
    "solve_batch",
]

COARSEST = 32
"""Cells along the shorter axis below which the problem's grid is not coarsened (GUESS, tuned on the
64²-512² Hertz problems of the benchmark: 48 → 32 cut their work, fine iterations + coarse
equivalents, by 8-20 %; the fine-grid iterations stay at 13-15; 16 saves a little more work but
its tiny grids cost more in per-iteration overhead than they save)."""
COARSE_TOLERANCE = 1e-3
"""Stop of the coarse solves of the nested start: Σ|Δp|/Σp (GUESS, tuned as :data:`COARSEST`:
1e-5 → 1e-3 halves the coarse work and leaves the fine-grid iterations unchanged; the coarse
pressure is only the initial guess of the next grid, whose own discretisation error is O(h²))."""
HERTZ_COARSEST = 64
"""Cells along the shorter axis below which a coarse grid of a nested start is not coarsened
further but starts from :func:`_hertz_start` (GUESS, tuned on the Hertz problems of the
benchmark against the uniform start on 32-63 cells: coarse work in fine-grid iterations at 128²
2.38 → 0.75 (sphere) and 2.44 → 1.75 (ellipse), at 256² 2.09 → 1.69 and 2.11 → 1.94, the
fine-grid iterations unchanged; 128 cells did better on the sphere, worse on the ellipse)."""
MIXED_SWITCH = 1e-5
"""Σ|Δp|/Σp at which the float32 iterations of the mixed-precision solve hand over to float64
(float32 FFTs carry a relative error ~1e-7·log N; measured to stall near 1e-6)."""


@dataclass
class BatchIterate:
    """State of a batch of contacts handed back by :func:`solve_batch`."""

    pressure: Any
    """(B, nx, ny) cell pressures [Pa]."""
    iterations: Any
    """(B,) iterations on the finest grid."""
    coarse_work: Any
    """(B,) coarse-grid iterations in fine-grid equivalents (each × its cell count / the fine)."""
    residual: Any
    """(B,) final Σ|p − p_old| / Σp."""
    converged: Any
    """(B,) whether the residual reached the tolerance."""
    displacement: Any = None
    """(B, nx, ny) u = K ∗ p of the final pressures [m] (None on the coarse grids of a nested
    start)."""


class SpectralPreconditioner:
    """z = M ∗ g with M̂(k) = (E*/2)·√(κx² + κy²), κ = (2/Δ)·sin(πf), f = cycles per cell.

    The half-space's displacement symbol is K̂(k) = 2/(E*|k|) (Johnson 1985, the Fourier transform
    of the Boussinesq kernel 1/(π E* r)); its inverse is the Dirichlet-to-Neumann map (E*/2)|k|,
    taken on the periodic nx × ny grid with the finite-difference wave number κ (positive, equal
    to |k| at low frequencies). The mean mode, where M̂ = 0, gets the smallest non-zero value.
    """

    def __init__(self, shape: tuple[int, int], dx: float, dy: float, e_star: float, xp: ModuleType):
        nx, ny = shape
        kx = 2.0 / dx * np.sin(np.pi * np.fft.fftfreq(nx))
        ky = 2.0 / dy * np.sin(np.pi * np.fft.rfftfreq(ny))
        symbol = 0.5 * e_star * np.hypot(kx[:, None], ky[None, :])
        nonzero = symbol[symbol > 0.0]
        symbol[0, 0] = nonzero.min() if nonzero.size else 0.5 * e_star / max(dx, dy)
        symbol /= nx * ny  # the unnormalised inverse FFT's factor
        self.shape = (nx, ny)
        self.xp = xp
        self._symbol = {np.float64: xp.asarray(symbol), np.float32: xp.asarray(symbol, np.float32)}

    def apply(self, g: Any, dtype: type[np.floating] = np.float64) -> Any:
        """M ∗ g of each (nx, ny) grid of the stack ``g`` (float64 result)."""
        xp, shape = self.xp, self.shape
        g = g.astype(dtype, copy=False)
        if xp is np:  # threads over a stack as its convolutions, or within one large grid
            workers = max(fft_threads(g[0].size), min(fft_threads(4 * g.size), len(g)))
            spectrum = scipy.fft.rfft2(g, workers=workers)
            spectrum *= self._symbol[dtype]
            z = scipy.fft.irfft2(spectrum, s=shape, norm="forward", workers=workers)
        else:
            z = xp.fft.irfft2(xp.fft.rfft2(g) * self._symbol[dtype], s=shape, norm="forward")
        return z.astype(np.float64, copy=False)

    def take(self, rows: Any) -> SpectralPreconditioner:
        """The preconditioner of the grids ``rows`` of a stack: this one (shared by all)."""
        return self


class PreconditionerStack(SpectralPreconditioner):
    """One :class:`SpectralPreconditioner` symbol per contact of the stack (own dx, dy, E*)."""

    def __init__(self, parts: list[SpectralPreconditioner]) -> None:
        self.parts = parts
        self.shape, self.xp = parts[0].shape, parts[0].xp
        self._symbol = {
            dtype: self.xp.stack([part._symbol[dtype] for part in parts])
            for dtype in (np.float64, np.float32)
        }

    def take(self, rows: Any) -> PreconditionerStack:
        """The stack of the contacts ``rows`` (indices or a boolean mask): slices of the symbols,
        not a new stack."""
        taken = object.__new__(PreconditionerStack)
        taken.parts = [self.parts[i] for i in np.arange(len(self.parts))[rows]]
        taken.shape, taken.xp = self.shape, self.xp
        taken._symbol = {dtype: symbol[rows] for dtype, symbol in self._symbol.items()}
        return taken


def _sums(a: Any) -> Any:
    """Σ over each grid of a (B, nx, ny) stack, shape (B,)."""
    return a.sum(axis=(1, 2))


def _dot(a: Any, b: Any) -> Any:
    """Σ a·b over each grid of two (B, nx, ny) stacks, shape (B,), without a temporary."""
    return array_module(a).einsum("bij,bij->b", a, b)


def _col(v: Any) -> Any:
    """A (B,) vector as (B, 1, 1) for broadcasting against the stack."""
    return v[:, None, None]


def _pcg(
    h: Any,
    p: Any,
    operator: DCFFTOperator | DCFFTStack,
    preconditioner: SpectralPreconditioner,
    tol: float,
    max_iterations: int,
    total: Any | None,
) -> tuple[Any, Any, Any, Any]:
    """Preconditioned projected CG on a (B, nx, ny) stack; returns p, iterations, residual, done.

    Load control (``total`` = W/(dx·dy) per contact) or displacement control (``total`` None,
    ``h`` = h − δ). Per contact and iteration (Polonsky & Keer 1999 with z in place of g):
    g = (u + h − ḡ)·[p > 0];  z = P(M ∗ g);  β = (g·z)/(g·z)_old (0 after a re-entry);
    t = z + β t;  r = K ∗ t;  τ = (g·t)/(r·t − r̄ Σt);  p ← max(p − τ t, 0);
    cells e with p = 0 and g = u + h − ḡ < 0 re-enter with p = −τ·min(M ∗ g_e, 0) (Polonsky &
    Keer's Eq. 37, p = −τ g, with the preconditioned gap; τ = 1 if the step was 0, as M ≈ K⁻¹);
    p ← p·total/Σp. The re-entry step 1/K(0, 0) of a lone cell, applied to hundreds of
    neighbouring cells at once on a rough gap, overshoots by their mutual influence and was
    measured to make the iterations cycle at Σ|Δp|/Σp ≈ 1 (docs/theory/contact.md).
    u ← (u − τ r)·total/Σp, recomputed as K ∗ p after an iteration that clipped or re-entered a
    cell (skipping that, and letting u drift, was measured to multiply the iterations by 1.3-40).
    Converged contacts leave the working stack; ``p`` is modified in place.
    """
    xp = array_module(h)
    batch = h.shape[0]
    load_control = total is not None
    dtype = operator.dtype
    iterations = np.zeros(batch, dtype=int)
    residual = np.full(batch, np.inf)
    done = np.zeros(batch, dtype=bool)
    work = np.arange(batch)  # indices of the contacts still iterating
    hw, pw = h, p.copy()
    totw = None if total is None else np.asarray(total, dtype=np.float64)
    u = operator.apply_batch(pw, xp.empty_like(pw))
    t = xp.zeros_like(pw)
    r, q, s, c, p_old = (xp.empty_like(pw) for _ in range(5))
    rho_old = np.ones(batch)
    conjugate = np.zeros(batch, dtype=bool)
    for iteration in range(1, max_iterations + 1):
        xp.add(u, hw, out=q)
        xp.greater(pw, 0.0, out=c)
        n_c = np.maximum(_host(_sums(c)), 1.0)
        if load_control:  # q = u + h − ḡ from here on
            q -= _col(xp.asarray(_host(_dot(q, c)) / n_c))
        xp.multiply(q, c, out=s)
        z = preconditioner.apply(s, dtype)
        z *= c
        if load_control:  # z = 0 off the contact set, so Σ z is its sum there
            z -= _col(xp.asarray(_host(_sums(z)) / n_c))
            z *= c
        rho = _host(_dot(s, z))
        beta = np.where(conjugate & (rho_old > 0.0), rho / np.where(rho_old > 0.0, rho_old, 1.0), 0)
        t *= c
        t *= _col(xp.asarray(beta))
        t += z
        rho_old = rho
        operator.apply_batch(t, r)
        curvature = _host(_dot(r, t))
        if load_control:
            curvature -= _host(_dot(r, c)) / n_c * _host(_sums(t))
        moving = (curvature > 0.0) & (rho > 0.0)
        tau = np.where(moving, _host(_dot(s, t)) / np.where(moving, curvature, 1.0), 0.0)
        tau_b = _col(xp.asarray(tau))
        xp.multiply(t, tau_b, out=z)
        p_old, pw = pw, p_old  # the buffers swap instead of a copy
        xp.subtract(p_old, z, out=pw)
        clipped = _host(pw.min(axis=(1, 2))) < 0.0
        xp.maximum(pw, 0.0, out=pw)
        xp.less_equal(pw, 0.0, out=c)  # cells with p = 0 and a negative gap re-enter (Eq. 37)
        xp.multiply(q, c, out=s)
        xp.minimum(s, 0.0, out=s)
        readmitted = _host(s.min(axis=(1, 2))) < 0.0
        if readmitted.any():  # p = −τ·min(M ∗ g, 0) on the re-entering cells (g < 0 there)
            entry = preconditioner.apply(s, dtype)
            entry *= s < 0.0
            xp.minimum(entry, 0.0, out=entry)
            entry *= _col(xp.asarray(np.where(tau > 0.0, tau, 1.0)))
            pw -= entry
        conjugate = ~readmitted
        current = _host(_sums(pw))
        alive = current > 0.0
        scale = totw / np.where(alive, current, 1.0) if load_control else np.ones(len(work))
        scale_b = _col(xp.asarray(scale))
        pw *= scale_b
        p_old -= pw
        norm = totw if load_control else np.where(alive, current, 1.0)
        res = _host(_sums(xp.abs(p_old, out=p_old))) / norm
        res = np.where(alive, res, np.inf)
        r *= tau_b
        u -= r
        u *= scale_b
        stopped = (res < tol) | ~alive
        exact = np.flatnonzero((clipped | readmitted) & ~stopped)
        if exact.size:  # a clipped or re-entered cell breaks p = scale·(p_old − τ t)
            rows = xp.asarray(exact)
            u[rows] = operator.take(exact).apply_batch(pw[rows], xp.empty_like(pw[rows]))
        residual[work], iterations[work] = res, iteration
        if stopped.any():
            p[xp.asarray(work[stopped])] = pw[xp.asarray(stopped)]
            done[work[stopped]] = res[stopped] < tol
            keep = ~stopped
            if not keep.any():
                break
            rows = xp.asarray(keep)
            hw, pw, u, t = hw[rows], pw[rows], u[rows], t[rows]
            r, q, s, c, p_old = r[rows], q[rows], s[rows], c[rows], p_old[rows]
            work, rho_old, conjugate = work[keep], rho_old[keep], conjugate[keep]
            totw = None if totw is None else totw[keep]
            operator, preconditioner = operator.take(keep), preconditioner.take(keep)
    else:
        p[xp.asarray(work)] = pw
    return p, iterations, residual, done


def _host(a: Any) -> np.ndarray:
    """A (B,) device vector as a NumPy array of float64 (or bool)."""
    a = a.get() if hasattr(a, "get") else a
    return np.asarray(a, dtype=bool if a.dtype == bool else np.float64)


def _coarsen(h: Any) -> Any:
    """Mean of each 2 × 2 block of cells of a (B, 2m, 2n) stack: (B, m, n).

    Summed as (h00 + h01) + (h10 + h11), the order of ``mean(axis=(2, 4))`` of the blocks (same
    bits), with slices instead of a strided reduction (8x faster at 32 × 128²)."""
    b, nx, ny = h.shape
    blocks = h.reshape(b, nx // 2, 2, ny // 2, 2)
    mean = blocks[:, :, 0, :, 0] + blocks[:, :, 0, :, 1]
    mean += blocks[:, :, 1, :, 0] + blocks[:, :, 1, :, 1]
    mean *= 0.25
    return mean


def _refine_axis(p: Any, axis: int) -> Any:
    """Cell-centred linear interpolation doubling ``axis``: 3/4 of the own cell + 1/4 of the
    neighbour on the side of the fine cell (the edge cell repeated).

    Written into the even and odd fine cells by slices (no gathered neighbour copies and no stack:
    18x faster at 32 × 128²)."""
    xp = array_module(p)
    n = p.shape[axis]

    def at(part: slice) -> tuple[slice, ...]:
        index = [slice(None)] * p.ndim
        index[axis] = part
        return tuple(index)

    shape = list(p.shape)
    shape[axis] *= 2
    fine = xp.empty(shape, dtype=p.dtype)
    own = 0.75 * p
    first, rest, last, head = (
        at(slice(0, 1)),
        at(slice(1, None)),
        at(slice(n - 1, n)),
        at(slice(0, n - 1)),
    )
    for cells, neighbour, edge, inner in (
        (fine[at(slice(0, None, 2))], p[head], first, rest),  # the lower neighbour
        (fine[at(slice(1, None, 2))], p[rest], last, head),  # the upper neighbour
    ):
        xp.multiply(neighbour, 0.25, out=cells[inner])
        xp.multiply(p[edge], 0.25, out=cells[edge])
        cells += own
    return fine


def _nested_start(h: Any, setting: _Setting, coarse: bool) -> tuple[Any, Any]:
    """Initial pressures for the (B, nx, ny) stack from the coarser grids, and their work.

    The coarsest grid starts from :func:`_hertz_start` if it is a ``coarse`` grid of a nested
    start, from uniform pressure if it is the grid of the problem itself."""
    xp = array_module(h)
    nx, ny = h.shape[1:]
    zero = np.zeros(h.shape[0])
    total = setting.total
    if nx % 2 or ny % 2 or min(nx, ny) // 2 < (HERTZ_COARSEST if coarse else COARSEST):
        if coarse:
            return _hertz_start(h, setting), zero
        return xp.broadcast_to(_col(xp.asarray(total)) / (nx * ny), h.shape).copy(), zero
    halved = replace(
        setting, dx=2 * setting.dx, dy=2 * setting.dy, total=total / 4.0, tol=COARSE_TOLERANCE
    )
    state = _solve(_coarsen(h), halved, None, True, None, check=False)
    rows, cols = _support(state.pressure)
    p = xp.zeros(h.shape)
    fine = p[:, 2 * rows.start : 2 * rows.stop, 2 * cols.start : 2 * cols.stop]
    fine[...] = _refine_axis(_refine_axis(state.pressure[:, rows, cols], 1), 2)
    fine *= _col(xp.asarray(total) / _sums(p))  # the whole grid: the bits of a contact alone
    return p, (state.iterations + state.coarse_work) / 4.0


def _support(p: Any) -> tuple[slice, slice]:
    """Rows and columns of the (B, nx, ny) stack ``p`` that hold a pressure in any grid, widened by
    a cell on each side: outside them the interpolated pressure of :func:`_refine_axis` is zero,
    inside it is that of the whole grids (a zero border cell stands for the repeated edge)."""
    spans = _spans(p > 0.0) or ((0, p.shape[1]), (0, p.shape[2]))
    rows, cols = (
        slice(max(lo - 1, 0), min(hi + 1, n))
        for (lo, hi), n in zip(spans, p.shape[1:], strict=True)
    )
    return rows, cols


def _spans(mask: Any) -> tuple[tuple[int, int], tuple[int, int]] | None:
    """The rows and the columns ``(first, last + 1)`` that hold a true cell of the (..., nx, ny)
    ``mask`` in any of its grids; None if no cell is true."""
    xp = array_module(mask)
    lead = tuple(range(mask.ndim - 2))
    rows = xp.flatnonzero(mask.any(axis=(*lead, mask.ndim - 1)))
    if not rows.size:
        return None
    cols = xp.flatnonzero(mask.any(axis=(*lead, mask.ndim - 2)))
    return (int(rows[0]), int(rows[-1]) + 1), (int(cols[0]), int(cols[-1]) + 1)


def _hertz_start(h: Any, setting: _Setting) -> Any:
    """Hertz-like pressures p ∝ √(c − h')⁺ (h' = h − min h) for the (B, nx, ny) stack, each with
    the sum ``total``: the Hertz pressure of a paraboloid gap, whose contact edge is the gap's
    level c = a²/(2R) (Johnson 1985, §4.2). The level solves W(c) = W with
    W(c) = (2√2 E*/π)·√(2πc/A(c))·Σ√(c − h')⁺ ΔA, A(c) the area where h' < c: exact for a
    paraboloid of revolution (R = A/(2πc)), where W ∝ c^(3/2); :data:`HERTZ_STEPS` steps
    c ← c·(W/W(c))^(2/3) from c = max h'. For other gaps only a start (GUESS): on an elliptic
    paraboloid its level set is the gap's ellipse, not Hertz's, and on the benchmark's slender
    ellipse its peak is 13 % below Hertz's p0 (tested)."""
    xp = array_module(h)
    area = setting.dx * setting.dy
    h = h - h.min(axis=(1, 2), keepdims=True)
    scale = 2.0 * np.sqrt(2.0) / np.pi * np.asarray(setting.e_star) * area
    load = np.asarray(setting.total) * area
    level = np.maximum(_host(h.max(axis=(1, 2))), np.finfo(float).tiny)
    for _ in range(HERTZ_STEPS):
        opening = xp.maximum(_col(xp.asarray(level)) - h, 0.0)
        cells = _host(_sums(opening > 0.0))
        radius_term = np.sqrt(2.0 * np.pi * level / (cells * area))  # 1/√R, R = A/(2πc)
        level = level * (load / (scale * radius_term * _host(_sums(xp.sqrt(opening))))) ** (2 / 3)
    p = xp.sqrt(xp.maximum(_col(xp.asarray(level)) - h, 0.0))
    p *= _col(xp.asarray(setting.total) / _sums(p))
    return p


HERTZ_STEPS = 4
"""Steps of the Hertz start's level (GUESS: on the benchmark's sphere and ellipse at 32² and 64²
the start's peak pressure settles to 0.3 % in three steps; the coarse solve corrects the rest)."""


@dataclass(frozen=True)
class _Setting:
    """What the iterations of a stack of contacts need besides the gaps and pressures."""

    dx: Any
    dy: Any
    e_star: Any
    total: Any | None
    tol: float
    max_iterations: int
    dtype: type[np.floating]

    def take(self, rows: Any) -> _Setting:
        """The setting of the contacts ``rows`` (indices or a slice): their entries of the
        per-contact arrays."""
        return replace(
            self, **{k: _take(getattr(self, k), rows) for k in ("dx", "dy", "e_star", "total")}
        )


def solve_batch(
    h: Any,
    dx: Any,
    dy: Any,
    e_star: Any,
    total: Any | None,
    tol: float,
    max_iterations: int,
    *,
    initial: Any = None,
    nested: bool = True,
    dtype: type[np.floating] = np.float64,
    operator: DCFFTOperator | DCFFTStack | None = None,
) -> BatchIterate:
    """Preconditioned CG on the (B, nx, ny) gaps ``h`` (checked by the caller).

    ``total`` (B,) = W/(dx·dy) per contact (load control) or None (displacement control, ``h`` =
    h − δ and ``initial`` required). ``initial`` (B, nx, ny) pressures, rescaled to ``total``;
    default: the nested-grid start (``nested``) or uniform pressure. ``dtype`` is the precision of
    the FFTs (float32: iterate to :data:`MIXED_SWITCH` in float32, then to ``tol`` in float64 if
    ``tol`` is below it; the coarse grids of a nested start stay in float32).
    ``operator``: the float64 DC-FFT operator of the grid (default: the cached one).
    ``dx``, ``dy`` [m] and ``e_star`` [Pa] are scalars shared by all contacts or (B,) arrays, one
    per contact (then each contact has its own operator and preconditioner symbol).

    When the start's pressure covers a small part of the grid, the CG runs on a window around it
    (:func:`_window`) and the result is checked on the whole grid (:func:`_outside_clear`).
    On the CPU the contacts are shared between :func:`~ballscrew.backend.fft_threads` threads
    (:func:`_solve_shared`).
    """
    setting = _Setting(dx, dy, e_star, total, tol, max_iterations, dtype)
    threads = min(fft_threads(4 * h.size), len(h)) if array_module(h) is np else 1
    if threads > 1:
        return _solve_shared(h, setting, initial, nested, operator, threads)
    return _solve(h, setting, initial, nested, operator, check=True)


def _solve_shared(
    h: Any,
    setting: _Setting,
    initial: Any,
    nested: bool,
    operator: DCFFTOperator | DCFFTStack | None,
    threads: int,
) -> BatchIterate:
    """:func:`_solve` on ``threads`` runs of consecutive contacts at once, each in a pool thread of
    one FFT thread (:func:`~ballscrew.backend.map_chunks`). The contacts of a stack are
    independent CGs, so each result is the one of its contact alone; sharing whole solves, not
    only their transforms, also puts the element-wise work and the coarse grids on both cores
    (measured on 2 cores at 32 × 128²: ``docs/benchmarks.md``)."""

    def run(rows: slice) -> BatchIterate:
        return _solve(
            h[rows], setting.take(rows), None if initial is None else initial[rows], nested,
            None if operator is None else operator.take(rows), check=True,
        )  # fmt: skip

    parts = map_chunks(run, len(h), threads)

    def joined(name: str) -> Any:
        return np.concatenate([getattr(part, name) for part in parts])

    xp = array_module(h)
    return BatchIterate(
        xp.concatenate([part.pressure for part in parts]),
        joined("iterations"),
        joined("coarse_work"),
        joined("residual"),
        joined("converged"),
        xp.concatenate([part.displacement for part in parts]),
    )


def _solve(
    h: Any,
    setting: _Setting,
    initial: Any,
    nested: bool,
    operator: DCFFTOperator | DCFFTStack | None,
    check: bool,
) -> BatchIterate:
    """:func:`solve_batch`; ``check`` False marks the coarse grids of a nested start, whose
    pressure is only the next grid's start: no whole-grid check of a window's result, and the
    Hertz start on the coarsest grid."""
    xp = array_module(h)
    nx, ny = h.shape[1:]
    coarse_work = np.zeros(h.shape[0])
    total = setting.total
    if initial is not None:
        p = xp.array(initial, dtype=np.float64, copy=True)
        if total is not None:
            p *= _col(xp.asarray(total) / _sums(p))
    elif nested:
        p, coarse_work = _nested_start(h, setting, coarse=not check)
    else:
        p = xp.broadcast_to(_col(xp.asarray(total)) / (nx * ny), h.shape).copy()
    windows = [_window(p[b]) for b in range(len(p))]
    groups: dict[Any, list[int]] = {}
    for b, window in enumerate(windows):
        groups.setdefault(None if window is None else _extent(window), []).append(b)
    # Contacts whose windows differ in size are iterated apart: each as it would be alone.
    iterations, residual = np.zeros(len(p), dtype=int), np.zeros(len(p))
    converged = np.zeros(len(p), dtype=bool)
    for extent, rows in groups.items():
        every = len(rows) == len(p)
        part = setting if every else setting.take(rows)
        if extent is None:
            whole = operator if every or operator is None else operator.take(rows)
            if every:
                p, iterations, residual, converged = _iterate(h, p, part, whole)
            else:
                p[rows], iterations[rows], residual[rows], converged[rows] = _iterate(
                    h[rows], p[rows], part, whole
                )
            continue
        inner, iterations[rows], residual[rows], converged[rows] = _iterate(
            xp.stack([h[b][windows[b]] for b in rows]),
            xp.stack([p[b][windows[b]] for b in rows]),
            part,
            None,
        )
        for k, b in enumerate(rows):
            p[b].fill(0.0)
            p[b][windows[b]] = inner[k]
    if not check:
        return BatchIterate(p, iterations, coarse_work, residual, converged)
    if operator is None:
        operator = _operator((nx, ny), setting.dx, setting.dy, setting.e_star, xp, np.float64)
    u = operator.apply_batch(p, xp.empty_like(p))
    out = np.flatnonzero(~_outside_clear(h, u, p, windows, total is not None))
    if out.size:  # a cell outside its window penetrates: on from here on the whole grids
        rows, whole = xp.asarray(out), operator.take(out)
        budget = max(setting.max_iterations - int(iterations[out].max()), 1)
        p[rows], more, residual[out], converged[out] = _iterate(
            h[rows], p[rows], replace(setting.take(out), max_iterations=budget), whole
        )
        iterations[out] += more
        u[rows] = whole.apply_batch(p[rows], xp.empty_like(p[rows]))
    return BatchIterate(p, iterations, coarse_work, residual, converged, u)


def _take(value: Any, rows: Any) -> Any:
    """The entries ``rows`` of a per-contact (B,) array; a shared scalar or None as it is."""
    return value if value is None or np.ndim(value) == 0 else value[rows]


def _extent(window: tuple[slice, slice]) -> tuple[int, int]:
    """Cells of a window along each axis."""
    return tuple(part.stop - part.start for part in window)  # type: ignore[return-value]


def _iterate(
    h: Any, p: Any, setting: _Setting, operator: DCFFTOperator | DCFFTStack | None
) -> tuple[Any, Any, Any, Any]:
    """:func:`_pcg` on the (B, nx, ny) stack ``h`` from ``p``, in float32 first if ``dtype`` says
    so, with the preconditioner of ``h``'s grid (periodic on a window when ``h`` is one)."""
    xp = array_module(h)
    shape = h.shape[1:]
    cells = (setting.dx, setting.dy, setting.e_star)
    total, tol, max_iterations = setting.total, setting.tol, setting.max_iterations
    apply = _preconditioner(shape, *cells, xp)
    iterations = np.zeros(h.shape[0], dtype=int)
    if setting.dtype is np.float32:
        single = _operator(shape, *cells, xp, np.float32)
        p, iterations, residual, converged = _pcg(
            h, p, single, apply, max(tol, MIXED_SWITCH), max_iterations, total
        )
        if tol >= MIXED_SWITCH:  # the float32 iterations met the stop (Σ|Δp| taken in float64)
            return p, iterations, residual, converged
    if operator is None:
        operator = _operator(shape, *cells, xp, np.float64)
    p, more, residual, converged = _pcg(
        h, p, operator, apply, tol, max(max_iterations - int(iterations.max()), 1), total
    )
    return p, iterations + more, residual, converged


WINDOW_MARGIN = 0.125
"""Cells added on each side of the start's pressure to make the window, as a fraction of the
pressure's extent (at least :data:`WINDOW_MIN_MARGIN` cells): room for the contact to grow (GUESS;
the nested start's contact edge is within a few cells of the converged one; 1/16 was 10-20 %
faster on the Hertz problems at 1024², 1/8 leaves room for other gaps and warm starts)."""
WINDOW_MIN_MARGIN = 4
"""Cells added on each side of the window at least."""
WINDOW_MAX_FRACTION = 0.5
"""Largest window, as a fraction of the grid's cells, worth solving on (GUESS: an iteration's cost
is proportional to the cells, but a window needs its own operator, preconditioner and FFT plans
and a whole-grid check at the end)."""


def _window(p: Any) -> tuple[slice, slice] | None:
    """Rows and columns around the pressure ``p`` (nx, ny), with a margin, sized to fast FFT
    lengths; None if that is more than :data:`WINDOW_MAX_FRACTION` of the grid."""
    support = _spans(p > 0.0)
    if support is None:
        return None
    spans = []
    for (lo, hi), n in zip(support, p.shape, strict=True):
        margin = max(WINDOW_MIN_MARGIN, int(np.ceil(WINDOW_MARGIN * (hi - lo))))
        size = min(scipy.fft.next_fast_len(hi - lo + 2 * margin, real=True), n)
        first = min(max((lo + hi - size) // 2, 0), n - size)
        spans.append(slice(first, first + size))
    rows, cols = spans
    if (rows.stop - rows.start) * (cols.stop - cols.start) > WINDOW_MAX_FRACTION * p.size:
        return None
    return rows, cols


def _outside_clear(h: Any, u: Any, p: Any, windows: list[Any], load: bool) -> np.ndarray:
    """(B,) whether no cell outside its contact's window penetrates: u + h ≥ ḡ there (ḡ = mean of
    u + h over the contact set, all in the window, under load control; 0 under displacement
    control), so each window's solution is its whole grid's (Polonsky & Keer 1999, Eq. 37 admits
    no cell).

    Taken on runs of at most :func:`~ballscrew.budget.check_chunk` contacts, so the copy of u + h
    and the masks hold O(:data:`~ballscrew.budget.CHECK_CELLS`) cells, not the whole batch's; each
    contact's sums and minimum are its own, whatever the run (the same bits)."""
    windowed = [b for b, window in enumerate(windows) if window is not None]
    clear = np.ones(len(h), dtype=bool)  # a contact without a window was solved on its grid
    step = check_chunk(*h.shape[1:])
    for start in range(0, len(windowed), step):
        run = windowed[start : start + step]
        clear[run] = _run_clear(h, u, p, run, [windows[b] for b in run], load)
    return clear


def _run_clear(
    h: Any, u: Any, p: Any, run: list[int], windows: list[tuple[slice, slice]], load: bool
) -> np.ndarray:
    """:func:`_outside_clear` of the contacts ``run`` (ascending indices of the stack)."""
    xp = array_module(h)
    consecutive = run[-1] - run[0] + 1 == len(run)
    rows = slice(run[0], run[-1] + 1) if consecutive else xp.asarray(run)
    q = u[rows] + h[rows]
    inside = _inside(windows, h.shape[1:], xp)
    g_bar = np.zeros(len(run))
    if load:
        contact = p[rows] > 0.0
        contact &= inside
        g_bar = _host(_dot(q, contact)) / np.maximum(_host(_sums(contact)), 1.0)
    xp.copyto(q, xp.inf, where=inside)
    return _host(q.min(axis=(1, 2))) >= g_bar


def _inside(windows: list[tuple[slice, slice]], shape: tuple[int, int], xp: ModuleType) -> Any:
    """(B, nx, ny) mask of the cells of each grid in its window."""
    bounds = np.array([[w.start, w.stop] for window in windows for w in window])
    bounds = xp.asarray(bounds.reshape(len(windows), 2, 2))  # (B, axis, start/stop)
    rows, cols = (xp.arange(n) for n in shape)
    in_rows = (bounds[:, 0, :1] <= rows) & (rows < bounds[:, 0, 1:])
    in_cols = (bounds[:, 1, :1] <= cols) & (cols < bounds[:, 1, 1:])
    return in_rows[:, :, None] & in_cols[:, None, :]


_CACHED = 16
"""Preconditioners kept (as the operators: nested levels × both precisions × a few cells)."""


def _operator(
    shape: tuple[int, int], dx: Any, dy: Any, e_star: Any, xp: ModuleType, dtype: type
) -> DCFFTOperator | DCFFTStack:
    """The cached DC-FFT operator of the grid, or the stack of them for per-contact cells."""
    if np.ndim(dx) == 0:
        return DCFFTOperator.for_grid(shape, dx, dy, e_star, xp, dtype)
    return DCFFTStack.for_grids(shape, dx, dy, e_star, xp, dtype)


def _preconditioner(
    shape: tuple[int, int], dx: Any, dy: Any, e_star: Any, xp: ModuleType
) -> SpectralPreconditioner:
    """The preconditioner of this grid from a small cache (the last ``_CACHED`` grids and
    windows), or the stack of them for per-contact cells."""
    if np.ndim(dx) != 0:
        return PreconditionerStack(
            [_preconditioner(shape, *cell, xp) for cell in zip(dx, dy, e_star, strict=True)]
        )
    return _cached_preconditioner(shape, float(dx), float(dy), float(e_star), xp)


@lru_cache(maxsize=_CACHED)
def _cached_preconditioner(
    shape: tuple[int, int], dx: float, dy: float, e_star: float, xp: ModuleType
) -> SpectralPreconditioner:
    return SpectralPreconditioner(shape, dx, dy, e_star, xp)
