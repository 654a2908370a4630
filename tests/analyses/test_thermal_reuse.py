"""``solve_field(reuse=...)`` re-binds a mesh only when it is the mesh the case asks for."""

from __future__ import annotations

import pytest

import ballscrew
from ballscrew.analyses.thermal import solve_field

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
