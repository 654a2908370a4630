"""The contacts of a flank (nuts and load classes) solved in one batch equal single solves."""

from __future__ import annotations

import numpy as np

from ballscrew.analyses.wear import wear_setup
from ballscrew.case import Case
from ballscrew.contact import solve_normal
from ballscrew.wear.profile import worn_gap
from ballscrew.wear.setup import nut_force_pair
from ballscrew.wear.step import StepContact, step_rates

from .conftest import SPEED


def _single(setup, flank, depth, load, initial):
    """The contact of one load, solved alone by the single solver."""
    gap = worn_gap(setup.nominal_gap[flank], depth)
    args = (gap, setup.dx, setup.dy, setup.e_star, load, setup.tolerance)
    return solve_normal(*args, max_iterations=setup.max_iterations, initial=initial)


def test_batched_class_contacts_equal_single_solves(coarse_case: Case) -> None:
    setup = wear_setup(coarse_case)
    f1, f2 = nut_force_pair(setup.initial_preload, 2000.0)
    contacts = [(f1, 0.8), (f1, 1.0), (f1, 1.2), (f2, 0.9), (f2, 1.1)]
    depth = 1e-8 * np.exp(-((setup.y / (0.3 * setup.y.max())) ** 2))  # a worn groove

    def rates(d, starts):
        return step_rates(
            setup,
            [
                StepContact(1, force, SPEED, d, start, None, ratio)
                for (force, ratio), start in zip(contacts, starts, strict=True)
            ],
        )

    cold = rates(depth, [None] * 5)
    # a later step: warm starts for some contacts, none for the others (two batches)
    starts = [cold[0].pressure, None, cold[2].pressure, None, cold[4].pressure]
    warm = rates(0.5 * depth, starts)
    for outs, d, initial in ((cold, depth, [None] * 5), (warm, 0.5 * depth, starts)):
        for (force, ratio), out, p0 in zip(contacts, outs, initial, strict=True):
            load = ratio * setup.ball_load(force)
            alone = _single(setup, 1, d, load, p0)
            assert out.load == load and out.iterations == alone.iterations
            scale = float(np.max(alone.pressure))
            np.testing.assert_allclose(out.pressure, alone.pressure, rtol=0, atol=1e-10 * scale)
