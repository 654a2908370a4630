"""Batched ball contacts: 32 contacts of 128 × 128 cells in one ``solve_normal_batch`` call.

The batch of ``run_batch`` in ``bench_contact.py`` (Hertz spheres, radii and loads ±20 %, box
3 contact diameters across), timed in separate processes, one per source tree given (this
checkout's ``src`` first, then each ``--against`` tree, e.g. an older checkout), alternating
the order from round to round. Per tree: contacts/s (median and best of the wall times), CPU
time per contact (process time, all threads: less sensitive to a shared machine than the wall
time), the fine iterations + coarse work per contact, the load average at each run, and the FFT
floor: the FFT pairs counted in one solve, each pair timed alone on one core (best of many,
FFTW_MEASURE), as contacts/s on two cores doing nothing but those FFTs.

Usage: python benchmarks/bench_ball_batch.py [--against OLD/src] [--rounds 3] [--repeats 7]
"""

from __future__ import annotations

import argparse
import collections
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"
BATCH, N, E_STAR = 32, 128, 113.19e9


def _problem():
    import numpy as np

    from ballscrew.contact import hertz

    rng = np.random.default_rng(0)
    dx = 6.0 * hertz(10e-3, 10e-3, E_STAR, 100.0).a / N
    centred = dx * (np.arange(N) - N // 2)
    radii = 10e-3 * (1.0 + 0.2 * rng.random(BATCH))
    gaps = (centred[:, None] ** 2 + centred[None, :] ** 2)[None] / (2.0 * radii[:, None, None])
    return gaps, dx, 100.0 * (1.0 + 0.2 * rng.random(BATCH))


def _best(func, calls: int = 50) -> float:
    """Best CPU time of one call [s] over 5 runs of ``calls`` calls."""
    best = float("inf")
    for _ in range(5):
        start = time.thread_time()
        for _ in range(calls):
            func()
        best = min(best, (time.thread_time() - start) / calls)
    return best


def _floor(gaps, dx, loads) -> tuple[float, dict[str, float]]:
    """FFT time per contact [s]: the pairs of one solve, counted, each timed alone (one core);
    and the pairs per contact by kind and size."""
    import numpy as np
    import scipy.fft

    from ballscrew.backend import limited_fft_threads, padded_rfft
    from ballscrew.contact import convolution, preconditioned, solve_normal_batch

    padded, periodic = collections.Counter(), collections.Counter()
    apply_with = convolution.DCFFTOperator._apply_with
    apply = preconditioned.SpectralPreconditioner.apply

    def count_padded(op, transform, p, out):
        padded[op.shape] += 1
        return apply_with(op, transform, p, out)

    def count_periodic(pre, g, dtype=np.float64):
        periodic[pre.shape] += len(g)
        return apply(pre, g, dtype)

    convolution.DCFFTOperator._apply_with = count_padded
    preconditioned.SpectralPreconditioner.apply = count_periodic
    try:
        with limited_fft_threads(1):
            solve_normal_batch(gaps, dx, dx, E_STAR, loads)
    finally:
        convolution.DCFFTOperator._apply_with = apply_with
        preconditioned.SpectralPreconditioner.apply = apply
    total = 0.0
    with limited_fft_threads(1):
        for shape, count in padded.items():
            transform = padded_rfft(shape)
            transform.plan_measured()
            op = convolution.DCFFTOperator(shape, dx, dx, E_STAR)
            p, out = np.random.default_rng(1).random(shape), np.empty(shape)
            total += count * _best(lambda op=op, t=transform, p=p, o=out: op._apply_with(t, p, o))
        for shape, count in periodic.items():
            g = np.random.default_rng(2).random((16, *shape))
            pair = _best(lambda g=g, s=shape: scipy.fft.irfft2(scipy.fft.rfft2(g), s=s), 10) / 16
            total += count * pair
    counts = {f"padded {m}x{n}": k / BATCH for (m, n), k in sorted(padded.items())}
    counts |= {f"periodic {m}x{n}": k / BATCH for (m, n), k in sorted(periodic.items())}
    return total / BATCH, counts


def _child(repeats: int) -> None:
    """One tree, in this process: JSON of wall and CPU times per batch, work and FFT floor."""
    import numpy as np

    from ballscrew.contact import solve_normal_batch

    gaps, dx, loads = _problem()
    for _ in range(3):  # plans, caches
        results = solve_normal_batch(gaps, dx, dx, E_STAR, loads)
    wall, cpu = [], []
    for _ in range(repeats):
        start, start_cpu = time.perf_counter(), time.process_time()
        solve_normal_batch(gaps, dx, dx, E_STAR, loads)
        wall.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    work = [np.mean([r.iterations for r in results]), np.mean([r.coarse_work for r in results])]
    load = os.getloadavg()[0]
    fft, counts = _floor(gaps, dx, loads)
    print(json.dumps({"wall": wall, "cpu": cpu, "work": work, "load": load, "fft": fft, **counts}))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--against", action="append", default=[], help="another src tree")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--child", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        sys.path.insert(0, args.child)
        _child(args.repeats)
        return
    trees = [str(SRC), *args.against]
    runs: dict[str, list[dict]] = {tree: [] for tree in trees}
    for round_ in range(args.rounds):
        for tree in trees if round_ % 2 == 0 else trees[::-1]:
            command = [sys.executable, __file__, "--child", tree, "--repeats", str(args.repeats)]
            out = subprocess.run(command, capture_output=True, text=True, check=True).stdout
            runs[tree].append(json.loads(out.strip().splitlines()[-1]))
    print(f"{BATCH} contacts of {N} x {N} cells, {args.rounds} processes x {args.repeats} batches")
    header = "tree | load | contacts/s median / best | CPU ms per contact median / min | work"
    print(f"| {header} | FFT floor |")
    print("|---|---|---|---|---|---|")
    for tree, done in runs.items():
        wall = [t for run in done for t in run["wall"]]
        cpu = [t for run in done for t in run["cpu"]]
        fft = statistics.median(run["fft"] for run in done)
        loads = [run["load"] for run in done]
        rates = f"{BATCH / statistics.median(wall):.0f} / {BATCH / min(wall):.0f}"
        work = "{:.2f} + {:.2f}".format(*done[0]["work"])
        print(
            f"| {tree} | {min(loads):.1f}-{max(loads):.1f} | {rates} | "
            f"{1e3 * statistics.median(cpu) / BATCH:.2f} / {1e3 * min(cpu) / BATCH:.2f} | {work} | "
            f"{1e3 * fft:.2f} ms, {2.0 / fft:.0f}/s |"
        )
    for tree, done in runs.items():
        pairs = ", ".join(f"{k} {v:.2f}" for k, v in done[0].items() if k.startswith("p"))
        print(f"FFT pairs per contact, {tree}: {pairs}")


if __name__ == "__main__":
    main()
