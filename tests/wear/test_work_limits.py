"""Runaway wear runs: the step count is estimated before starting and guarded while running."""

from __future__ import annotations

import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from ballscrew import budget
from ballscrew.analyses.wear import wear_life, wear_options
from ballscrew.case import CaseError, case_from_dict, with_overrides
from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.wear import life

from .conftest import REF_PATH

runner = CliRunner()

RUNAWAY = [
    ({"coefficient": 10.0}, "wear.max_depth_step"),
    ({"coefficient": 1e300}, "wear.max_depth_step"),
    ({"max_depth_step": 1e-15}, "wear.max_depth_step"),
    ({"stroke": 1e-9}, "wear.max_depth_step"),
    ({"torque_sampling": 1e-3}, "wear.torque_sampling"),
]


def unchecked(case, **wear):
    """``case`` with ``[wear]`` values the case file refuses (no validation): the guard's input."""
    return case.model_copy(update={"wear": case.wear.model_copy(update=wear)})


@pytest.mark.parametrize(("wear", "field"), RUNAWAY)
def test_the_case_file_refuses_runaway_values(ref_case, wear, field):
    key, value = next(iter(wear.items()))
    with pytest.raises(CaseError, match=rf"^{ref_case.name}: wear.{key} = "):
        with_overrides(ref_case, {f"wear.{key}": value})


@pytest.mark.parametrize(("wear", "field"), RUNAWAY)
def test_runaway_inputs_end_quickly_with_one_line(ref_case, tmp_path, wear, field):
    """The run's own guard, whatever the case ranges let through."""
    checkpoint = tmp_path / "wear.npz"
    start = time.perf_counter()
    with pytest.raises(InputError) as info:
        wear_life(unchecked(ref_case, **wear), checkpoint=checkpoint)
    assert time.perf_counter() - start < 5.0
    message = str(info.value)
    assert message.startswith(f"{field} = ") and "\n" not in message
    assert "time steps of the wear run" in message and "more than the limit of 1000000" in message
    assert not checkpoint.exists()


def test_infinite_revolutions_refused(ref_case):
    raw = ref_case.model_dump()
    raw["wear"]["programme"][1]["revolutions"] = float("inf")
    with pytest.raises(CaseError, match=r"wear.programme.1.revolutions = inf"):
        case_from_dict(raw)
    programme = list(ref_case.wear.programme)
    programme[1] = programme[1].model_copy(update={"revolutions": float("inf")})
    start = time.perf_counter()
    with pytest.raises(InputError, match=r"^wear.programme\[1\].revolutions = inf"):
        wear_life(unchecked(ref_case, programme=programme))
    assert time.perf_counter() - start < 5.0


def test_step_limit_is_configurable(ref_case, monkeypatch):
    monkeypatch.setenv(budget.STEPS_ENV, "10")
    with pytest.raises(InputError, match=r"^wear.torque_sampling = .*about 33.*limit of 10"):
        wear_life(ref_case)


def test_guard_stops_a_run_that_outgrows_its_estimate(ref_case, monkeypatch):
    """Steps already taken count: a run past the limit stops with an error, not silently."""
    monkeypatch.setenv(budget.STEPS_ENV, "1000")
    with pytest.raises(InputError, match=r"\(1000 taken, .*more than the limit of 1000"):
        life.check_wear_work(wear_options(ref_case), 1000, 1.0e5, 0)


def test_guard_refuses_non_finite_rates(ref_case):
    import numpy as np

    rates = np.full((2, 8), np.nan)
    with pytest.raises(InputError, match=r"^wear.max_depth_step = .*depth-limited at inf"):
        life.check_wear_work(wear_options(ref_case), 3, 1.0e5, 0, rates)


def test_cli_refuses_and_writes_nothing(tmp_path: Path):
    text = REF_PATH.read_text()
    assert 'max_depth_step = "0.1 um"' in text
    case = tmp_path / "case.toml"
    case.write_text(text.replace('max_depth_step = "0.1 um"', "max_depth_step = 1e-15", 1))
    out = tmp_path / "out"
    result = runner.invoke(app, ["wear", str(case), "--out", str(out)])
    assert result.exit_code == 2, result.output
    assert result.output.startswith("error: ") and result.output.count("\n") == 1
    assert "wear.max_depth_step = 1e-15 is not allowed" in result.output
    assert not out.exists()
    assert list(tmp_path.iterdir()) == [case]
