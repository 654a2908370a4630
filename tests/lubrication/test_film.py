"""Hamrock–Dowson film thickness and EHL rolling resistance ((E6.1)–(E6.3), (E3.4)).

Contact A of the wear reference screw with the cosλ curvature radii of (G18): R_x = 2.8196 mm,
R_y = 34.925 mm; E′ = 2.2637e11 Pa, η₀ = 0.06 Pa s, α_p = 2.1e-8 1/Pa, u_e = 0.09333 m/s.
"""

from __future__ import annotations

import math

import pytest

from ballscrew.errors import InputError
from ballscrew.lubrication import dimensionless_groups, ehl_rolling_resistance, hamrock_dowson

# (G18): 1/R_xA = 2/D_w + 2 cosβ cosλ/(d_m − D_w cosβ), 1/R_yA = 2/D_w − 1/r_s.
LAM = math.atan(0.010 / (math.pi * 0.040))
RX = 1.0 / (2 / 6.35e-3 + 2 * math.cos(math.pi / 4) * math.cos(LAM) / (0.040 - 6.35e-3 / 2**0.5))
RY = 1.0 / (2 / 6.35e-3 - 1 / (0.55 * 6.35e-3))
E_PRIME, ETA, ALPHA, U_E = 2.2637e11, 0.06, 2.1e-8, 0.09333


def test_t1_2_radii_used_here():
    assert RX == pytest.approx(2.820e-3, rel=5e-4)
    assert RY == pytest.approx(34.93e-3, rel=5e-4)


def test_t6_1_groups_and_film():
    u, g, w, k = dimensionless_groups(RX, RY, E_PRIME, ETA, ALPHA, U_E, 39.41)
    assert (u, g, w, k) == pytest.approx((8.774e-12, 4754, 2.190e-5, 5.156), rel=5e-4)
    film = hamrock_dowson(RX, RY, E_PRIME, ETA, ALPHA, U_E, 39.41)
    assert film.central == pytest.approx(53.30e-9, rel=5e-4)
    assert film.minimum == pytest.approx(41.70e-9, rel=5e-4)


@pytest.mark.parametrize(
    ("load", "w", "h_c", "h_min"),
    [(68.69, 3.817e-5, 51.35e-9, 40.04e-9), (105.79, None, 49.89e-9, 38.80e-9)],
)
def test_film_falls_slowly_with_load(load, w, h_c, h_min):
    film = hamrock_dowson(RX, RY, E_PRIME, ETA, ALPHA, U_E, load)
    if w is not None:
        assert film.load_parameter == pytest.approx(w, rel=5e-4)
    assert film.central == pytest.approx(h_c, rel=5e-4)
    assert film.minimum == pytest.approx(h_min, rel=5e-4)


def test_film_scaling_laws_and_zero_speed():
    base = hamrock_dowson(RX, RY, E_PRIME, ETA, ALPHA, U_E, 50.0).central
    double = hamrock_dowson(RX, RY, E_PRIME, ETA, ALPHA, 2 * U_E, 50.0).central
    assert double / base == pytest.approx(2**0.67, rel=1e-12)
    assert hamrock_dowson(RX, RY, E_PRIME, ETA, ALPHA, 0.0, 50.0).central == 0.0


def test_t3_7_rolling_resistance():
    assert ehl_rolling_resistance(RX, RY, E_PRIME, ETA, ALPHA, U_E, 68.69) == pytest.approx(
        4.637e-3, rel=5e-4
    )


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"viscosity": 0.0}, "viscosity"),
        ({"viscosity": -0.06}, "viscosity"),
        ({"entrainment_speed": -1.0}, "entrainment_speed"),
        ({"load": 0.0}, "load"),
        ({"pressure_viscosity": -1e-8}, "pressure_viscosity"),
    ],
)
def test_bad_input(kwargs, field):
    args = {
        "rx": RX,
        "ry": RY,
        "e_prime": E_PRIME,
        "viscosity": ETA,
        "pressure_viscosity": ALPHA,
        "entrainment_speed": U_E,
        "load": 39.41,
    } | kwargs
    with pytest.raises(InputError, match=field):
        hamrock_dowson(**args)
