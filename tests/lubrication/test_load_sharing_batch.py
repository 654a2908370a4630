"""The vectorised JGP load sharing against an independent scalar Brent solve, and its limits."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from ballscrew.contact import hertz
from ballscrew.errors import ConvergenceError, InputError
from ballscrew.fractal import yan_komvopoulos as yk
from ballscrew.lubrication import AsperitySurface, hamrock_dowson, share_load, share_loads
from ballscrew.lubrication.film import hamrock_dowson_central
from ballscrew.lubrication.roots import bracketed_roots
from ballscrew.lubrication.supply import supplied_film_model

from .test_film import ALPHA, ETA, RX, RY, U_E

E_STAR, H = 1.1319e11, 7.0e9
T_MIN = math.log(1e-300)


def area(load: float) -> float:
    c = hertz(RX, RY, E_STAR, load)
    return math.pi * c.a * c.b


def brent_psi(load, speed, surface, film=hamrock_dowson, factor=1.0):
    """t = ln(1 − ψ) of (E6.4) by scipy's scalar Brent, one contact, written out independently."""
    sigma = yk.rms_height(surface.Ds, surface.G, math.sqrt(surface.cell_area))
    a_n = area(load)

    def r(t):
        h = factor * film(RX, RY, 2 * E_STAR, ETA, ALPHA, speed, math.exp(t) * load).central
        a_l = yk.max_largest_area(surface.cell_area, surface.Ds) * yk.bearing_ratio(h, sigma)
        cell = yk.total_force(a_l, surface.Ds, surface.G, E_STAR, H)
        return a_n * float(cell) / surface.cell_area + math.expm1(t) * load

    if r(0.0) <= 0.0:
        return 0.0
    grid = [T_MIN] if r(T_MIN) <= 0.0 else list(-np.geomspace(1e-12, -T_MIN, 97))
    upper = 0.0
    for t in grid:
        if r(float(t)) <= 0.0:
            return brentq(r, float(t), upper, xtol=1e-14, rtol=1e-14)
        upper = float(t)
    return None  # dry


CASES = [
    (load, u, G)
    for load in (5.0, 39.41, 300.0)
    for u in (0.01, U_E, 3.0)
    for G in (1e-13, 1e-11, 1e-10, 1e-9, 1e-8)
]


@pytest.mark.parametrize(
    "film",
    [
        "hamrock_dowson",
        supplied_film_model("hamrock_dowson", inlet_ratio=1.5),
        supplied_film_model("hamrock_dowson", thermal=(0.03, 0.14)),
    ],
    ids=["flooded", "starved", "inlet_heating"],
)
def test_batch_equals_a_scalar_brent_solve_of_each_contact(film):
    """Old solver tolerance: Brent in t = ln(1 − ψ) with xtol = rtol = 1e-14; the batch certifies a
    bracket of width ≤ 1e-14 + 2e-14 |t|, so the two roots agree to the sum of both."""
    scalar = hamrock_dowson if isinstance(film, str) else film
    for u, G in {(u, G) for _, u, G in CASES}:
        surface = AsperitySurface(2.4, G, E_STAR, H, 100e-12)
        loads = [c[0] for c in CASES if c[1:] == (u, G)]
        got = share_loads(
            loads, RX, RY, ETA, ALPHA, u, [area(q) for q in loads], surface, film_model=film
        )
        for q, share in zip(loads, got, strict=True):
            t_ref = brent_psi(q, u, surface, scalar)
            if t_ref is None:
                assert share.psi == 1.0 and share.film is None
                continue
            t = math.log1p(-share.psi) if share.psi < 1.0 else T_MIN
            # where ψ is within ~1e-11 of 1, r varies with t only at the rounding level of Q and
            # the root in t is defined no better than that: there ψ itself agrees to 1e-15
            close_t = abs(t - t_ref) <= 4e-14 * (1.0 + abs(t_ref))
            assert close_t or abs(share.psi + math.expm1(t_ref)) <= 1e-15, (q, u, G)


def test_a_supply_factor_scales_the_film_in_the_batch():
    surface = AsperitySurface(2.4, 1e-10, E_STAR, H, 100e-12)
    share = share_loads([39.41], RX, RY, ETA, ALPHA, U_E, [area(39.41)], surface, film_factor=0.5)
    t_ref = brent_psi(39.41, U_E, surface, factor=0.5)
    assert math.log1p(-share[0].psi) == pytest.approx(t_ref, abs=4e-14 * (1 + abs(t_ref)))


def lam(load: float, speed: float, surface: AsperitySurface) -> float:
    """Λ = h_c(Q)/σ, the film of the whole load over the RMS roughness."""
    film = hamrock_dowson(RX, RY, 2 * E_STAR, ETA, ALPHA, speed, load)
    return film.central / surface.rms_height


def test_limits_dry_and_thick_film():
    """Λ = h/σ → 0: the asperities carry all; Λ ≫ 3: the film carries all (Johnson et al. 1972)."""
    q = 39.41
    rough = AsperitySurface(2.4, 1e-8, E_STAR, H, 100e-12)
    dry = share_loads([q], RX, RY, ETA, ALPHA, 1e-8, [area(q)], rough)[0]
    assert lam(q, 1e-8, rough) < 0.01
    assert dry.psi > 1.0 - 1e-9
    smooth = AsperitySurface(2.4, 1e-13, E_STAR, H, 100e-12)
    thick = share_loads([q], RX, RY, ETA, ALPHA, 3.0, [area(q)], smooth)[0]
    assert lam(q, 3.0, smooth) > 3.0
    assert thick.psi < 1e-6
    assert share_loads([q], RX, RY, ETA, ALPHA, 0.0, [area(q)], rough)[0].film is None


def test_batch_equals_one_at_a_time():
    loads = [2.0, 16.15, 39.41, 105.79]
    surface = AsperitySurface(2.4, 1e-10, E_STAR, H, 100e-12)
    batch = share_loads(loads, RX, RY, ETA, ALPHA, U_E, [area(q) for q in loads], surface)
    for q, b in zip(loads, batch, strict=True):
        one = share_load(q, RX, RY, ETA, ALPHA, U_E, area(q), surface)
        assert b.psi == pytest.approx(one.psi, rel=1e-12)
        assert b.separation == pytest.approx(one.separation, rel=1e-12)


def test_vectorised_film_is_the_scalar_film():
    loads = np.array([1e-6, 0.3, 39.41, 2e4])
    got = hamrock_dowson_central(RX, RY, 2 * E_STAR, ETA, ALPHA, U_E)(loads)
    want = [hamrock_dowson(RX, RY, 2 * E_STAR, ETA, ALPHA, U_E, q).central for q in loads]
    np.testing.assert_allclose(got, want, rtol=1e-15)
    with pytest.raises(InputError, match="load"):
        hamrock_dowson_central(RX, RY, 2 * E_STAR, ETA, ALPHA, U_E)(np.array([1.0, 0.0]))


def test_bad_batch_input():
    s = AsperitySurface(2.4, 1e-10, E_STAR, H, 100e-12)
    with pytest.raises(InputError, match="nominal_areas"):
        share_loads([1.0, 2.0], RX, RY, ETA, ALPHA, U_E, [1e-8], s)
    with pytest.raises(InputError, match="nominal_area"):
        share_loads([1.0], RX, RY, ETA, ALPHA, U_E, [math.nan], s)


def test_bracketed_roots_of_a_batch_and_their_certificate():
    c = np.array([0.1, 1.0, 10.0])

    def r(x, i):
        return np.cos(x) - c[i] * x

    lo, hi = np.zeros(3), np.full(3, 2.0)
    x = bracketed_roots(r, lo, hi, r(lo, np.arange(3)), r(hi, np.arange(3)), 1e-14, 1e-14, "t")
    want = [brentq(lambda v, k=k: math.cos(v) - k * v, 0.0, 2.0, xtol=1e-14) for k in c]
    np.testing.assert_allclose(x, want, rtol=0, atol=3e-14)
    with pytest.raises(ConvergenceError, match="residual") as err:
        bracketed_roots(r, lo, hi, r(lo, np.arange(3)), r(hi, np.arange(3)), 1e-14, 0.0, "t", 2)
    assert err.value.residual > 0.0
