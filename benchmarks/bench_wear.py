"""Benchmark of the wear life: the full three-level step-stress test of the reference screw.

examples/wear_step_stress.toml (theory manual ``docs/theory/wear.md``): 2000/3000/4000 N, 4.8e5 rev
per level at 100 rpm, 32 × 128 contact grid, Model A with K = 1.304e-4, torque sampled every 4.8e4
rev. Reports the wall time (median of the repeats after a warm-up run), the number of time steps and
contact solutions, and the end values next to the reference run (h_max = 2.430 µm, F_p = 244.3 N).
Target: < 60 s.

Usage: BALLSCREW_FFT_THREADS=1 python benchmarks/bench_wear.py [--repeats N] [--model A|C]
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import ballscrew
from ballscrew.case import with_overrides

CASE = Path(__file__).resolve().parents[1] / "examples" / "wear_step_stress.toml"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--model", choices=("A", "C"), default="A")
    args = parser.parse_args()
    case = ballscrew.load_case(CASE)
    if args.model == "C":
        case = with_overrides(case, {"wear.model": "C", "wear.coefficient": 1.289e-4})
    ballscrew.wear_life(case)  # warm-up: FFT plans, imports
    times, life = [], None
    for _ in range(args.repeats):
        start = time.perf_counter()
        life = ballscrew.wear_life(case)
        times.append(time.perf_counter() - start)
    assert life is not None
    print(f"wear life, reference screw, three-level test, Model {args.model}")
    print(
        f"  wall time      {statistics.median(times):8.3f} s (median of {args.repeats}; "
        f"best {min(times):.3f} s; target < 60 s)"
    )
    print(f"  time steps     {life.steps:8d}")
    print(f"  contact solves {life.contact_solves:8d}")
    print(f"  h_max          {1e6 * life.max_wear_depth[-1]:8.4f} µm   (reference: 2.430)")
    print(f"  final preload  {life.preload[-1]:8.1f} N    (reference: 244.3)")
    print(f"  final torque   {life.friction_torque[-1]:8.4f} N m  (reference: 0.0689)")
    print(
        f"  contact width  {1e6 * life.ellipse_major_axis:8.0f} µm   (reference: 1089; "
        f"unworn {1e6 * life.ellipse_major_axis_unworn:.0f}, reference: 808)"
    )


if __name__ == "__main__":
    main()
