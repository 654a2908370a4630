"""The bordered solve (a symmetric FE block and a small non-symmetric coolant block) against
SuperLU, on its GMRES path and on its LU fallback, and its refusal when GMRES misses the stop."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from ballscrew.errors import ConvergenceError
from ballscrew.thermal import timestepping
from ballscrew.thermal.timestepping import factorize

WALL, COOLANT = 20, 12
"""Wall cells along each side of the FE block, upwind coolant cells of the border."""


def bordered_matrix() -> sp.csr_matrix:
    """[[K, E], [Eᵀ, G]]: K a 2-D grid Laplacian with a lumped mass (symmetric), the coolant cells
    exchanging heat with the first wall cells (E, symmetric coupling) and carried upwind along
    themselves (G, not symmetric), as a coolant's time-step matrix is built."""
    one = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(WALL, WALL))
    k = sp.kron(one, sp.eye(WALL)) + sp.kron(sp.eye(WALL), one) + 0.05 * sp.eye(WALL**2)
    exchange, flow = 0.7, 1.5
    e = sp.lil_matrix((WALL**2, COOLANT))
    for i in range(COOLANT):
        e[i, i] = -exchange
    g = sp.diags([-flow, exchange + flow], [-1, 0], shape=(COOLANT, COOLANT))
    k = k + sp.diags(np.r_[np.full(COOLANT, exchange), np.zeros(WALL**2 - COOLANT)])
    return sp.csr_matrix(sp.bmat([[k, e], [e.T, g]]))


@pytest.fixture
def bordered_calls(monkeypatch):
    """The borders that factorize hands to the bordered GMRES."""
    calls = []
    bordered = timestepping._bordered
    monkeypatch.setattr(
        timestepping,
        "_bordered",
        lambda m, border, rtol: calls.append(border) or bordered(m, border, rtol),
    )
    return calls


def loads(n: int) -> list[np.ndarray]:
    """Three right-hand sides (successive solves: the warm start is used from the second)."""
    rng = np.random.default_rng(9)
    return [rng.random(n), rng.random(n), np.zeros(n)]


def test_bordered_gmres_equals_superlu(bordered_calls):
    m = bordered_matrix()
    assert timestepping._symmetric_block(m) == WALL**2 and not np.allclose(
        m.toarray(), m.T.toarray()
    )
    exact = splu(m.tocsc())
    solve = factorize(m, rtol=1e-13, direct_limit=0)
    assert bordered_calls == [WALL**2]
    for b in loads(m.shape[0]):
        x = exact.solve(b)
        assert np.linalg.norm(solve(b) - x) <= 1e-10 * max(np.linalg.norm(x), 1.0)


def test_a_border_above_its_limit_falls_back_to_lu_with_the_same_answer(
    bordered_calls, monkeypatch
):
    m = bordered_matrix()
    gmres_solve = factorize(m, rtol=1e-13, direct_limit=0)
    monkeypatch.setattr(timestepping, "BORDER_LIMIT", COOLANT - 1)
    lu_solve = factorize(m, rtol=1e-13, direct_limit=0)
    assert bordered_calls == [WALL**2]  # the second factorize did not take the GMRES path
    for b in loads(m.shape[0]):
        x = lu_solve(b)
        np.testing.assert_array_equal(x, splu(m.tocsc()).solve(b))
        assert np.linalg.norm(gmres_solve(b) - x) <= 1e-10 * max(np.linalg.norm(x), 1.0)


def test_bordered_gmres_that_misses_its_stop_is_a_convergence_error(monkeypatch):
    monkeypatch.setattr(timestepping, "GMRES_RESTART", 1)
    monkeypatch.setattr(timestepping, "GMRES_CYCLES", 1)
    m = bordered_matrix()
    with pytest.raises(ConvergenceError, match="block-preconditioned GMRES") as error:
        factorize(m, rtol=1e-13, direct_limit=0)(np.ones(m.shape[0]))
    assert error.value.residual > 1e-12 and error.value.tolerance == 1e-13
