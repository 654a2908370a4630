"""The reported film parameter Λ and asperity share ψ are the wear engine's own."""

from __future__ import annotations

import math

import pytest

import ballscrew
import ballscrew.wear.life
from ballscrew.analyses.wear import wear_setup
from ballscrew.analyses.wear_film import part_films
from ballscrew.contact import hertz
from ballscrew.lubrication import share_load
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
