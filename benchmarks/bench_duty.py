"""Benchmark of the duty-cycle transient with the friction heat following the temperature.

The 8-hour working day of the example case (examples/gao2019_tcr.toml: 40 min of 400 mm strokes
at 1500 rpm and 2 kN, 20 min at rest, eight times) on the network and the axisymmetric models,
once with the example's catalogue friction (heat independent of the viscosity) and once with the
ball-model friction and an ISO VG 68 oil whose viscosity follows the contact temperature of each
time step. Target of the project: ≤ 30 s for the day on the axisymmetric model. Then the coupled
``thermal_field`` of the example (operating point → field) on each model.

Usage: python benchmarks/bench_duty.py
"""

from __future__ import annotations

import time
from pathlib import Path

import ballscrew as bs
from ballscrew.analyses.duty_thermal import thermal_duty
from ballscrew.analyses.thermal import thermal_field

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "gao2019_tcr.toml"
OIL = {
    "medium.viscosity": None,
    "medium.pressure_viscosity": None,
    "kinematics.lubricant": "iso_vg_68",
    "friction.model": "ball_model",
}


def main() -> None:
    example = bs.load_case(EXAMPLE)
    cases = {"catalogue friction": example, "ball model + VG 68": bs.load_case(EXAMPLE, OIL)}
    for case in cases.values():  # the contact resistance of each load, solved once
        thermal_duty(case.model_copy(update={"duty_repeat": 1}), "network")
    print(f"{'friction':>20} {'model':>13} {'time [s]':>9} {'peak ΔL [µm]':>13} "
          f"{'Q min–max [W]':>14} {'T_c end [°C]':>12} {'balance':>8}")  # fmt: skip
    for label, case in cases.items():
        for model in ("network", "axisymmetric"):
            start = time.perf_counter()
            day = thermal_duty(case, model)
            seconds = time.perf_counter() - start
            turning = day.friction_heat[day.friction_heat > 0]
            print(
                f"{label:>20} {model:>13} {seconds:9.2f} {1e6 * day.elongation.max():13.2f} "
                f"{turning.min():6.2f}–{turning.max():<7.2f} "
                f"{day.contact_temperature[-1] - 273.15:12.2f} {day.heat_balance_error:8.1e}"
            )
    print(f"\n{'coupled thermal_field':>22} {'time [s]':>9} {'iter':>5} {'Q [W]':>7} "
          f"{'T_c [°C]':>9} {'max rise [K]':>12}")  # fmt: skip
    for model in ("network", "axisymmetric"):
        start = time.perf_counter()
        field = thermal_field(example, model, duty=False)  # the operating point: the day is above
        seconds = time.perf_counter() - start
        c = field.coupling
        print(
            f"{model:>22} {seconds:9.2f} {c.iterations:5d} {c.heat:7.2f} "
            f"{c.contact_temperature - 273.15:9.2f} {field.max_temperature_rise:12.2f}"
        )


if __name__ == "__main__":
    main()
