"""Benchmark of the design check and the elastic ball-load distribution.

The 40 × 10 example screw (examples/gao2019_tcr.toml) with a 2 × 5-turn double nut (90 balls per
nut, 180 balls): one elastic distribution (Hertz contacts, shaft and nut bars, ring expansion;
preload solve plus load solve) at F_a = 2 kN, the same with non-Hertzian contacts on every ball
(``loads.contact = "numerical"``: the contact law tabulated afresh each time, one batched solve
of the exact groove gap per raceway, then Newton), the same with the nut free to shift and tilt
(``loads.nut_support = "free"``: five DOFs of the nut), and ``ballscrew.design_check`` (which
solves it). Then long double nuts (15, 30 and 40 turns per nut, 294–788 balls per nut: the
sparse bar system of Newton above ``SPARSE_BALLS`` balls): one distribution, the design check
and, at 30 turns, the report's stiffness curve (41 elastic solves and the lift-off search, the
bulk of ``ballscrew check``), best of ``--long-repeats``. Prints a table of median wall times
after a warm-up run. Targets: distribution ≤ 20 ms (Hertz) and ≤ 1 s (numerical contacts),
design check ≤ 50 ms.

Usage: python benchmarks/bench_design.py [--repeats N]
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable
from functools import partial
from pathlib import Path

import ballscrew
from ballscrew.analyses import contact_law, design_check_report
from ballscrew.analyses.ball_loads import elastic_distribution
from ballscrew.analyses.parameters import ScrewParameters

CASE = Path(__file__).resolve().parents[1] / "examples" / "gao2019_tcr.toml"
OVERRIDES = {
    "screw.balls_per_nut": 90,
    "operating.axial_load": 2000.0,
    "loads.distribution": "elastic",
    "design.unsupported_length": 1.3,
    "thermal.shaft_length": 1.3,  # the span lies on the shaft
    "design.dynamic_load_rating": 52_700.0,
    "design.static_load_rating": 141_100.0,
}
LONG_NUTS = {15: 294, 30: 591, 40: 788}
"""Balls per nut of the 40 × 10 screw's long nuts by turns (``ballscrew init`` 5 × 3, 10 × 3 and
10 × 4 turns)."""


def _median(work: Callable[[], object], repeats: int) -> tuple[float, float]:
    work()  # warm-up
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return statistics.median(times), min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--long-repeats", type=int, default=3)
    args = parser.parse_args()
    case = ballscrew.load_case(CASE, OVERRIDES)
    params = ScrewParameters.from_case(case)
    dist = elastic_distribution(params, case.loads)
    numerical = ballscrew.load_case(CASE, OVERRIDES | {"loads.contact": "numerical"})
    free = ballscrew.load_case(CASE, OVERRIDES | {"loads.nut_support": "free"}).loads

    def non_hertzian() -> object:
        contact_law.clear_cache()  # tabulate afresh: the cost of a new screw or load range
        return elastic_distribution(params, numerical.loads, numerics=numerical.numerics)

    rows = [
        (
            f"elastic distribution, 2 × {dist.layout.turns} turns, {dist.loads.size} balls",
            _median(lambda: elastic_distribution(params, case.loads), args.repeats),
            "≤ 20 ms",
        ),
        (
            f"the same, numerical contacts ({contact_law.TABLE_POINTS} loads per raceway, "
            f"{numerical.numerics.cells_across} cells across)",
            _median(non_hertzian, max(args.repeats // 4, 3)),
            "≤ 1 s",
        ),
        (
            "the same, Hertz contacts, free nut (radial displacement and tilt)",
            _median(lambda: elastic_distribution(params, free), args.repeats),
            "≤ 20 ms",
        ),
        (
            "ballscrew.design_check (includes the distribution)",
            _median(lambda: ballscrew.design_check(case), args.repeats),
            "≤ 50 ms",
        ),
    ]
    for turns, balls in LONG_NUTS.items():
        long_nut = ballscrew.load_case(
            CASE,
            OVERRIDES | {"screw.balls_per_nut": balls, "thermal.nut_length": (turns + 2) * 0.01},
        )
        long_params = ScrewParameters.from_case(long_nut)
        rows.append(
            (
                f"{turns}-turn double nut ({2 * balls} balls): one elastic distribution",
                _median(
                    partial(elastic_distribution, long_params, long_nut.loads), args.long_repeats
                ),
                "",
            )
        )
        rows.append(
            (
                f"{turns}-turn double nut: ballscrew.design_check",
                _median(partial(ballscrew.design_check, long_nut), args.long_repeats),
                "",
            )
        )
        if turns == 30:
            checked = ballscrew.design_check(long_nut)
            rows.append(
                (
                    "30-turn double nut: the report's stiffness curve",
                    _median(
                        partial(design_check_report.stiffness_curve, checked), args.long_repeats
                    ),
                    "",
                )
            )
    print("| Work | Median | Best | Target |")
    print("|---|---|---|---|")
    for label, (median, best), target in rows:
        print(f"| {label} | {1e3 * median:.1f} ms | {1e3 * best:.1f} ms | {target} |")
    first = dist.per_nut(dist.loads)[0]
    print(
        f"\nnut forces {dist.nut_forces[0]:.1f} / {dist.nut_forces[1]:.1f} N, largest / mean "
        f"ball load of nut 1 {first.max() / first.mean():.3f}, stiffness "
        f"{dist.stiffness * 1e-6:.0f} N/µm, Newton iterations {dist.iterations}"
    )


if __name__ == "__main__":
    main()
