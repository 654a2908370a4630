"""The default headline TCR has no cell size: CMY integrated over the pressure field (theory
manual: *Which model is the headline*). It converges with the solver grid, ignores
``tcr.cell_size``, and the paper's cell model stays available as ``tcr.headline = "V2"``."""

from __future__ import annotations

import warnings
from functools import cache

import numpy as np
import pytest

import ballscrew
from ballscrew import load_case
from ballscrew.errors import InputError

V2_CELLS_R = 0.0194763643439291
"""R of the example with the paper's V2 on 8 µm cells (64 cells across) [K/W]: the default
before the headline became CMY."""


@cache
def _result(case_path: str, **overrides: object) -> ballscrew.ScrewTCR:
    case = load_case(case_path, {"tcr.models": ["CMY"], **overrides})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ballscrew.screw_tcr(case)


def test_default_headline_is_cmy(gao_case_path):
    result = _result(str(gao_case_path))
    assert result.headline == "CMY"
    assert result.resistance == result.models["CMY"].resistance
    assert result.resistance_per_area == pytest.approx(1.4443e-6, rel=1e-4)
    spread = result.uncertainty
    assert spread is None  # one model asked for (tcr.models = ["CMY"])
    model = result.models["CMY"]
    assert {type(model.resistance), type(model.resistance_per_area)} == {float}  # not NumPy's


def test_default_converges_with_the_solver_grid(gao_case_path):
    """R″ between successive doublings of the solver grid: each change below 5 % and shrinking
    (24 → 48 → 96 cells across: −0.97 %, −0.39 %); 64 → 128 moves it by 0.35 %."""
    r2 = [
        _result(str(gao_case_path), **{"numerics.cells_across": n}).resistance_per_area
        for n in (24, 48, 96)
    ]
    steps = np.abs(np.diff(r2)) / r2[:-1]
    assert np.all(steps < 0.05) and steps[1] < steps[0], steps
    fine = [
        _result(str(gao_case_path), **{"numerics.cells_across": n}).resistance_per_area
        for n in (64, 128)
    ]
    assert fine[1] == pytest.approx(fine[0], rel=0.01)


@pytest.mark.parametrize(
    "cells",
    [{"tcr.cell_size": 4e-6}, {"tcr.cell_size": 16e-6}, {"tcr.rebin": False}],
    ids=["4um", "16um", "solver-grid"],
)
def test_default_does_not_depend_on_the_cell_size(gao_case_path, cells):
    """The cell model follows Δ_f (R″ ∝ Δ_f^0.53); the default headline does not move at all."""
    base = _result(str(gao_case_path))
    other = _result(str(gao_case_path), **cells)
    assert other.resistance_per_area == pytest.approx(base.resistance_per_area, rel=1e-12)
    assert other.resistance == pytest.approx(base.resistance, rel=1e-12)


def test_the_paper_cell_model_is_the_option(gao_case_path):
    """``tcr.headline = "V2"`` (and ``variant="V2"``) give the paper's cell model exactly, with its
    cell-size dependence; its R is a tenth of CMY's on this screw."""
    cells = _result(str(gao_case_path), **{"tcr.headline": "V2"})
    assert cells.headline == "V2" and cells.cell_size == 8e-6
    assert cells.resistance == pytest.approx(V2_CELLS_R, rel=1e-12)
    case = load_case(gao_case_path, {"tcr.models": ["CMY"]})
    assert ballscrew.screw_tcr(case, variant="V2").resistance == pytest.approx(
        V2_CELLS_R, rel=1e-12
    )
    coarse = _result(str(gao_case_path), **{"tcr.headline": "V2", "tcr.cell_size": 16e-6})
    assert coarse.resistance / cells.resistance > 1.3
    assert _result(str(gao_case_path)).resistance / cells.resistance == pytest.approx(
        10.57, rel=0.01
    )


def test_patch_headline_is_cell_free(gao_case_path):
    """``V2/patch``: the MB population of the whole patch, one element per contact, the same R
    for any Δ_f."""
    a = _result(str(gao_case_path), **{"tcr.headline": "V2/patch"})
    b = _result(str(gao_case_path), **{"tcr.headline": "V2/patch", "tcr.cell_size": 4e-6})
    assert a.cell_size is None and a.nuts[0].screw.tcr.loaded_cells == 1
    assert a.resistance == pytest.approx(b.resistance, rel=1e-12)
    assert a.resistance == pytest.approx(a.models["V2/patch"].resistance, rel=1e-12)


def test_a_correlation_headline_beyond_its_range_is_refused(gao_case_path):
    """Soft raceways reach p/H ≥ 0.5 where CMY's Gaussian surfaces touch everywhere: the
    default headline is refused naming the key; a fractal headline still runs."""
    soft = {"materials.screw.hardness": 1.5e9, "materials.nut.hardness": 1.5e9}
    case = load_case(gao_case_path, soft)
    with pytest.raises(InputError, match=r"^tcr\.headline = 'CMY' is not allowed: .*p/H = 0\.6"):
        ballscrew.screw_tcr(case)
    patch = load_case(gao_case_path, {**soft, "tcr.headline": "V2/patch"})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert np.isfinite(ballscrew.screw_tcr(patch).resistance)


def test_summary_and_report_name_the_headline_model(gao_case_path):
    result = _result(str(gao_case_path))
    summary = result.summary()
    assert summary["headline_model"] == summary["options"]["headline"] == "CMY"
    note = summary["headline_model_note"]
    assert "no fractal cell size" in note and "the paper's option" in note
    assert note in result.report()[0].paragraphs
    cells = _result(str(gao_case_path), **{"tcr.headline": "V2"}).summary()
    assert "8 µm cells: it follows the cell size" in cells["headline_model_note"]


def test_report_marks_the_headline_among_the_rival_models(gao_case_path):
    """The side-by-side table of the report: every model once, the headline marked, and the
    spread stated with its factor."""
    case = load_case(gao_case_path, {"numerics.cells_across": 16})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = ballscrew.screw_tcr(case)
    [section] = [s for s in result.report() if s.title.startswith("Rival models")]
    names = [row[0] for row in section.tables[0].rows]
    assert names == [f"{n} (headline)" if n == "CMY" else n for n in result.models]
    spread = result.uncertainty
    assert f"a factor {spread.ratio:.3g}" in section.paragraphs[0]
    assert spread.low <= result.resistance_per_area <= spread.high


def test_bad_headline_is_a_case_error(gao_case_path):
    with pytest.raises(ballscrew.case.CaseError, match=r"tcr\.headline.*V2/patch"):
        load_case(gao_case_path, {"tcr.headline": "Holm"})


@pytest.mark.parametrize(
    ("options", "line"),
    [
        ((), "  headline model: CMY, no fractal cell size (the paper's cell model: --variant V2"),
        (("--variant", "V2"), "  headline model: V2 on 8 µm fractal cells, the paper's cell"),
    ],
    ids=["default", "paper"],
)
def test_console_names_the_headline_model(tmp_path, gao_case_path, options, line):
    """``ballscrew tcr`` says which model its numbers are, before them, and how to get the
    paper's cell model; ``-q`` prints only the folder."""
    from typer.testing import CliRunner

    from ballscrew.cli import app

    out = tmp_path / "tcr"
    args = ["tcr", str(gao_case_path), "--out", str(out), "--set", "numerics.cells_across=16"]
    result = CliRunner().invoke(app, [*args, *options])
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines[0].startswith(line), lines
    assert lines[1].startswith("  resistance ") and lines[-1] == f"results: {out.resolve()}"
    quiet = CliRunner().invoke(app, [*args, "--force", "-q", *options])
    assert quiet.output.strip() == f"results: {out.resolve()}"


def test_patch_headline_figures_draw_the_one_element_without_warnings(gao_case_path, tmp_path):
    """A patch headline's element map is one element over the whole grid: it is drawn over the
    grid's extent with no matplotlib warning (a 1 × 1 map once gave a singular axis)."""
    from ballscrew.analyses import tcr_report

    result = _result(str(gao_case_path), **{"tcr.headline": "V2/patch"})
    figure = next(f for f in tcr_report.figures(result) if f.name == "tcr_nut1_screw")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        path = figure.draw(tmp_path / "map.png")
    assert path.is_file()
