"""The iterative time-step solver: Jacobi-CG first, AMG-CG when Jacobi is too slow."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import spsolve

from ballscrew.thermal import timestepping
from ballscrew.thermal.timestepping import factorize


def _step_matrix(n: int, mass_over_dt: float) -> sp.csr_matrix:
    """C/Δt + A of a 2-D grid Laplacian (A) with a lumped mass (C/Δt)."""
    one = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(n, n))
    a = sp.kron(one, sp.eye(n)) + sp.kron(sp.eye(n), one)
    return sp.csr_matrix(a + mass_over_dt * sp.eye(n * n))


def test_jacobi_and_amg_steps_meet_the_same_tolerance(monkeypatch):
    m = _step_matrix(40, 0.05)
    rng = np.random.default_rng(3)
    loads = [rng.random(m.shape[0]) for _ in range(3)]
    exact = [spsolve(m.tocsc(), b) for b in loads]
    plain = factorize(m, rtol=1e-8, direct_limit=0)
    jacobi = factorize(m, rtol=1e-8, direct_limit=0, jacobi_first=True)
    for b, x in zip(loads, exact, strict=True):
        for solve in (plain, jacobi):
            assert np.linalg.norm(solve(b) - x) <= 1e-6 * np.linalg.norm(x)
    # Jacobi that cannot converge in its iterations hands over to AMG-CG, same answer.
    monkeypatch.setattr(timestepping, "JACOBI_MAXITER", 2)
    fallback = factorize(m, rtol=1e-8, direct_limit=0, jacobi_first=True)
    for b, x in zip(loads, exact, strict=True):
        assert np.linalg.norm(fallback(b) - x) <= 1e-6 * np.linalg.norm(x)


def test_a_non_symmetric_matrix_is_factorised_not_given_to_cg():
    """A coolant's upwind transport makes the matrix non-symmetric: CG would converge to a wrong
    answer (or not at all), so it is factorised however large it is."""
    m = _step_matrix(20, 0.05).tolil()
    n = m.shape[0]
    flow = 0.8  # upwind coupling of each unknown to the one before it
    for i in range(1, n):
        m[i, i] += flow
        m[i, i - 1] -= flow
    m = m.tocsr()
    b = np.random.default_rng(5).random(n)
    x = factorize(m, rtol=1e-10, direct_limit=0, jacobi_first=True)(b)
    assert np.linalg.norm(m @ x - b) <= 1e-10 * np.linalg.norm(b)
