"""Benchmark: a sweep's points per second on 1 and 2 local Dask workers, and the speed-up.

Run: ``python benchmarks/bench_sweep.py [--points 100] [--repeats 3]``. Prints a table; not a
test. Both clusters are started and warmed once (every worker runs one point first), then the
same sweep runs on 1 and 2 workers in alternating order (1, 2 / 2, 1 / ...), so slow drifts of
the machine's load fall on both. Points/s exclude the start-up and the warm-up; the load average
(``os.getloadavg``) is printed with each run, for judging the noise, with three diagnostics:
``busy``, the workers' task time over workers × wall (Dask's task stream; below 100 % the
workers waited for tasks: scheduling and the tail), ``cores``, the CPU seconds the worker
processes got over the wall time (below the worker count the machine's other load took the
rest), and the CPU seconds of this process (client and scheduler, sharing the cores). The
summary adds the points per CPU second of the workers, which the load changes least: on a quiet
machine the speed-up is about (cores with 2 / with 1) × (points per CPU-s with 2 / with 1).
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from pathlib import Path

import ballscrew
from ballscrew.analyses.screw_tcr import tcr_scalars
from ballscrew.sweep import parse_axis, run_sweep, warm_workers
from ballscrew.sweep.cluster import close_clients, shared_client

CASE = Path(__file__).resolve().parents[1] / "examples" / "gao2019_tcr.toml"
WORKERS = (1, 2)


def load() -> str:
    """The 1-, 5- and 15-minute load averages."""
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def timed_sweep(base, axis, store: Path, workers: int) -> tuple[float, float, float, float]:
    """(wall [s], busy share of the workers, cores the workers got, CPU [s] here) of one sweep."""
    from distributed import get_task_stream

    client = shared_client(None, workers)
    worker_cpu = sum(client.run(time.process_time).values())
    cpu, start = time.process_time(), time.perf_counter()
    with get_task_stream(client) as stream:
        run_sweep(base, [axis], tcr_scalars, "tcr", store, workers=workers)
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu
    worker_cpu = sum(client.run(time.process_time).values()) - worker_cpu
    busy = sum(
        step["stop"] - step["start"]
        for task in stream.data
        for step in task["startstops"]
        if step["action"] == "compute"
    )
    return wall, busy / (workers * wall), worker_cpu / wall, cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--points", type=int, default=100, help="points of the sweep")
    parser.add_argument("--repeats", type=int, default=3, help="timed sweeps per worker count")
    args = parser.parse_args()
    base = ballscrew.load_case(CASE)
    axis = parse_axis(f"operating.axial_load=0:6000:{args.points}")
    print(f"Sweep of {args.points} points (TCR vs axial load 0-6000 N), {os.cpu_count()} cores")
    print(f"load average at the start: {load()}")
    for workers in WORKERS:
        start = time.perf_counter()
        shared_client(None, workers)
        started = time.perf_counter() - start
        warm = warm_workers(tcr_scalars, base, workers=workers)
        print(
            f"{workers} worker(s): start {started:.2f} s, warm-up point "
            f"{', '.join(f'{s:.2f}' for s in warm.values())} s"
        )
    print(
        f"\n{'repeat':>6}{'workers':>8}{'wall [s]':>10}{'points/s':>10}{'busy':>7}{'cores':>7}"
        f"{'CPU [s]':>9}  load average"
    )
    rates: dict[int, list[float]] = {w: [] for w in WORKERS}
    per_cpu: dict[int, list[float]] = {w: [] for w in WORKERS}
    with tempfile.TemporaryDirectory() as scratch:
        for repeat in range(args.repeats):
            for workers in WORKERS if repeat % 2 == 0 else WORKERS[::-1]:
                store = Path(scratch) / f"{repeat}-{workers}"
                wall, busy, cores, cpu = timed_sweep(base, axis, store, workers)
                rates[workers].append(args.points / wall)
                per_cpu[workers].append(args.points / (cores * wall))
                print(
                    f"{repeat:>6}{workers:>8}{wall:>10.2f}{args.points / wall:>10.2f}"
                    f"{busy:>7.0%}{cores:>7.2f}{cpu:>9.2f}  {load()}"
                )
    close_clients()
    ratios = [two / one for one, two in zip(rates[1], rates[2], strict=True)]
    print(f"\n{'':>28}{'median':>8}{'min':>8}{'max':>8}")
    rows = (
        ("points/s, 1 worker", rates[1]),
        ("points/s, 2 workers", rates[2]),
        ("speed-up", ratios),
        ("points per CPU-s, 1 worker", per_cpu[1]),
        ("points per CPU-s, 2 workers", per_cpu[2]),
    )
    for label, values in rows:
        low, high = min(values), max(values)
        print(f"{label:>28}{statistics.median(values):>8.2f}{low:>8.2f}{high:>8.2f}")
    print(f"load average at the end: {load()}  (speed-up: 2 workers / 1 worker, same repeat)")


if __name__ == "__main__":
    main()
