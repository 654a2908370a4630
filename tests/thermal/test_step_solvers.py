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
