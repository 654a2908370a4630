"""``[loads] contact = "numerical"``: the ball contacts of the distribution from the solver."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.ball_contact import solve_ball_contacts
from ballscrew.analyses.ball_loads import elastic_distribution, nut_model
from ballscrew.analyses.contact_law import (
    TABLE_POINTS,
    TABLE_SPAN,
    ContactLawWarning,
    numerical_contact,
    table_loads,
)
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.case.loader import CaseError
from ballscrew.contact import hertz
from ballscrew.errors import ConvergenceError, InputError
from ballscrew.geometry import raceway_curvature
from ballscrew.units import format_quantity

ELASTIC = {"loads.distribution": "elastic", "operating.axial_load": 2000.0}
NUMERICAL = ELASTIC | {"loads.contact": "numerical"}
HERTZ_GAP = {"numerics.gap_model": "quadratic"}


def test_the_table_spans_the_nominal_ball_load():
    loads = table_loads(31.5)
    assert loads.size == TABLE_POINTS and loads[-1] == 256.0  # 2^⌈log2(6 × 31.5)⌉
    assert loads[-1] / loads[0] == pytest.approx(TABLE_SPAN)


def _hertz_approach(params: ScrewParameters, loads: np.ndarray) -> np.ndarray:
    """δ_A + δ_B of the Hertz contacts at ``loads`` (computed per load, not from K)."""
    total = np.zeros_like(loads)
    for side in ("screw", "nut"):
        c, e_star = raceway_curvature(params.geometry, side), params.contact_modulus(side)
        total += [hertz(c.rx, c.ry, e_star, q).approach for q in loads]
    return total


def test_the_tabulated_law_reproduces_hertz_between_its_points(gao_case_path):
    case = ballscrew.load_case(gao_case_path, NUMERICAL | HERTZ_GAP)
    params = ScrewParameters.from_case(case)
    law = numerical_contact(params, case.numerics)
    # one batch per raceway on the grid of the largest load: 64 cells across it,
    # 64 / 128^(1/3) ≈ 13 at the smallest
    np.testing.assert_allclose(law.approaches, _hertz_approach(params, law.loads), rtol=2e-3)
    q = np.geomspace(law.loads[0], law.loads[-1], 50)
    load, _ = law.load(sum(params.hertz_constants) * q ** (2.0 / 3.0))
    np.testing.assert_allclose(load, q, rtol=3e-3)  # δ to 2e-3 ⇒ Q to 3e-3


def test_in_the_hertz_limit_the_numerical_distribution_is_the_hertz_one(gao_case_path):
    hertz_case = ballscrew.load_case(gao_case_path, ELASTIC)
    case = ballscrew.load_case(gao_case_path, NUMERICAL | HERTZ_GAP)
    reference, balls = ballscrew.ball_loads(hertz_case), ballscrew.ball_loads(case)
    assert balls.axial_forces[0] - balls.axial_forces[1] == pytest.approx(2000.0, rel=1e-10)
    np.testing.assert_allclose(balls.loads, reference.loads, rtol=1e-3)
    assert balls.spread == pytest.approx(reference.spread, rel=1e-4)


def test_the_conforming_groove_changes_the_distribution_a_little(gao_case_path):
    params_case = ballscrew.load_case(gao_case_path, ELASTIC)
    params = ScrewParameters.from_case(params_case)
    hertz_run = elastic_distribution(params, params_case.loads)
    case = ballscrew.load_case(gao_case_path, NUMERICAL)
    exact = elastic_distribution(params, case.loads, numerics=case.numerics)
    assert exact.nut_forces[0] - exact.nut_forces[1] == pytest.approx(2000.0, rel=1e-10)
    change = np.max(np.abs(exact.loads / hertz_run.loads - 1.0))
    assert 1e-5 < change < 0.05
    assert exact.stiffness == pytest.approx(hertz_run.stiffness, rel=0.05)


def test_the_contact_law_is_a_case_choice(gao_case_path):
    with pytest.raises(CaseError, match=r"loads\.contact"):
        ballscrew.load_case(gao_case_path, ELASTIC | {"loads.contact": "dmt"})


@pytest.mark.parametrize(
    ("numerics", "field"),
    [
        ({"numerics.cells_across": 8}, "numerics.cells_across"),
        ({"numerics.cells": [6, 6]}, "cells"),
    ],
)
def test_too_coarse_a_grid_for_the_smallest_tabulated_load_is_refused(
    gao_case_path, numerics, field
):
    """The table's loads share the top load's grid: with 8 cells across it the smallest load
    (Q_top/128) has ~1.6 across and its ball loads are 3.6 % off; refused, naming the field."""
    case = ballscrew.load_case(gao_case_path, NUMERICAL | numerics)
    params = ScrewParameters.from_case(case)
    with pytest.raises(InputError, match=rf"{field} = .*\(8 cells across the smallest") as info:
        numerical_contact(params, case.numerics)
    assert len(str(info.value).splitlines()) == 1


def test_both_raceways_in_one_call_equal_each_alone(gao_case_path, monkeypatch):
    """The table of both raceways from one batched solve (each raceway on its own cells and E*)
    equals each raceway's table solved alone (one shared grid) to 1e-10."""
    from ballscrew.analyses import contact_law
    from ballscrew.contact import grid

    case = ballscrew.load_case(gao_case_path, NUMERICAL | {"numerics.cells_across": 48})
    params = ScrewParameters.from_case(case)
    e_stars = {side: params.contact_modulus(side) for side in ("screw", "nut")}
    loads = table_loads(300.0)
    calls, original = [], grid.solve_normal_batch
    monkeypatch.setattr(
        grid,
        "solve_normal_batch",
        lambda h, *a, **k: calls.append(len(h)) or original(h, *a, **k),
    )
    both = contact_law.raceways_approaches(params.geometry, e_stars, loads, case.numerics)
    assert calls == [2 * TABLE_POINTS]
    for side, e_star in e_stars.items():
        alone = contact_law.raceway_approaches(params.geometry, side, e_star, loads, case.numerics)
        np.testing.assert_allclose(both[side], alone, rtol=1e-10)


def test_a_ball_above_the_table_is_named_in_the_results_warnings(gao_case_path):
    """A 20 µm larger first ball carries ~910 N, above the table's top (512 N, the power of two
    above 6 × the nominal 53 N): the warnings of the contact and TCR analyses name both loads
    and the exponent that continues the law. Without it the balls stay in the table: no
    warning."""
    case = ballscrew.load_case(gao_case_path, NUMERICAL)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        inside = ballscrew.ball_loads(case)
    assert inside.max_load < 512.0
    assert not [w for w in caught if issubclass(w.category, ContactLawWarning)]
    balls = nut_model(ScrewParameters.from_case(case), case.loads)[0].z.size
    error = [20e-6] + [0.0] * (balls - 1)
    case = ballscrew.load_case(gao_case_path, NUMERICAL | {"loads.ball_diameter_error": error})
    with pytest.warns(ContactLawWarning):
        result = solve_ball_contacts(case)
    assert result.ball_load > 512.0
    (message,) = [w for w in result.warnings if "tabulated contact law" in w]
    assert f"largest ball load, {format_quantity(result.ball_load, 'force')}," in message
    assert "(512 N, at least 6 × the nominal ball load)" in message
    assert "end exponent n = 0.6" in message  # the groove's law near Hertz, n ≈ 2/3
    with pytest.warns(ContactLawWarning):
        assert message in ballscrew.screw_tcr(case).warnings
    with pytest.warns(ContactLawWarning):
        assert message in ballscrew.design_check(case).warnings


def test_a_tabulation_that_does_not_converge_names_the_raceways_and_the_case_fields(
    gao_case_path,
):
    """Ten iterations, the least a case allows, cannot reach a tolerance of 1e-14: the error says
    which batch contact is which raceway and names the case field that bounds the iterations,
    with its residual."""
    limits = {"numerics.max_iterations": 10, "numerics.tolerance": 1e-14}
    case = ballscrew.load_case(gao_case_path, NUMERICAL | limits)
    with pytest.raises(ConvergenceError) as caught:
        ballscrew.ball_loads(case)
    message = str(caught.value)
    assert "contact 0 = the screw raceway, contact 1 = the nut raceway" in message
    assert "numerics.max_iterations = 10" in message
    assert np.isfinite(caught.value.residual) and caught.value.residual > caught.value.tolerance
