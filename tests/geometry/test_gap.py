"""Exact and quadratic initial gap (G11)–(G18) against the TCR reference screw."""

import math
import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ballscrew.geometry.gap as gap_module
from ballscrew.errors import ConvergenceError, InputError
from ballscrew.geometry import (
    ScrewGeometry,
    ball_height,
    contact_frame,
    gap_exact,
    gap_function,
    gap_quadratic,
    project_onto_raceway,
    raceway_curvature,
    raceway_surface,
)

REFERENCE = ScrewGeometry(40.0e-3, 10.0e-3, 6.35e-3, 0.52, 0.52, math.radians(45.0))
UM = 1e-6


@st.composite
def geometries(draw: st.DrawFn) -> ScrewGeometry:
    """Screws from miniature to large, lead angles up to ~25°, any practical conformity."""
    d_m = draw(st.floats(8e-3, 120e-3))
    return ScrewGeometry(
        pitch_diameter=d_m,
        lead=draw(st.floats(0.1, 1.5)) * d_m,
        ball_diameter=draw(st.floats(0.05, 0.35)) * d_m,
        screw_conformity=draw(st.floats(0.505, 0.6)),
        nut_conformity=draw(st.floats(0.505, 0.6)),
        contact_angle=math.radians(draw(st.floats(10.0, 80.0))),
    )


@pytest.mark.parametrize(
    ("x", "y", "screw", "nut"),
    [
        (100.0, 0.0, 1.772949e-6, 1.417147e-6),
        (0.0, 300.0, 5.486611e-7, 5.486611e-7),
        (50.0, 200.0, 6.818426e-7, 5.987473e-7),
        (-50.0, -200.0, 6.885876e-7, 5.944720e-7),
    ],
)
def test_t_g3_exact_gap(x: float, y: float, screw: float, nut: float) -> None:
    assert float(gap_exact(REFERENCE, "screw", x * UM, y * UM)) == pytest.approx(screw, rel=1e-6)
    assert float(gap_exact(REFERENCE, "nut", x * UM, y * UM)) == pytest.approx(nut, rel=1e-6)


def test_t_g3_quadratic_form_and_asymmetry() -> None:
    x, y = np.array([50.0, -50.0]) * UM, np.array([200.0, -200.0]) * UM
    quadratic = gap_quadratic(REFERENCE, "screw", x, y)
    np.testing.assert_allclose(quadratic, 6.8370e-7, rtol=1e-5)
    exact = gap_exact(REFERENCE, "screw", x, y)
    split = (exact[1] - exact[0]) / (exact[1] + exact[0])
    assert split == pytest.approx(0.0049, abs=1e-4)  # "±0.5 %": the lead-angle asymmetry
    assert abs(0.5 * (exact[0] + exact[1]) / quadratic[0] - 1) < 3e-3  # quartic terms, ≈0.2 %


@pytest.mark.parametrize("side", ["screw", "nut"])
def test_numerical_hessian_equals_closed_form(side: str) -> None:
    """Central differences of the exact gap converge to (G17); the closed form is exact."""
    c = raceway_curvature(REFERENCE, side)
    h_xx, h_yy, h_xy = _hessian(side, 1.0 * UM)
    assert h_xx == pytest.approx(c.h_xx, rel=1e-6)
    assert h_yy == pytest.approx(c.h_yy, rel=1e-6)
    assert h_xy == pytest.approx(c.h_xy, rel=1e-6)


def test_documented_numerical_hessian_is_a_20_micron_difference() -> None:
    """A published numerical Hessian is 354.510, 12.1142, −0.171164. These are the central
    differences with a 20 µm step, biased by the quartic terms (+9e-6 and +2.7e-5 relative);
    the step → 0 limit is the closed form 354.5069, 12.11387, −0.171163."""
    h_xx, h_yy, h_xy = _hessian("screw", 20.0 * UM)
    assert h_xx == pytest.approx(354.510, abs=5e-4)
    assert h_yy == pytest.approx(12.1142, abs=5e-5)
    assert h_xy == pytest.approx(-0.171164, abs=5e-7)
    assert h_yy / raceway_curvature(REFERENCE, "screw").h_yy - 1 == pytest.approx(2.8e-5, abs=2e-6)


def _hessian(side: str, step: float) -> tuple[float, float, float]:
    offsets = np.array([-1.0, 0.0, 1.0]) * step
    h = gap_exact(REFERENCE, side, offsets[:, None], offsets[None, :])  # h[i, j] = h(x_i, y_j)
    h_xx = (h[2, 1] - 2 * h[1, 1] + h[0, 1]) / step**2
    h_yy = (h[1, 2] - 2 * h[1, 1] + h[1, 0]) / step**2
    h_xy = (h[2, 2] - h[2, 0] - h[0, 2] + h[0, 0]) / (4 * step**2)
    return float(h_xx), float(h_yy), float(h_xy)


@pytest.mark.parametrize("side", ["screw", "nut"])
def test_exact_minus_quadratic_is_cubic(side: str) -> None:
    """h − h_quad = c₃ r³ + c₄ r⁴ + …: the odd part scales as r³, the whole as ≈ r³."""
    direction = np.array([1.0, 4.0]) / math.sqrt(17.0)
    r = np.array([2.5, 5.0, 10.0, 20.0]) * UM

    def difference(sign: float) -> np.ndarray:
        x, y = sign * r * direction[0], sign * r * direction[1]
        return gap_exact(REFERENCE, side, x, y) - gap_quadratic(REFERENCE, side, x, y)

    forward, backward = difference(1.0), difference(-1.0)
    odd = 0.5 * (forward - backward)
    np.testing.assert_allclose(odd / r**3, odd[0] / r[0] ** 3, rtol=1e-4)
    assert abs(odd[0] / r[0] ** 3) > 100.0  # m⁻², a genuine cubic term
    np.testing.assert_allclose(forward[1:] / forward[:-1], 8.0, rtol=0.06)
    relative = np.abs(forward) / gap_quadratic(REFERENCE, side, r * direction[0], r * direction[1])
    assert relative[0] < 2e-4
    assert np.all(np.diff(relative) > 0)


@pytest.mark.parametrize("side", ["screw", "nut"])
def test_flanks_are_half_turn_images(side: str) -> None:
    """The half-turn about n maps flank +1 onto flank −1 and (x, y) onto (−x, −y)."""
    x, y = np.meshgrid(np.linspace(-300, 300, 7) * UM, np.linspace(-1, 1, 5) * 1e-3)
    np.testing.assert_allclose(
        gap_exact(REFERENCE, side, x, y, -1), gap_exact(REFERENCE, side, -x, -y, 1), rtol=1e-9
    )


@pytest.mark.parametrize("side", ["screw", "nut"])
@pytest.mark.parametrize("flank", [1, -1])
def test_projection_lies_on_raceway_surface(side: str, flank: int) -> None:
    """The Newton solution, put through (G9)–(G11) and frame (G13)/(G14), gives back (x, y, z_r)."""
    x, y = np.meshgrid(np.linspace(-2.5, 2.5, 6) * 1e-3, np.linspace(-2.0, 2.0, 5) * 1e-3)
    inside = x**2 + y**2 < (0.99 * REFERENCE.ball_radius) ** 2
    x, y = x[inside], y[inside]
    point = project_onto_raceway(REFERENCE, side, x, y, flank)
    surface = raceway_surface(REFERENCE, side, point.theta, point.phi, flank)
    local = contact_frame(REFERENCE, side, flank).to_local(surface)
    np.testing.assert_allclose(local[:, 0], x, atol=1e-14)
    np.testing.assert_allclose(local[:, 1], y, atol=1e-14)
    np.testing.assert_allclose(local[:, 2], point.z, atol=1e-14)
    assert np.all(gap_exact(REFERENCE, side, x, y, flank) > 0)


@settings(max_examples=25, deadline=None)
@given(geometry=geometries(), seed=st.integers(0, 2**16))
def test_gap_zero_at_origin_and_positive_near_it(geometry: ScrewGeometry, seed: int) -> None:
    rng = np.random.default_rng(seed)
    r_b = geometry.ball_radius
    radius = 0.05 * r_b * np.sqrt(rng.uniform(0.0, 1.0, 30))
    angle = rng.uniform(0.0, 2.0 * np.pi, 30)
    x, y = radius * np.cos(angle), radius * np.sin(angle)
    for side in ("screw", "nut"):
        for flank in (1, -1):
            assert float(gap_exact(geometry, side, 0.0, 0.0, flank)) == 0.0
            h = gap_exact(geometry, side, x, y, flank)
            quadratic = gap_quadratic(geometry, side, x, y, flank)
            assert np.all(h >= 0.0)
            np.testing.assert_allclose(h, quadratic, rtol=0.05)


@settings(max_examples=15, deadline=None)
@given(geometry=geometries())
def test_closed_form_hessian_for_random_geometries(geometry: ScrewGeometry) -> None:
    """(G15)–(G17) against central differences of the exact gap, step 1e-3 r_b."""
    r_b = geometry.ball_radius
    step = 1e-3 * r_b
    offsets = np.array([-step, 0.0, step])
    for side in ("screw", "nut"):
        h = gap_exact(geometry, side, offsets[:, None], offsets[None, :])
        c = raceway_curvature(geometry, side)
        assert (h[2, 1] - 2 * h[1, 1] + h[0, 1]) / step**2 == pytest.approx(c.h_xx, abs=2e-6 / r_b)
        assert (h[1, 2] - 2 * h[1, 1] + h[1, 0]) / step**2 == pytest.approx(c.h_yy, abs=2e-6 / r_b)
        h_xy = (h[2, 2] - h[2, 0] - h[0, 2] + h[0, 0]) / (4 * step**2)
        assert h_xy == pytest.approx(c.h_xy, abs=2e-6 / r_b)


def test_large_grid_is_fast_and_keeps_shape() -> None:
    x = (np.arange(200) + 0.5) / 200 * 1.0e-3 - 0.5e-3
    y = (np.arange(200) + 0.5) / 200 * 4.0e-3 - 2.0e-3
    gap_exact(REFERENCE, "screw", x[:2, None], y[None, :2])  # warm-up
    start = time.perf_counter()
    h = gap_exact(REFERENCE, "screw", x[:, None], y[None, :])
    elapsed = time.perf_counter() - start
    assert h.shape == (200, 200)
    assert np.all(h >= 0.0)
    assert elapsed < 1.0


def test_gap_function_models() -> None:
    x, y = np.array([30.0, -80.0]) * UM, np.array([400.0, 100.0]) * UM
    exact = gap_function(REFERENCE, "nut", flank=-1)
    quadratic = gap_function(REFERENCE, "nut", -1, "quadratic")
    np.testing.assert_array_equal(exact(x, y), gap_exact(REFERENCE, "nut", x, y, -1))
    np.testing.assert_array_equal(quadratic(x, y), gap_quadratic(REFERENCE, "nut", x, y))
    with pytest.raises(InputError) as info:
        gap_function(REFERENCE, "nut", model="hertz")
    assert info.value.field == "numerics.gap_model"
    assert "exact, quadratic" in str(info.value)


def test_ball_height_is_the_sphere() -> None:
    x, y = 1.0e-3, -2.0e-3
    z = float(ball_height(REFERENCE, x, y))
    assert x**2 + y**2 + (REFERENCE.ball_radius - z) ** 2 == pytest.approx(REFERENCE.ball_radius**2)


def test_points_off_the_ball_are_rejected() -> None:
    r_b = REFERENCE.ball_radius
    with pytest.raises(InputError) as info:
        gap_exact(REFERENCE, "screw", np.array([0.0, r_b]), 0.0)
    assert info.value.field == "x, y"
    with pytest.raises(InputError):
        gap_exact(REFERENCE, "nut", 0.0, np.nan)


def test_non_convergence_raises(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(gap_module, "_MAX_ITERATIONS", 1)
    with pytest.raises(ConvergenceError, match="raceway projection"):
        gap_exact(REFERENCE, "screw", 2.0e-3, 2.0e-3)
