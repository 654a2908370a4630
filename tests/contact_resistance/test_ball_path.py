"""The screw's ball path in both modes of ``tcr.film_path``: without film (micro TCR plus the
macro-constriction of the patches) in every run, with film beside it when asked, and the
headline micro TCR untouched by either (theory manual: *Contact resistance*, *Which number is
the headline*)."""

from __future__ import annotations

import math

import pytest

from ballscrew.analyses.screw_tcr import tcr_scalars
from ballscrew.analyses.tcr_report import HEADLINE

from .test_film_path import _tcr

MICRO = 0.03825179077420288
"""Micro TCR of a nut of the example at 0 kN, R_sbn/n_b [K/W] (the thermal interfaces' value)."""
CONSTRICTION = 2.5129744276823214
"""Macro-constriction (A6) of a nut's 54 balls at 0 kN [K/W] (closed form, test_heat_paths)."""


def test_without_film_path_every_loaded_nut_has_its_ball_path() -> None:
    """film_path = "none": one path per loaded nut, micro + constriction; the screw's path is
    the two nuts in parallel, (MICRO + CONSTRICTION)/2 = 1.2756 K/W, a number, no film value."""
    result = _tcr(0.0, "none")
    paths = result.heat_paths()
    assert [(p.index, p.film, p.ball_path_with_film) for p in paths] == [
        (1, False, None),
        (2, False, None),
    ]
    for path, nut in zip(paths, result.nuts, strict=True):
        assert path.micro == pytest.approx(nut.resistance, rel=1e-12)
        assert path.micro == pytest.approx(MICRO, rel=1e-9)
        assert path.constriction == pytest.approx(CONSTRICTION, rel=1e-9)
        assert path.without_film == path.ball_path_without_film
        assert path.resistance == pytest.approx(path.ball_path_without_film, rel=1e-12)
    expected = 0.5 * (MICRO + CONSTRICTION)
    assert result.ball_path_without_film == pytest.approx(expected, rel=1e-9)
    assert result.heat_path_resistance == pytest.approx(result.ball_path_without_film, rel=1e-12)
    assert result.ball_path_with_film is None
    summary = result.summary()
    assert summary["ball_path_with_film"] is None and summary["film_path"] is None
    assert summary["ball_path_without_film"]["value"] == pytest.approx(expected, rel=1e-9)
    nut1 = summary["nuts"]["nut1"]
    assert nut1["micro_resistance"]["value"] == pytest.approx(nut1["resistance"]["value"])
    assert nut1["constriction"]["value"] == pytest.approx(CONSTRICTION, rel=1e-9)
    assert nut1["ball_path_with_film"] is None


def test_with_film_path_both_values_side_by_side() -> None:
    """film_path = "meniscus": the path without film is that of the film-free run (1e-12), the
    path with film (P3) lies below it (0.310 against 1.276 K/W, theory manual's table), and the
    headline R is the film-free run's."""
    off, on = _tcr(0.0, "none"), _tcr(0.0, "meniscus")
    assert on.resistance == off.resistance
    assert on.ball_path_without_film == pytest.approx(off.ball_path_without_film, rel=1e-12)
    assert on.ball_path_with_film == on.heat_path_resistance
    assert on.ball_path_with_film == pytest.approx(0.310, abs=5e-4)
    assert on.ball_path_with_film < on.ball_path_without_film
    film = on.summary()["film_path"]["nuts"]["nut1"]
    path = on.heat_paths()[0]
    assert film["ball_path_without_film"] == film["resistance_without_film"]  # older name kept
    assert film["ball_path_with_film"] == film["resistance"]
    assert film["ball_path_with_film"]["value"] == pytest.approx(path.resistance)
    assert on.summary()["nuts"]["nut1"]["ball_path_with_film"] == film["ball_path_with_film"]


def test_lift_off_without_film_keeps_the_loaded_nut() -> None:
    """At 5 kN nut 2 is lifted off: without film the path is nut 1's alone (1.701 K/W, theory
    manual); with film the lifted-off nut's films join it (infinite path without film)."""
    off, on = _tcr(5000.0, "none"), _tcr(5000.0, "meniscus")
    assert [p.index for p in off.heat_paths()] == [1]
    assert off.heat_path_resistance == pytest.approx(1.701, abs=1e-3)
    assert on.ball_path_without_film == pytest.approx(off.ball_path_without_film, rel=1e-12)
    lifted = {p.index: p for p in on.heat_paths()}[2]
    assert math.isinf(lifted.ball_path_without_film) and lifted.ball_path_with_film < math.inf


@pytest.mark.parametrize("film_path", ["none", "meniscus"])
def test_summary_and_report_name_the_headline(film_path: str) -> None:
    """The summary and the report say which number is the headline and why the film path
    leaves it unchanged; the report's screw table carries the ball path(s)."""
    result = _tcr(0.0, film_path)
    assert result.summary()["headline"] == HEADLINE
    assert "tcr.film_path leaves R unchanged" in HEADLINE
    first = result.report()[0]
    assert HEADLINE in first.paragraphs
    labels = [row[0] for row in first.tables[0].rows]
    assert "ball path without film, micro + constriction [K/W]" in labels
    assert ("ball path with film [K/W]" in labels) == (film_path == "meniscus")


@pytest.mark.parametrize("film_path", ["none", "meniscus"])
def test_sweep_scalars_carry_the_ball_paths(film_path: str) -> None:
    """tcr_scalars give the path without film and the thermal model's path in both modes,
    the path with film only with films."""
    case = _tcr(0.0, film_path).case
    scalars = tcr_scalars(case)
    assert scalars["ball_path_without_film"][0] == pytest.approx(0.5 * (MICRO + CONSTRICTION))
    assert ("ball_path_with_film" in scalars) == (film_path == "meniscus")
    assert math.isfinite(scalars["heat_path_resistance"][0])
