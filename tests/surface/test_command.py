"""``ballscrew surface`` as a user runs it (registered here; cli.py wires it for the package)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import typer
from typer.testing import CliRunner

from ballscrew.commands.surface import surface
from ballscrew.surface import weierstrass_mandelbrot_profile, write_sdf

app = typer.Typer()
app.command()(surface)
app.command(name="noop")(lambda: None)  # a second command keeps the subcommand name
runner = CliRunner()


def test_surface_writes_summary_plots_and_report(tmp_path: Path) -> None:
    D, G = 1.59, 9e-10
    p = weierstrass_mandelbrot_profile(D, G, 2**13 * 0.5e-6, 0.5e-6, seed=5, profiles=8)
    src = write_sdf(tmp_path / "raceway.sdf", p)
    out = tmp_path / "out"
    result = runner.invoke(app, ["surface", str(src), "--out", str(out)])
    assert result.exit_code == 0, result.output
    names = {f.name for f in out.iterdir()}
    assert {"summary.json", "report.html", "psd.png", "structure_function.png"} <= names
    summary = json.loads((out / "summary.json").read_text())
    assert summary["recommended"]["method"] == "psd"
    assert summary["recommended"]["D"] == pytest.approx(D, rel=0.02)
    assert summary["recommended"]["G"] == {"value": pytest.approx(G, rel=0.1), "unit": "m"}
    psd = summary["methods"]["psd"]
    assert psd["fit_range"]["min"]["unit"] == "1/m"
    sf = summary["methods"]["structure_function"]
    assert sf["fit_range"]["max"]["unit"] == "m"
    assert sf["D"] == pytest.approx(D, rel=0.02)
    assert summary["profiles"] == 8
    assert "Fractal parameters" in (out / "report.html").read_text(encoding="utf-8")


def test_surface_result_follows_the_result_protocol(tmp_path: Path) -> None:
    from ballscrew.analyses.surface import surface_characterisation
    from ballscrew.results import write_results
    from protocol_check import assert_protocol_folder

    p = weierstrass_mandelbrot_profile(1.5, 1e-10, 2**11 * 1e-6, 1e-6, seed=5)
    src = write_sdf(tmp_path / "p.sdf", p)
    result = surface_characterisation(src, gamma=1.6, resolution=2e-6)
    folder = write_results(result, tmp_path / "out")
    summary = assert_protocol_folder(result, folder, case_file=False)
    assert summary["inputs"]["profile_file"] == str(src)
    assert summary["inputs"]["spacing"] == {"value": pytest.approx(1e-6), "unit": "m"}
    assert summary["inputs"]["resolution"] == {"value": 2e-6, "unit": "m"}
    assert summary["inputs"]["gamma"] == summary["gamma"] == 1.6
    assert summary["inputs"]["points_per_profile"] == 2**11
    assert "profile_file" in (folder / "report.html").read_text(encoding="utf-8")


def test_one_column_text_file_with_spacing_option(tmp_path: Path) -> None:
    p = weierstrass_mandelbrot_profile(1.5, 1e-10, 2**13 * 1e-6, 1e-6, seed=5)
    zonly = tmp_path / "z.txt"  # heights in m: a bare column carries no unit
    zonly.write_text("\n".join(repr(float(h)) for h in p.heights))
    result = runner.invoke(
        app, ["surface", str(zonly), "--out", str(tmp_path / "o"), "--spacing", "1 um"]
    )
    assert result.exit_code == 0, result.output
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["spacing"]["value"] == pytest.approx(1e-6)


def test_bad_file_is_exit_2_with_a_message(tmp_path: Path) -> None:
    bad = tmp_path / "bad.csv"
    bad.write_text("")
    result = runner.invoke(app, ["surface", str(bad), "--out", str(tmp_path / "o")])
    assert result.exit_code == 2
    assert "bad.csv" in result.output
    assert not (tmp_path / "o").exists()
