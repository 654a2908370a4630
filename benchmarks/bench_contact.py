"""Benchmark of the normal-contact solver against Hertz, the FFT floor and peer solvers.

Cases (those the peers Tamaas 2.9.0 and ContactMechanics 1.8.3 were timed on): sphere
R = 10 mm, W = 100 N and the ellipse Rx = 3.6 mm, Ry = 40 mm, W = 1000 N, E* = 113.19 GPa, box
side 3 × the Hertz contact diameter along each axis, N × N cells, tol 1e-8. For each N: median
wall time of 5 solves after a warm-up, iterations, peak-pressure error against Hertz, and the
ratio of the time to the "FFT floor" = iterations × one forward + inverse real FFT of 2N × 2N
with the same backend (pyFFTW, same threads).

The grid has a cell centred on the origin (as the peers' grids, whose peak-pressure errors are
positive), so the peak cell samples p0 itself.

Columns: ``cold`` = solve_normal from the uniform start of Polonsky & Keer, including the set-up
of a new DC-FFT operator (Love coefficients + kernel FFT), comparable with the peers' times
(median; ``best`` = the fastest repeat, as this machine's timings are noisy); ``warm`` = the same
started from the Hertz pressure (as solve_contact does), cached operator.

Usage: python benchmarks/bench_contact.py [--quick]   (--quick: N = 64, 128 and 2 repeats)
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable

import numpy as np
import pyfftw

from ballscrew.backend import blas_single_thread, fft_threads, padded_rfft
from ballscrew.contact import DCFFTOperator, hertz, solve_normal

E_STAR = 113.19e9
CASES = {"sphere": (10e-3, 10e-3, 100.0), "ellipse": (3.6e-3, 40e-3, 1000.0)}
PEERS = {  # (plain NumPy PK, Tamaas, ContactMechanics) [s], same machine, anchors file
    "sphere": {128: (0.055, 0.141, 0.155), 256: (0.31, 0.82, 0.92), 512: (1.5, 5.2, 7.4),
               1024: (10.9, 36.9, 56.3)},
    "ellipse": {128: (0.072, 0.186, 0.198), 256: (0.38, 1.07, 1.19), 512: (1.9, 6.6, 9.7),
                1024: (14.3, 51.0, 83.0)},
}  # fmt: skip


def wall_times(func: Callable[[], object], repeats: int) -> tuple[float, float]:
    """Median and best wall time of ``repeats`` calls after one warm-up call [s]."""
    func()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        func()
        times.append(time.perf_counter() - start)
    return statistics.median(times), min(times)


def fft_pair_time(n: int, repeats: int = 20) -> float:
    """Best time of one forward + inverse real FFT of 2n × 2n with pyFFTW, FFTW_MEASURE [s]."""
    real = pyfftw.zeros_aligned((2 * n, 2 * n), dtype=np.float64)
    spectrum = pyfftw.empty_aligned((2 * n, n + 1), dtype=np.complex128)
    kw = {"axes": (0, 1), "flags": ("FFTW_MEASURE",), "threads": fft_threads()}
    forward = pyfftw.FFTW(real, spectrum, **kw)
    backward = pyfftw.FFTW(spectrum, real, direction="FFTW_BACKWARD", **kw)
    real[:] = np.random.default_rng(0).random(real.shape)
    best = np.inf
    for _ in range(repeats):
        start = time.perf_counter()
        forward.execute()
        backward.execute()
        best = min(best, time.perf_counter() - start)
    return best


def run_case(name: str, n: int, repeats: int) -> dict[str, float]:
    rx, ry, load = CASES[name]
    estimate = hertz(rx, ry, E_STAR, load)
    dx, dy = 6.0 * estimate.a / n, 6.0 * estimate.b / n
    centred = np.arange(n) - n // 2  # one cell centred on the origin, as the peers' grids
    x, y = dx * centred[:, None], dy * centred[None, :]
    gap = x**2 / (2.0 * rx) + y**2 / (2.0 * ry)
    initial = estimate.pressure(x, y)

    def cold() -> object:
        operator = DCFFTOperator(gap.shape, dx, dy, E_STAR)
        return solve_normal(gap, dx, dy, E_STAR, load, operator=operator)

    def warm() -> object:
        return solve_normal(gap, dx, dy, E_STAR, load, initial=initial)

    padded_rfft(gap.shape).plan_measured()  # steady state: no planning inside the timed solves
    result = solve_normal(gap, dx, dy, E_STAR, load)
    warm_result = warm()
    with blas_single_thread():
        pair = fft_pair_time(n)
    t_cold, t_best = wall_times(cold, repeats)
    t_warm, _ = wall_times(warm, repeats)
    return {
        "time": t_cold,
        "best": t_best,
        "iterations": result.iterations,
        "error": result.peak_pressure / estimate.p0 - 1.0,
        "floor": t_cold / (result.iterations * pair),
        "warm_time": t_warm,
        "warm_iterations": warm_result.iterations,
        "pair_ms": 1e3 * pair,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="N = 64, 128 and 2 repeats only")
    args = parser.parse_args()
    sizes, repeats = ((64, 128), 2) if args.quick else ((128, 256, 512, 1024), 5)
    print(
        f"pyFFTW {pyfftw.__version__}, {fft_threads()} FFT threads, E* = {E_STAR:.5g} Pa, tol 1e-8"
    )
    header = (
        f"{'case':8s} {'N':>5s} {'cold [s]':>9s} {'best':>7s} {'it':>4s} {'p_max err':>10s} "
        f"{'/floor':>7s} "
        f"{'warm [s]':>9s} {'it':>4s} {'FFT pair':>9s} | peers [s]: NumPy PK, Tamaas, CM"
    )
    print(header)
    print("-" * len(header))
    print("targets (sphere, cold): N = 256 <= 0.10 s, N = 512 <= 0.6 s")
    for name in CASES:
        for n in sizes:
            row = run_case(name, n, repeats)
            peers = PEERS[name].get(n)
            peer_text = "  ".join(f"{t:6.3f}" for t in peers) if peers else "   -"
            print(
                f"{name:8s} {n:5d} {row['time']:9.4f} {row['best']:7.4f} {row['iterations']:4d} "
                f"{row['error']:+10.2e} {row['floor']:7.2f} {row['warm_time']:9.4f} "
                f"{row['warm_iterations']:4d} {row['pair_ms']:7.3f}ms | {peer_text}"
            )


if __name__ == "__main__":
    main()
