"""3-D hexahedral model (``model="3d"``): mesh, energy, the reference problem, agreement with the
axisymmetric model, and the helical contact patches (reference problems in ``test_network.py``).

Coarse meshes throughout (1–15k unknowns) so the file runs in well under a minute.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from skfem import Basis, ElementHex1

import ballscrew as bs
from ballscrew.errors import InputError
from ballscrew.thermal.axisymmetric import build_axisymmetric
from ballscrew.thermal.mesh3d import build_mesh3d, disc_section
from ballscrew.thermal.problem import Sensor, axial_grid
from ballscrew.thermal.simulate import simulate
from ballscrew.thermal.threed import (
    BallPatches,
    axial_grid_3d,
    bore_temperatures,
    build_threed,
    interface_conductance,
    patch_centres,
)

from . import test_network as ref

PATCHES = BallPatches(30, 0.02)  # 30 balls on a 20 mm lead helix inside the 100 mm nut


@pytest.fixture(scope="module")
def engine_3d():
    """Engine problem, 32 divisions, 10 mm axial (40 mm far), 8k unknowns; steady + 90 × 60 s."""
    return simulate(build_threed(ref.engine_problem(), 0.01, 32, 3), 5400.0, 60.0)


@pytest.fixture(scope="module")
def engine_axisymmetric():
    return simulate(build_axisymmetric(ref.engine_problem(), 0.004, order=2), None)


@pytest.fixture(scope="module")
def helical():
    """Engine problem with 30 helical patches (5 mm axial, 15k unknowns), steady state; nut
    sensors 1 mm outside the bore on the centre of patch 15 and opposite it (θ + π)."""
    theta, z = patch_centres(PATCHES, 0.45, 0.55, 0.75 * 0.005)  # mesh-sized patches
    sensors = (
        Sensor("on patch", "nut", 0.021, float(z[15]), float(theta[15])),
        Sensor("opposite", "nut", 0.021, float(z[15]), float(theta[15]) + math.pi),
    )
    problem = replace(ref.engine_problem(), sensors=sensors)
    return simulate(build_threed(problem, 0.005, 32, 3, patches=[PATCHES]), None)


def test_mesh_is_valid_and_tagged():
    """Positive Jacobians, the volume of the polygonal bodies, duplicated interface nodes."""
    problem = ref.engine_problem()
    grid = axial_grid_3d(problem, 0.01, 0.04)
    m3 = build_mesh3d(problem, grid, 16, 2)
    basis = Basis(m3.mesh, ElementHex1(), intorder=2)
    assert basis.dx.min() > 0.0
    polygon = 16 / (2 * math.pi) * math.sin(2 * math.pi / 16)  # area ratio of the 16-gon
    volume = polygon * (math.pi * 0.02**2 * 1.0 + math.pi * (0.035**2 - 0.02**2) * 0.1)
    assert basis.dx.sum() == pytest.approx(volume, rel=1e-12)
    assert m3.section_area == pytest.approx(polygon * math.pi * 0.02**2, rel=1e-12)
    f = m3.facets
    # 16 facets around × axial cells, on each side of the interface
    assert f["bore0"].size == f["interface0"].size == 16 * grid.ring_cells
    assert f["shaft_surface"].size == 16 * (grid.z.size - 1)
    assert f["shaft_ends"].size == 2 * disc_section(0.02, 16, 2).t.shape[1]
    bore = np.unique(m3.mesh.facets[:, f["bore0"]])
    shaft = np.unique(m3.mesh.facets[:, f["shaft_surface"]])
    assert not np.intersect1d(bore, shaft).size  # separate copies …
    on_shaft = {tuple(x) for x in np.round(m3.mesh.p[:, shaft].T, 12)}
    assert all(tuple(x) in on_shaft for x in np.round(m3.mesh.p[:, bore].T, 12))  # … coincident
    with pytest.raises(InputError, match="multiple of 4"):
        build_mesh3d(problem, axial_grid(problem, 0.01), 18, 2)


def test_energy_balance_steady_and_transient(engine_3d):
    assert engine_3d.heat_input == pytest.approx(30.0, rel=1e-13)
    assert engine_3d.heat_balance_error < 1e-6
    t = engine_3d.transient
    assert t.heat_in == pytest.approx(30.0 * 5400.0, rel=1e-12)
    assert t.heat_balance_error < 1e-6


def test_reference_problem(engine_3d):
    """Reference values: 45.169 °C and 104.68 µm (2-D P2, 1 mm), and the transient:
    the coarse 3-D mesh within 0.5 % of the rise and 0.5 % of the elongation."""
    assert engine_3d.max_temperature_rise == pytest.approx(ref.FE_T_MAX - 20.0, rel=5e-3)
    assert engine_3d.elongation == pytest.approx(ref.FE_ELONGATION, rel=5e-3)
    t = engine_3d.transient
    for minute, value in ref.FE_HISTORY.items():
        assert t.max_rise[minute] == pytest.approx(value - 20.0, rel=1e-2), minute


def test_uniform_interface_matches_axisymmetric_and_converges(engine_3d, engine_axisymmetric):
    """With the balls smeared over the bore the 3-D model is the axisymmetric one: within 1 %
    on peak rise and elongation on a coarse mesh, and closer on the refined mesh."""
    ax = engine_axisymmetric
    coarse = simulate(build_threed(ref.engine_problem(), 0.02, 16, 2), None)
    errors = []
    for sol in (coarse, engine_3d):
        errors.append(
            (
                abs(sol.max_temperature_rise / ax.max_temperature_rise - 1),
                abs(sol.elongation / ax.elongation - 1),
            )
        )
    assert max(errors[0]) < 1.5e-2
    assert max(errors[1]) < 5e-3
    assert errors[1][0] < errors[0][0] and errors[1][1] < errors[0][1]


def test_total_conductance_is_the_nuts(engine_3d, helical):
    """Σ∫h_c dΓ = 1/R of the nut, smeared or as 30 patches (each 1/30 of it)."""
    g = ref.engine_problem().parts[0].contact_conductance
    assert interface_conductance(engine_3d.discretisation) == pytest.approx(g, rel=1e-12)
    disc = helical.discretisation
    assert interface_conductance(disc) == pytest.approx(g, rel=1e-12)
    info = disc.extra["interfaces"][0]
    assert info["patches"] == 30 and np.all(info["areas"] > 0.0)


def test_helical_patches_break_the_axisymmetry(helical, engine_3d):
    """The nut-bore temperature varies around the circumference with patches (≫ the O-grid's
    discretisation noise of the smeared model), while the global results stay close."""
    _, _, bore = bore_temperatures(helical.discretisation, helical.steady)
    _, _, smeared = bore_temperatures(engine_3d.discretisation, engine_3d.steady)
    mid = bore.shape[0] // 2
    variation = np.ptp(bore[mid])
    assert variation > 0.2  # K
    assert variation > 100 * np.ptp(smeared, axis=1).max()
    assert helical.heat_balance_error < 1e-6
    on_patch, opposite = helical.sensors  # (r, θ, z) sensors see the pattern
    assert abs(on_patch - opposite) > 0.1
    assert helical.max_temperature_rise == pytest.approx(engine_3d.max_temperature_rise, rel=0.05)
    assert helical.elongation == pytest.approx(engine_3d.elongation, rel=0.02)


def test_patch_jump_is_q_times_r():
    """Sleeve problem (all 20 W enter the screw and cross the balls): every patch carries
    about Q/n_b, and its mean jump is q_patch·R″_patch = (Q/n_b)/G_c, G_c = G/n_b, within the
    scatter of the patch shapes sampled by the bore quadrature on 32 × 40 facets (±6 %);
    the heat through all patches is Q exactly."""
    problem = ref.sleeve_problem()
    balls = 24
    disc = build_threed(problem, 0.005, 32, 3, patches=[BallPatches(balls, 0.03)])
    sol = simulate(disc, None)
    info = disc.extra["interfaces"][0]
    fb, index, areas = info["facet_basis"], info["index"], info["areas"]
    dofs, pair = info["dofs"], info["pairs"][0]
    theta = np.zeros(disc.unknowns)
    jump_nodal = sol.steady[pair] - sol.steady[dofs]  # shaft − nut on the bore DOFs
    theta[dofs] = jump_nodal
    jump = np.asarray(fb.interpolate(theta))  # (facets, quadrature points)
    inside = index >= 0
    mean_jump = np.bincount(index[inside], weights=(jump * fb.dx)[inside]) / areas
    g_c = problem.parts[0].contact_conductance / balls
    q = problem.parts[0].screw_heat
    crossing = g_c * mean_jump  # heat through each patch
    assert crossing.sum() == pytest.approx(q, rel=1e-9)
    np.testing.assert_allclose(mean_jump, q / balls / g_c, rtol=0.06)
    assert np.all(jump_nodal > -1e-9)  # heat flows from the screw into the nut


def test_sleeve_sensors_match_closed_form():
    """Smeared interface on the sleeve: the nut follows the logarithmic profile and the jump
    is q·R″ (sensors read at θ = 0 through the hexahedron probes)."""
    problem = ref.sleeve_problem()
    sol = simulate(build_threed(problem, 0.01, 32, 3), None)
    q = problem.parts[0].screw_heat / (2 * math.pi * problem.shaft_radius * problem.shaft_length)
    mid, od, axis, bore, surface = sol.sensors
    assert surface - bore == pytest.approx(q * ref.R_PP, rel=1e-2)
    assert axis == pytest.approx(surface, rel=1e-3)
    expected = [ref.sleeve_solution(problem, s.r) for s in problem.sensors[:2]]
    np.testing.assert_allclose([mid, od], expected, rtol=1e-2)


def test_patches_that_do_not_fit_are_errors():
    with pytest.raises(InputError, match="patches"):
        build_threed(
            ref.engine_problem(), 0.01, 16, 2, patches=[BallPatches(10, 0.01, (0.06, 0.06))]
        )
    with pytest.raises(InputError, match="one entry per part"):
        build_threed(ref.engine_problem(), 0.01, 16, 2, patches=[PATCHES, PATCHES])


def test_thermal_field_3d_on_the_example():
    """``thermal_field(case, model="3d")``: TCR-fed patches (54 balls per nut, Hertz semi-axes
    enlarged to the mesh), both nuts, bearings; energy balanced and close to the axisymmetric
    model's peak rise and elongation."""
    path = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
    case = bs.load_case(
        path,
        {
            "thermal.mesh.size": "5 mm",
            "thermal.mesh.size_3d": "5 mm",
            "thermal.mesh.far_size_3d": "40 mm",
            "thermal.mesh.divisions_3d": 24,
            "thermal.mesh.layers_3d": 2,
            "thermal.transient.time_step": "900 s",
        },
    )
    tcr = bs.screw_tcr(case, variant=None)
    r3 = bs.thermal_field(case, model="3d", tcr=tcr, duty=False)
    ax = bs.thermal_field(case, model="axisymmetric", tcr=tcr, transient=False)
    assert r3.model == "3d"
    assert r3.heat_input == pytest.approx(ax.heat_input, rel=1e-12)
    assert r3.heat_balance_error < 1e-6 and r3.transient_heat_balance_error < 1e-6
    infos = r3.solution.discretisation.extra["interfaces"]
    assert [i["patches"] for i in infos] == [54, 54]
    g = sum(p.contact_conductance for p in r3.problem.parts)
    assert interface_conductance(r3.solution.discretisation) == pytest.approx(g, rel=1e-12)
    assert r3.max_temperature_rise == pytest.approx(ax.max_temperature_rise, rel=0.05)
    assert r3.elongation == pytest.approx(ax.elongation, rel=0.03)
    assert {s.name for s in r3.sensors} == {"nut 1", "spacer", "nut 2", "screw"}
    ds = r3.to_xarray()
    assert ds["temperature_steady"].attrs["units"] == "K" and "node_x" in ds


def test_time_averaged_stroke_matches_axisymmetric():
    """A 100 mm stroke, time-averaged (the bore paired with the shaft at every offset, the
    film weighted by the uncovered fraction) as in the axisymmetric model."""
    problem = ref.engine_problem(0.1)
    sol = simulate(build_threed(problem, 0.01, 16, 2), 1800.0, 300.0)
    ax = simulate(build_axisymmetric(problem, 0.005, order=2), None)
    assert sol.heat_balance_error < 1e-9 and sol.transient.heat_balance_error < 1e-6
    assert sol.max_temperature_rise == pytest.approx(ax.max_temperature_rise, rel=2e-2)
    assert sol.elongation == pytest.approx(ax.elongation, rel=2e-2)


def test_sensor_angle_comes_from_the_case_file(gao_case_path):
    case = bs.load_case(
        gao_case_path,
        {
            "thermal.sensors": [
                {"name": "side", "body": "nut", "r": "30 mm", "z": "500 mm", "theta": "90 deg"}
            ]
        },
    )
    assert case.thermal.sensors[0].theta == pytest.approx(math.pi / 2)
