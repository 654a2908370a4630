"""Benchmark of the coupled operating point (friction ↔ heat ↔ temperature ↔ viscosity).

The 40 × 10 example screw (examples/gao2019_tcr.toml) with a named ISO VG 68 oil whose viscosity
follows the temperature, on the 1-D network thermal model: the time of one steady coupled
operating point (the TCR of the contacts cached, as in a sweep over speed), its fixed-point
iterations, and a speed curve of 10 points. Target of the project: ≤ 50 ms per point.

Usage: python benchmarks/bench_operating_point.py
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import ballscrew as bs
from ballscrew.analyses.operating_point import operating_point

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "gao2019_tcr.toml"
RPM = 2 * math.pi / 60


def main() -> None:
    case = bs.load_case(
        EXAMPLE,
        {
            "medium.viscosity": None,
            "medium.pressure_viscosity": None,
            "kinematics.lubricant": "iso_vg_68",
        },
    )
    for model in ("catalogue", "ball_model"):
        friction = bs.case.with_overrides(case, {"friction.model": model})
        operating_point(friction)  # solves and caches the contacts of this load
        print(f"\nfriction model {model!r} (network thermal model, TCR cached)")
        print(f"{'speed [rpm]':>12} {'time [ms]':>10} {'iter':>5} {'M [N m]':>9} "
              f"{'Q [W]':>8} {'nut [°C]':>9} {'screw [°C]':>10} {'η [mPa s]':>10}")  # fmt: skip
        for rpm in range(300, 3001, 300):
            start = time.perf_counter()
            point = operating_point(friction, speed=rpm * RPM)
            ms = 1e3 * (time.perf_counter() - start)
            print(
                f"{rpm:12d} {ms:10.1f} {point.iterations:5d} {point.friction_torque:9.4f} "
                f"{point.heat:8.2f} {point.nut_temperature - 273.15:9.2f} "
                f"{point.screw_temperature - 273.15:10.2f} {1e3 * point.viscosity:10.2f}"
            )


if __name__ == "__main__":
    main()
