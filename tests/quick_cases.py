"""Helpers of the API/CLI parity, example and README tests: case files with quick numerics."""

from __future__ import annotations

import json
import math
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from typer.testing import CliRunner

from ballscrew.case import Case
from ballscrew.case.loader import apply_overrides
from ballscrew.cli import app

REPO = Path(__file__).resolve().parents[1]
EXAMPLES = REPO / "examples"
SPEED_100_RPM = 100.0 * math.pi / 30.0

#: Quick numerics for every analysis of a case: coarse contact grids, a short transient.
QUICK: dict[str, Any] = {
    "numerics.cells_across": 16,
    "thermal.transient.duration": "10 min",
    "thermal.mesh.size": "10 mm",
    "kinematics.speed_points": 3,
}

#: Quick wear: a coarse grid and two short levels.
QUICK_WEAR: dict[str, Any] = {
    "wear.grid": [12, 48],
    "wear.torque_sampling": 2.5e4,
    "wear.programme": [
        {"axial_load": 2000.0, "speed": SPEED_100_RPM, "revolutions": 5.0e4},
        {"axial_load": 4000.0, "speed": SPEED_100_RPM, "revolutions": 5.0e4},
    ],
}


def _toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, int | float):
        return repr(value)
    if isinstance(value, Mapping):
        return (
            "{" + ", ".join(f"{json.dumps(k)} = {_toml_value(v)}" for k, v in value.items()) + "}"
        )
    return "[" + ", ".join(_toml_value(v) for v in value) + "]"


def dump_toml(data: Mapping[str, Any]) -> str:
    """TOML text of nested dicts and lists (every table inline: enough for a case file)."""
    return "".join(f"{json.dumps(key)} = {_toml_value(value)}\n" for key, value in data.items())


def write_case(folder: Path, example: str, overrides: Mapping[str, Any]) -> Path:
    """``examples/<example>`` with dotted-key ``overrides`` applied, written to ``folder``."""
    source = EXAMPLES / example
    raw = tomllib.loads(source.read_text(encoding="utf-8"))
    path = folder / f"{source.stem}_edited.toml"
    path.write_text(dump_toml(apply_overrides(raw, overrides, str(source))), encoding="utf-8")
    return path


def run_cli(*args: object) -> dict[str, Any]:
    """Run ``ballscrew ARGS`` in-process; it must succeed. Returns its ``summary.json``."""
    argv = [str(a) for a in args]
    result = CliRunner().invoke(app, argv)
    assert result.exit_code == 0, f"ballscrew {' '.join(argv)}:\n{result.output}"
    out = Path(argv[argv.index("--out") + 1])
    return json.loads((out / "summary.json").read_text(encoding="utf-8"))


def quick_overrides(case: Case) -> dict[str, Any]:
    """:data:`QUICK` (and :data:`QUICK_WEAR`) for the sections ``case`` has."""
    quick = {k: v for k, v in QUICK.items() if case.thermal is not None or "thermal." not in k}
    return quick | (QUICK_WEAR if case.wear is not None else {})
