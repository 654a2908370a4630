"""DC-FFT convolution against a direct double sum written here (Liu, Wang & Liu 2000)."""

import threading

import numpy as np
import pytest

from ballscrew.contact import DCFFTOperator, direct_convolution, love_coefficient

E_STAR = 113.19e9


def naive_sum(p, dx, dy):
    """u_ij = Σ_kl K(x_i − x_k, y_j − y_l) p_kl, one cell pair at a time (K5)."""
    nx, ny = p.shape
    u = np.zeros_like(p)
    for i in range(nx):
        for j in range(ny):
            for k in range(nx):
                for m in range(ny):
                    offset_x, offset_y = (i - k) * dx, (j - m) * dy
                    u[i, j] += float(love_coefficient(offset_x, offset_y, dx, dy, E_STAR)) * p[k, m]
    return u


@pytest.fixture(scope="module")
def t_k2():
    """8 × 6 cells, Δx = 10 µm, Δy = 20 µm, random p ≤ 1 GPa."""
    p = np.random.default_rng(20000101).uniform(0.0, 1e9, (8, 6))
    return p, 10e-6, 20e-6, naive_sum(p, 10e-6, 20e-6)


def test_dcfft_equals_direct_sum_t_k2(t_k2):
    p, dx, dy, reference = t_k2
    operator = DCFFTOperator(p.shape, dx, dy, E_STAR)
    first = operator.apply(p)
    second = operator.apply(p)  # the FFT buffers are reused: a second call must not drift
    for u in (first, second):
        assert np.max(np.abs(u - reference)) / np.max(np.abs(reference)) < 1e-12


def test_direct_convolution_equals_naive_sum(t_k2):
    p, dx, dy, reference = t_k2
    np.testing.assert_allclose(direct_convolution(p, dx, dy, E_STAR), reference, rtol=1e-13)


@pytest.mark.parametrize("shape", [(1, 1), (5, 1), (7, 4), (16, 9), (33, 32)])
def test_dcfft_odd_even_and_degenerate_shapes(shape):
    """Aperiodic (no wrap-around) on odd, even and one-cell-wide grids."""
    rng = np.random.default_rng(sum(shape))
    p = rng.uniform(0.0, 2e9, shape)
    dx, dy = 3e-6, 5e-6
    u = DCFFTOperator(shape, dx, dy, E_STAR)(p)
    reference = direct_convolution(p, dx, dy, E_STAR)
    assert np.max(np.abs(u - reference)) / np.max(np.abs(reference)) < 1e-12


def test_out_argument_and_cache():
    """`out` receives u; for_grid returns one operator per grid."""
    shape, dx, dy = (12, 10), 2e-6, 3e-6
    operator = DCFFTOperator.for_grid(shape, dx, dy, E_STAR)
    assert DCFFTOperator.for_grid(shape, dx, dy, E_STAR) is operator
    assert DCFFTOperator.for_grid(shape, dx, 2 * dy, E_STAR) is not operator
    p = np.ones(shape)
    out = np.empty(shape)
    assert operator.apply(p, out=out) is out
    np.testing.assert_allclose(out, direct_convolution(p, dx, dy, E_STAR), rtol=1e-12)


def test_concurrent_threads_use_their_own_buffers():
    """Two threads convolving different pressures on one grid get their own answers."""
    shape, dx, dy = (24, 20), 1e-6, 1e-6
    operator = DCFFTOperator(shape, dx, dy, E_STAR)
    pressures = [np.full(shape, 1e8), np.random.default_rng(3).uniform(0, 1e9, shape)]
    expected = [direct_convolution(p, dx, dy, E_STAR) for p in pressures]
    errors = []

    def work(index):
        for _ in range(50):
            u = operator.apply(pressures[index])
            errors.append(np.max(np.abs(u - expected[index])) / np.max(expected[index]))

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert len(errors) == 100
    assert max(errors) < 1e-12


@pytest.mark.parametrize("batch, n", [(3, 8), (8, 128)])  # one thread; the stack split in two
def test_stack_convolution_equals_each_grid_alone(batch, n):
    """apply_batch of a shared operator and of a stack of own-cell operators: each u equals that
    grid's own DC-FFT bit for bit, and the 8 × 8 stack equals the direct sum (K5)."""
    from ballscrew.contact.convolution import DCFFTStack

    rng = np.random.default_rng(7)
    p = rng.uniform(0.0, 1e9, (batch, n, n))
    dx = 1e-6 * (1.0 + rng.random(batch))
    shared = DCFFTOperator.for_grid((n, n), 1e-6, 2e-6, E_STAR)
    stack = DCFFTStack.for_grids((n, n), dx, 2.0 * dx, np.full(batch, E_STAR))
    u_shared = shared.apply_batch(p, np.empty_like(p))
    u_stack = stack.apply_batch(p, np.empty_like(p))
    for b in range(batch):
        assert np.array_equal(u_shared[b], shared.apply(p[b]))
        assert np.array_equal(u_stack[b], stack.operators[b].apply(p[b]))
        if n <= 8:
            direct = direct_convolution(p[b], dx[b], 2.0 * dx[b], E_STAR)
            np.testing.assert_allclose(u_stack[b], direct, rtol=1e-12, atol=0.0)
