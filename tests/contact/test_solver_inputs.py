"""Every entry point of the normal contact solver checks the memory budget before it allocates,
refuses integer gaps and non-finite or non-positive moduli, and warns of a modulus no solid has."""

import tracemalloc
import warnings

import numpy as np
import pytest

from ballscrew.budget import BudgetError
from ballscrew.contact import (
    ContactRequest,
    hamrock_brewe,
    hertz,
    solve_contact,
    solve_contacts,
    solve_normal,
    solve_normal_batch,
    solve_normal_displacement,
)
from ballscrew.errors import ImplausibleValueWarning, InputError

E_STAR = 113.19e9
N = 512
X = np.linspace(-1.0, 1.0, N) * 50e-6
GAP = np.add.outer(X**2, X**2) / 20e-3  # sphere R = 10 mm over ±50 µm
DX = X[1] - X[0]


def sphere_gap(x, y):
    return (x**2 + y**2) / 20e-3


ENTRY_POINTS = {
    "solve_normal": lambda: solve_normal(GAP, DX, DX, E_STAR, 10.0),
    "solve_normal_displacement": lambda: solve_normal_displacement(GAP, DX, DX, E_STAR, 1e-7),
    "solve_normal_batch": lambda: solve_normal_batch(GAP[None], DX, DX, E_STAR, [10.0]),
    "solve_contact": lambda: solve_contact(sphere_gap, 10e-3, 10e-3, E_STAR, 10.0, cells=(N, N)),
    "solve_contacts": lambda: solve_contacts(
        [ContactRequest(sphere_gap, 10e-3, 10e-3, E_STAR, 10.0)], cells=(N, N)
    ),
}


@pytest.mark.parametrize("name", ENTRY_POINTS)
def test_every_entry_point_refuses_a_grid_over_the_budget_before_allocating(monkeypatch, name):
    """A 512² solve needs about 78 MiB (36 float64 arrays of the grid's cells); under a 1 MB budget
    each entry point raises a BudgetError that names the size, having allocated less than the
    512² gap itself (2 MB) on the way."""
    monkeypatch.setenv("BALLSCREW_MEMORY_BUDGET", "1 MB")
    tracemalloc.start()
    try:
        with pytest.raises(BudgetError, match=r"512 × 512 .*needs about 78 MiB"):
            ENTRY_POINTS[name]()
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < GAP.nbytes


def test_the_budget_error_names_the_argument_and_the_batch():
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("BALLSCREW_MEMORY_BUDGET", "100 MB")
        solve_normal_batch(GAP[None, ::4, ::4].copy(), 4 * DX, 4 * DX, E_STAR, [10.0])
        match = r"^gaps = 'array of shape \(2, 512, 512\)'.*2 normal contact solves"
        with pytest.raises(BudgetError, match=match):
            solve_normal_batch(np.stack([GAP, GAP]), DX, DX, E_STAR, [10.0, 10.0])


@pytest.mark.parametrize("dtype", [np.int64, np.int32, bool])
def test_an_integer_gap_is_refused(dtype):
    gap = np.ones((16, 16), dtype=dtype)
    with pytest.raises(InputError, match=r"^gap = .*float array of gaps in metres"):
        solve_normal(gap, 1e-6, 1e-6, E_STAR, 1.0)
    with pytest.raises(InputError, match=r"^gaps = .*float array"):
        solve_normal_batch(gap[None], 1e-6, 1e-6, E_STAR, [1.0])
    with pytest.raises(InputError, match=r"^gap = .*float array"):
        solve_normal(gap.tolist(), 1e-6, 1e-6, E_STAR, 1.0)


def test_a_float32_gap_and_a_list_of_floats_are_taken():
    small = GAP[::32, ::32]
    reference = solve_normal(small, 32 * DX, 32 * DX, E_STAR, 10.0)
    for gap in (small.astype(np.float32), small.tolist()):
        result = solve_normal(gap, 32 * DX, 32 * DX, E_STAR, 10.0)
        np.testing.assert_allclose(result.pressure, reference.pressure, rtol=1e-5)


@pytest.mark.parametrize("e_star", [0.0, -113e9, np.nan, np.inf])
def test_a_modulus_that_is_not_finite_and_positive_is_refused(e_star):
    for call in (
        lambda: hertz(10e-3, 10e-3, e_star, 10.0),
        lambda: hamrock_brewe(10e-3, 10e-3, e_star, 10.0),
        lambda: solve_normal(GAP[::32, ::32], 32 * DX, 32 * DX, e_star, 10.0),
        lambda: solve_normal_batch(GAP[None, ::32, ::32], 32 * DX, 32 * DX, [e_star], [10.0]),
    ):
        with pytest.raises(InputError, match=r"^e_star = "):
            call()


@pytest.mark.parametrize("e_star", [206.0, 113.19e6, 5e12])
def test_a_modulus_outside_engineering_solids_is_warned_at_the_callers_line(e_star):
    """206 Pa (206 GPa without its unit), 113 MPa (a MPa slip) and 5 TPa are no solid's E*."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        hertz(10e-3, 10e-3, e_star, 10.0)
        solve_normal(GAP[::32, ::32], 32 * DX, 32 * DX, e_star, 10.0, raise_on_failure=False)
        solve_normal_batch(GAP[None, ::32, ::32], 32 * DX, 32 * DX, [e_star], [10.0])
    implausible = [w for w in caught if issubclass(w.category, ImplausibleValueWarning)]
    assert len(implausible) == 3
    assert all("e_star = " in str(w.message) and "GPa" in str(w.message) for w in implausible)
    assert {w.filename for w in implausible} == {__file__}


def test_a_batch_of_implausible_moduli_warns_once():
    """Eight contacts with E* in GPa without the unit (200 ... 207 'Pa'): one warning naming the
    first, not one per value; a plausible E* among them is not the one named."""
    moduli = [113.19e9, *np.arange(200.0, 207.0)]
    gaps = np.repeat(GAP[None, ::32, ::32], len(moduli), axis=0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        solve_normal_batch(gaps, 32 * DX, 32 * DX, moduli, [10.0] * len(moduli),
                           raise_on_failure=False)  # fmt: skip
    implausible = [w for w in caught if issubclass(w.category, ImplausibleValueWarning)]
    assert len(implausible) == 1 and "e_star = 200 Pa" in str(implausible[0].message)
    assert implausible[0].filename == __file__


def test_plausible_moduli_are_not_warned():
    """Two polymers (E* ≈ 0.6 GPa), steel on steel, diamond on diamond (≈ 530 GPa)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleValueWarning)
        for e_star in (0.6e9, E_STAR, 530e9):
            hertz(10e-3, 10e-3, e_star, 10.0)
