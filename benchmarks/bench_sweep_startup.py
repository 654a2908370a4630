"""Benchmark: the wall time of a short ``ballscrew sweep`` command, start-up included.

Run: ``python benchmarks/bench_sweep_startup.py [--points 4] [--repeats 4] [SRC ...]``. Each run
is a fresh ``python -m ballscrew sweep`` process (a thermal-network sweep of the reference case
over the speed, 2 local workers), so the command's imports, the local cluster's start, the
workers' imports and the results folder are in its wall time, as a user meets them. Given
several source folders (``src`` of two checkouts), the runs alternate between them (A, B / B, A /
...), so slow drifts of the machine's load fall on all. Prints each run's wall time, the points'
own seconds (summed, as the workers measured them) and the load average; then median, min and
max of the wall time per source folder. ``--phases`` instead times the command's steps in this
process (imports, cluster start, the workers' first points, the rest of the points, the
results folder) and the same points run here, warm. Not a test.
"""

from __future__ import annotations

import argparse
import itertools
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "examples" / "gao2019_tcr.toml"


def run(src: Path, points: int, out: Path) -> tuple[float, float]:
    """(wall [s], Σ points' own seconds) of one sweep command with ``src`` on the path."""
    command = [
        sys.executable, "-m", "ballscrew", "sweep", str(CASE), "--analysis", "thermal-network",
        "--vary", f"operating.speed=500 rpm:3000 rpm:{points}", "--workers", "2", "-q",
        "-o", str(out),
    ]  # fmt: skip
    env = {**os.environ, "PYTHONPATH": str(src)}
    start = time.perf_counter()
    subprocess.run(command, env=env, check=True, capture_output=True)
    wall = time.perf_counter() - start
    own = sum(json.loads(f.read_text())["seconds"] for f in (out / "points").glob("*.json"))
    return wall, own


def phases(points: int) -> None:
    """Seconds of each step of the sweep command, taken one after the other in this process."""
    marks = [("start", time.perf_counter())]

    def mark(step: str) -> None:
        marks.append((step, time.perf_counter()))

    from ballscrew.sweep.cluster import close_clients, shared_client

    client = shared_client(None, 2)
    client.wait_for_workers(2)
    mark("local cluster start (2 workers)")
    import ballscrew
    from ballscrew.analyses.thermal import thermal_network_scalars
    from ballscrew.sweep import parse_axis, run_sweep, warm_workers
    from ballscrew.sweep.axes import grid_points, validate_points
    from ballscrew.sweep.runner import run_chunk

    base = ballscrew.load_case(CASE)
    mark("imports and case here")
    warm = warm_workers(thermal_network_scalars, base, workers=2)
    mark(f"workers' first point (own {max(warm.values()):.2f} s)")
    axis = parse_axis(f"operating.speed=500 rpm:3000 rpm:{points}")
    with tempfile.TemporaryDirectory() as scratch:
        from ballscrew.results.folder import prepare_sweep_folder

        out = Path(scratch) / "out"
        out.mkdir()
        prepare_sweep_folder(out)
        dataset, _ = run_sweep(base, [axis], thermal_network_scalars, "thermal-network", out,
                               workers=2)  # fmt: skip
        mark(f"{points} points on the warm workers")
        from ballscrew.results.sweep_report import write_sweep

        write_sweep(dataset, out, points, base, [axis])
        mark("results folder (figures, report)")
    close_clients()
    grid = grid_points([axis])
    run_chunk(thermal_network_scalars, [base], [{}])
    mark("first point here (after imports)")
    run_chunk(thermal_network_scalars, validate_points(base, grid), grid)
    mark(f"{points} points here, warm")
    for (_, before), (step, after) in itertools.pairwise(marks):
        print(f"{step:<40}{after - before:>8.2f} s")
    print("load average:", " ".join(f"{x:.2f}" for x in os.getloadavg()))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("sources", nargs="*", type=Path, default=[ROOT / "src"])
    parser.add_argument("--points", type=int, default=4, help="points of the sweep")
    parser.add_argument("--repeats", type=int, default=4, help="runs per source folder")
    parser.add_argument("--phases", action="store_true", help="time the steps in this process")
    args = parser.parse_args()
    if args.phases:
        phases(args.points)
        return
    walls: dict[Path, list[float]] = {src: [] for src in args.sources}
    print(f"{'repeat':>6}  {'source':<28}{'wall [s]':>9}{'points [s]':>11}  load average")
    with tempfile.TemporaryDirectory() as scratch:
        for repeat in range(args.repeats):
            order = args.sources if repeat % 2 == 0 else args.sources[::-1]
            for k, src in enumerate(order):
                wall, own = run(src, args.points, Path(scratch) / f"{repeat}-{k}")
                walls[src].append(wall)
                loads = " ".join(f"{x:.2f}" for x in os.getloadavg())
                print(f"{repeat:>6}  {str(src)[-28:]:<28}{wall:>9.2f}{own:>11.2f}  {loads}")
    print(f"\n{'source':<30}{'median':>8}{'min':>8}{'max':>8}")
    for src, values in walls.items():
        median, low, high = statistics.median(values), min(values), max(values)
        print(f"{str(src)[-30:]:<30}{median:>8.2f}{low:>8.2f}{high:>8.2f}")


if __name__ == "__main__":
    main()
