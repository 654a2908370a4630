"""Benchmark of the design check (``ballscrew.design_check``).

The 40 × 10 example screw (examples/gao2019_tcr.toml) with its [[duty]] cycle: the time of one
design check with the catalogue ratings of its [design] section, and with the load ratings
computed from the geometry (Lundberg–Palmgren C_a, ISO 76 C_0a), of the ratings alone, and of
the report's stiffness curve (built once per check: 121 Hertz points, 41 elastic solves of the
body curve and the lift-off search). Target of the project: design_check ≤ 50 ms.

Usage: python benchmarks/bench_design_check.py
"""

from __future__ import annotations

import statistics
import time
import warnings
from collections.abc import Callable
from functools import partial
from pathlib import Path

import ballscrew as bs
from ballscrew.analyses import design_check_report
from ballscrew.analyses.design_check import design_check, load_ratings
from ballscrew.analyses.parameters import ScrewParameters

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "gao2019_tcr.toml"
REPEAT = 20


def _ms(run: Callable[[], object]) -> tuple[float, float]:
    """(median, best) wall time of ``run`` over REPEAT calls after one warm-up [ms]."""
    run()
    times = []
    for _ in range(REPEAT):
        start = time.perf_counter()
        run()
        times.append(1e3 * (time.perf_counter() - start))
    return statistics.median(times), min(times)


def main() -> None:
    case = bs.load_case(EXAMPLE)
    computed = bs.case.with_overrides(
        case, {"design.dynamic_load_rating": None, "design.static_load_rating": None}
    )
    params = ScrewParameters.from_case(computed)
    print(f"{'design check, 40 x 10 example':40} {'median [ms]':>12} {'best [ms]':>10}")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        checked = design_check(case)
        rows = {
            "catalogue ratings": lambda: design_check(case),
            "ratings computed from the geometry": lambda: design_check(computed),
            "load ratings alone (C_a, C_0a)": lambda: load_ratings(computed, params),
            "report's stiffness curve": partial(design_check_report.stiffness_curve, checked),
        }
        for label, run in rows.items():
            median, best = _ms(run)
            print(f"{label:40} {median:12.2f} {best:10.2f}")


if __name__ == "__main__":
    main()
