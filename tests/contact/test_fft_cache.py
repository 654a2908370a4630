"""The process-wide byte bound of the FFT transform caches of ballscrew.backend."""

import gc
import threading

import numpy as np
import pytest

from ballscrew import backend
from ballscrew.contact import hertz, solve_normal_batch
from ballscrew.contact.grid import cell_centres

pytestmark = pytest.mark.skipif(backend.pyfftw is None, reason="pyFFTW not installed")

BUDGET = 100_000
"""Bytes: room for four to eight transforms of 12-23 x 16 (13-24 kB each)."""


@pytest.fixture(autouse=True)
def empty_caches():
    """Start with empty caches: each thread keeps its last transform (that of an earlier test)."""
    with backend._caches_lock:
        for cache in backend._caches:
            cache.transforms.clear()
            cache.nbytes = 0


def test_the_caches_of_all_threads_stay_under_the_byte_budget(monkeypatch):
    monkeypatch.setattr(backend, "fft_cache_budget", lambda: BUDGET)
    monkeypatch.setenv("BALLSCREW_FFT_THREADS", "1")
    seen, newest_kept = [], []
    lock, done = threading.Lock(), threading.Barrier(4)

    def fill(shift: int) -> None:
        for k in range(12):
            rows = 12 + (k + shift) % 12
            transform = backend.padded_rfft((rows, 16))
            kept = backend.padded_rfft((rows, 16)) is transform
            with lock:
                seen.append(backend.cached_fft_bytes())
                newest_kept.append(kept)
        done.wait()  # the caches of the threads live until all have filled theirs

    workers = [threading.Thread(target=fill, args=(3 * k,)) for k in range(3)]
    for worker in workers:
        worker.start()
    fill(9)
    for worker in workers:
        worker.join()
    # Every thread keeps its newest transform, so four threads inserting at once may overshoot
    # the budget by at most one transform each (without eviction: about 860 kB here).
    largest = backend.padded_rfft((23, 16)).nbytes
    assert 0 < max(seen) <= BUDGET + 4 * largest
    assert all(newest_kept)
    gc.collect()
    assert backend.cached_fft_bytes() <= backend.padded_rfft((16, 16)).nbytes + max(seen)


def test_a_thread_cache_goes_with_its_thread(monkeypatch):
    monkeypatch.setenv("BALLSCREW_FFT_THREADS", "1")
    before = backend.cached_fft_bytes()
    thread = threading.Thread(target=backend.padded_rfft, args=((40, 40),))
    thread.start()
    thread.join()
    gc.collect()
    assert backend.cached_fft_bytes() <= before


def test_evicting_transforms_leaves_the_batch_results_unchanged(monkeypatch):
    """A budget of one byte keeps only each thread's newest transform: every grid level of the
    nested start is planned anew, and the pressures are those of the unbounded caches."""
    reference = hertz(10e-3, 10e-3, 113.19e9, 100.0)
    dx = 3 * reference.a / 64
    x = cell_centres(64, dx)
    radii = np.array([8e-3, 10e-3, 12e-3, 9e-3])[:, None, None]
    gaps = (x[None, :, None] ** 2 + x[None, None, :] ** 2) / (2 * radii)
    loads = np.array([80.0, 100.0, 120.0, 90.0])
    free = solve_normal_batch(gaps, dx, dx, 113.19e9, loads, precision="mixed")
    monkeypatch.setattr(backend, "fft_cache_budget", lambda: 1)
    bounded = solve_normal_batch(gaps, dx, dx, 113.19e9, loads, precision="mixed")
    for a, b in zip(free, bounded, strict=True):
        np.testing.assert_allclose(b.pressure, a.pressure, rtol=0, atol=1e-9 * reference.p0)
    assert backend.cached_fft_bytes() <= max(
        backend.padded_rfft((64, 64), dtype=d).nbytes for d in (np.float32, np.float64)
    ) * (1 + backend.MAX_FFT_THREADS)
