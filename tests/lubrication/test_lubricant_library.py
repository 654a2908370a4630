"""The library of named oils and greases and their properties against temperature."""

from __future__ import annotations

import pytest

from ballscrew.errors import InputError
from ballscrew.lubrication.lubricant_library import (
    LUBRICANT_LIBRARY,
    LibraryLubricant,
    library_lubricant,
)

GRADES = (10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460)


def test_library_holds_iso_vg_10_to_460_and_greases():
    for grade in GRADES:
        oil = library_lubricant(f"iso_vg_{grade}")
        assert (oil.kind, oil.nu40, oil.thickener) == ("oil", pytest.approx(grade * 1e-6), None)
    greases = [lub for lub in LUBRICANT_LIBRARY.values() if lub.kind == "grease"]
    thickeners = {g.thickener for g in greases}
    assert {"lithium soap", "lithium complex soap", "calcium sulfonate complex", "polyurea"} <= (
        thickeners
    )
    assert all(g.nlgi_grade == 2 and "ASSUMED" in g.source for g in greases)


@pytest.mark.parametrize("name", sorted(LUBRICANT_LIBRARY))
def test_every_entry_meets_its_anchors_and_thins_with_temperature(name):
    lub = LUBRICANT_LIBRARY[name]
    at40, at100 = lub.at(313.15), lub.at(373.15)
    assert at40.kinematic == pytest.approx(lub.nu40, rel=1e-12)
    assert at100.kinematic == pytest.approx(lub.nu100, rel=1e-12)
    states = [lub.at(t) for t in (293.15, 313.15, 333.15, 353.15, 373.15)]
    for hot, cold in zip(states[1:], states, strict=False):
        assert hot.viscosity < cold.viscosity
        assert hot.pressure_viscosity < cold.pressure_viscosity
        assert hot.density < cold.density and hot.conductivity < cold.conductivity
    assert at40.viscosity == pytest.approx(at40.density * at40.kinematic)
    assert 0.01 < at40.temperature_viscosity < 0.1
    assert 0.11 < at40.conductivity < 0.15
    assert 1e-8 < at40.pressure_viscosity < 3e-8


def test_vg68_at_40c():
    state = library_lubricant("iso_vg_68").at(313.15)
    assert state.density == pytest.approx(880.0 * (1 - 6.4e-4 * 25.0))
    assert state.viscosity == pytest.approx(0.0589, rel=1e-3)
    assert state.pressure_viscosity == pytest.approx(9.904e-9 * 68**0.139)


def test_unknown_lubricant_lists_the_names():
    with pytest.raises(
        InputError, match=r"^lubricant = 'vg68' .*one of calcium_sulfonate.*iso_vg_10,"
    ):
        library_lubricant("vg68")


def test_an_entry_whose_viscosity_rises_with_temperature_is_refused():
    with pytest.raises(InputError, match=r"^nu100 = .*falls with temperature"):
        LibraryLubricant("bad", "oil", 10e-6, 12e-6, 870.0, "test")
    with pytest.raises(InputError, match=r"^kind = 'paste'"):
        LibraryLubricant("bad", "paste", 10e-6, 2.6e-6, 870.0, "test")


@pytest.mark.parametrize("name", ["iso_vg_10", "iso_vg_68", "lithium_complex_nlgi2_vg220"])
def test_temperature_at_inverts_the_viscosity_law(name):
    lub = LUBRICANT_LIBRARY[name]
    for temperature in (273.15, 313.15, 353.15, 393.15):
        eta = lub.at(temperature).viscosity
        assert lub.temperature_at(eta) == pytest.approx(temperature, abs=1e-6)


def test_library_oils_have_the_viscosity_index_their_source_states():
    """The oils' ν100 are stated as typical of VI ≈ 95–100 mineral oils: their ASTM D2270 VI,
    computed from ν40 and ν100, is 95.6–100.5 (VG 460 lowest, VG 22 highest)."""
    vis = {g: library_lubricant(f"iso_vg_{g}").viscosity_index for g in GRADES}
    assert all(95.0 <= vi <= 100.6 for vi in vis.values()), vis
    # a grease carries its base oil's VI
    grease = library_lubricant("lithium_nlgi2_vg100")
    assert grease.viscosity_index == pytest.approx(vis[100], rel=1e-12)
