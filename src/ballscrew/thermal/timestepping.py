"""Linear solves of the heat equation C dθ/dt + A θ = f: steady state and implicit Euler.

Theory manual ``docs/theory/thermal.md``, time integration and solvers: a sparse LU (SuperLU, COLAMD
ordering) up to a model's ``direct_limit`` (2-D and 1-D models), factorised once and reused for
every step of a constant time step; above it smoothed-aggregation AMG preconditioned CG (pyamg),
which the 3-D model always uses (its LU fills in: 16–24 s for 35k unknowns against 1.3 s).
A hollow shaft's coolant makes the matrix non-symmetric in a small trailing block (its upwind
cells): there GMRES (Saad & Schultz 1986) with a block-triangular preconditioner, an AMG V-cycle
on the symmetric FE block and an exact LU of the small block.
Implicit Euler with consistent matrices conserves energy discretely:
    1ᵀC(θₙ − θₙ₋₁) + Δt·1ᵀAθₙ = Δt·1ᵀf,   and 1ᵀA θ is the convective loss (1ᵀK = 0).
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Hashable
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from numpy.typing import NDArray
from scipy.sparse.linalg import LinearOperator, cg, gmres, splu

from ballscrew.errors import ConvergenceError

DIRECT_LIMIT = 60_000
"""Largest system solved with a sparse LU by default (3-D meshes); larger ones use AMG-CG.
2-D meshes factorise with little fill: 88k unknowns in 0.4 s, 350k in 4.5 s."""

Solve = Callable[[NDArray[np.float64]], NDArray[np.float64]]


BORDER_LIMIT = 2_000
"""Largest non-symmetric trailing block (coolant cells) solved by block-preconditioned GMRES;
a larger non-symmetric part is factorised. GUESS: the block is LU-factorised inside the
preconditioner, which stays cheap to about this size."""

GMRES_RESTART = 60
"""Krylov vectors kept between GMRES restarts. GUESS: about three times the iterations the
block-preconditioned solve takes (18–23 measured on the 3-D coolant meshes)."""

GMRES_CYCLES = 20
"""Restart cycles before the solve is a ConvergenceError. GUESS: a generous bound."""

JACOBI_MAXITER = 400
"""Iterations of diagonally preconditioned CG tried on a time step's matrix before AMG-CG."""


def factorize(
    matrix: sp.spmatrix,
    rtol: float = 1e-10,
    direct_limit: int = DIRECT_LIMIT,
    jacobi_first: bool = False,
) -> Solve:
    """A solver for ``matrix``: LU once, or AMG-CG when it is symmetric (positive definite) and
    larger than ``direct_limit`` unknowns. A matrix that is symmetric but for a trailing block
    of at most :data:`BORDER_LIMIT` unknowns (a coolant's upwind transport) is solved by
    :func:`_bordered` GMRES above ``direct_limit``; any other non-symmetric matrix is factorised.
    The iterative paths raise :class:`ConvergenceError` when they miss ``rtol``.

    ``jacobi_first``: the matrix is a time step's C/Δt + A, whose condition number
    1 + Δt·λ_max(C⁻¹A) (over 1 + Δt·λ_min) stays moderate at the model's steps, so CG with the
    diagonal as preconditioner converges in a few hundred iterations of one matrix product each:
    on the 3-D model (16k unknowns) about 140 iterations in a fifth of the time of 28 AMG
    V-cycles. Should it miss ``rtol`` in :data:`JACOBI_MAXITER` iterations, AMG-CG takes over
    for this and every later solve. The stop is the same: ‖b − Ax‖ ≤ rtol‖b‖.
    """
    matrix = sp.csc_matrix(matrix)
    n = matrix.shape[0]
    border = n if n <= direct_limit else _symmetric_block(matrix)
    if n <= direct_limit or n - border > BORDER_LIMIT:
        lu = splu(matrix)
        return lu.solve
    if border < n:
        return _bordered(sp.csr_matrix(matrix), border, rtol)
    import pyamg

    csr = sp.csr_matrix(matrix)
    amg: list[pyamg.MultilevelSolver] = []  # built at the first solve that needs it
    jacobi = sp.diags(1.0 / csr.diagonal()) if jacobi_first else None
    steps = _WarmStarts(csr, rtol)

    def solve(b: NDArray[np.float64]) -> NDArray[np.float64]:
        nonlocal jacobi
        x0 = steps.start()
        if jacobi is not None:
            x, _ = cg(csr, b, x0=x0, rtol=rtol, maxiter=JACOBI_MAXITER, M=jacobi)
            if steps.accepts(b, x):
                return x
            jacobi = None  # too slow a contraction for Jacobi: AMG from now on
        if not amg:
            amg.append(pyamg.smoothed_aggregation_solver(csr, symmetry="symmetric"))
        residuals: list[float] = []
        x = amg[0].solve(b, x0=x0, tol=rtol, accel="cg", maxiter=500, residuals=residuals)
        return steps.accept("pyamg smoothed-aggregation CG", b, x, len(residuals))

    return solve


class _WarmStarts:
    """What the iterative solves of one matrix share: the warm start and the acceptance.

    Successive solves are time steps, so each starts from the linear extrapolation
    2xₙ₋₁ − xₙ₋₂ of the last two accepted solutions (the last one after the first solve). A
    solution is accepted when ‖b − Ax‖ ≤ 10 rtol‖b‖: the iterative solvers stop on their own
    (preconditioned or restarted) residual estimate, which may differ from the true one.
    """

    def __init__(self, matrix: sp.csr_matrix, rtol: float) -> None:
        self.matrix = matrix
        self.rtol = rtol
        self.previous: list[NDArray[np.float64]] = []  # the last two accepted solutions

    def start(self) -> NDArray[np.float64] | None:
        """Initial guess of the next solve (None before the first)."""
        previous = self.previous
        return 2.0 * previous[1] - previous[0] if len(previous) == 2 else (previous or [None])[-1]

    def residual(self, b: NDArray[np.float64], x: NDArray[np.float64]) -> float:
        """‖b − Ax‖ / ‖b‖ (‖b − Ax‖ for b = 0)."""
        return float(np.linalg.norm(b - self.matrix @ x)) / (float(np.linalg.norm(b)) or 1.0)

    def accepts(self, b: NDArray[np.float64], x: NDArray[np.float64]) -> bool:
        """Whether ``x`` solves A x = b within 10 rtol; if so, it is kept for the warm start."""
        return self._kept(x, self.residual(b, x))

    def accept(
        self, method: str, b: NDArray[np.float64], x: NDArray[np.float64], iterations: int
    ) -> NDArray[np.float64]:
        """``x`` if :meth:`accepts` it, else a :class:`ConvergenceError` of ``method``."""
        residual = self.residual(b, x)
        if not self._kept(x, residual):
            raise ConvergenceError(method, iterations, residual, self.rtol)
        return x

    def _kept(self, x: NDArray[np.float64], residual: float) -> bool:
        if not residual <= 10 * self.rtol:
            return False
        self.previous[:] = [*self.previous[-1:], x]
        return True


def solve_steady(
    conductance: sp.spmatrix, load: NDArray[np.float64], direct_limit: int = DIRECT_LIMIT
) -> NDArray[np.float64]:
    """Steady temperature rise θ = A⁻¹ f."""
    return factorize(conductance, direct_limit=direct_limit)(np.asarray(load, dtype=float))


@dataclass(frozen=True)
class StepSystem:
    """Conductance matrix and load vector in force during a step (may depend on the step)."""

    key: Hashable
    """Equal keys mean equal (A, f), so the factorisation is reused."""
    conductance: sp.spmatrix
    load: NDArray[np.float64]


def implicit_euler(
    capacity: sp.spmatrix,
    time_step: float,
    steps: int,
    system: Callable[[int], StepSystem],
    observe: Callable[[int, NDArray[np.float64], float], None],
    initial: NDArray[np.float64] | None = None,
    cache_size: int = 32,
    direct_limit: int = DIRECT_LIMIT,
) -> tuple[NDArray[np.float64], float, float]:
    """March (C/Δt + Aₙ) θₙ = C θₙ₋₁/Δt + fₙ from θ₀ (ambient: 0) for ``steps`` steps.

    ``system(n)`` gives (Aₙ, fₙ) of step n = 1 … steps; the matrix C/Δt + Aₙ is factorised
    once per distinct key (LRU cache of ``cache_size``). ``observe(n, θₙ, loss)`` is called after
    every step with the convective loss 1ᵀAₙθₙ [W]. Returns (θ_end, heat in [J], heat
    convected [J]) for the energy balance.
    """
    c = sp.csr_matrix(capacity)
    n_dof = c.shape[0]
    theta = np.zeros(n_dof) if initial is None else np.array(initial, dtype=float)
    cache: OrderedDict[Hashable, tuple[Solve, NDArray[np.float64]]] = OrderedDict()
    heat_in = 0.0
    heat_out = 0.0
    for n in range(1, steps + 1):
        s = system(n)
        if s.key in cache:
            cache.move_to_end(s.key)
        else:
            a = sp.csr_matrix(s.conductance)
            cache[s.key] = (
                factorize(c / time_step + a, 1e-8, direct_limit, jacobi_first=True),
                np.asarray(a.sum(axis=0)).ravel(),
            )
            if len(cache) > cache_size:
                cache.popitem(last=False)
        solve, loss_row = cache[s.key]
        theta = solve(c @ theta / time_step + s.load)
        loss = float(loss_row @ theta)
        heat_in += time_step * float(np.sum(s.load))
        heat_out += time_step * loss
        observe(n, theta, loss)
    return theta, heat_in, heat_out


def _symmetric_block(matrix: sp.spmatrix) -> int:
    """Size of the leading block outside which ``matrix`` differs from its transpose by more
    than round-off (1e-12 of its largest entry): its size when it is symmetric."""
    scale = abs(matrix).max()
    skew = sp.coo_matrix(matrix - matrix.T)
    off = np.abs(skew.data) > 1e-12 * scale
    return int(min(skew.row[off].min(), skew.col[off].min())) if off.any() else matrix.shape[0]


def _bordered(matrix: sp.csr_matrix, border: int, rtol: float) -> Solve:
    """GMRES for A = [[K, E], [F, G]], K symmetric (the FE block) and G small and not.

    Preconditioner: the block lower triangle, P⁻¹b = (x₁, G⁻¹(b₂ − F x₁)) with x₁ one
    smoothed-aggregation V-cycle on K (block-triangular preconditioning: Elman, Silvester &
    Wathen 2005, *Finite Elements and Fast Iterative Solvers*; preconditioned GMRES:
    Saad 2003, *Iterative Methods for Sparse Linear Systems*, Sec. 9.3). With an exact
    K⁻¹ the preconditioned matrix is the identity plus a rank of the border, so GMRES needs
    about as many iterations as AMG-CG on K. Stops at ‖b − Ax‖ ≤ rtol‖b‖; warm start and
    acceptance (within 10 rtol, checked) are those of the AMG path (:class:`_WarmStarts`).
    """
    import pyamg

    n = matrix.shape[0]
    k = matrix[:border, :border]
    f = matrix[border:, :border]
    g = splu(sp.csc_matrix(matrix[border:, border:]))
    cycle = pyamg.smoothed_aggregation_solver(k, symmetry="symmetric").aspreconditioner()

    def apply(b: NDArray[np.float64]) -> NDArray[np.float64]:
        x1 = cycle @ b[:border]
        return np.concatenate([x1, g.solve(b[border:] - f @ x1)])

    preconditioner = LinearOperator((n, n), matvec=apply, dtype=float)
    steps = _WarmStarts(matrix, rtol)

    def solve(b: NDArray[np.float64]) -> NDArray[np.float64]:
        count = [0]

        def counted(_: object) -> None:
            count[0] += 1

        x, _ = gmres(
            matrix,
            b,
            x0=steps.start(),
            rtol=rtol,
            atol=0.0,
            restart=GMRES_RESTART,
            maxiter=GMRES_CYCLES,
            M=preconditioner,
            callback=counted,
            callback_type="pr_norm",
        )
        return steps.accept("AMG block-preconditioned GMRES", b, x, count[0])

    return solve
