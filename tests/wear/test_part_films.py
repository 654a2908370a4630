"""The reported asperity share ψ is the wear engine's own; the reported film parameter Λ is the
operating point's, h_c of the whole ball load over σ_Λ."""

from __future__ import annotations

import dataclasses
import math

import pytest

import ballscrew
import ballscrew.wear.life
from ballscrew.analyses.operating_point import OperatingPointWarning
from ballscrew.analyses.wear import wear_setup
from ballscrew.analyses.wear_film import part_films
from ballscrew.analyses.wear_report import history, summary
from ballscrew.contact import hertz
from ballscrew.lubrication import regime, share_load
from ballscrew.wear.programme import WearLevel
from ballscrew.wear.setup import nut_force_pair
from ballscrew.wear.step import entrainment_speed


def test_reported_psi_is_the_one_the_engine_applies(coarse_case) -> None:
    """Level 1's ψ in the result equals the ψ the engine applied to the nut-1 contact at the first
    step (uniform load distribution: the mean ball is the engine's contact), to round-off; a run
    stopped there reports only the level it reached."""
    result = ballscrew.wear_life(coarse_case, max_steps=1)
    (first,) = result.films
    assert first.asperity_share == pytest.approx(result.life.initial_psi["+1_1"], rel=1e-12)
    assert 0.0 < first.asperity_share < 1.0
    assert first.film_parameter is not None and first.film_parameter > 0.0


def test_every_level_reports_the_psi_the_engine_applies_at_its_start(
    coarse_case, monkeypatch
) -> None:
    """Each level's reported Λ and ψ are those of the engine's first step of that level (worn
    raceway, preload lost so far): the step's contacts are spied on. Before, ψ came from a
    start-of-run estimate (unworn raceway, Hertz ellipse) that differed from the engine's."""
    applied: dict[int, tuple[float, float | None]] = {}
    solve = ballscrew.wear.life.step_rates

    def spy(setup, contacts):
        rates = solve(setup, contacts)
        for contact, rate in zip(contacts, rates, strict=True):
            level = setup.spec.programme.index(contact.level)
            loaded = contact.nut_force == max(c.nut_force for c in contacts)
            if contact.flank == 1 and loaded:
                applied.setdefault(level, (rate.psi, rate.film_parameter))
        return rates

    monkeypatch.setattr(ballscrew.wear.life, "step_rates", spy)
    result = ballscrew.wear_life(coarse_case)
    assert [f.level for f in result.films] == [0, 1, 2]
    for film in result.films:
        psi, lam = applied[film.level]
        assert film.asperity_share == pytest.approx(psi, rel=1e-9)
        assert film.film_parameter == pytest.approx(lam, rel=1e-9)
    assert result.films[2].asperity_share != pytest.approx(result.films[0].asperity_share)


def test_the_engine_psi_uses_the_loaded_cells_not_the_hertz_ellipse(coarse_case) -> None:
    """The start-of-run estimate of earlier versions (A_n = π a b of the Hertz ellipse) is not
    what is reported: the engine's nominal area is the loaded cells of the solved contact (on
    this coarse grid larger than π a b, so the asperities carry a larger share: 0.719 against
    0.676 at the rolling entrainment speed), and the reported ψ is the one of that area."""
    setup = wear_setup(coarse_case)
    level = setup.spec.programme[0]
    film = part_films(setup, (level,))[0]
    q = setup.ball_load(max(nut_force_pair(setup.initial_preload, level.axial_load)))
    eta, alpha = setup.lubricant(level)
    contact = hertz(setup.rx, setup.ry, setup.e_star, q)
    ellipse = share_load(
        q,
        setup.rx,
        setup.ry,
        eta,
        alpha,
        abs(entrainment_speed(setup.geometry, level.speed, setup.entrainment)),
        math.pi * contact.a * contact.b,
        setup.surface,
        film_model=setup.film_model,
    )
    assert film.ball_load == pytest.approx(q, rel=1e-12)
    assert film.asperity_share == pytest.approx(0.719, abs=1e-3)
    assert ellipse.psi == pytest.approx(0.676, abs=1e-3)


RPM = math.pi / 30.0


def test_the_reported_film_parameter_is_the_operating_points(coarse_case) -> None:
    """The wear results' Λ is the operating point's, h_c of the whole ball load over σ_Λ
    (E6.6), at the same speed, load and viscosity (the example's constant [medium]); it used to
    be the engine's separation h((1 − ψ)Q) over σ_Λ, 0.0417 against 0.0392 at level 1."""
    setup = wear_setup(coarse_case)
    levels = (WearLevel(2000.0, 100 * RPM, 1.0), WearLevel(3000.0, 1000 * RPM, 1.0))
    for film, level in zip(part_films(setup, levels), levels, strict=True):
        with pytest.warns(OperatingPointWarning, match="boundary lubrication"):
            point = ballscrew.operating_point(coarse_case, level.speed, level.axial_load)
        assert film.film_parameter == pytest.approx(point.film_parameter, rel=1e-9)
        assert film.film_thickness == pytest.approx(point.film_thickness, rel=1e-9)
        assert film.film_roughness == point.film_roughness
        assert film.regime == regime(point.film_parameter) == "boundary"
        # Hamrock & Dowson (1977): h_c ∝ Q_f^−0.067, so the engine's separation under the
        # film-borne load (1 − ψ)Q is (1 − ψ)^−0.067 times the film of the whole load
        ratio = (1.0 - film.asperity_share) ** -0.067
        assert film.separation == pytest.approx(ratio * film.film_thickness, rel=1e-12)


def test_the_supply_factor_thins_the_reported_film(coarse_case) -> None:
    """wear.film_factor φ scales the wear engine's film, h = φ h_c, and with it the reported Λ
    (where the operating point, which does not read [wear], keeps the flooded film)."""
    setup = wear_setup(coarse_case)
    level = setup.spec.programme[0]
    flooded = part_films(setup, (level,))[0]
    starved = dataclasses.replace(setup, spec=dataclasses.replace(setup.spec, film_factor=0.5))
    half = part_films(starved, (level,))[0]
    assert half.film_parameter == pytest.approx(0.5 * flooded.film_parameter, rel=1e-12)
    assert half.asperity_share > flooded.asperity_share


def test_summary_and_history_give_the_film_parameter_and_its_regime(coarse_case) -> None:
    """summary.json's lubrication entries and the history dataset carry Λ = h_c/σ_Λ, its
    regime, ψ and the engine's separation of each part; the wear history is unchanged."""
    result = ballscrew.wear_life(coarse_case, max_steps=1)
    (entry,) = summary(result)["lubrication"]
    (film,) = result.films
    assert entry["film_parameter"]["value"] == film.film_parameter
    assert entry["film_parameter"]["value"] == pytest.approx(
        entry["film_thickness"]["value"] / entry["film_roughness"]["value"], rel=1e-15
    )
    assert entry["lubrication_regime"] == "boundary"
    assert entry["separation"]["value"] > entry["film_thickness"]["value"]
    data = history(result)
    assert data["film_parameter"].sel(part="level 1").item() == film.film_parameter
    assert data["asperity_share"].sel(part="level 1").item() == film.asperity_share
