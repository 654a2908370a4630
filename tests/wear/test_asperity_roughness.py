"""``wear.asperity_roughness``: which σ the asperities of the wear engine's JGP load sharing have
(theory manual, *Wear*, which roughness the asperity share sees)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from ballscrew.analyses.wear import fingerprint, wear_life, wear_setup
from ballscrew.analyses.wear_report import summary
from ballscrew.case import CaseError, with_overrides
from ballscrew.case.wear_spec import WearSpec
from ballscrew.loads import nut_forces
from ballscrew.wear import ASPERITY_HEIGHTS
from ballscrew.wear.step import flank_rate

from .conftest import SPEED

RPM = math.pi / 30.0


def _first_contact(case, rpm: float = 100.0):
    """The level-1 nut-1 contact of ``case`` on the unworn groove at ``rpm``."""
    setup = wear_setup(case)
    f1, _ = nut_forces(1500.0, 2000.0)
    return setup, flank_rate(setup, 1, f1, rpm * RPM, np.zeros(setup.y.size))


def test_the_cell_option_keeps_the_reference_history(ref_case) -> None:
    """Option "cell" (the example's, with which its K was calibrated) keeps the reference run
    of the version before the option to 1e-12 (the numbers of
    ``test_reference_run_is_kept_to_1e_12_by_the_reported_film``); "film" is the default."""
    assert WearSpec().asperity_roughness == "film"
    assert ref_case.wear.asperity_roughness == "cell"
    life = wear_life(ref_case)
    assert summary(life)["options"]["asperity_roughness"] == "cell"
    assert life.steps == 34
    assert life.max_wear_depth[-1] == pytest.approx(2.429758023544411e-06, rel=1e-12)
    assert life.preload[-1] == pytest.approx(244.33178071227547, rel=1e-12)
    assert life.friction_torque[-1] == pytest.approx(0.06892472280377022, rel=1e-12)
    assert life.profiles[-1].sum() == pytest.approx(3.912344252766731e-04, rel=1e-12)


def test_the_cell_share_does_not_read_the_film_roughness(ref_case) -> None:
    """With "cell", a measured σ_Λ of 1 nm (Λ ≫ 3) leaves ψ of the cell's asperities unchanged
    to the bit; with "film" the same σ_Λ leaves practically the whole load to the film
    (ψ < 1e-6)."""
    smooth = {"tcr.rms_roughness": "1 nm", "tcr.rms_slope": 0.05}
    _, cell = _first_contact(ref_case)
    _, cell_smooth = _first_contact(with_overrides(ref_case, smooth))
    assert cell_smooth.psi == cell.psi
    assert 0.1 < cell.psi < 0.9
    film_case = with_overrides(ref_case, {**smooth, "wear.asperity_roughness": "film"})
    _, film = _first_contact(film_case)
    assert film.film_parameter > 10.0
    assert film.psi < 1e-6


def test_with_the_film_roughness_a_boundary_contact_wears_as_a_dry_one(ref_case) -> None:
    """Option "film" on the example raceway (σ_Λ = 1.005 µm, Λ = 0.051 and 0.31 at 100 and
    1500 rpm): the asperities carry the whole load, ψ → 1, so the wear per revolution is that of
    the dry contact (ψ = 1 exactly, the cell law of Archard type being per unit sliding
    distance) at any speed (to 3e-3: 1 − ψ = 4e-15 at 100 rpm, 2.1e-3 at 1500 rpm; 1.5e-5 with
    the σ_Λ = 1.405 µm of the surface G read as a profile G before surface.G_convention), where
    "cell" loses it to the film (ψ 0.64 → 1.5e-6)."""
    film_case = with_overrides(ref_case, {"wear.asperity_roughness": "film"})
    setup, slow = _first_contact(film_case, 100.0)
    _, fast = _first_contact(film_case, 1500.0)
    dry_setup = dataclasses.replace(setup, viscosity=None, pressure_viscosity=None)
    f1, _ = nut_forces(1500.0, 2000.0)
    dry = flank_rate(dry_setup, 1, f1, SPEED, np.zeros(setup.y.size))
    assert dry.psi == 1.0 and dry.film_parameter is None
    assert slow.film_parameter < fast.film_parameter < 1.0  # boundary by Tallian's measure
    for rate in (slow, fast):
        assert rate.psi == pytest.approx(1.0, abs=3e-3)
        np.testing.assert_allclose(
            rate.depth_per_revolution, dry.depth_per_revolution, rtol=3e-3, atol=0.0
        )
    _, cell_fast = _first_contact(ref_case, 1500.0)
    assert cell_fast.psi < 1e-3


def test_the_option_changes_only_the_load_split(ref_case) -> None:
    """Both options solve the same pressure field, and each one's cell rates are those of the
    cell-scale wear law at its own ψ: the rates scale with ψ p through the same micro-contact."""
    _, cell = _first_contact(ref_case)
    _, film = _first_contact(with_overrides(ref_case, {"wear.asperity_roughness": "film"}))
    np.testing.assert_array_equal(cell.pressure, film.pressure)
    assert film.psi > cell.psi
    assert film.depth_per_revolution.max() > cell.depth_per_revolution.max()


def test_the_option_is_part_of_the_fingerprint(ref_case) -> None:
    """A checkpoint of one option does not resume the other; "cell" keeps the fingerprint of
    the version before the option (and before surface.G_convention: the example gives the 3-D
    G its wear law reads), so its checkpoints stay valid."""
    film_case = with_overrides(ref_case, {"wear.asperity_roughness": "film"})
    cell_print = fingerprint(ref_case, wear_setup(ref_case))
    assert cell_print == "8ec04f5b740b851a5ef0fb0bb0e8082078cd3eb77e2caca711488647873a3751"
    assert fingerprint(film_case, wear_setup(film_case)) != cell_print


def test_unknown_option_is_refused_with_the_names(ref_case) -> None:
    with pytest.raises(CaseError, match=r"wear\.asperity_roughness = 'bulk' .* one of film, cell"):
        with_overrides(ref_case, {"wear.asperity_roughness": "bulk"})
    assert ASPERITY_HEIGHTS.names == ("film", "cell")
