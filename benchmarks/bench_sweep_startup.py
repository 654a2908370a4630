"""Benchmark: the wall time of a short ``ballscrew sweep`` command, start-up included.

Run: ``python benchmarks/bench_sweep_startup.py [--points 4] [--repeats 4] [SRC ...]``. Each run
is a fresh ``python -m ballscrew sweep`` process (a thermal-network sweep of the reference case
over the speed, 2 local workers), so the command's imports, the local cluster's start, the
workers' imports and the results folder are in its wall time, as a user meets them. Given
several source folders (``src`` of two checkouts), the runs alternate between them (A, B / B, A /
...), so slow drifts of the machine's load fall on all. Prints each run's wall time, the points'
own seconds (summed, as the workers measured them) and the load average; then median, min and
max of the wall time per source folder. Not a test.
"""

from __future__ import annotations

import argparse
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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("sources", nargs="*", type=Path, default=[ROOT / "src"])
    parser.add_argument("--points", type=int, default=4, help="points of the sweep")
    parser.add_argument("--repeats", type=int, default=4, help="runs per source folder")
    args = parser.parse_args()
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
