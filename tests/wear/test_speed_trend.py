"""Wear per revolution against speed at the coupled operating point (theory manual, *Wear*, wear
at high speed): the flooded film ends the wear at speed, a starved inlet keeps part of it."""

from __future__ import annotations

import math

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.wear import wear_setup
from ballscrew.analyses.wear_duty import duty_programme
from ballscrew.case import Case
from ballscrew.lubrication import share_load
from ballscrew.wear.life import _State, _step_rates
from ballscrew.wear.setup import nut_force_pair
from ballscrew.wear.step import entrainment_speed

from .conftest import REF_PATH

RPM = math.pi / 30.0


def supplied(supply: str) -> dict:
    """The reference case as a dict, ISO VG 68 following the operating point's temperature,
    with the ``[lubrication]`` supply (starved: inlet meniscus m = 1.2)."""
    raw = ballscrew.load_case(REF_PATH).model_dump()
    raw["medium"].update({"viscosity": None, "pressure_viscosity": None})
    raw["kinematics"]["lubricant"] = "iso_vg_68"
    if supply == "starved":
        raw["lubrication"] = {"supply": "starved", "inlet_ratio": 1.2}
    return raw


def wear_and_film(rpm: float, supply: str) -> tuple[float, float, float]:
    """(largest ḣ per revolution of the unworn groove [m/rev], film thickness h [m] of the
    nut-1 contact, contact temperature [K]) of the reference screw at 2000 N and ``rpm``.

    The lubricant state is that of the coupled operating point of a 2000 N duty segment at
    ``rpm``; the grid is the reference programme's own (the fractal roughness σ, hence the film
    parameter, depends on the cell area)."""
    raw = supplied(supply)
    setup = wear_setup(Case.model_validate(raw))
    raw["wear"].pop("programme")
    raw["duty"] = [{"speed": rpm * RPM, "axial_load": 2000.0, "stroke": 0.3, "duration": 600.0}]
    (level,) = duty_programme(Case.model_validate(raw))
    state = _State(0, 0.0, np.zeros((2, setup.y.size)), {}, {}, 0, 0, {})
    rates = _step_rates(setup, state, setup.initial_preload, level)
    load = setup.ball_load(nut_force_pair(setup.initial_preload, level.axial_load)[0])
    eta, alpha = setup.lubricant(level)
    area = float(np.count_nonzero(state.warm["+1_1"] > 0.0)) * setup.cell_area
    film = share_load(
        load,
        setup.rx,
        setup.ry,
        eta,
        alpha,
        entrainment_speed(setup.geometry, rpm * RPM),
        area,
        setup.surface,
        film_model=setup.film_model,
    ).separation
    return float(rates.max()), film, level.temperature


@pytest.fixture(scope="module")
def runs() -> dict[tuple[str, int], tuple[float, float, float]]:
    return {(s, n): wear_and_film(n, s) for s in ("flooded", "starved") for n in (100, 1500)}


def test_flooded_film_ends_the_wear_at_speed(runs) -> None:
    """Flooded: the film grows with speed faster than the operating point's temperature thins
    it (21 → 34 °C), so ḣ(1500 rpm) is about 5e-8 of ḣ(100 rpm) (the separation over the σ of
    one wear-grid cell from 1.8 to 6.2; Λ = h_c/σ_Λ only from 0.08 to 0.27)."""
    slow, fast = runs["flooded", 100], runs["flooded", 1500]
    assert fast[2] > slow[2]  # hotter at speed ...
    assert fast[1] > 2.0 * slow[1]  # ... yet a much thicker film
    assert fast[0] < 1e-5 * slow[0]


def test_a_starved_inlet_keeps_part_of_the_wear_at_speed(runs) -> None:
    """Starved (m = 1.2): the inlet meniscus limits the film's growth with speed, the asperities
    keep carrying load and ḣ(1500 rpm) stays above 1e-3 of ḣ(100 rpm) (about 1.5 %, the
    separation over the cell's σ from 1.2 to 3.6)."""
    slow, fast = runs["starved", 100], runs["starved", 1500]
    flooded = runs["flooded", 100], runs["flooded", 1500]
    assert fast[1] / slow[1] < flooded[1][1] / flooded[0][1]  # the film grows less
    assert slow[0] > flooded[0][0] and fast[0] > flooded[1][0]  # a thinner film wears more
    assert fast[0] > 1e-3 * slow[0]
    assert fast[0] < slow[0]  # still less wear per revolution at speed
