"""``solve_field`` reuses a mesh only when it is the mesh the case asks for, and the coupled
operating point's steady field only when it is this problem's."""

from __future__ import annotations

import importlib
from pathlib import Path

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses import thermal
from ballscrew.analyses.operating_point import coupled_heat
from ballscrew.analyses.thermal import solve_field, thermal_field

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
FIXED_HEAT = {"thermal.drag_torque.source": "catalogue"}


@pytest.mark.parametrize("model", ["network", "axisymmetric"])
def test_a_mesh_of_other_mesh_options_is_not_reused(gao_case_path, model):
    """The reused discretisation of a coarser mesh gave the coarse field for a finer case."""
    mesh = ("thermal.mesh.network_cell", "thermal.mesh.size")
    coarse = ballscrew.load_case(gao_case_path, FIXED_HEAT | dict.fromkeys(mesh, "10 mm"))
    fine = ballscrew.load_case(gao_case_path, FIXED_HEAT | dict.fromkeys(mesh, "5 mm"))
    first = solve_field(coarse, model, transient=False, thermoelastic=False)
    reused = solve_field(
        fine, model, transient=False, thermoelastic=False, reuse=first.solution.discretisation
    )
    fresh = solve_field(fine, model, transient=False, thermoelastic=False)
    assert reused.solution.discretisation.unknowns == fresh.solution.discretisation.unknowns
    assert fresh.solution.discretisation.unknowns != first.solution.discretisation.unknowns


@pytest.fixture(scope="module")
def coarse_case():
    return ballscrew.load_case(
        EXAMPLE,
        {
            "numerics.cells_across": 16,
            "thermal.mesh.size": "10 mm",
            "thermal.transient.duration": "10 min",
            "duty": [],  # the operating point alone: what these tests are about
        },
    )


def test_the_transient_does_not_solve_the_operating_points_steady_state_again(
    coarse_case, monkeypatch
):
    """The thermal field's transient re-solved the steady FE field the coupled operating point
    had just solved (one more FE solve with the transient than without) and rebuilt its
    problem; with a given TCR equal to the case's it takes that steady field too."""
    simulate = importlib.import_module("ballscrew.thermal.simulate")
    sizes: list[int] = []
    solve = simulate.solve_steady

    def counted(a, f, limit):
        sizes.append(a.shape[0])
        return solve(a, f, limit)

    monkeypatch.setattr(simulate, "solve_steady", counted)
    builds: list[int] = []
    build = thermal.build_problem

    def built(*args, **kwargs):
        builds.append(1)
        return build(*args, **kwargs)

    monkeypatch.setattr(thermal, "build_problem", built)
    steady_only = thermal_field(coarse_case, "axisymmetric", transient=False)
    fe_size = steady_only.unknowns
    solves, problems = sizes.count(fe_size), len(builds)
    sizes.clear()
    builds.clear()
    with_transient = thermal_field(coarse_case, "axisymmetric")
    assert with_transient.solution.transient is not None
    assert (sizes.count(fe_size), len(builds)) == (solves, problems)
    sizes.clear()
    given = thermal_field(coarse_case, "axisymmetric", tcr=ballscrew.screw_tcr(coarse_case))
    assert sizes.count(fe_size) == solves
    assert np.array_equal(given.solution.steady, with_transient.solution.steady)


@pytest.mark.parametrize("model", ["network", "axisymmetric"])
def test_the_reused_steady_field_is_the_one_solved_afresh(coarse_case, model):
    """Same steady field, transient and summary as a fresh solve of the resolved case."""
    field = thermal_field(coarse_case, model)
    resolved, _, _ = coupled_heat(coarse_case, model)
    fresh = solve_field(resolved, model)
    scale = np.max(np.abs(fresh.solution.steady))
    assert np.max(np.abs(field.solution.steady - fresh.solution.steady)) <= 1e-10 * scale
    history = fresh.solution.transient.max_rise
    assert np.allclose(field.solution.transient.max_rise, history, rtol=1e-10, atol=0.0)
    ours, theirs = _numbers(field.summary()), _numbers(fresh.summary())
    assert ours.keys() == theirs.keys() and len(ours) > 20
    for key, value in theirs.items():
        assert ours[key] == pytest.approx(value, rel=1e-10, abs=1e-14, nan_ok=True), key


def _numbers(tree, path: str = "") -> dict[str, float]:
    """The numbers of a summary by their path, without the timing and the operating point."""
    if isinstance(tree, dict):
        items = tree.items()
    elif isinstance(tree, list):
        items = enumerate(tree)
    else:
        return {path: tree} if isinstance(tree, float | int) and not isinstance(tree, bool) else {}
    out: dict[str, float] = {}
    for key, value in items:
        if key not in ("timing", "operating_point"):
            out |= _numbers(value, f"{path}.{key}")
    return out


def test_a_steady_field_of_another_heat_is_not_taken(gao_case_path):
    """A steady solution of another problem only lends its mesh: the field is solved anew."""
    other = ballscrew.load_case(gao_case_path, FIXED_HEAT)
    case = ballscrew.load_case(gao_case_path, FIXED_HEAT | {"operating.speed": "1500 rpm"})
    first = solve_field(other, "network", transient=False, thermoelastic=False)
    taken = solve_field(
        case, "network", transient=False, thermoelastic=False, steady=first.solution
    )
    fresh = solve_field(case, "network", transient=False, thermoelastic=False)
    assert np.array_equal(taken.solution.steady, fresh.solution.steady)
    assert taken.max_temperature_rise > 1.1 * first.max_temperature_rise
