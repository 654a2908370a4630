"""Benchmark of the mixed-lubrication load sharing as the wear chain calls it.

examples/wear_step_stress.toml (theory manual ``docs/theory/lubrication.md``, load sharing): one
JGP solve at contact A (``share_load``, the call of the kinematics and friction chains); a warm
step on a worn groove (both flanks, both nuts: 4 contacts in one ``step_rates`` call) and the
load sharing of its contacts alone, one ``share_load`` call each and all in one ``share_loads``
call (as the wear step does); the example's whole wear run. Medians of the repeats after a
warm-up.

Usage: BALLSCREW_FFT_THREADS=1 python benchmarks/bench_load_sharing.py [--repeats N]
"""

from __future__ import annotations

import argparse
import statistics
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

import ballscrew
from ballscrew.analyses.wear import wear_setup
from ballscrew.lubrication import share_load, share_loads
from ballscrew.wear.setup import FLANKS, nut_force_pair
from ballscrew.wear.step import StepContact, entrainment_speed, step_rates

CASE = Path(__file__).resolve().parents[1] / "examples" / "wear_step_stress.toml"


def _median_ms(work: Callable[[], object], repeats: int) -> float:
    work()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        work()
        times.append(1e3 * (time.perf_counter() - start))
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=20)
    args = parser.parse_args()
    case = ballscrew.load_case(CASE)
    setup = wear_setup(case)
    speed = 100.0 * np.pi / 30.0
    depth = 1e-7 * np.exp(-((setup.y / (0.3 * setup.y.max())) ** 2))
    forces = nut_force_pair(setup.initial_preload, 2000.0)
    cold = [StepContact(s, f, speed, depth) for s in FLANKS for f in forces]
    solved = step_rates(setup, cold)
    warm = [
        StepContact(c.flank, c.nut_force, speed, depth, r.pressure)
        for c, r in zip(cold, solved, strict=True)
    ]
    eta, alpha = setup.lubricant(None)
    u_e = entrainment_speed(setup.geometry, speed)
    surface = setup.surface_at(float(np.max(depth)))
    shares = [(r.load, float(np.count_nonzero(r.pressure > 0.0)) * setup.cell_area) for r in solved]

    def sharing(contacts: list[tuple[float, float]]) -> object:
        return [share_load(q, setup.rx, setup.ry, eta, alpha, u_e, a, surface) for q, a in contacts]

    def batch() -> object:
        loads, areas = zip(*shares, strict=True)
        return share_loads(list(loads), setup.rx, setup.ry, eta, alpha, u_e, list(areas), surface)

    rows = [
        ("one load sharing (contact A)", _median_ms(lambda: sharing(shares[:1]), args.repeats)),
        (
            "load sharing of the step's 4 contacts",
            _median_ms(lambda: sharing(shares), args.repeats),
        ),
        ("the same in one share_loads call", _median_ms(batch, args.repeats)),
        (
            "warm wear step, 4 contacts, worn",
            _median_ms(lambda: step_rates(setup, warm), args.repeats),
        ),
        (
            "example wear run",
            _median_ms(lambda: ballscrew.wear_life(case), max(3, args.repeats // 5)),
        ),
    ]
    for label, ms in rows:
        print(f"{label:40s} {ms:10.3f} ms")


if __name__ == "__main__":
    main()
