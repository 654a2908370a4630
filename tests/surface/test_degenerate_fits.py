"""Degenerate profiles and undetermined fits are refused, never reported as a fractal."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.surface import fit as fit_module
from ballscrew.surface import fractal_parameters, weierstrass_mandelbrot_profile
from ballscrew.surface.fit import fit_power_spectrum, fit_structure_function

runner = CliRunner()
N = 2048
DX = 1e-6
FLAT = {
    "constant": np.full(N, 3e-6),
    "zero": np.zeros(N),
    "ramp": np.linspace(0.0, 1e-6, N),
    "rounding noise": 3e-6 + 1e-20 * np.random.default_rng(0).standard_normal(N),
    "constant rows": np.full((4, N), -2e-6),
}


@pytest.mark.parametrize("fit", [fractal_parameters, fit_power_spectrum, fit_structure_function])
@pytest.mark.parametrize("heights", FLAT.values(), ids=FLAT.keys())
def test_flat_profile_refused(fit, heights):
    with pytest.raises(InputError, match=r"^heights = 'a profile with no height variation"):
        fit(heights, DX)


@pytest.mark.parametrize(
    ("heights", "message"),
    [(np.ones(8), "at least 16 points"), (np.full(N, np.nan), "at least one complete profile")],
    ids=["too short", "not finite"],
)
def test_short_or_non_finite_profile_refused(heights, message):
    with pytest.raises(InputError, match=message):
        fractal_parameters(heights, DX)


@pytest.fixture(scope="module")
def wm():
    return weierstrass_mandelbrot_profile(1.5, 1e-10, 2**13 * DX, DX, seed=5)


def test_implausible_g_refused(monkeypatch, wm):
    monkeypatch.setattr(fit_module, "PLAUSIBLE_G", (1e-3, 1e-2))
    with pytest.raises(InputError, match=r"no fractal fit.*PSD fit gives G = .* outside the"):
        fractal_parameters(wm.heights, DX)


def test_undetermined_dimension_is_no_fit():
    notes: list[str] = []
    assert not fit_module._determined(1.5, 1e-10, notes, "PSD", D_se=0.6)
    assert notes == ["PSD fit undetermined: D = 1.5 ± 0.6, an uncertainty larger than D − 1"]
    assert fit_module._determined(1.5, 1e-10, [], "PSD", D_se=0.05)


def test_cli_refuses_a_constant_profile_and_writes_nothing(tmp_path: Path):
    src = tmp_path / "flat.txt"
    src.write_text("\n".join("3e-6" for _ in range(N)))
    out = tmp_path / "out"
    result = runner.invoke(app, ["surface", str(src), "--out", str(out), "--spacing", "1 um"])
    assert result.exit_code == 2, result.output
    assert result.output.startswith("error: heights = 'a profile with no height variation")
    assert not out.exists()
