"""Benchmark of the normal-contact solvers against Hertz, the FFT floor and peer solvers.

Cases (those the peers Tamaas 2.9.0 and ContactMechanics 1.8.3 were timed on): sphere
R = 10 mm, W = 100 N and the ellipse Rx = 3.6 mm, Ry = 40 mm, W = 1000 N, E* = 113.19 GPa, box
side 3 × the Hertz contact diameter along each axis, N × N cells, tol 1e-8. For each N: median
wall time of the solves after a warm-up, iterations, peak-pressure error against Hertz, and the
ratio of the time to the "FFT floor" = iterations × one forward + inverse real FFT of 2N × 2N
with the same backend (pyFFTW, same threads).

The grid has a cell centred on the origin (as the peers' grids, whose peak-pressure errors are
positive), so the peak cell samples p0 itself.

Columns: ``pcg`` = solve_normal with its default method (spectral preconditioner, nested-grid
start), including the set-up of a new DC-FFT operator; ``it`` = iterations on the N × N grid +
the coarse grids' iterations in N × N equivalents; ``best`` = the fastest repeat (this machine's
timings are noisy); ``/floor`` for pcg counts its work (fine + coarse iterations; pcg iterates
on a window around the contact, whose FFT pairs are smaller than 2N × 2N, so it can fall below
1); ``mixed`` =
the same with float32 FFTs finished in float64; ``pk`` = the plain Polonsky & Keer CG (method
"pk", uniform start); ``x pk`` = pk time / pcg time; ``x Tamaas`` = Tamaas 2.9.0's time on the
same problem, measured in the same run when Tamaas is installed (``make bench`` installs it in
its own environment, ``.venv-peers``), else its time recorded earlier on this machine (marked *),
over the pcg time.

Then ``solve_normal_batch`` on 32 ball contacts of 128 × 128 cells (--quick: 8 of 64 × 64; radii
and loads drawn around the sphere case): contacts per second, batched and one at a time.

Usage: python benchmarks/bench_contact.py [--quick]   (--quick: N = 64, 128 and 2 repeats)
"""

from __future__ import annotations

import argparse
import importlib.util
import statistics
import time
from collections.abc import Callable

import numpy as np
import pyfftw

from ballscrew.backend import blas_single_thread, fft_threads, padded_rfft
from ballscrew.contact import DCFFTOperator, hertz, solve_normal, solve_normal_batch

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


def problem(name: str, n: int) -> tuple[np.ndarray, float, float, float, object]:
    """Gap, cell sizes, load and Hertz estimate of a benchmark case on N × N cells."""
    rx, ry, load = CASES[name]
    estimate = hertz(rx, ry, E_STAR, load)
    dx, dy = 6.0 * estimate.a / n, 6.0 * estimate.b / n
    centred = np.arange(n) - n // 2  # one cell centred on the origin, as the peers' grids
    x, y = dx * centred[:, None], dy * centred[None, :]
    return x**2 / (2.0 * rx) + y**2 / (2.0 * ry), dx, dy, load, estimate


def tamaas_time(name: str, n: int, repeats: int) -> tuple[float, str]:
    """Tamaas's time on the case, measured if Tamaas is installed, else the recorded one [s]."""
    recorded = PEERS[name].get(n, (np.nan,) * 3)[1]
    if importlib.util.find_spec("tamaas") is None:
        return recorded, "*"
    import tamaas as tm

    gap, dx, dy, load, _ = problem(name, n)
    model = tm.ModelFactory.createModel(
        tm.model_type.basic_2d, [2 * n * dx, 2 * n * dy], [2 * n] * 2
    )
    model.E, model.nu = E_STAR, 0.0
    surface = np.full((2 * n, 2 * n), -float(gap.max()))  # padded: non-periodic as the DC-FFT
    surface[:n, :n] = -gap

    def solve() -> object:
        model.traction[...] = 0.0  # cold start: Tamaas starts from the model's last traction
        solver = tm.PolonskyKeerRey(model, surface, 1e-8)
        return solver.solve(load / (4 * n * n * dx * dy))

    return wall_times(solve, repeats)[0], ""


def run_case(name: str, n: int, repeats: int) -> dict[str, float]:
    gap, dx, dy, load, estimate = problem(name, n)

    def cold(method: str = "pcg", precision: str = "float64") -> object:
        operator = DCFFTOperator(gap.shape, dx, dy, E_STAR)
        return solve_normal(
            gap, dx, dy, E_STAR, load, operator=operator, method=method, precision=precision
        )

    padded_rfft(gap.shape).plan_measured()  # steady state: no planning inside the timed solves
    padded_rfft(gap.shape, dtype=np.float32).plan_measured()
    result, old, mixed = cold(), cold("pk"), cold("pcg", "mixed")
    with blas_single_thread():
        pair = fft_pair_time(n)
    t_new, t_best = wall_times(cold, repeats)
    t_mixed, _ = wall_times(lambda: cold("pcg", "mixed"), repeats)
    t_old, _ = wall_times(lambda: cold("pk"), repeats)
    t_tamaas, mark = tamaas_time(name, n, repeats)
    work = result.iterations + result.coarse_work
    return {
        "time": t_new,
        "best": t_best,
        "iterations": f"{result.iterations}+{result.coarse_work:.1f}",
        "error": result.peak_pressure / estimate.p0 - 1.0,
        "floor": t_new / (work * pair),
        "mixed_time": t_mixed,
        "mixed_error": float(np.abs(mixed.pressure - result.pressure).max() / estimate.p0),
        "pk_time": t_old,
        "pk_iterations": old.iterations,
        "pk_ratio": t_old / t_new,
        "tamaas": f"{t_tamaas / t_new:6.1f}{mark}",
    }


def run_batch(batch: int = 32, n: int = 128, repeats: int = 3) -> tuple[float, float, int]:
    """Contacts per second of solve_normal_batch and of one-at-a-time solves, and iterations."""
    rng = np.random.default_rng(0)
    estimate = hertz(10e-3, 10e-3, E_STAR, 100.0)
    dx = dy = 6.0 * estimate.a / n
    centred = dx * (np.arange(n) - n // 2)
    x, y = centred[:, None], centred[None, :]
    radii = 10e-3 * (1.0 + 0.2 * rng.random(batch))
    gaps = (x**2 + y**2)[None] / (2.0 * radii[:, None, None])
    loads = 100.0 * (1.0 + 0.2 * rng.random(batch))
    together = solve_normal_batch(gaps, dx, dy, E_STAR, loads)
    t_batch, _ = wall_times(lambda: solve_normal_batch(gaps, dx, dy, E_STAR, loads), repeats)
    t_alone, _ = wall_times(
        lambda: [solve_normal(g, dx, dy, E_STAR, w) for g, w in zip(gaps, loads, strict=True)],
        repeats,
    )
    return batch / t_batch, batch / t_alone, max(r.iterations for r in together)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="N = 64, 128 and 2 repeats only")
    args = parser.parse_args()
    sizes, repeats = ((64, 128), 2) if args.quick else ((128, 256, 512, 1024, 2048), 3)
    print(
        f"pyFFTW {pyfftw.__version__}, {fft_threads()} FFT threads, E* = {E_STAR:.5g} Pa, tol 1e-8"
    )
    header = (
        f"{'case':8s} {'N':>5s} {'pcg [s]':>9s} {'best':>7s} {'it':>8s} {'p_max err':>10s} "
        f"{'/floor':>7s} {'mixed [s]':>9s} {'mix err':>8s} {'pk [s]':>8s} {'it':>4s} "
        f"{'x pk':>5s} {'x Tamaas':>8s}"
    )
    print(header)
    print("-" * len(header))
    print("targets: 1024² sphere <= 1.5 s, ellipse <= 2.0 s; 2048² sphere <= 8 s")
    for name in CASES:
        for n in sizes:
            row = run_case(name, n, repeats if n < 2048 else 1)
            print(
                f"{name:8s} {n:5d} {row['time']:9.4f} {row['best']:7.4f} {row['iterations']:>8s} "
                f"{row['error']:+10.2e} {row['floor']:7.2f} {row['mixed_time']:9.4f} "
                f"{row['mixed_error']:8.1e} {row['pk_time']:8.4f} {row['pk_iterations']:4d} "
                f"{row['pk_ratio']:5.2f} {row['tamaas']:>8s}"
            )
    batch, n = (8, 64) if args.quick else (32, 128)
    batch_rate, alone_rate, iterations = run_batch(batch, n, repeats=1 if args.quick else 3)
    print(
        f"batch of {batch} ball contacts, {n} x {n} cells: {batch_rate:.0f} contacts/s batched, "
        f"{alone_rate:.0f} contacts/s one at a time (<= {iterations} fine iterations; "
        "target >= 2000/s)"
    )


if __name__ == "__main__":
    main()
