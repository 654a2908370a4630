"""Benchmark of the batched contact solves in the chains that solve more than one contact.

1. Wear: the contacts of one flank in a step (two nuts × three ball-load classes) on the fixed
   32 × 128 grid of examples/wear_step_stress.toml, from a cold start and warm-started: the whole
   step of the flank (contacts, film, sliding, wear rates) batched
   (``ballscrew.wear.step.flank_rates``) against one ``flank_rate`` call (a batch of one)
   per contact, and the contact solves alone; and both flanks of a warm step on a worn groove,
   one ``flank_rates`` call per flank against one ``step_rates`` call for all twelve contacts.
2. The non-Hertzian distribution's contact law (``loads.contact = "numerical"``): the 7 tabulation
   loads of each raceway of the 40 × 10 example on one 84 × 84 grid, one
   ``solve_normal_batch`` call per raceway against one ``solve_normal`` call per load, and both
   raceways in one call (each on its own cells) against one call per raceway.
3. TCR: the four raceway contacts of the 40 × 10 example under an axial load (two sides × two
   nuts, each on the cells of its own Hertz ellipse, 64 cells across), one
   ``solve_raceway_contacts`` call against one ``solve_raceway_contact`` call per contact.

Runs alternate (single, batched) and the median of the repeats is printed with the speed-up.

Usage: BALLSCREW_FFT_THREADS=1 python benchmarks/bench_batch.py [--repeats N]
"""

from __future__ import annotations

import argparse
import statistics
import time
import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np

import ballscrew
from ballscrew.analyses import contact_law
from ballscrew.analyses.ball_contact import solve_raceway_contact, solve_raceway_contacts
from ballscrew.analyses.ball_loads import chain_ball_loads
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.wear import wear_setup
from ballscrew.contact import solve_normal, solve_normal_batch
from ballscrew.wear.profile import worn_gap
from ballscrew.wear.setup import FLANKS, nut_force_pair
from ballscrew.wear.step import StepContact, flank_rate, flank_rates, step_rates

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
RATIOS = (0.8, 1.0, 1.2)


def _pair(single: Callable[[], object], batched: Callable[[], object], repeats: int) -> tuple:
    """Median wall times [ms] of ``single`` and ``batched``, alternating, after a warm-up."""
    single(), batched()
    a, b = [], []
    for _ in range(repeats):
        for work, times in ((single, a), (batched, b)):
            start = time.perf_counter()
            work()
            times.append(1e3 * (time.perf_counter() - start))
    return statistics.median(a), statistics.median(b)


def _wear_rows(repeats: int) -> list[tuple[str, float, float]]:
    setup = wear_setup(ballscrew.load_case(EXAMPLES / "wear_step_stress.toml"))
    forces = nut_force_pair(setup.initial_preload, 2000.0)
    contacts = [(f, r) for f in forces for r in RATIOS]
    loads = [r * setup.ball_load(f) for f, r in contacts]
    depth = np.zeros(setup.y.size)
    gap = worn_gap(setup.nominal_gap[1], depth)
    speed = 100.0 * np.pi / 30.0
    rows = []
    cold = flank_rates(setup, 1, contacts, speed, depth, [None] * len(loads))
    stack = np.broadcast_to(gap, (len(loads), *gap.shape)).copy()
    for label, starts in (("cold", [None] * len(loads)), ("warm", [c.pressure for c in cold])):

        def step(starts: list = starts) -> object:
            return [
                flank_rate(setup, 1, f, speed, depth, p, load_ratio=r)
                for (f, r), p in zip(contacts, starts, strict=True)
            ]

        def step_batched(starts: list = starts) -> object:
            return flank_rates(setup, 1, contacts, speed, depth, starts)

        def solves(starts: list = starts) -> object:
            return [
                solve_normal(gap, setup.dx, setup.dy, setup.e_star, q, setup.tolerance, initial=p)
                for q, p in zip(loads, starts, strict=True)
            ]

        initial = None if starts[0] is None else np.stack(starts)

        def solves_batched(initial: np.ndarray | None = initial) -> object:
            args = (stack, setup.dx, setup.dy, setup.e_star, np.array(loads), setup.tolerance)
            return solve_normal_batch(*args, initial=initial)

        where = f"{len(loads)} contacts of a flank, {gap.shape[0]} × {gap.shape[1]}, {label}"
        rows.append((f"wear step: {where}", *_pair(step, step_batched, repeats)))
        rows.append((f"their contact solves: {where}", *_pair(solves, solves_batched, repeats)))
    return [*rows, _step_row(setup, contacts, speed, repeats)]


def _step_row(setup, contacts, speed: float, repeats: int) -> tuple[str, float, float]:
    """Both flanks of a warm-started step on a worn groove: one ``flank_rates`` call per flank
    against one ``step_rates`` call for all the step's contacts."""
    depth = 1e-7 * np.exp(-((setup.y / (0.3 * setup.y.max())) ** 2))
    cold = [None] * len(contacts)
    starts = {
        s: [c.pressure for c in flank_rates(setup, s, contacts, speed, depth, cold)] for s in FLANKS
    }

    def per_flank() -> object:
        return [flank_rates(setup, s, contacts, speed, depth, starts[s]) for s in FLANKS]

    def one_call() -> object:
        return step_rates(
            setup,
            [
                StepContact(s, f, speed, depth, p, load_ratio=r)
                for s in FLANKS
                for (f, r), p in zip(contacts, starts[s], strict=True)
            ],
        )

    where = f"both flanks, {2 * len(contacts)} contacts, worn, warm"
    return (f"wear step per flank / one call: {where}", *_pair(per_flank, one_call, repeats))


def _law_rows(repeats: int) -> list[tuple[str, float, float]]:
    overrides = {"screw.balls_per_nut": 90, "operating.axial_load": 2000.0}
    case = ballscrew.load_case(EXAMPLES / "gao2019_tcr.toml", overrides)
    params = ScrewParameters.from_case(case)
    loads = contact_law.table_loads(
        max(params.preload, params.axial_load) / (90 * params.axial_projection)
    )
    sides = [(s, params.contact_modulus(s)) for s in ("screw", "nut")]
    geometry, numerics = params.geometry, case.numerics
    spec = numerics.model_copy(update={"max_iterations": numerics.max_iterations})

    def batched() -> object:
        return [contact_law.raceway_approaches(geometry, s, e, loads, spec) for s, e in sides]

    def single() -> object:
        return [
            contact_law.raceway_approaches(geometry, s, e, loads[k : k + 1], spec)
            for s, e in sides
            for k in range(loads.size)
        ]

    def together() -> object:
        return contact_law.raceways_approaches(geometry, dict(sides), loads, spec)

    # one load at a time on its own (smaller) Hertz grid: the cost of solving the table unbatched
    text = f"numerical contact law: 2 raceways × {loads.size} loads"
    return [
        (f"{text}, one call per raceway", *_pair(single, batched, repeats)),
        (f"{text}: both in one call against one per raceway", *_pair(batched, together, repeats)),
    ]


def _tcr_row(repeats: int) -> tuple[str, float, float]:
    case = ballscrew.load_case(EXAMPLES / "gao2019_tcr.toml", {"operating.axial_load": 1500.0})
    params = ScrewParameters.from_case(case)
    chain = chain_ball_loads(case, params)
    contacts = [
        (side, used.ball_load, params.contact_modulus(side), nut.flank)
        for nut, used in zip(params.nuts, chain, strict=True)
        for side in ("screw", "nut")
    ]

    def single() -> object:
        return [
            solve_raceway_contact(params.geometry, side, q, e_star, case.numerics, flank)
            for side, q, e_star, flank in contacts
        ]

    def batched() -> object:
        return solve_raceway_contacts(params.geometry, contacts, case.numerics)

    text = "TCR: 2 sides × 2 nuts, each on its own cells, 90 × 90"
    return (text, *_pair(single, batched, repeats))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rows = [*_wear_rows(args.repeats), *_law_rows(args.repeats), _tcr_row(args.repeats)]
    print("| Work | one at a time | batched | speed-up |")
    print("|---|---|---|---|")
    for label, single, batched in rows:
        print(f"| {label} | {single:.1f} ms | {batched:.1f} ms | {single / batched:.2f}× |")


if __name__ == "__main__":
    main()
