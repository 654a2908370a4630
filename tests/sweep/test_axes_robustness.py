"""``--vary`` axes: repeated keys refused before any work, values with units, bad values."""

from __future__ import annotations

import math
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from ballscrew.case import CaseError, load_case
from ballscrew.cli import app
from ballscrew.sweep import grid_points, parse_axis, run_sweep
from ballscrew.sweep.axes import MAX_AXIS_POINTS


def _never_called(case):  # pragma: no cover - the sweep must stop before any point runs
    raise AssertionError("a point ran")


def test_a_key_varied_twice_is_refused_before_any_point_runs(
    gao_case_path: Path, tmp_path: Path
) -> None:
    axes = [parse_axis("surface.D=1.4,1.5"), parse_axis("surface.D=1.6,1.7")]
    with pytest.raises(CaseError, match=r"surface\.D: the key is varied twice"):
        grid_points(axes)
    with pytest.raises(CaseError, match="varied twice"):
        run_sweep(load_case(gao_case_path), axes, _never_called, "tcr", tmp_path)
    assert not (tmp_path / "points").exists()


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "operating.speed=1500 rpm:3000 rpm:4",
            [n * math.pi / 30 for n in (1500, 2000, 2500, 3000)],
        ),
        ("operating.speed=10 Hz,20", [20 * math.pi, 20.0]),
        ("operating.axial_load=1 kN, 2.5 kN", [1000.0, 2500.0]),
        ("surface.G=1 nm:3 nm:3", [1e-9, 2e-9, 3e-9]),
        ("surface.D=1.4:1.6:3", [1.4, 1.5, 1.6]),
    ],
)
def test_axis_values_may_carry_units(text: str, expected: list[float]) -> None:
    assert parse_axis(text).values == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    "text",
    [
        "screw.lead=9**9**9 mm:1:2",
        "screw.lead=10**400 mm,1",
        "surface.D=1.4:nan:3",
        "surface.D=inf,1.5",
        "screw.lead=1 %:2 %:2",
        "operating.speed=1 m/s,2",
        f"surface.D=1.4:1.6:{MAX_AXIS_POINTS + 1}",
        "surface.D=1.4:1.6:1e9",
    ],
)
def test_bad_axis_values_are_refused_at_once(text: str) -> None:
    start = time.perf_counter()
    with pytest.raises(CaseError, match="--vary"):
        parse_axis(text)
    assert time.perf_counter() - start < 0.5


def test_the_sweep_command_refuses_a_repeated_vary_key(gao_case_path: Path, tmp_path: Path):
    vary = ["--vary", "surface.D=1.4,1.5", "--vary", "surface.D=1.5,1.6"]
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["sweep", str(gao_case_path), *vary, "--out", str(out)])
    assert result.exit_code == 2
    assert "surface.D: the key is varied twice" in result.output
    assert not (out / "points").exists()
