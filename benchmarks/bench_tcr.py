"""Benchmark: the reference screw's TCR (a sweep's scaling: ``bench_sweep.py``).

Run: ``python benchmarks/bench_tcr.py``. Prints a table; not a test.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import ballscrew
from ballscrew.case import with_overrides

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
    argparse.ArgumentParser(description=__doc__).parse_args()
    base = ballscrew.load_case(CASE)
    spec = base.tcr
    print(
        f"Reference screw TCR (headline {spec.headline}, with {', '.join(spec.models)} and their "
        f"patch variants beside it; details on Δ_f = {spec.cell_size * 1e6:g} µm cells; "
        f"{base.numerics.cells_across} cells across, {base.numerics.gap_model} gap)"
    )
    print(f"{'operating point':<28}{'solves':>7}{'first [s]':>11}{'warm [s]':>10}")
    for label, overrides in (
        ("preload only (F1 = F2)", {}),
        ("F_a = 3000 N (F1 ≠ F2)", {"operating.axial_load": 3000.0}),
    ):
        first, warm, solves = time_tcr(with_overrides(base, overrides))
        print(f"{label:<28}{solves:>7}{first:>11.3f}{warm:>10.3f}")


if __name__ == "__main__":
    main()
