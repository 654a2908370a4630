"""Synthetic W–M profiles (F1) against a scalar evaluation of the sum, and the band they hold."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.surface import Profile, weierstrass_mandelbrot_profile, wm_frequency_indices

GAMMA = 1.5


def test_profile_is_the_f1_sum_with_the_seeded_phases() -> None:
    D, G, L, dx, seed = 1.59, 9e-10, 2.0e-3, 0.5e-6, 7
    p = weierstrass_mandelbrot_profile(D, G, L, dx, seed=seed)
    n = np.arange(p.metadata["n1"], p.metadata["n_max"] + 1)
    phases = np.random.default_rng(seed).uniform(0.0, 2.0 * math.pi, size=(1, n.size))[0]
    for j in (0, 1, 777, 3999):
        x = j * dx
        ref = sum(
            G ** (D - 1) * math.cos(2 * math.pi * GAMMA ** int(k) * x + ph) / GAMMA ** ((2 - D) * k)
            for k, ph in zip(n, phases, strict=True)
        )
        assert p.heights[j] == pytest.approx(ref, rel=1e-11, abs=1e-20)
    assert isinstance(p, Profile)
    assert p.heights.shape == (4000,)
    assert p.spacing == dx
    assert p.length == pytest.approx(L)


@pytest.mark.parametrize(("L", "dx"), [(1e-3, 1e-6), (6.5536e-3, 1e-7), (0.37e-3, 0.82e-6)])
def test_band_runs_from_the_sampling_length_to_below_nyquist(L: float, dx: float) -> None:
    n = wm_frequency_indices(L, dx)
    assert GAMMA ** n[0] >= 1.0 / L > GAMMA ** (n[0] - 1)
    assert GAMMA ** n[-1] < 0.5 / dx <= GAMMA ** (n[-1] + 1)
    assert np.all(np.diff(n) == 1)


def test_rows_have_independent_phases_and_same_statistics() -> None:
    p = weierstrass_mandelbrot_profile(1.5, 1e-10, 1e-3, 1e-6, seed=1, profiles=3)
    assert p.heights.shape == (3, 1000)
    assert p.n_profiles == 3
    assert not np.allclose(p.heights[0], p.heights[1])
    again = weierstrass_mandelbrot_profile(1.5, 1e-10, 1e-3, 1e-6, seed=1, profiles=3)
    np.testing.assert_array_equal(p.heights, again.heights)


def test_line_variance_sum() -> None:
    """Σ A_n²/2 is the mean square of the sum of cosines; a long record reproduces it."""
    D, G = 1.7, 1e-10
    p = weierstrass_mandelbrot_profile(D, G, 2**16 * 1e-7, 1e-7, seed=3, profiles=4)
    n = np.arange(p.metadata["n1"], p.metadata["n_max"] + 1)
    lines = np.sum(G ** (2 * (D - 1)) * GAMMA ** (-2 * (2 - D) * n)) / 2
    measured = np.mean(p.heights**2)
    assert measured == pytest.approx(lines, rel=0.05)


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"D": 2.0}, "D"),
        ({"G": -1e-9}, "G"),
        ({"gamma": 1.0}, "gamma"),
        ({"length": 1e-9}, "length"),
        ({"profiles": 0}, "profiles"),
    ],
)
def test_bad_arguments(kwargs: dict, field: str) -> None:
    args = {"D": 1.5, "G": 1e-10, "length": 1e-3, "spacing": 1e-6} | kwargs
    with pytest.raises(InputError) as err:
        weierstrass_mandelbrot_profile(**args)
    assert err.value.field == field
