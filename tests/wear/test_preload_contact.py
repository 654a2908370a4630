"""The preload update through the worn groove's own contact (``wear.preload_contact = "worn"``):
the closed-form limits of (E1.13) and the sign of the conforming groove's effect."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.wear import wear_setup
from ballscrew.case import Case, with_overrides
from ballscrew.contact import solve_normal_batch
from ballscrew.errors import ConvergenceError, InputError
from ballscrew.wear import GridEdgeWarning, preload_after
from ballscrew.wear import preload as preload_module
from ballscrew.wear.profile import worn_gap
from ballscrew.wear.setup import FLANKS, WearSetup

from .conftest import REF_PATH

LOADS = {"wear.grid": [16, 64]}


@pytest.fixture(scope="module")
def case() -> Case:
    return ballscrew.load_case(REF_PATH, {**LOADS, "wear.preload_contact": "worn"})


def test_a_uniformly_lowered_groove_is_the_hertz_law(case: Case) -> None:
    """A depth h over the whole groove shifts the contact rigidly: δ_worn − δ_unworn = h, so the
    worn contact's preload is (E1.13) with h_max = h (to the solver's tolerance)."""
    setup = wear_setup(case)
    for h in (0.3e-6, 1.0e-6, 2.0e-6):
        depth = np.full((2, setup.y.size), h)
        preload, solves = preload_after(setup, depth)
        assert solves >= 2
        assert preload == pytest.approx(setup.preload(h), rel=1e-4)


def test_no_wear_keeps_the_initial_preload_without_a_solve(case: Case) -> None:
    setup = wear_setup(case)
    preload, solves = preload_after(setup, np.zeros((2, setup.y.size)))
    assert solves == 0 and preload == pytest.approx(setup.initial_preload, rel=1e-12)


def test_a_conforming_groove_keeps_more_preload_than_its_deepest_point_says(case: Case) -> None:
    """A groove worn deepest at the contact's centre and less towards its edges (the worn shape)
    carries the ball over a wider, more conforming contact: it loses less interference than
    h_max, so more preload is left than (E1.13) with h_max gives, and less than none worn."""
    setup = wear_setup(case)
    b = 0.6 * float(np.max(np.abs(setup.y)))
    shape = np.clip(1.0 - (setup.y / b) ** 2, 0.0, None)
    for h in (0.5e-6, 1.5e-6):
        depth = np.vstack([h * shape, 0.9 * h * shape])
        preload, _ = preload_after(setup, depth)
        hertz = setup.preload(h)
        assert hertz < preload < setup.initial_preload
        assert preload > 1.02 * hertz


def test_the_default_is_the_hertz_law_of_the_largest_depth() -> None:
    """The default (``"hertz"``) history: F_p of (E1.13) at every recorded h_max,
    (F_p0^(2/3) − h_max/(sinβ cosλ C_a))^(3/2)."""
    case = ballscrew.load_case(REF_PATH, {**LOADS, "wear.max_depth_step": 3e-7})
    life = ballscrew.wear_life(case)
    setup = wear_setup(case)
    g = setup.geometry
    s = math.sin(g.contact_angle) * math.cos(g.lead_angle)
    assert setup.body_compliance == 0.0  # the uniform distribution: contacts only
    left = setup.initial_preload ** (2 / 3) - life.max_wear_depth / (s * setup.compliance)
    expected = np.clip(left, 0.0, None) ** 1.5  # (E1.13) written out
    np.testing.assert_allclose(life.preload, expected, rtol=1e-12)


def test_a_life_with_the_worn_contact(case: Case) -> None:
    """Monotone depth, preload ≥ 0 and falling; more preload left than the Hertz update
    (about +10 % on the step-stress test), the same wear to a few per cent."""
    coarse = with_overrides(case, {"wear.max_depth_step": 3e-7})
    worn = ballscrew.wear_life(coarse)
    hertz = ballscrew.wear_life(with_overrides(coarse, {"wear.preload_contact": "hertz"}))
    assert np.all(np.diff(worn.max_wear_depth) >= 0.0)
    assert np.all(worn.preload >= 0.0) and np.all(np.diff(worn.preload) <= 1e-9)
    ratio = worn.preload[-1] / hertz.preload[-1]
    assert 1.04 < ratio < 1.25, ratio
    assert worn.max_wear_depth[-1] == pytest.approx(hertz.max_wear_depth[-1], rel=0.05)
    assert worn.contact_solves > hertz.contact_solves
    assert math.isclose(worn.revolutions[-1], hertz.revolutions[-1])


def _balance(setup: WearSetup, depth: np.ndarray, preload: float) -> tuple[float, object]:
    """G(F_p) − F_p of (E1.13) with h_eff = δ_worn − δ_unworn of the deeper flank at
    Q(F_p), written out, and the worn contact's solution."""
    k = int(np.argmax(depth.max(axis=1)))
    nominal = setup.nominal_gap[FLANKS[k]]
    q = setup.ball_load(preload)
    worn, unworn = solve_normal_batch(
        np.stack([worn_gap(nominal, depth[k]), nominal]), setup.dx, setup.dy, setup.e_star,
        np.array([q, q]), setup.tolerance, max_iterations=setup.max_iterations,
    )  # fmt: skip
    h_eff = min(worn.approach - unworn.approach, float(depth.max()))
    return setup.preload(h_eff) - preload, worn


def _groove(setup: WearSetup, half_width: float, h: float) -> np.ndarray:
    """A conforming worn groove on flank +1: depth h(1 − y²/b²) over |y| < b = ``half_width``
    times the grid's half-width."""
    b = half_width * float(np.max(np.abs(setup.y)))
    return np.vstack([h * np.clip(1.0 - (setup.y / b) ** 2, 0.0, None), np.zeros(setup.y.size)])


def test_the_worn_preload_solves_its_balance_to_the_stated_tolerance(case: Case) -> None:
    """The returned F_p is the root of F = G(F) (E1.13 with h_eff(Q(F))) to 1e-6 F_p0, from the
    initial preload and from a start just above the root."""
    setup = wear_setup(case)
    depth = _groove(setup, 0.6, 1.5e-6)
    limit = preload_module.TOLERANCE * setup.initial_preload
    preload, _ = preload_after(setup, depth)
    assert abs(_balance(setup, depth, preload)[0]) <= limit
    again, solves = preload_after(setup, depth, previous=preload + 5.0)
    assert again == pytest.approx(preload, abs=limit) and solves >= 4


def test_a_deep_narrow_groove_keeps_preload_that_the_hertz_law_loses(case: Case) -> None:
    """4 µm worn over half the grid: (E1.13) with h_max leaves no preload, the worn groove's
    wide contact keeps some, and that F_p satisfies its own balance (the iteration starts from
    above: from the Hertz floor of 0 N it would stop at once). The ball bridges this groove on
    its shoulders: G falls with F (G(F_p0) lies below the root), so the iterates alternate
    about the root rather than fall to it, and still converge."""
    setup = wear_setup(case)
    depth = _groove(setup, 0.5, 4.0e-6)
    preload, _ = preload_after(setup, depth)
    assert setup.preload(4.0e-6) == 0.0
    assert preload > 0.3 * setup.initial_preload
    residual, _ = _balance(setup, depth, preload)
    assert abs(residual) <= preload_module.TOLERANCE * setup.initial_preload
    top = setup.initial_preload
    assert _balance(setup, depth, top)[0] + top < preload


def test_an_unconverged_worn_preload_raises_with_its_residual(
    case: Case, monkeypatch: pytest.MonkeyPatch
) -> None:
    setup = wear_setup(case)
    monkeypatch.setattr(preload_module, "MAX_ITERATIONS", 1)
    with pytest.raises(ConvergenceError, match=r"preload_contact = 'worn'.*residual") as error:
        preload_after(setup, _groove(setup, 0.6, 1.5e-6))
    assert error.value.residual > preload_module.TOLERANCE


def test_the_reference_worn_contact_stays_inside_the_grid() -> None:
    """The step-stress run with the worn contact: no contact reaches the grid's edge, and at the
    end the worn groove's contact at Q(F_p) has no pressure on the boundary cells (a clipped
    contact would press on them)."""
    case = ballscrew.load_case(REF_PATH, {"wear.preload_contact": "worn"})
    with warnings.catch_warnings():
        warnings.simplefilter("error", GridEdgeWarning)
        life = ballscrew.wear_life(case).life
    setup = wear_setup(case)
    preload = float(life.preload[-1])
    residual, worn = _balance(setup, life.profiles[-1], preload)
    assert abs(residual) <= preload_module.TOLERANCE * setup.initial_preload
    p = np.asarray(worn.pressure)
    assert not (p[[0, -1], :].any() or p[:, [0, -1]].any())
    assert worn.semi_axes[1] > setup.y.max() / 4  # a wide, worn contact, not a point


def test_a_worn_contact_clipped_by_the_grid_warns(case: Case) -> None:
    """A groove worn 4 µm deep across the whole grid: the ball rides on its shoulders, the grid's
    edge cells, and the preload update says so."""
    setup = wear_setup(case)
    with pytest.warns(GridEdgeWarning, match="preload update.*box_factor"):
        preload_after(setup, _groove(setup, 1.0, 4.0e-6))


def test_an_unknown_preload_contact_is_refused() -> None:
    with pytest.raises((InputError, ValueError), match="preload_contact"):
        ballscrew.load_case(REF_PATH, {"wear.preload_contact": "exact"})


def test_a_wide_bridged_groove_keeps_the_root_that_the_fixed_point_jumps_over(case: Case) -> None:
    """8 µm worn over 0.84 of the grid: at F_p0 the ball sinks into the groove and the worn
    contact takes the whole interference (G(F_p0) = 0, the first iterate 0 N), while at a
    vanishing load it rides on the shoulders, G(0+) ≈ 42 N > 0: the balance has a root near
    36 N, and that, not 0 N, is returned (the contact at F_p0 reaches the grid's edge)."""
    setup = wear_setup(case)
    depth = _groove(setup, 0.84, 8.0e-6)
    top = setup.initial_preload
    assert _balance(setup, depth, top)[0] == -top  # G(F_p0) = 0
    with pytest.warns(GridEdgeWarning):
        preload, _ = preload_after(setup, depth)
    assert 20.0 < preload < 42.0
    assert abs(_balance(setup, depth, preload)[0]) <= preload_module.TOLERANCE * top


def test_the_zero_exit_finds_a_root_that_the_fixed_point_jumped_over() -> None:
    """G(F) = 800 (1 − F/500) N, 0 above 500 N (a bridged groove: G(0+) > 0, falling with F):
    from 1000 N the first iterate is G = 0, yet F = G(F) has its root at 800/2.6 N. A G with
    G(0+) = 0 and no positive root still gives 0 N."""
    limit = preload_module.TOLERANCE * 1000.0
    bridged, _ = preload_module._preload_root(
        lambda f: max(800.0 * (1.0 - f / 500.0), 0.0), 1000.0, 1000.0, ""
    )
    assert bridged == pytest.approx(800.0 / 2.6, abs=limit)
    none, evaluations = preload_module._preload_root(
        lambda f: max(0.5 * (f - 200.0), 0.0), 1000.0, 1000.0, ""
    )
    assert none == 0.0 and evaluations == 4  # G(1000), G(400), G(100) = 0 and G(ε) = 0


def test_a_clipped_preload_update_warns_once(case: Case) -> None:
    """A tight box (1.01 Hertz semi-axes) and 3 µm worn across the grid: the worn contact
    touches the grid's edge at each of its seven iterates, and the update warns once."""
    setup = wear_setup(with_overrides(case, {"wear.box_factor": 1.01}))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _, solves = preload_after(setup, _groove(setup, 1.0, 3.0e-6))
    edge = [w for w in caught if issubclass(w.category, GridEdgeWarning)]
    assert solves > 2 and len(edge) == 1
