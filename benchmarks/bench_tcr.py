"""Benchmark: the reference screw's TCR, and a sweep's scaling with Dask workers.

Run: ``python benchmarks/bench_tcr.py [--quick]``. Prints a table; not a test.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

import ballscrew
from ballscrew.analyses.screw_tcr import tcr_scalars
from ballscrew.case import with_overrides
from ballscrew.sweep import parse_axis, run_sweep
from ballscrew.sweep.cluster import close_clients

CASE = Path(__file__).resolve().parents[1] / "examples" / "gao2019_tcr.toml"


def time_tcr(case, repeats: int = 5) -> tuple[float, float, int]:
    """(first call, median of warm calls) in s, and the contact solves per call."""
    start = time.perf_counter()
    result = ballscrew.screw_tcr(case)
    first = time.perf_counter() - start
    warm = []
    for _ in range(repeats):
        start = time.perf_counter()
        ballscrew.screw_tcr(case)
        warm.append(time.perf_counter() - start)
    solves = len({(id(n.screw), id(n.nut)) for n in result.nuts}) * 2
    return first, statistics.median(warm), solves


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true", help="small sweep only")
    args = parser.parse_args()
    base = ballscrew.load_case(CASE)
    print("Reference screw TCR (V2, Δ_f = 8 µm, 64 cells across, exact gap)")
    print(f"{'operating point':<28}{'solves':>7}{'first [s]':>11}{'warm [s]':>10}")
    for label, overrides in (
        ("preload only (F1 = F2)", {}),
        ("F_a = 3000 N (F1 ≠ F2)", {"operating.axial_load": 3000.0}),
    ):
        first, warm, solves = time_tcr(with_overrides(base, overrides))
        print(f"{label:<28}{solves:>7}{first:>11.3f}{warm:>10.3f}")

    points = 20 if args.quick else 100
    axis = parse_axis(f"operating.axial_load=0:6000:{points}")
    warm_up = parse_axis("operating.axial_load=0:6000:4")
    print(f"\nSweep of {points} points (R vs axial load) on a local Dask cluster")
    print("(the cluster is started and warmed by a 4-point sweep first; points/s exclude it)")
    print(f"{'workers':>8}{'start [s]':>11}{'wall [s]':>10}{'points/s':>10}{'speed-up':>10}")
    rates = {}
    for workers in (1, 2):
        with tempfile.TemporaryDirectory() as store:
            start = time.perf_counter()
            run_sweep(base, [warm_up], tcr_scalars, "tcr", Path(store) / "w", workers=workers)
            startup = time.perf_counter() - start
            start = time.perf_counter()
            run_sweep(base, [axis], tcr_scalars, "tcr", Path(store) / "s", workers=workers)
            wall = time.perf_counter() - start
        rates[workers] = points / wall
        close_clients()
        print(
            f"{workers:>8}{startup:>11.2f}{wall:>10.2f}{rates[workers]:>10.1f}"
            f"{rates[workers] / rates[1]:>10.2f}"
        )


if __name__ == "__main__":
    main()
