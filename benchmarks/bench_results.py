"""Benchmark of writing a results folder (``ballscrew.results.write_results``).

The contact analysis of the 40 × 10 example screw (examples/gao2019_tcr.toml): four figures,
NetCDF, summary and report. Wall time depends on the machine's load; the process's CPU time is
the steadier number. Median of REPEAT writes after a warm-up (imports, font cache), and of the
figures alone.

Usage: python benchmarks/bench_results.py
"""

from __future__ import annotations

import statistics
import tempfile
import time
import warnings
from collections.abc import Callable
from pathlib import Path

import ballscrew as bs
from ballscrew.analyses.ball_contact import solve_ball_contacts
from ballscrew.results import write_results

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "gao2019_tcr.toml"
REPEAT = 7


def _median(run: Callable[[int], object]) -> tuple[float, float]:
    """(median wall, median CPU) seconds of ``run(k)`` over REPEAT calls after one warm-up."""
    run(-1)
    wall, cpu = [], []
    for k in range(REPEAT):
        start, start_cpu = time.perf_counter(), time.process_time()
        run(k)
        wall.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return statistics.median(wall), statistics.median(cpu)


def main() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = solve_ball_contacts(bs.load_case(EXAMPLE))
    out = Path(tempfile.mkdtemp())
    figures = result.figures()
    rows = {
        "write_results (contact)": lambda k: write_results(result, out / f"run{k}"),
        f"its {len(figures)} figures alone": lambda k: [
            f.draw(out / f"{k}_{f.name}.png") for f in figures
        ],
    }
    print(f"{'results folder, 40 x 10 example':32} {'wall [s]':>9} {'CPU [s]':>8}")
    for label, run in rows.items():
        wall, cpu = _median(run)
        print(f"{label:32} {wall:9.2f} {cpu:8.2f}")


if __name__ == "__main__":
    main()
