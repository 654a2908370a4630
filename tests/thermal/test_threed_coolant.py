"""Hollow-shaft coolant on the 3-D model: energy balance, the axisymmetric model, limits, input."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest
from typer.testing import CliRunner

from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.thermal.axisymmetric import build_axisymmetric
from ballscrew.thermal.coolant import ShaftCoolant
from ballscrew.thermal.simulate import simulate
from ballscrew.thermal.threed import build_threed

from .test_boundary_conditions import EXAMPLE
from .test_fe_coolant import BORE, FAST, TABLE, solve

COARSE = {
    "thermal.mesh.size_3d": "8 mm",
    "thermal.mesh.far_size_3d": "80 mm",
    "thermal.mesh.divisions_3d": 12,
    "thermal.mesh.layers_3d": 2,
}


@pytest.fixture(scope="module")
def case():
    from ballscrew import load_case

    return load_case(EXAMPLE, FAST)


@pytest.fixture(scope="module")
def cooled(case):
    """The bore coolant (1 K below ambient) and the table on the coarse 3-D mesh, transient."""
    return solve(case, COARSE | BORE | TABLE, "3d", transient=True)


@pytest.fixture(scope="module")
def problem(case):
    """The SI problem of the cooled case, uniform (smeared) heat over each nut's bore."""
    return solve(case, COARSE | BORE, "3d").problem


def test_heat_balance_from_the_faces_the_coolant_and_the_table(cooled):
    """Steady: friction + bearings = convection (from the face film matrices) + the coolant's
    outflow W(θ_out − θ_in) + the table's G_t θ_t, to 1e-9 (measured 1e-11 to 1e-10: the GMRES
    stop 1e-10); transient: heat in = stored + convected to 1e-8 (its stop)."""
    problem, sol = cooled.problem, cooled.solution
    disc, theta = sol.discretisation, sol.steady
    op = disc.extra["operator"]
    n = op.size
    conv = problem.convection
    faces = (
        conv.screw * op.film(disc.grid.weights)
        + conv.screw_ends * op.faces["shaft_ends"]
        + conv.nut * op.faces["ring_outer"]
        + conv.nut_ends * op.faces["ring_ends"]
    )
    convected = float(np.sum(faces @ theta[:n]))
    cells = disc.extra["coolant"]
    assert cells.size == disc.grid.z.size - 1 and cells[-1] == disc.unknowns - 2
    cool, table = problem.shaft_coolant, problem.table
    to_coolant = cool.capacity_rate * (theta[cells[-1]] - cool.inlet_rise)
    to_table = table.conductance * theta[-1]
    assert to_coolant > 0.05 * problem.heat_input and to_table > 0.0
    residual = abs(problem.heat_input - convected - to_coolant - to_table) / problem.heat_input
    assert residual < 1e-9
    assert cooled.heat_balance_error < 1e-9
    t = sol.transient
    assert t.stored > 0.0 and t.heat_in == pytest.approx(t.stored + t.convected, rel=1e-8)
    # the bulk rise climbs from the inlet along the flow
    assert np.all(np.diff(theta[cells]) > 0.0) and theta[cells[0]] > cool.inlet_rise
    assert cooled.coolant_outlet_temperature == cooled.ambient_temperature + theta[cells[-1]]


def _steady(disc):
    return simulate(disc, duration=None).steady


def test_the_3d_model_agrees_with_the_axisymmetric_one_closer_when_refined(problem):
    """Uniform heat (the nuts' friction heat smeared over their bores, the axisymmetric
    interface; bearings off): the shaft's section mean at the 3-D model's axial lines and the
    coolant's pick-up θ_out − θ_in against the axisymmetric model (2 mm, quadratic). Tolerance
    on the coarse 3-D mesh (12 divisions, 8 mm, 32 mm away from the nut): 4 % of the largest
    section-mean rise and 1 % of the pick-up (measured 3.2 % at the end of the fine axial zone,
    0.30 %); both shrink on the mesh refined by 2 in every direction (measured 1.1 % and
    0.25 %)."""
    problem = replace(problem, bearings=tuple(replace(b, power=0.0) for b in problem.bearings))
    reference = build_axisymmetric(problem, 0.002, 2)
    ref_theta = _steady(reference)
    inlet = problem.shaft_coolant.inlet_rise
    ref_pickup = ref_theta[reference.extra["coolant"][-1]] - inlet
    errors = []
    for size, divisions in ((0.008, 12), (0.004, 24)):
        disc = build_threed(problem, size, divisions, 2, far_size=4.0 * size)
        theta = _steady(disc)
        ref_mean = np.interp(disc.axis_z, reference.axis_z, reference.axis @ ref_theta)
        mean_error = np.abs(disc.axis @ theta - ref_mean).max() / ref_mean.max()
        pickup = theta[disc.extra["coolant"][-1]] - inlet
        errors.append((mean_error, abs(pickup - ref_pickup) / ref_pickup))
    (mean_coarse, pickup_coarse), (mean_fine, pickup_fine) = errors
    assert mean_coarse < 0.04 and pickup_coarse < 0.01
    assert mean_fine < 0.5 * mean_coarse and pickup_fine < pickup_coarse


def test_a_very_high_flow_holds_the_bore_at_the_inlet_temperature(problem):
    """W and h → ∞: the coolant and the bore wall stay at the inlet rise θ_in (a fixed-temperature
    bore), while the shaft under the nut warms by more than a kelvin (1.3 K)."""
    inlet = -1.0
    strong = replace(problem, shaft_coolant=ShaftCoolant(problem.bore_radius, 1e8, 1e8, inlet))
    disc = build_threed(strong, 0.008, 12, 2, far_size=0.08)
    theta = _steady(disc)
    m3 = disc.extra["mesh"]
    n2 = m3.shaft_section.p.shape[1]
    bore = (np.arange(m3.z_shaft.size)[:, None] * n2 + np.arange(m3.divisions)).ravel()
    assert np.abs(theta[bore] - inlet).max() < 1e-3
    assert np.abs(theta[disc.extra["coolant"]] - inlet).max() < 1e-3
    assert theta[: m3.shaft_nodes].max() > inlet + 1.0


def test_a_bore_too_big_for_the_3d_mesh_is_one_line_and_exit_2(tmp_path, problem):
    """A 39 mm bore in the 40 mm shaft leaves a 0.5 mm wall: 4 layers of about 0.125 mm under
    2.6 mm circumferential elements; refused in one line naming the field, nothing written."""
    with pytest.raises(InputError, match=r"^thermal.shaft_coolant.bore_diameter = 0.039 "):
        thin = replace(problem.shaft_coolant, bore_radius=0.0195)
        build_threed(replace(problem, shaft_coolant=thin), 0.008, 48, 4)
    out = tmp_path / "out"
    sets = ["--set", "thermal.model=3d", "--set", "thermal.shaft_coolant.bore_diameter=39 mm"]
    result = CliRunner().invoke(app, ["thermal", str(EXAMPLE), "--out", str(out), *sets])
    assert result.exit_code == 2, result.output
    assert "thermal.shaft_coolant.bore_diameter" in result.output
    assert "Traceback" not in result.output and len(result.output.strip().splitlines()) == 1
    assert not out.exists()


def test_the_cli_runs_the_cooled_3d_case_and_writes_the_outlet(tmp_path):
    out = tmp_path / "out"
    args = ["thermal", str(EXAMPLE), "--out", str(out), "-q"]
    for key, value in (FAST | COARSE | BORE | {"thermal.model": "3d"}).items():
        args += ["--set", f"{key}={value}"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["model"] == "3d"
    outlet = summary["steady"]["coolant_outlet_temperature"]
    assert outlet["unit"] == "K" and 292.15 < outlet["value"] < 293.15
    assert "coolant outlet temperature" in (out / "report.html").read_text()


def test_the_bore_cells_split_each_wall_integral_by_length(problem):
    """B[i, k] = ∫_cell k φ_i dA: each cell's column sums to the bore polygon's perimeter times
    its length (the wall area of the faceted bore), each bore node's row to its wall integral,
    and a node between two cells splits it in proportion to their lengths."""
    disc = build_threed(problem, 0.008, 12, 2, far_size=0.032)
    channel = disc.extra["operator"].coolant
    m3 = disc.extra["mesh"]
    n = m3.divisions
    perimeter = 2.0 * n * m3.bore_radius * np.sin(np.pi / n)
    dz = np.diff(m3.z_shaft)
    cells = channel.cells.toarray()
    np.testing.assert_allclose(cells.sum(axis=0), perimeter * dz, rtol=1e-12)
    wall = np.asarray(channel.wall.sum(axis=1)).ravel()
    np.testing.assert_allclose(cells.sum(axis=1), wall, rtol=1e-12, atol=1e-18)
    n2 = m3.shaft_section.p.shape[1]
    for j in (1, dz.size // 2, dz.size - 1):  # an interior axial line: cells j − 1 and j
        node = j * n2  # the first bore node of line j
        share = dz[j - 1] / (dz[j - 1] + dz[j])
        assert cells[node, j - 1] == pytest.approx(share * wall[node], rel=1e-12)
        assert cells[node, j] == pytest.approx((1.0 - share) * wall[node], rel=1e-12)


def test_a_small_cooled_bore_is_resolved_by_geometric_rings(problem):
    """A 1 mm bore held at the inlet rise (W, h → ∞; bearings off): radial conduction next to it
    is logarithmic, which geometric rings follow. The coarse 3-D mesh with 4 rings misses the
    axisymmetric model's elongation (1 mm, quadratic) by 6.2 % (measured; equal rings: 15.5 %);
    tested to 8 %."""
    strong = ShaftCoolant(0.0005, 1e8, 1e8, -1.0)
    small = replace(
        problem,
        bearings=tuple(replace(b, power=0.0) for b in problem.bearings),
        shaft_coolant=strong,
    )
    reference = build_axisymmetric(small, 0.001, 2)
    expected = reference.elongation @ _steady(reference)
    disc = build_threed(small, 0.008, 12, 4, far_size=0.032)
    assert disc.elongation @ _steady(disc) == pytest.approx(expected, rel=0.08)
