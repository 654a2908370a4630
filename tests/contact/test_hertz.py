"""Hertz closed forms against reference numbers (sphere, ellipsoid, and the screw and nut contacts
of the TCR reference screw; 1e-5 relative),
the circular limit (H1), and the pressure field's integral (the load) by quadrature."""

import dataclasses

import numpy as np
import pytest
from scipy.integrate import dblquad

from ballscrew.contact import hamrock_brewe, hertz
from ballscrew.errors import InputError

E_STAR = 113.187e9  # composite modulus of these reference cases
Q_BALL = 39.40790  # N, ball load (Q1) of the TCR reference screw


def radii(a_h, b_h):
    """Relative radii of the gap A_H x² + B_H y² = x²/(2 rx) + y²/(2 ry)."""
    return 1.0 / (2.0 * a_h), 1.0 / (2.0 * b_h)


def check(result, a, b, p0, approach, rel=1e-5):
    assert result.a == pytest.approx(a, rel=rel)
    assert result.b == pytest.approx(b, rel=rel)
    assert result.p0 == pytest.approx(p0, rel=rel)
    assert result.approach == pytest.approx(approach, rel=rel)


def test_t_pk1_sphere_on_plane():
    """R = 10 mm, W = 100 N: a = 0.1878258 mm, p0 = 1.353415 GPa, δ = 3.527851 µm."""
    result = hertz(10e-3, 10e-3, E_STAR, 100.0)
    check(result, 0.1878258e-3, 0.1878258e-3, 1.353415e9, 3.527851e-6)
    assert result.eccentricity == 0.0


def test_t_pk2_ellipsoid_exact():
    """h = x²/(2·50 mm) + y²/(2·10 mm), W = 100 N; the major axis lies along x."""
    result = hertz(50e-3, 10e-3, E_STAR, 100.0)
    check(result, 0.4037272e-3, 0.1396892e-3, 0.8466238e9, 2.605610e-6)
    assert result.eccentricity == pytest.approx(0.938235, rel=1e-5)


def test_t_pk2_hamrock_brewe():
    result = hamrock_brewe(50e-3, 10e-3, E_STAR, 100.0)
    check(result, 0.402447e-3, 0.139857e-3, 0.848294e9, 2.61738e-6)


@pytest.mark.parametrize(
    ("a_h", "b_h", "exact", "fits"),
    [
        # Screw contact of the TCR reference screw; its a (across the groove) lies along y here.
        (177.2534, 6.056935, (47.29638e-6, 0.4135337e-3, 0.9620238e9, 1.432304e-6),
         (47.1109e-6, 0.417055e-3, 0.957656e9, 1.41952e-6)),
        # Nut contact: A_H = h_xx/2, B_H = h_yy/2 from the exact gap Hessian.
        (283.3550 / 2, 12.11387 / 2, (53.27936e-6, 0.4063867e-3, 0.8690128e9, 1.402484e-6),
         None),
    ],
)  # fmt: skip
def test_ball_screw_contacts(a_h, b_h, exact, fits):
    rx, ry = radii(a_h, b_h)
    result = hertz(rx, ry, E_STAR, Q_BALL)
    check(result, *exact)
    if fits is not None:
        check(hamrock_brewe(rx, ry, E_STAR, Q_BALL), *fits)


@pytest.mark.parametrize(("rx", "ry"), [(50e-3, 10e-3), (3.6e-3, 40e-3), (30e-3, 2e-3)])
def test_hamrock_brewe_within_one_percent(rx, ry):
    exact, fits = hertz(rx, ry, E_STAR, 250.0), hamrock_brewe(rx, ry, E_STAR, 250.0)
    for field in ("a", "b", "p0", "approach"):
        assert getattr(fits, field) == pytest.approx(getattr(exact, field), rel=0.01), field


def test_orientation_swaps_the_axes():
    """Exchanging rx and ry exchanges a and b and nothing else."""
    one, other = hertz(50e-3, 10e-3, E_STAR, 100.0), hertz(10e-3, 50e-3, E_STAR, 100.0)
    assert (one.a, one.b) == (other.b, other.a)
    assert (one.p0, one.approach) == (other.p0, other.approach)


@pytest.mark.parametrize("ratio", [1 + 1e-12, 1 + 1e-8, 1 + 1e-5])
def test_circular_limit_is_continuous(ratio):
    """Nearly equal radii tend to (H1) with R = rx = ry."""
    radius, load = 10e-3, 100.0
    a = (3.0 * load * radius / (4.0 * E_STAR)) ** (1.0 / 3.0)
    result = hertz(radius * ratio, radius, E_STAR, load)
    tolerance = 2 * (ratio - 1) + 1e-12
    for value, limit in ((result.a, a), (result.b, a), (result.approach, a * a / radius),
                         (result.p0, 3 * load / (2 * np.pi * a * a))):  # fmt: skip
        assert value == pytest.approx(limit, rel=tolerance)


def test_pressure_field_carries_the_load():
    """∬ p dA over the ellipse equals W (quadrature), and the derived quantities agree."""
    result = hertz(3.6e-3, 40e-3, E_STAR, 1000.0)
    a, b = result.a, result.b

    def integrand(y, x):
        return float(result.pressure(x, y))

    load, _ = dblquad(integrand, -a, a, lambda x: -b * np.sqrt(max(1 - (x / a) ** 2, 0.0)),
                      lambda x: b * np.sqrt(max(1 - (x / a) ** 2, 0.0)), epsrel=1e-10)  # fmt: skip
    assert load == pytest.approx(1000.0, rel=1e-7)
    assert result.mean_pressure * result.area == pytest.approx(1000.0, rel=1e-12)
    assert result.pressure(1.01 * a, 0.0) == 0.0
    assert result.pressure(0.0, 0.0) == result.p0


def test_result_is_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        hertz(1e-2, 1e-2, E_STAR, 1.0).a = 1.0


@pytest.mark.parametrize("field", ["rx", "ry", "e_star", "load"])
@pytest.mark.parametrize("value", [0.0, -1.0, np.nan, np.inf])
def test_invalid_arguments_name_the_field(field, value):
    arguments = {"rx": 1e-2, "ry": 2e-2, "e_star": E_STAR, "load": 10.0, field: value}
    for function in (hertz, hamrock_brewe):
        with pytest.raises(InputError, match=field):
            function(**arguments)
