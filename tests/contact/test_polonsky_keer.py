"""Polonsky-Keer solver against Hertz (Johnson 1985), reference grid results (sphere and ellipsoid),
a grid-convergence study, and the complementarity conditions (C1)-(C2) on random ellipsoids."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscrew.contact import (
    DCFFTOperator,
    hertz,
    solve_normal,
    solve_normal_displacement,
)
from ballscrew.contact.grid import cell_centres
from ballscrew.errors import ConvergenceError, InputError

E_STAR = 113.187e9
SPHERE = (10e-3, 10e-3, 100.0)
T_PK2 = (50e-3, 10e-3, 100.0)
T_H3 = (1 / (2 * 177.2534), 1 / (2 * 6.056935), 39.40790)  # A_H, B_H of the screw contact
T_H4 = (1 / 283.3550, 1 / 12.11387, 39.40790)  # A_H = h_xx/2, B_H = h_yy/2 of the nut contact


def quadratic_gap(rx, ry, nx, ny, half_x, half_y):
    """h = x²/(2 rx) + y²/(2 ry) on nx × ny cells over ±half_x × ±half_y; returns h, dx, dy."""
    dx, dy = 2 * half_x / nx, 2 * half_y / ny
    x, y = cell_centres(nx, dx)[:, None], cell_centres(ny, dy)[None, :]
    return x**2 / (2 * rx) + y**2 / (2 * ry), dx, dy


def cells_across(case, cells, box=1.5):
    """Grid with `cells` cells across the Hertz contact along each axis, box ±box × semi-axes."""
    rx, ry, load = case
    reference = hertz(rx, ry, E_STAR, load)
    n = round(box * cells)
    gap, dx, dy = quadratic_gap(rx, ry, n, n, box * reference.a, box * reference.b)
    return gap, dx, dy, reference


@pytest.mark.parametrize(
    "case", [SPHERE, T_PK2, T_H3, T_H4], ids=["sphere", "ellipsoid", "screw-contact", "nut-contact"]
)
def test_quadratic_gaps_match_hertz_at_128_cells_across(case):
    """Peak pressure within 0.1 % of p0, exact load balance, approach within 0.01 %."""
    gap, dx, dy, reference = cells_across(case, 128)
    result = solve_normal(gap, dx, dy, E_STAR, case[2])
    assert result.converged and result.residual < 1e-8
    assert result.pressure.shape == gap.shape
    assert result.peak_pressure == pytest.approx(reference.p0, rel=1e-3)
    assert dx * dy * result.pressure.sum() == pytest.approx(case[2], rel=1e-10)
    assert result.load == pytest.approx(case[2], rel=1e-10)
    assert result.approach == pytest.approx(reference.approach, rel=1e-4)
    assert result.contact_area == pytest.approx(reference.area, rel=0.01)


def test_sphere_on_the_reference_grid():
    """128 × 128 cells over a box of side 4a, ε0 = 1e-9: p_max = 1.353131 GPa, δ = 3.527680 µm."""
    a = hertz(*SPHERE[:2], E_STAR, SPHERE[2]).a
    gap, dx, dy = quadratic_gap(*SPHERE[:2], 128, 128, 2 * a, 2 * a)
    result = solve_normal(gap, dx, dy, E_STAR, 100.0, tol=1e-9)
    assert result.peak_pressure == pytest.approx(1.353131e9, rel=2e-6)
    assert result.approach == pytest.approx(3.527680e-6, rel=2e-6)


def test_t_pk1_coarse_grid_errors():
    """64 × 64 cells on the same box: p_max −0.087 %, δ −0.023 % against Hertz."""
    reference = hertz(*SPHERE[:2], E_STAR, SPHERE[2])
    gap, dx, dy = quadratic_gap(*SPHERE[:2], 64, 64, 2 * reference.a, 2 * reference.a)
    result = solve_normal(gap, dx, dy, E_STAR, 100.0, tol=1e-9)
    assert result.peak_pressure / reference.p0 - 1 == pytest.approx(-0.087e-2, abs=0.001e-2)
    assert result.approach / reference.approach - 1 == pytest.approx(-0.023e-2, abs=0.001e-2)


@pytest.fixture(scope="module")
def t_pk2_grid():
    """128 × 64 cells over ±2.6a × ±2.6b of the reference ellipsoid."""
    reference = hertz(*T_PK2[:2], E_STAR, T_PK2[2])
    gap, dx, dy = quadratic_gap(*T_PK2[:2], 128, 64, 2.6 * reference.a, 2.6 * reference.b)
    return gap, dx, dy, reference


def test_ellipsoid_on_the_reference_grid(t_pk2_grid):
    """p_max −0.078 %, δ −0.012 % against Hertz."""
    gap, dx, dy, reference = t_pk2_grid
    result = solve_normal(gap, dx, dy, E_STAR, 100.0, tol=1e-9)
    assert result.peak_pressure / reference.p0 - 1 == pytest.approx(-0.078e-2, abs=0.001e-2)
    assert result.approach / reference.approach - 1 == pytest.approx(-0.012e-2, abs=0.001e-2)


def test_t_pk3_displacement_control_on_the_t_pk2_grid(t_pk2_grid):
    """δ = 2.605610 µm in, W = 100.018 N out."""
    gap, dx, dy, _ = t_pk2_grid
    result = solve_normal_displacement(gap, dx, dy, E_STAR, 2.605610e-6, tol=1e-9)
    assert result.load == pytest.approx(100.018, abs=1e-3)
    assert result.approach == 2.605610e-6


@pytest.mark.parametrize("case", [SPHERE, T_H3], ids=["sphere", "screw-contact"])
def test_displacement_control_returns_the_hertz_load(case):
    """Hertz δ in → Hertz load out within 0.1 % at 128 cells across; load control agrees."""
    gap, dx, dy, reference = cells_across(case, 128)
    result = solve_normal_displacement(gap, dx, dy, E_STAR, reference.approach)
    assert result.load == pytest.approx(case[2], rel=1e-3)
    assert result.peak_pressure == pytest.approx(reference.p0, rel=1e-3)
    loaded = solve_normal(gap, dx, dy, E_STAR, result.load)
    assert loaded.approach == pytest.approx(reference.approach, rel=1e-7)


def observed_order(spacings, errors):
    slope, _ = np.polyfit(np.log(spacings), np.log(np.abs(errors)), 1)
    return slope


@pytest.mark.parametrize("case", [SPHERE, T_H3], ids=["sphere", "screw-contact"])
def test_grid_convergence_is_second_order(case):
    """Errors in p_max and δ against Hertz fall as h² on 16, 32, 64 cells across the contact."""
    cells = np.array([16, 32, 64])
    peak_errors, approach_errors = [], []
    for count in cells:
        gap, dx, dy, reference = cells_across(case, int(count))
        result = solve_normal(gap, dx, dy, E_STAR, case[2])
        peak_errors.append(result.peak_pressure / reference.p0 - 1)
        approach_errors.append(result.approach / reference.approach - 1)
    assert np.all(np.diff(np.abs(peak_errors)) < 0)
    assert np.all(np.diff(np.abs(approach_errors)) < 0)
    assert 1.8 < observed_order(1.0 / cells, peak_errors) < 2.3
    assert observed_order(1.0 / cells, approach_errors) > 1.8


def test_odd_and_even_grids_agree():
    """A node on the centre (odd n) or not (even n): both within 0.1 % of Hertz."""
    reference = hertz(*SPHERE[:2], E_STAR, SPHERE[2])
    for n in (95, 96):
        gap, dx, dy = quadratic_gap(*SPHERE[:2], n, n, 1.5 * reference.a, 1.5 * reference.a)
        result = solve_normal(gap, dx, dy, E_STAR, 100.0)
        assert result.peak_pressure == pytest.approx(reference.p0, rel=1e-3)


def test_warm_start_and_operator_reuse_give_the_same_solution():
    gap, dx, dy, reference = cells_across(T_PK2, 48)
    cold = solve_normal(gap, dx, dy, E_STAR, 100.0)
    x = cell_centres(gap.shape[0], dx)[:, None]
    y = cell_centres(gap.shape[1], dy)[None, :]
    operator = DCFFTOperator(gap.shape, dx, dy, E_STAR)
    warm = solve_normal(
        gap, dx, dy, E_STAR, 100.0, initial=reference.pressure(x, y), operator=operator
    )
    assert warm.iterations < cold.iterations
    np.testing.assert_allclose(warm.pressure, cold.pressure, atol=1e-6 * reference.p0)


def test_start_far_from_the_contact_grows_the_active_rows():
    """Initial pressure in a corner: cells far outside it re-enter (Eq. 37) and the answer holds."""
    gap, dx, dy, reference = cells_across(SPHERE, 32)
    cold = solve_normal(gap, dx, dy, E_STAR, 100.0)
    corner = np.zeros(gap.shape)
    corner[:2, :2] = 1.0
    far = solve_normal(gap, dx, dy, E_STAR, 100.0, initial=corner)
    np.testing.assert_allclose(far.pressure, cold.pressure, atol=1e-6 * reference.p0)
    lone_cell = np.zeros(gap.shape)
    lone_cell[0, -1] = 1.0  # one cell: the gap is uniform on the contact set at the start
    single = solve_normal(gap, dx, dy, E_STAR, 100.0, initial=lone_cell)
    np.testing.assert_allclose(single.pressure, cold.pressure, atol=1e-6 * reference.p0)
    edge = np.zeros(gap.shape)
    edge[-1, :] = 1e9
    pushed = solve_normal_displacement(gap, dx, dy, E_STAR, reference.approach, initial=edge)
    assert pushed.load == pytest.approx(100.0, rel=2e-3)


def test_no_interference_gives_no_contact():
    """Displacement control with δ below the smallest gap: p = 0, W = 0."""
    gap, dx, dy, _ = cells_across(SPHERE, 16)
    result = solve_normal_displacement(gap + 1e-6, dx, dy, E_STAR, 0.5e-6)
    assert result.load == 0.0
    assert not result.pressure.any()
    assert result.converged


@settings(max_examples=25, deadline=None)
@given(
    rx=st.floats(2e-3, 60e-3),
    ry=st.floats(2e-3, 60e-3),
    load=st.floats(1.0, 2000.0),
    cells=st.integers(12, 24),
)
def test_complementarity_on_random_ellipsoids(rx, ry, load, cells):
    """p ≥ 0; s = u + h − δ = 0 on the contact set and ≥ 0 off it (C1); dx·dy·Σp = W (C2)."""
    gap, dx, dy, reference = cells_across((rx, ry, load), cells)
    result = solve_normal(gap, dx, dy, E_STAR, load)
    p = result.pressure
    separation = result.displacement + gap - result.approach
    assert np.all(p >= 0.0)
    assert np.max(np.abs(separation[p > 0])) < 1e-6 * result.approach
    assert np.min(separation[p == 0]) > -1e-6 * result.approach
    assert dx * dy * p.sum() == pytest.approx(load, rel=1e-10)
    assert result.approach == pytest.approx(reference.approach, rel=0.02)


@settings(max_examples=25, deadline=None)
@given(rx=st.floats(2e-3, 60e-3), ry=st.floats(2e-3, 60e-3), load=st.floats(1.0, 2000.0))
def test_displacement_control_inverts_load_control(rx, ry, load):
    """The approach of a load-controlled solve, fed back, returns that load (C1)."""
    gap, dx, dy, _ = cells_across((rx, ry, load), 16)
    loaded = solve_normal(gap, dx, dy, E_STAR, load)
    pushed = solve_normal_displacement(gap, dx, dy, E_STAR, loaded.approach)
    assert pushed.load == pytest.approx(load, rel=1e-6)
    separation = pushed.displacement + gap - pushed.approach
    assert np.all(pushed.pressure >= 0.0)
    assert np.min(separation) > -1e-6 * pushed.approach


def test_non_convergence_raises_with_residual_and_iterations():
    gap, dx, dy, _ = cells_across(SPHERE, 32)
    with pytest.raises(ConvergenceError, match=r"after 2 iterations") as caught:
        solve_normal(gap, dx, dy, E_STAR, 100.0, max_iterations=2)
    error = caught.value
    assert error.iterations == 2
    assert error.residual > error.tolerance == 1e-8
    assert f"{error.residual:.3e}" in str(error)
    with pytest.raises(ConvergenceError, match=r"after 3 iterations"):
        solve_normal_displacement(gap, dx, dy, E_STAR, 3e-6, max_iterations=3)


def test_opting_out_of_the_error_returns_the_unconverged_iterate():
    gap, dx, dy, _ = cells_across(SPHERE, 32)
    result = solve_normal(gap, dx, dy, E_STAR, 100.0, max_iterations=2, raise_on_failure=False)
    assert not result.converged
    assert result.iterations == 2
    assert result.residual > 1e-8


GOOD = {"gap": np.zeros((4, 5)), "dx": 1e-6, "dy": 1e-6, "e_star": E_STAR, "load": 1.0}


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("load", 0.0), ("load", -1.0), ("load", np.nan), ("dx", 0.0), ("dy", -1e-6),
        ("e_star", 0.0), ("e_star", np.inf), ("tol", 0.0), ("gap", np.zeros(5)),
        ("gap", np.zeros((0, 3))), ("gap", np.full((3, 3), np.nan)), ("max_iterations", 0),
        ("max_iterations", 2.5), ("initial", np.ones((3, 3))), ("initial", -np.ones((4, 5))),
        ("initial", np.zeros((4, 5))),
        ("operator", DCFFTOperator((4, 5), 2e-6, 1e-6, E_STAR)),
    ],
)  # fmt: skip
def test_invalid_inputs_name_the_argument(field, value):
    with pytest.raises(InputError, match=field):
        solve_normal(**{**GOOD, field: value})


@pytest.mark.parametrize(("field", "value"), [("approach", 0.0), ("approach", -1e-6)])
def test_invalid_approach(field, value):
    arguments = {**GOOD, field: value}
    del arguments["load"]
    with pytest.raises(InputError, match=field):
        solve_normal_displacement(**arguments)
