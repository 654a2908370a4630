"""Every contact of a wear step in one batched solve: equal to the per-flank and single solves."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.analyses.wear import wear_setup
from ballscrew.budget import BudgetError
from ballscrew.case import Case
from ballscrew.contact import solve_normal
from ballscrew.wear import step
from ballscrew.wear.life import _State, _step_rates
from ballscrew.wear.profile import worn_gap
from ballscrew.wear.programme import WearLevel
from ballscrew.wear.setup import FLANKS, nut_force_pair
from ballscrew.wear.step import StepContact, flank_rate, step_rates
from ballscrew.wear.strips import reciprocating_rate

from .conftest import SPEED


@pytest.fixture()
def calls(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Batch sizes of the contact solver's calls from the wear step."""
    sizes: list[int] = []
    original = step.solve_normal_batch

    def counted(gaps, *args, **kwargs):
        sizes.append(len(gaps))
        return original(gaps, *args, **kwargs)

    monkeypatch.setattr(step, "solve_normal_batch", counted)
    return sizes


def _groove(setup, scale: float) -> np.ndarray:
    return scale * np.exp(-((setup.y / (0.3 * setup.y.max())) ** 2))


def _per_flank(setup, state: _State, preload: float, level: WearLevel) -> np.ndarray:
    """The step of the per-flank path: each contact solved on its own (single solver's
    pressure, :func:`flank_rate` rate), the flanks one after the other."""
    rates = np.zeros_like(state.depth)
    for index, (share, part) in enumerate(level.parts()):
        forces = nut_force_pair(preload, part.axial_load)
        for k, flank in enumerate(FLANKS):
            nuts = []
            for nut, force in enumerate(forces, start=1):
                if force <= 0.0:
                    nuts.append(None)
                    continue
                key = f"{flank:+d}_{nut}" + (f"_{index}" if level.segments else "")
                start = state.warm.get(key)
                out = flank_rate(setup, flank, force, part.speed, state.depth[k], start, part)
                gap = worn_gap(setup.nominal_gap[flank], state.depth[k])
                alone = solve_normal(
                    gap, setup.dx, setup.dy, setup.e_star, out.load, setup.tolerance,
                    max_iterations=setup.max_iterations, initial=start,
                )  # fmt: skip
                scale = float(alone.pressure.max())
                np.testing.assert_allclose(out.pressure, alone.pressure, atol=1e-10 * scale)
                nuts.append(out.depth_per_revolution)
            first = nuts[0] if nuts[0] is not None else np.zeros(setup.y.size)
            rates[k] += share * reciprocating_rate(first, nuts[1])
    return rates


def test_a_step_is_one_batched_solve_equal_to_the_per_flank_path(
    coarse_case: Case, calls: list[int]
) -> None:
    """Two duty segments × two flanks × two nuts: 8 contacts, one solver call per step (cold
    first step, warm second step on a worn groove), and the per-flank rates to 1e-10."""
    setup = wear_setup(coarse_case)
    slow = WearLevel(2000.0, SPEED, 400.0, viscosity=0.06)
    fast = WearLevel(3000.0, 5 * SPEED, 600.0, viscosity=0.03)
    level = WearLevel(3000.0, 3 * SPEED, 1000.0, segments=(slow, fast))
    state = _State(0, 0.0, np.zeros((2, setup.y.size)), {}, {}, 0, 0, {})
    preload = setup.initial_preload
    for depth in (0.0, 2e-8):
        state.depth = np.stack([_groove(setup, depth), _groove(setup, 0.5 * depth)])
        warm = dict(state.warm)
        calls.clear()
        batched = _step_rates(setup, state, preload, level)
        assert calls == [8]
        before = _State(0, 0.0, state.depth, warm, {}, 0, 0, {})
        reference = _per_flank(setup, before, preload, level)
        assert batched.max() > 0.0
        np.testing.assert_allclose(batched, reference, rtol=0, atol=1e-10 * batched.max())


def test_worn_and_unworn_contacts_in_one_call(coarse_case: Case, calls: list[int]) -> None:
    """Worn and unworn gaps of both flanks together (no warm starts): one call, each contact
    equal to its own single solve."""
    setup = wear_setup(coarse_case)
    f1, _ = nut_force_pair(setup.initial_preload, 2000.0)
    worn, zero = _groove(setup, 3e-8), np.zeros(setup.y.size)
    contacts = [StepContact(s, f1, SPEED, d) for s in FLANKS for d in (worn, zero)]
    outs = step_rates(setup, contacts)
    assert calls == [4]
    for contact, out in zip(contacts, outs, strict=True):
        alone = flank_rate(setup, contact.flank, f1, SPEED, contact.depth)
        np.testing.assert_allclose(out.pressure, alone.pressure, atol=1e-10 * alone.pressure.max())
        np.testing.assert_allclose(
            out.depth_per_revolution,
            alone.depth_per_revolution,
            atol=1e-10 * alone.depth_per_revolution.max(),
        )
    assert outs[0].pressure.max() < outs[1].pressure.max()  # the worn groove conforms


def test_a_step_beyond_the_memory_budget_is_refused(
    coarse_case: Case, calls: list[int], monkeypatch: pytest.MonkeyPatch
) -> None:
    """The batch's memory is checked before the solve: 40 contacts of 12 × 48 cells need about
    6.6 MB, more than a 1 MB budget."""
    setup = wear_setup(coarse_case)
    monkeypatch.setenv("BALLSCREW_MEMORY_BUDGET", "1 MB")
    zero = np.zeros(setup.y.size)
    with pytest.raises(BudgetError, match=r"wear\.grid.*40 contacts of a wear step"):
        step_rates(setup, [StepContact(1, 1000.0, SPEED, zero)] * 40)
    assert calls == []
