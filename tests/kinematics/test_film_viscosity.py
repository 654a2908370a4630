"""The viscosity of the kinematics' film is reported with where it comes from, so the film of
``ballscrew kinematics`` and of ``ballscrew operating-point`` can be told apart: a named oil is
taken at ``[lubrication] temperature`` unless ``[operating] coupled = true``, and then the two
commands give one film."""

from __future__ import annotations

import math

import pytest
from typer.testing import CliRunner

import ballscrew
from ballscrew.analyses.kinematics import run_kinematics
from ballscrew.case.loader import with_overrides
from ballscrew.cli import app

SHEET = ["--d0", "32", "--lead", "5", "--ball", "3.175", "--turns", "2.5x2", "--nuts", "1"]
POINT = {"operating.speed": 2000 * math.pi / 30, "operating.axial_load": 1500.0}


@pytest.fixture(scope="module")
def single_nut(tmp_path_factory) -> ballscrew.case.Case:
    """A 32 x 5 four-point single nut of ``ballscrew init`` (ISO VG 68 named), 2000 rpm, 1.5 kN."""
    result = CliRunner().invoke(app, ["init", *SHEET])
    assert result.exit_code == 0, result.output
    path = tmp_path_factory.mktemp("case") / "single.toml"
    path.write_text(result.stdout.replace("cells_across = 32", "cells_across = 16"))
    return ballscrew.load_case(path, POINT)


def test_a_named_oil_is_taken_at_the_lubrication_temperature(single_nut) -> None:
    run = run_kinematics(single_nut)
    # ISO VG 68 at 40 °C, the default: ν40 = 68 mm²/s, ρ ≈ 880 kg/m³ at 15 °C less ~1.5 %
    assert run.viscosity == pytest.approx(68e-6 * 866.0, rel=0.01)
    assert "at [lubrication] temperature = 40 °C" in run.viscosity_source
    summary = run.summary()
    assert summary["viscosity"] == {"value": run.viscosity, "unit": "Pa*s"}
    assert summary["viscosity_source"] == run.viscosity_source


def test_coupled_kinematics_give_the_film_of_the_operating_point(single_nut) -> None:
    point = ballscrew.operating_point(single_nut)
    run = run_kinematics(with_overrides(single_nut, {"operating.coupled": True}))
    assert run.viscosity == pytest.approx(point.viscosity, rel=1e-9)
    assert run.films[0].central == pytest.approx(point.film_thickness, rel=1e-9)
    assert "contact temperature of the coupled operating point" in run.viscosity_source
    assert point.viscosity > 2 * run_kinematics(single_nut).viscosity  # 25 °C, not 40 °C
