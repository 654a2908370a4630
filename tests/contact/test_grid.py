"""Automatic grid sizing: Hertz-sized grid, edge check and box enlargement (theory manual)."""

from dataclasses import replace

import numpy as np
import pytest

from ballscrew.contact import (
    ContactRequest,
    GridContactResult,
    grid,
    hertz,
    solve_contact,
    solve_contacts,
    solve_normal,
)
from ballscrew.contact.polonsky_keer import SOLVER
from ballscrew.errors import BallscrewError, ConvergenceError, InputError

E_STAR = 113.19e9
RX, RY, LOAD = 3.6e-3, 40e-3, 1000.0


def ellipsoid(x, y):
    return x**2 / (2 * RX) + y**2 / (2 * RY)


def test_grid_follows_the_hertz_ellipse():
    result = solve_contact(ellipsoid, RX, RY, E_STAR, LOAD, cells_across=32)
    assert isinstance(result, GridContactResult)
    reference = hertz(RX, RY, E_STAR, LOAD)
    assert result.hertz == reference
    dx, dy = result.x[1] - result.x[0], result.y[1] - result.y[0]
    assert dx == pytest.approx(2 * reference.a / 32, rel=1e-12)
    assert dy == pytest.approx(2 * reference.b / 32, rel=1e-12)
    assert -result.x[0] >= 1.3 * reference.a - dx  # box half-width ≥ 1.3 a (cell centres)
    np.testing.assert_allclose(result.x, -result.x[::-1], atol=1e-18)
    np.testing.assert_allclose(result.gap, ellipsoid(result.x[:, None], result.y[None, :]))
    assert result.pressure.shape == (result.x.size, result.y.size)
    assert result.enlargements == 0
    assert result.edge_pressure == 0.0
    assert result.solution.peak_pressure == pytest.approx(reference.p0, rel=2e-3)
    assert result.approach == pytest.approx(reference.approach, rel=1e-3)


def test_box_too_small_is_enlarged_until_the_edge_is_free():
    """box_factor 0.8 cuts the patch; the box grows (same spacing) until its edge is unloaded."""
    small = solve_contact(ellipsoid, RX, RY, E_STAR, LOAD, cells_across=24, box_factor=0.8)
    assert small.enlargements >= 1
    assert small.edge_pressure <= 1e-6
    p = small.pressure
    assert max(p[0].max(), p[-1].max(), p[:, 0].max(), p[:, -1].max()) <= 1e-6 * p.max()
    normal = solve_contact(ellipsoid, RX, RY, E_STAR, LOAD, cells_across=24)
    assert small.x[1] - small.x[0] == pytest.approx(normal.x[1] - normal.x[0], rel=1e-12)
    assert small.approach == pytest.approx(normal.approach, rel=1e-6)


def test_gap_wider_than_the_estimate_triggers_enlargement():
    """A flatter gap than rx, ry say: the patch (1.6 × larger) outgrows the box, which follows."""
    result = solve_contact(
        lambda x, y: 0.25 * ellipsoid(x, y), RX, RY, E_STAR, LOAD, cells_across=16
    )
    assert result.enlargements >= 1
    assert result.edge_pressure <= 1e-6


def test_still_cut_after_the_allowed_enlargements_raises():
    with pytest.raises(BallscrewError, match="edge of the grid after 0 enlargements"):
        solve_contact(
            ellipsoid, RX, RY, E_STAR, LOAD, cells_across=16, box_factor=0.8, max_enlargements=0
        )


def test_warm_start_saves_iterations():
    """Starting from the Hertz pressure needs fewer iterations than the uniform start."""
    warm = solve_contact(ellipsoid, RX, RY, E_STAR, LOAD, cells_across=64)
    cold = solve_contact(ellipsoid, RX, RY, E_STAR, LOAD, cells_across=64, warm_start=False)
    assert warm.solution.iterations < cold.solution.iterations
    np.testing.assert_allclose(warm.pressure, cold.pressure, atol=1e-6 * cold.pressure.max())


@pytest.mark.parametrize(
    ("arguments", "field"),
    [
        ({"cells_across": 1}, "cells_across"),
        ({"cells_across": 8.0}, "cells_across"),
        ({"box_factor": 0.0}, "box_factor"),
        ({"max_enlargements": -1}, "max_enlargements"),
        ({"edge_tolerance": -1.0}, "edge_tolerance"),
        ({"rx": -1.0}, "rx"),
    ],
)
def test_invalid_arguments(arguments, field):
    with pytest.raises(InputError, match=field):
        solve_contact(**{"gap_function": ellipsoid, "rx": RX, "ry": RY, "e_star": E_STAR,
                         "load": LOAD, **arguments})  # fmt: skip


@pytest.mark.parametrize(
    "gap_function",
    [lambda x, y: np.zeros(3), lambda x, y: np.full(np.broadcast(x, y).shape, np.nan)],
)
def test_bad_gap_function_results(gap_function):
    with pytest.raises(InputError, match="gap_function"):
        solve_contact(gap_function, RX, RY, E_STAR, LOAD, cells_across=8)


MANY = [
    ContactRequest(ellipsoid, RX, RY, E_STAR, LOAD),
    ContactRequest(lambda x, y: x**2 / 8e-3 + y**2 / 30e-3, 4e-3, 15e-3, 0.9 * E_STAR, 300.0),
    ContactRequest(lambda x, y: 0.25 * ellipsoid(x, y), RX, RY, E_STAR, LOAD),
    ContactRequest(lambda x, y: (x**2 + y**2) / 20e-3, 10e-3, 10e-3, 1.2 * E_STAR, 50.0),
    ContactRequest(lambda x, y: 0.3 * ellipsoid(x, y), RX, RY, 1.1 * E_STAR, 0.8 * LOAD),
]


def test_many_contacts_solved_together_equal_one_at_a_time():
    """Five contacts (own radii, so own cells, own E* and load) solved together in one call; the
    two with gaps flatter than their estimate are cut by the box and enlarged (solved again in
    later rounds, on their larger grids). Each equals :func:`solve_contact` of that contact."""
    requests = MANY
    together = solve_contacts(requests, cells_across=24)
    assert [r.enlargements for r in together] == [0, 0, 1, 0, 1]
    assert together[2].pressure.shape == together[4].pressure.shape  # batched again in round 2
    for request, result in zip(requests, together, strict=True):
        alone = solve_contact(
            request.gap_function, request.rx, request.ry, request.e_star, request.load,
            cells_across=24,
        )  # fmt: skip
        assert result.solution.iterations == alone.solution.iterations
        np.testing.assert_array_equal(result.x, alone.x)
        np.testing.assert_array_equal(result.y, alone.y)
        scale = alone.solution.peak_pressure
        np.testing.assert_allclose(result.pressure, alone.pressure, rtol=0, atol=1e-10 * scale)
        assert result.approach == pytest.approx(alone.approach, rel=1e-10)
    with pytest.raises(BallscrewError, match="after 0 enlargements"):
        solve_contacts(requests, cells_across=24, max_enlargements=0)


def test_extra_loads_share_the_grid_of_the_load():
    """A load–approach table: the request's extra loads are solved on the grid of its load, in
    the same batched call as another contact; each equals a solve of that load on that grid
    (warm-started from its own Hertz pressure) and follows Hertz."""
    extra = (LOAD / 64, LOAD / 8, LOAD / 2)
    table, other = solve_contacts(
        [ContactRequest(ellipsoid, RX, RY, E_STAR, LOAD, extra), MANY[1]], cells_across=32
    )
    alone = solve_contact(ellipsoid, RX, RY, E_STAR, LOAD, cells_across=32)
    np.testing.assert_array_equal(table.x, alone.x)
    assert table.approach == pytest.approx(alone.approach, rel=1e-10)
    assert len(table.extra) == len(extra) and other.extra == ()
    dx, dy = table.x[1] - table.x[0], table.y[1] - table.y[0]
    for load, solution in zip(extra, table.extra, strict=True):
        assert (solution.dx, solution.dy) == pytest.approx((dx, dy), rel=1e-12)
        assert solution.load == pytest.approx(load, rel=1e-12)
        estimate = hertz(RX, RY, E_STAR, load)
        start = estimate.pressure(table.x[:, None], table.y[None, :])
        own = solve_normal(table.gap, dx, dy, E_STAR, load, initial=start)
        assert solution.approach == pytest.approx(own.approach, rel=1e-10)
        # 32 cells across the top load's contact, 8 across the smallest: δ to 2 %
        assert solution.approach == pytest.approx(estimate.approach, rel=2e-2)
    assert table.extra[-1].approach == pytest.approx(hertz(RX, RY, E_STAR, LOAD / 2).approach,
                                                     rel=1e-3)  # fmt: skip


@pytest.mark.parametrize("extra", [(0.0,), (2 * LOAD,), (-1.0,), ("10",)])
def test_extra_loads_outside_the_load_are_refused(extra):
    with pytest.raises(InputError, match="extra_loads"):
        solve_contacts([ContactRequest(ellipsoid, RX, RY, E_STAR, LOAD, extra)], cells_across=8)


def _failing_at(monkeypatch, load, call=1):
    """Make the ``call``-th batched solve report the contact at ``load`` [N] unconverged (as a
    solve that ran out of iterations does), raising as it does when asked to."""
    original, calls = grid.solve_normal_batch, []

    def solve(gaps, dx, dy, e_star, loads, *args, raise_on_failure=True, **kwargs):
        results = original(gaps, dx, dy, e_star, loads, *args, raise_on_failure=False, **kwargs)
        calls.append(len(gaps))
        results = tuple(
            replace(r, converged=False)
            if len(calls) == call and r.load == pytest.approx(load)
            else r
            for r in results
        )
        for b, r in enumerate(results):
            if raise_on_failure and not r.converged:
                where = f"{SOLVER} (contact {b} of the batch)"
                raise ConvergenceError(where, r.iterations, r.residual, 1e-8)
        return results

    monkeypatch.setattr(grid, "solve_normal_batch", solve)


def test_a_failing_contact_is_named_by_its_index_in_the_callers_batch(monkeypatch):
    """Contacts 2 and 4 are enlarged and solved again together: contact 4 is second in that
    group, and the error names it as the caller does (4), not by its place in the group (1)."""
    _failing_at(monkeypatch, MANY[4].load, call=2)
    with pytest.raises(ConvergenceError, match=r"\(contact 4 of the batch\)") as caught:
        solve_contacts(MANY, cells_across=24)
    assert caught.value.iterations > 0


def test_a_failing_extra_load_is_named_with_its_contact(monkeypatch):
    """The extra loads of contact 0 come first in the batch, so contact 1 is its fourth entry."""
    requests = [ContactRequest(ellipsoid, RX, RY, E_STAR, LOAD, (100.0, 400.0)), MANY[1]]
    _failing_at(monkeypatch, MANY[1].load)
    with pytest.raises(ConvergenceError, match=r"\(contact 1 of the batch\)"):
        solve_contacts(requests, cells_across=16)
    monkeypatch.undo()
    _failing_at(monkeypatch, 400.0)
    with pytest.raises(ConvergenceError, match=r"\(contact 0 of the batch, extra load 400 N\)"):
        solve_contacts(requests, cells_across=16)


def test_extra_loads_take_any_real_number_but_a_bool():
    """NumPy scalars are loads; True is not a load of 1 N, NaN is no load at all."""
    from ballscrew.contact.grid import _extra_load

    assert _extra_load(np.float32(50.0), 100.0) == 50.0
    assert _extra_load(np.int64(50), 100.0) == 50.0
    for bad in (True, float("nan"), 0.0, 101.0):
        with pytest.raises(InputError, match="extra_loads"):
            _extra_load(bad, 100.0)
