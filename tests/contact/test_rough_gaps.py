"""The default solver ("pcg") on rough gaps: it converges and agrees with the plain Polonsky & Keer
CG ("pk"), where it used to cycle at Σ|Δp|/Σp ≈ 1 (its re-entry step, 1/K(0, 0) per cell,
overshot when hundreds of neighbouring cells re-entered at once)."""

from pathlib import Path

import numpy as np
import pytest

from ballscrew.contact import (
    cell_centres,
    hertz,
    solve_normal,
    solve_normal_batch,
    solve_normal_displacement,
)
from ballscrew.errors import ConvergenceError
from ballscrew.surface import read_profile

ROOT = Path(__file__).resolve().parents[2]
PROFILE = ROOT / "examples" / "profiles" / "synthetic_wm_D1.59_G9e-10.sdf"
E_STAR = 113.19e9
RX, RY, LOAD = 1 / 354.5, 1 / 12.11, 85.9
"""Screw contact A of the reference screw at F_a = 3 kN (curvatures 354.5 and 12.11 1/m)."""


def hertz_gap(n: int) -> tuple[np.ndarray, np.ndarray, float, float]:
    """Paraboloid gap of contact A on n × n cells over 3a × 3b, and the x of the cell centres."""
    reference = hertz(RX, RY, E_STAR, LOAD)
    dx, dy = 3 * reference.a / n, 3 * reference.b / n
    x, y = cell_centres(n, dx), cell_centres(n, dy)
    return x[:, None] ** 2 / (2 * RX) + y[None, :] ** 2 / (2 * RY), x, dx, dy


def profile_gap(n: int = 64) -> tuple[np.ndarray, float, float]:
    """Contact A plus the example's measured W-M profile (Rq 0.37 µm) across the rolling
    direction, extruded along the groove."""
    gap, x, dx, dy = hertz_gap(n)
    profile = read_profile(PROFILE)
    z = np.asarray(profile.heights).ravel()
    gap = gap + np.interp(x - x[0], np.arange(z.size) * profile.spacing, z)[:, None]
    return gap - gap.min(), dx, dy


def random_gap(rq: float, seed: int, n: int = 64) -> tuple[np.ndarray, float, float]:
    """Contact A plus Gaussian heights of standard deviation ``rq``, uncorrelated cell to cell."""
    gap, _, dx, dy = hertz_gap(n)
    gap = gap + rq * np.random.default_rng(seed).standard_normal(gap.shape)
    return gap - gap.min(), dx, dy


def assert_agree(gap: np.ndarray, dx: float, dy: float) -> int:
    """pcg and pk converge to one pressure field (to 1e-6 of the peak); pcg's iterations."""
    plain = solve_normal(gap, dx, dy, E_STAR, LOAD, method="pk", max_iterations=400)
    default = solve_normal(gap, dx, dy, E_STAR, LOAD, max_iterations=400, raise_on_failure=False)
    assert default.converged, f"pcg residual {default.residual:.2g} after 400 iterations"
    peak = plain.pressure.max()
    np.testing.assert_allclose(default.pressure, plain.pressure, rtol=0, atol=1e-6 * peak)
    assert default.contact_area == pytest.approx(plain.contact_area, rel=0.01)
    return default.iterations


def test_default_solver_converges_on_a_measured_rough_gap():
    """Walkthrough finding: pk 53 iterations, pcg residual 0.88 after 400; now 31 iterations."""
    assert assert_agree(*profile_gap()) <= 60


@pytest.mark.parametrize(("rq", "seed"), [(0.05e-6, 0), (0.2e-6, 1), (0.5e-6, 2), (1e-6, 3)])
def test_default_solver_converges_on_random_roughness(rq, seed):
    """Rq from 0.05 to 1 µm (contact A's Hertz approach is 2.4 µm): from a few hundred cells in
    contact to a few dozen islands, pcg agrees with pk in under 60 iterations."""
    assert assert_agree(*random_gap(rq, seed)) <= 60


def test_default_solver_converges_on_a_rough_gap_of_a_finer_grid():
    """The cycling was worse on finer grids (pk 81 iterations, pcg residual 1.8 at 128²)."""
    assert assert_agree(*profile_gap(128)) <= 80


def test_rough_gaps_under_displacement_control_and_in_a_batch():
    """The re-entry serves all paths: displacement control at pk's approach gives pk's load and
    pressure; a batch of three rough gaps with their own cells equals pk contact by contact."""
    gaps = [profile_gap(), random_gap(0.2e-6, 1), random_gap(0.05e-6, 0)]
    plain = [solve_normal(*g, E_STAR, LOAD, method="pk") for g in gaps]
    for g, reference in zip(gaps, plain, strict=True):
        result = solve_normal_displacement(*g, E_STAR, reference.approach, max_iterations=400)
        assert result.load == pytest.approx(LOAD, rel=1e-6)
        peak = reference.pressure.max()
        np.testing.assert_allclose(result.pressure, reference.pressure, atol=1e-6 * peak)
    stack = np.stack([g[0] for g in gaps])
    cells = [g[1] for g in gaps], [g[2] for g in gaps]
    batch = solve_normal_batch(stack, *cells, E_STAR, [LOAD] * 3, max_iterations=400)
    for result, reference in zip(batch, plain, strict=True):
        peak = reference.pressure.max()
        np.testing.assert_allclose(result.pressure, reference.pressure, atol=1e-6 * peak)


def test_a_pcg_that_does_not_converge_names_its_residual_and_suggests_pk():
    gap, dx, dy = profile_gap()
    with pytest.raises(ConvergenceError, match=r'residual .* after 3 iterations; try method="pk"'):
        solve_normal(gap, dx, dy, E_STAR, LOAD, max_iterations=3)
    with pytest.raises(ConvergenceError) as plain:
        solve_normal(gap, dx, dy, E_STAR, LOAD, method="pk", max_iterations=3)
    assert "try" not in str(plain.value)


def test_a_batch_or_grid_solve_that_does_not_converge_suggests_what_it_takes():
    """solve_normal_batch and solve_contact take no ``method``: their hint names the arguments
    they have and solve_normal's "pk" for the contact alone, not a ``method`` of their own."""
    from ballscrew.contact import solve_contact

    gap, dx, dy = profile_gap()
    hint = (
        r'try a larger max_iterations, or the contact alone by solve_normal\(\.\.\., method="pk"\)'
    )
    with pytest.raises(ConvergenceError, match=r"contact 0 of the batch.*" + hint):
        solve_normal_batch(gap[None], dx, dy, E_STAR, [LOAD], max_iterations=3)
    with pytest.raises(ConvergenceError, match=hint):
        solve_contact(lambda x, y: x**2 / (2 * RX) + y**2 / (2 * RY), RX, RY, E_STAR, LOAD,
                      max_iterations=3, warm_start=False)  # fmt: skip
