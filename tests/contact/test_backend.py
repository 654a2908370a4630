"""Array-module dispatch and the zero-padded FFT backends of ballscrew.backend, checked against
numpy.fft on explicitly padded arrays."""

import threading

import numpy as np
import pytest
from threadpoolctl import threadpool_info

from ballscrew import backend
from ballscrew.contact import hertz, solve_normal, solve_normal_batch
from ballscrew.contact.grid import cell_centres


def padded_spectrum(a):
    m, n = a.shape
    padded = np.zeros((2 * m, 2 * n))
    padded[:m, :n] = a
    return np.fft.rfft2(padded)


def implementations(shape):
    yield backend._ScipyPadded(shape, 2)
    if backend.pyfftw is not None:
        yield backend._FFTWPadded(shape, 2)


@pytest.mark.parametrize("shape", [(1, 1), (6, 5), (16, 9), (32, 32)])
def test_forward_is_the_spectrum_of_the_padded_array_and_inverse_undoes_it(shape):
    a = np.random.default_rng(7).standard_normal(shape)
    for transform in implementations(shape):
        for _ in range(2):  # buffers are reused between calls
            spectrum = transform.forward(a)
            np.testing.assert_allclose(spectrum, padded_spectrum(a), atol=1e-12)
            out = transform.inverse(spectrum.copy(), np.empty(shape))
            np.testing.assert_allclose(out * transform.scale, a, atol=1e-13)
        assert transform.scale == 1.0 / (4 * shape[0] * shape[1])


@pytest.mark.skipif(backend.pyfftw is None, reason="pyFFTW not installed")
def test_fftw_replanning_with_measure_keeps_results_exact():
    """Force the ski-rental switch to FFTW_MEASURE; the zero padding must survive re-planning."""
    shape = (12, 10)
    transform = backend._FFTWPadded(shape, 2)
    a = np.random.default_rng(1).standard_normal(shape)
    transform.forward(a + 1.0)
    transform._spent = np.inf
    spectrum = transform.forward(a)
    assert transform._measured
    np.testing.assert_allclose(spectrum, padded_spectrum(a), atol=1e-12)


def test_padded_rfft_is_cached_per_thread():
    here = backend.padded_rfft((8, 8))
    assert backend.padded_rfft((8, 8)) is here
    other = []
    thread = threading.Thread(target=lambda: other.append(backend.padded_rfft((8, 8))))
    thread.start()
    thread.join()
    assert other[0] is not here


def test_transform_cache_keeps_the_recent_shapes():
    first = backend.padded_rfft((3, 2))
    for rows in range(4, 4 + backend.CACHED_SHAPES):
        backend.padded_rfft((rows, 2))
    assert backend.padded_rfft((3, 2)) is not first
    assert backend.padded_rfft((4 + backend.CACHED_SHAPES - 1, 2)) is backend.padded_rfft(
        (4 + backend.CACHED_SHAPES - 1, 2)
    )


def test_array_module_is_numpy_for_numpy_and_without_cupy(monkeypatch):
    assert backend.array_module(np.zeros(3)) is np
    monkeypatch.setattr(backend, "cupy", None)
    assert backend.array_module(np.zeros(3)) is np
    assert backend.array_module([1.0, 2.0]) is np


def test_fft_threads_setting(monkeypatch):
    monkeypatch.setenv("BALLSCREW_FFT_THREADS", "1")
    assert backend.fft_threads() == 1
    monkeypatch.delenv("BALLSCREW_FFT_THREADS")
    assert 1 <= backend.fft_threads() <= backend.MAX_FFT_THREADS


def test_blas_runs_single_threaded_inside_the_context():
    with backend.blas_single_thread():
        blas = [info for info in threadpool_info() if info["user_api"] == "blas"]
        assert all(info["num_threads"] == 1 for info in blas)


def test_solver_runs_on_cupy_arrays():
    """The same solver code on the GPU gives the NumPy answer (skipped without CuPy)."""
    cupy = pytest.importorskip("cupy")
    reference = hertz(10e-3, 10e-3, 113.19e9, 100.0)
    dx = 3 * reference.a / 48
    x = cell_centres(48, dx)
    gap = (x[:, None] ** 2 + x[None, :] ** 2) / 20e-3
    on_cpu = solve_normal(gap, dx, dx, 113.19e9, 100.0)
    on_gpu = solve_normal(cupy.asarray(gap), dx, dx, 113.19e9, 100.0)
    assert backend.array_module(on_gpu.pressure) is cupy
    np.testing.assert_allclose(
        cupy.asnumpy(on_gpu.pressure), on_cpu.pressure, atol=1e-6 * reference.p0
    )


def test_small_transforms_are_serial_and_the_limit_applies(monkeypatch):
    monkeypatch.delenv("BALLSCREW_FFT_THREADS", raising=False)
    assert backend.fft_threads(64 * 64) == 1
    with backend.limited_fft_threads(1):
        assert backend.fft_threads(4096 * 4096) == 1
        transform = backend.padded_rfft((512, 512))
    assert backend.fft_threads() >= 1
    # A transform planned inside the limit is not handed out outside it (thread count is keyed).
    if backend.fft_threads(4 * 512 * 512) > 1:
        assert backend.padded_rfft((512, 512)) is not transform


def test_batched_solver_runs_on_cupy_arrays():
    """solve_normal_batch on the GPU (batched cuFFT) gives the NumPy answer (skipped, no CuPy)."""
    cupy = pytest.importorskip("cupy")

    reference = hertz(10e-3, 10e-3, 113.19e9, 100.0)
    dx = 3 * reference.a / 96
    x = cell_centres(96, dx)
    gaps = np.stack([(x[:, None] ** 2 + x[None, :] ** 2) / (2 * r) for r in (10e-3, 12e-3, 9e-3)])
    loads = [100.0, 80.0, 120.0]
    on_cpu = solve_normal_batch(gaps, dx, dx, 113.19e9, loads)
    on_gpu = solve_normal_batch(cupy.asarray(gaps), dx, dx, 113.19e9, loads, precision="mixed")
    for gpu, cpu in zip(on_gpu, on_cpu, strict=True):
        assert backend.array_module(gpu.pressure) is cupy
        np.testing.assert_allclose(
            cupy.asnumpy(gpu.pressure), cpu.pressure, atol=1e-6 * reference.p0
        )


def test_batched_solver_with_per_contact_cells_runs_on_cupy_arrays():
    """Per-contact dx, dy and E* on the GPU (a stack of kernel spectra) give the NumPy answer
    (skipped, no CuPy)."""
    cupy = pytest.importorskip("cupy")

    e_stars = np.array([113.19e9, 150e9, 90e9])
    loads = np.array([100.0, 80.0, 120.0])
    radii = [(10e-3, 10e-3), (5e-3, 20e-3), (4e-3, 30e-3)]
    gaps, dx, dy = [], [], []
    for (rx, ry), e_star, load in zip(radii, e_stars, loads, strict=True):
        reference = hertz(rx, ry, e_star, load)
        dx.append(3 * reference.a / 64)
        dy.append(3 * reference.b / 64)
        x, y = cell_centres(64, dx[-1])[:, None], cell_centres(64, dy[-1])[None, :]
        gaps.append(x**2 / (2 * rx) + y**2 / (2 * ry))
    on_cpu = solve_normal_batch(np.stack(gaps), dx, dy, e_stars, loads)
    on_gpu = solve_normal_batch(cupy.asarray(np.stack(gaps)), dx, dy, e_stars, loads)
    for gpu, cpu in zip(on_gpu, on_cpu, strict=True):
        assert backend.array_module(gpu.pressure) is cupy
        np.testing.assert_allclose(
            cupy.asnumpy(gpu.pressure), cpu.pressure, atol=1e-9 * cpu.peak_pressure
        )


def _rows_seen(rows):
    """What a run of map_chunks saw: its rows, its thread and its FFT threads."""
    return list(range(rows.start, rows.stop)), threading.current_thread(), backend.fft_threads()


def test_map_chunks_keeps_the_order_of_the_rows_in_pool_threads_of_one_fft_thread(monkeypatch):
    monkeypatch.setenv("BALLSCREW_FFT_THREADS", "4")
    runs = backend.map_chunks(_rows_seen, 10, 3)
    assert [rows for rows, _, _ in runs] == [[0, 1, 2, 3], [4, 5, 6], [7, 8, 9]]
    assert all(t.name.startswith("ballscrew-fft") and fft == 1 for _, t, fft in runs)
    # More threads than rows: one row a run, no empty run.
    assert [rows for rows, _, _ in backend.map_chunks(_rows_seen, 3, 8)] == [[0], [1], [2]]


def test_map_chunks_on_one_thread_runs_in_the_caller_under_its_limit(monkeypatch):
    monkeypatch.setenv("BALLSCREW_FFT_THREADS", "4")
    for size, threads in ((10, 1), (1, 4), (0, 4)):
        [(rows, thread, fft)] = backend.map_chunks(_rows_seen, size, threads)
        assert rows == list(range(size)) and thread is threading.current_thread() and fft == 4


def test_map_chunks_raises_the_exception_of_a_run():
    def fail_on_seven(rows):
        if rows.start <= 7 < rows.stop:
            raise ValueError("row 7")
        return rows

    with pytest.raises(ValueError, match="row 7"):
        backend.map_chunks(fail_on_seven, 10, 4)
    assert backend.map_chunks(fail_on_seven, 7, 4) == [
        slice(0, 2),
        slice(2, 4),
        slice(4, 6),
        slice(6, 7),
    ]
