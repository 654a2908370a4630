"""Array-module dispatch and the zero-padded real FFT used by every convolution in ballscrew.

``array_module(x)`` returns :mod:`numpy` or, for CuPy arrays, :mod:`cupy`, so numerical code can be
written once as ``xp = array_module(a)``. ``padded_rfft(shape, xp)`` returns a transform pair for
the linear (aperiodic) convolution of an ``(m, n)`` array: the spectrum of the array zero-padded to
``(2m, 2n)`` and, back, the first ``(m, n)`` block of the inverse.

Backends, chosen by the array module:

* NumPy with pyFFTW: planned real FFTs on pre-allocated aligned buffers, ``fft_threads()`` threads.
  The zero padding is pruned (the transforms of rows known to be zero are skipped): forward =
  ``rfft`` along axis 1 of the ``m`` data rows only, then the ``fft`` along axis 0; inverse =
  ``ifft`` along axis 0, then ``irfft`` of the first ``m`` rows only.
  Measured on 2 cores: 20-25 % faster than a full ``(2m, 2n)`` real FFT pair.
  Plans start as ``FFTW_ESTIMATE`` (no planning cost). Once the time spent executing a shape exceeds
  the estimated cost of planning it with ``FFTW_MEASURE``, the shape is re-planned with
  ``FFTW_MEASURE`` and the faster of the two plans is kept (a ski-rental rule: planning never costs
  much more than the execution already done). Measured on 2 cores, ``FFTW_MEASURE`` gains 0-15 % up
  to 1024 x 1024 padded and ~25 % at 2048 x 2048, for 0.06-0.5 s of planning. The planning is held
  to that estimate by FFTW's time limit: on the shared, loaded machine an unlimited
  ``FFTW_MEASURE`` of 1024 x 1024 padded took 14-46 s (measured).
* NumPy without pyFFTW: :mod:`scipy.fft` with the same pruning.
* CuPy: :mod:`cupy.fft` (cuFFT caches its own plans).

Both directions are unnormalised (as in FFTW): ``inverse(forward(a))`` is ``a / scale`` with
``scale = 1 / (4 m n)`` held by the transform, so a caller can fold ``scale`` into its kernel once.

Plans and buffers are cached per shape and per thread, so transforms are safe to use from several
threads at once; the caches of all threads together hold at most :func:`fft_cache_budget` bytes.
"""

from __future__ import annotations

import contextlib
import os
import threading
import time
import weakref
from collections import OrderedDict
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from functools import cache
from types import ModuleType
from typing import Any, Protocol, TypeVar

import numpy as np
import scipy.fft

from ballscrew.budget import memory_budget

try:
    import cupy
except ImportError:
    cupy = None

__all__ = [
    "PaddedRealFFT",
    "array_module",
    "blas_single_thread",
    "cached_fft_bytes",
    "fft_cache_budget",
    "fft_pool",
    "fft_threads",
    "limited_fft_threads",
    "map_chunks",
    "padded_rfft",
    "single_thread_pools",
]


@cache
def _pyfftw() -> ModuleType | None:
    """pyFFTW, imported on first use: it imports dask.array (about 1 s), which a command that
    solves no contact (``--help``, ``init``, ``check``) should not wait for."""
    try:
        import pyfftw
    except ImportError:  # pragma: no cover - a hard dependency, the fallback is for safety
        return None
    return pyfftw


def __getattr__(name: str) -> Any:
    """``backend.pyfftw``: the lazily imported module (None where it is not installed)."""
    if name == "pyfftw":
        return _pyfftw()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


MAX_FFT_THREADS = 8
"""Upper bound of the FFT threads: beyond this the 2-D transforms of contact grids stop scaling."""


def array_module(x: Any) -> ModuleType:
    """Return the array module of ``x``: :mod:`cupy` for CuPy arrays, :mod:`numpy` otherwise."""
    if cupy is not None:
        return cupy.get_array_module(x)
    return np


THREADED_MIN_POINTS = 512 * 512
"""Padded transforms smaller than this run on one thread.

Threads gain little on small transforms, and when the cores are shared (a Dask worker per core,
a parallel test run) a threaded FFTW plan of a small grid was measured 100-1000x slower than a
serial one: the threads wait for each other's time slices.
"""


def fft_threads(points: int | None = None) -> int:
    """Threads for an FFT of ``points`` (padded) values on the CPU.

    The limit of an enclosing :func:`limited_fft_threads` block, else ``BALLSCREW_FFT_THREADS``
    if set, else 1 below :data:`THREADED_MIN_POINTS`, else ``os.cpu_count()`` capped at
    :data:`MAX_FFT_THREADS`.
    """
    limit = getattr(_thread_limit, "value", None)
    if limit is not None:
        return limit
    env = os.environ.get("BALLSCREW_FFT_THREADS")
    if env:
        return max(1, int(env))
    if points is not None and points < THREADED_MIN_POINTS:
        return 1
    return max(1, min(_cpu_count(), MAX_FFT_THREADS))


@cache
def _cpu_count() -> int:
    return os.cpu_count() or 1


_thread_limit = threading.local()


@cache
def fft_pool() -> ThreadPoolExecutor:
    """Threads that share out the grids or contacts of a stack (FFTW, pocketfft and NumPy's
    element-wise loops release the GIL while they run); each runs with one FFT thread."""
    return ThreadPoolExecutor(MAX_FFT_THREADS, thread_name_prefix="ballscrew-fft")


_T = TypeVar("_T")


def map_chunks(function: Callable[[slice], _T], size: int, threads: int) -> list[_T]:
    """``function(rows)`` for ``threads`` runs of consecutive rows of a leading batch axis of
    ``size``, at once in :func:`fft_pool` threads of one FFT thread each; the results in the order
    of the rows.

    The runs are those of ``numpy.array_split`` (sizes differ by at most one; an empty run is
    skipped). With ``threads`` ≤ 1 (or one row) ``function(slice(0, size))`` runs in the calling
    thread under its own FFT thread limit. ``threads`` is capped by the calling thread's limit
    (:func:`limited_fft_threads`), which is 1 inside a run, so a nested call stays in its
    thread and never waits on the pool it runs in. The exception of the first failing run (in
    row order) is raised here; runs not yet started are cancelled, running ones finish.
    """
    limit = getattr(_thread_limit, "value", None)
    if limit is not None:
        threads = min(threads, limit)
    if threads <= 1 or size <= 1:
        return [function(slice(0, size))]
    split = np.array_split(np.arange(size), threads)
    runs = [slice(int(c[0]), int(c[-1]) + 1) for c in split if c.size]

    def run(rows: slice) -> _T:
        with limited_fft_threads(1):
            return function(rows)

    return list(fft_pool().map(run, runs))


@contextlib.contextmanager
def limited_fft_threads(threads: int = 1) -> Iterator[None]:
    """Run the block with at most ``threads`` FFT threads (in the calling thread).

    Sweeps run each point like this: their Dask workers already fill the cores.
    """
    previous = getattr(_thread_limit, "value", None)
    _thread_limit.value = max(1, int(threads))
    try:
        yield
    finally:
        _thread_limit.value = previous


@cache
def _threadpool_controller() -> Any:
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()


@contextlib.contextmanager
def blas_single_thread() -> Iterator[None]:
    """Run the block with BLAS limited to one thread.

    Threaded OpenBLAS competes with the FFT threads for the cores: on 2 cores a ``numpy.vdot`` of
    65k doubles issued between two threaded FFTs took 4.6 ms instead of 40 us (measured). Solvers
    that mix FFTs and BLAS reductions run their loop inside this context.
    """
    with _threadpool_controller().limit(limits=1, user_api="blas"):
        yield


@contextlib.contextmanager
def single_thread_pools() -> Iterator[None]:
    """Run the block with every BLAS and OpenMP pool of the process on one thread.

    A sweep's worker runs its points like this: the workers, one per core, already fill the
    cores (the pools loaded when the process first used this are the ones limited).
    """
    with _threadpool_controller().limit(limits=1):
        yield


class PaddedRealFFT(Protocol):
    """Unnormalised real FFT of an ``(m, n)`` array zero-padded to ``(2m, 2n)``, and back."""

    shape: tuple[int, int]
    """``(m, n)``, the shape of the data."""
    scale: float
    """``1 / (4 m n)``: ``inverse(forward(a)) * scale == a``."""

    def forward(self, a: Any) -> Any:
        """Spectrum ``(2m, n + 1)`` (complex) of ``a`` zero-padded to ``(2m, 2n)``.

        The returned array may be an internal buffer, valid until the next call; the caller may
        modify it in place before passing it to :meth:`inverse`.
        """
        ...

    def inverse(self, spectrum: Any, out: Any) -> Any:
        """Write the first ``(m, n)`` block of the unnormalised inverse of ``spectrum`` to ``out``.

        ``spectrum`` may be destroyed. Returns ``out``.
        """
        ...

    def plan_measured(self) -> None:
        """Plan as well as the backend can now, ahead of many calls (benchmarks, sweeps)."""
        ...


class _Padded:
    """What every implementation of :class:`PaddedRealFFT` holds: the data shape ``(m, n)``,
    ``scale = 1/(4 m n)``, the precision and the CPU threads it may use."""

    def __init__(
        self, shape: tuple[int, int], threads: int = 1, dtype: type[np.floating] = np.float64
    ) -> None:
        m, n = shape
        self.shape = shape
        self.scale = 1.0 / (4 * m * n)
        self._threads = threads
        self._dtype = dtype
        self.nbytes = 0
        """Host memory held between calls [bytes]: 0 unless the backend keeps buffers."""

    def plan_measured(self) -> None:
        """Nothing to plan: the library plans on its own."""


class _FFTWPadded(_Padded):
    """pyFFTW implementation of :class:`PaddedRealFFT` with pruned zero padding."""

    _PLAN_EXECUTIONS = 5
    """Executions timed when a plan is made, to compare ESTIMATE with MEASURE."""

    def __init__(
        self, shape: tuple[int, int], threads: int, dtype: type[np.floating] = np.float64
    ) -> None:
        super().__init__(shape, threads, dtype)
        m, n = shape
        pyfftw = self._fftw = _pyfftw()
        self._rows_in = pyfftw.zeros_aligned((m, 2 * n), dtype=dtype)
        self._rows_out = pyfftw.empty_aligned((m, 2 * n), dtype=dtype)
        self._spectrum = pyfftw.zeros_aligned((2 * m, n + 1), dtype=np.result_type(dtype, 1j))
        self.nbytes = self._rows_in.nbytes + self._rows_out.nbytes + self._spectrum.nbytes
        self._plan("FFTW_ESTIMATE")
        self._exec_time = self._time_pair()
        self._spent = 0.0
        self._measured = False

    def _plan(self, flag: str) -> None:
        m = self.shape[0]
        kw: dict[str, Any] = {"flags": (flag,), "threads": self._threads}
        if flag == "FFTW_MEASURE":  # each of the 4 plans within a quarter of the estimated cost
            kw["planning_timelimit"] = 0.25 * self._planning_cost_estimate()
        # In-place column transforms: measured up to 2x faster than out-of-place at 2048 x 1025.
        spectrum, pyfftw = self._spectrum, self._fftw
        self._rfft_rows = pyfftw.FFTW(self._rows_in, spectrum[:m], axes=(1,), **kw)
        self._fft_cols = pyfftw.FFTW(spectrum, spectrum, axes=(0,), **kw)
        self._ifft_cols = pyfftw.FFTW(
            spectrum, spectrum, axes=(0,), direction="FFTW_BACKWARD", **kw
        )
        self._irfft_rows = pyfftw.FFTW(
            spectrum[:m], self._rows_out, axes=(1,), direction="FFTW_BACKWARD", **kw
        )
        self._rows_in.fill(0.0)  # planning may overwrite the buffers; restore the zero padding

    def _time_pair(self) -> float:
        """Best time of one forward + inverse pair with the current plans [s]."""
        best = np.inf
        for _ in range(self._PLAN_EXECUTIONS):
            start = time.perf_counter()
            self._execute_all()
            best = min(best, time.perf_counter() - start)
        return best

    def _execute_all(self) -> None:
        self._rfft_rows.execute()
        self._spectrum[self.shape[0] :] = 0.0
        self._fft_cols.execute()
        self._ifft_cols.execute()
        self._irfft_rows.execute()

    def _maybe_measure(self) -> None:
        """Re-plan with FFTW_MEASURE once the execution time spent exceeds its planning cost."""
        self._spent += self._exec_time
        if not self._measured and self._spent >= self._planning_cost_estimate():
            self.plan_measured()

    def plan_measured(self) -> None:
        """Re-plan with FFTW_MEASURE now; keep the faster of the old and the new plans."""
        if self._measured:
            return
        self._measured = True
        old = (self._rfft_rows, self._fft_cols, self._ifft_cols, self._irfft_rows)
        old_time = self._time_pair()
        self._plan("FFTW_MEASURE")
        self._exec_time = self._time_pair()
        if old_time < self._exec_time:
            self._rfft_rows, self._fft_cols, self._ifft_cols, self._irfft_rows = old
            self._exec_time = old_time

    def _planning_cost_estimate(self) -> float:
        """FFTW_MEASURE planning time [s] of the four plans, from the ESTIMATE pair time.

        Fit to measurements on 2 cores (0.06 s at 128 x 128 data, 0.15 s at 256, 0.23 s at 512,
        0.46 s at 1024): within a factor 2, which keeps the ski-rental rule within ~3x of optimal.
        """
        return 0.1 + 15.0 * self._exec_time

    def forward(self, a: np.ndarray) -> np.ndarray:
        self._maybe_measure()
        m, n = self.shape
        np.copyto(self._rows_in[:, :n], a)
        self._rfft_rows.execute()
        self._spectrum[m:] = 0.0
        self._fft_cols.execute()
        return self._spectrum

    def inverse(self, spectrum: np.ndarray, out: np.ndarray) -> np.ndarray:
        if spectrum is not self._spectrum:
            np.copyto(self._spectrum, spectrum)
        self._ifft_cols.execute()
        self._irfft_rows.execute()
        np.copyto(out, self._rows_out[:, : self.shape[1]])
        return out


class _ScipyPadded(_Padded):
    """:mod:`scipy.fft` implementation of :class:`PaddedRealFFT` with pruned zero padding."""

    def forward(self, a: np.ndarray) -> np.ndarray:
        m, n = self.shape
        a = np.asarray(a, dtype=self._dtype)
        rows = scipy.fft.rfft(a, n=2 * n, axis=1, workers=self._threads)
        return scipy.fft.fft(rows, n=2 * m, axis=0, overwrite_x=True, workers=self._threads)

    def inverse(self, spectrum: np.ndarray, out: np.ndarray) -> np.ndarray:
        m, n = self.shape
        cols = scipy.fft.ifft(spectrum, axis=0, norm="forward", workers=self._threads)
        rows = scipy.fft.irfft(cols[:m], n=2 * n, axis=1, norm="forward", workers=self._threads)
        out[...] = rows[:, :n]
        return out


class _CupyPadded(_Padded):
    """:mod:`cupy.fft` implementation of :class:`PaddedRealFFT` (cuFFT caches the plans)."""

    def forward(self, a: Any) -> Any:
        m, n = self.shape
        return cupy.fft.rfft2(a.astype(self._dtype, copy=False), s=(2 * m, 2 * n))

    def inverse(self, spectrum: Any, out: Any) -> Any:
        m, n = self.shape
        full = cupy.fft.irfft2(spectrum, s=(2 * m, 2 * n), norm="forward")
        out[...] = full[:m, :n]
        return out


CACHED_SHAPES = 16
"""Transforms kept per thread (plans + buffers: ~66 MB at 1024 x 1024), least recently used out.

A nested-grid solve uses one per grid level (5-6), twice over with mixed precision: with fewer
slots the two hierarchies evicted each other and every solve planned its transforms anew."""

CACHE_SHARE = 0.125
"""GUESS: share of :func:`ballscrew.budget.memory_budget` that the cached transforms of all threads
may hold together. A nested-grid solve of 1024 x 1024 holds ~130 MB of transforms (both
precisions); with the default budget (half the RAM) a 16 GiB machine caches 1 GiB, enough for
eight such solves at once (:func:`fft_pool`), instead of up to 8 threads x 16 x 66 MB."""


class _ThreadCache:
    """One thread's transforms, least recently used first, and the bytes they hold."""

    def __init__(self) -> None:
        self.transforms: OrderedDict[tuple, Any] = OrderedDict()
        self.nbytes = 0

    def pop_oldest(self) -> None:
        self.nbytes -= self.transforms.popitem(last=False)[1].nbytes


_local = threading.local()
_caches: weakref.WeakSet[_ThreadCache] = weakref.WeakSet()
"""The caches of the live threads (a thread's cache goes with the thread)."""
_caches_lock = threading.Lock()


def fft_cache_budget() -> int:
    """Bytes the cached transforms of all threads may hold: :data:`CACHE_SHARE` of the budget."""
    return int(CACHE_SHARE * memory_budget())


def cached_fft_bytes() -> int:
    """Bytes held by the cached transforms of all threads of the process."""
    with _caches_lock:
        return sum(cache.nbytes for cache in list(_caches))


def _thread_cache() -> _ThreadCache:
    cache = getattr(_local, "cache", None)
    if cache is None:
        cache = _local.cache = _ThreadCache()
        with _caches_lock:
            _caches.add(cache)
    return cache


def _make_room(own: _ThreadCache, budget: int) -> None:
    """Evict least recently used transforms until all caches hold at most ``budget`` bytes: the
    calling thread's first, then those of the fullest other thread. Each thread keeps its most
    recently used transform (likely in use: evicting it would plan it anew at every call), so the
    caches exceed ``budget`` by at most one transform per thread, no more than the threads' last
    solves held at once (a solve checks its memory, these buffers included, against the budget:
    :func:`ballscrew.budget.contact_grid_bytes`)."""
    with _caches_lock:
        caches = list(_caches)
        total = sum(cache.nbytes for cache in caches)
        while total > budget:
            if len(own.transforms) > 1:
                victim = own
            else:
                others = [c for c in caches if len(c.transforms) > 1]
                if not others:
                    return
                victim = max(others, key=lambda c: c.nbytes)
            before = victim.nbytes
            victim.pop_oldest()
            total -= before - victim.nbytes


def padded_rfft(
    shape: tuple[int, int], xp: ModuleType = np, dtype: type[np.floating] = np.float64
) -> PaddedRealFFT:
    """The :class:`PaddedRealFFT` of ``shape`` for array module ``xp``, cached per thread.

    ``dtype`` (``numpy.float64`` or ``numpy.float32``) is the precision of the transform: its
    spectrum is complex of the same precision and its input is cast to it. Each thread keeps up to
    :data:`CACHED_SHAPES` transforms; all threads together hold at most :func:`fft_cache_budget`
    bytes (least recently used out, see :func:`_make_room`).
    """
    shape = (int(shape[0]), int(shape[1]))
    dtype = np.dtype(dtype).type
    cache = _thread_cache()
    threads = fft_threads(4 * shape[0] * shape[1])
    key = (shape, xp.__name__, threads, dtype.__name__)
    with _caches_lock:  # another thread may evict from this cache
        transform = cache.transforms.get(key)
        if transform is not None:
            cache.transforms.move_to_end(key)
            return transform
    if xp is not np:
        transform = _CupyPadded(shape, dtype=dtype)
    elif _pyfftw() is not None:
        transform = _FFTWPadded(shape, threads, dtype)
    else:
        transform = _ScipyPadded(shape, threads, dtype)
    with _caches_lock:
        cache.transforms[key] = transform
        cache.nbytes += transform.nbytes
        if len(cache.transforms) > CACHED_SHAPES:
            cache.pop_oldest()
    _make_room(cache, fft_cache_budget())
    return transform
