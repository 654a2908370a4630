"""Malformed sweep files end in one line naming the key, never a traceback."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from ballscrew.case import CaseError
from ballscrew.cli import app
from ballscrew.sweep.spec import is_sweep_file, load_sweep

VARY = 'vary = ["surface.D=1.4:1.5:2"]'


def sweep_file(tmp_path: Path, gao_case_path: Path, body: str) -> Path:
    shutil.copy(gao_case_path, tmp_path / "case.toml")
    path = tmp_path / "sweep.toml"
    path.write_text(body + "\n")
    return path


@pytest.mark.parametrize(
    ("body", "named"),
    [
        ("sweep = 5", "sweep = 5"),
        ('sweep = ["case.toml"]', "sweep = ["),
        ("[sweep]\ncase = 5", "sweep.case = 5"),
        ('[sweep]\ncase = ["case.toml"]', "sweep.case = ["),
        (f'[sweep]\ncase = "case.toml"\nset = [1, 2]\n{VARY}', "sweep.set = [1, 2]"),
        ('[sweep]\ncase = "case.toml"\nset = "surface.D=1.5"', "sweep.set = "),
        ('[sweep]\ncase = "case.toml"\nvary = [1, 2]', "sweep.vary item 1"),
        ('[sweep]\ncase = "case.toml"\nvary = "surface.D=1:2:3"', "sweep.vary = "),
        (f'[sweep]\ncase = "case.toml"\nanalysis = 5\n{VARY}', "sweep.analysis = 5"),
        (f'[sweep]\ncase = "case.toml"\nanalysis = "nope"\n{VARY}', "sweep.analysis = 'nope'"),
        (f'[sweep]\ncase = "case.toml"\ndescription = []\n{VARY}', "sweep.description"),
        (
            '[sweep]\ncase = "case.toml"\nvary = ["surface.D=1.4:1.5:2", "surface.D=1,2"]',
            "surface.D is swept twice",
        ),
    ],
)
def test_malformed_sweep_file_names_the_key(tmp_path, gao_case_path, body, named):
    path = sweep_file(tmp_path, gao_case_path, body)
    with pytest.raises(CaseError) as info:
        load_sweep(path)
    assert named in str(info.value)
    assert "\n" not in str(info.value)
    result = CliRunner().invoke(app, ["sweep", str(path), "--out", str(tmp_path / "out")])
    assert result.exit_code == 2, result.output
    assert named in result.output
    assert "Traceback" not in result.output
    assert not (tmp_path / "out").exists()


def test_nested_set_table_is_read_as_dotted_keys(tmp_path, gao_case_path):
    body = f'[sweep]\ncase = "case.toml"\n{VARY}\n[sweep.set]\nsurface.G = "0.2 nm"'
    spec = load_sweep(sweep_file(tmp_path, gao_case_path, body))
    assert spec.fixed == {"surface.G": "0.2 nm"}
    assert spec.case.surface.G == pytest.approx(2e-10)


def test_sweep_file_that_is_not_utf8_is_one_line(tmp_path):
    path = tmp_path / "sweep.toml"
    path.write_bytes('[sweep]\ncase = "é.toml"\n'.encode("utf-16"))
    assert not is_sweep_file(path)
    with pytest.raises(CaseError, match="save it as UTF-8"):
        load_sweep(path)
