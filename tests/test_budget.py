"""Resource budgets: memory and work are estimated and refused before anything is allocated."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import ballscrew as bs
from ballscrew import budget
from ballscrew.analyses.ball_contact import solve_ball_contacts
from ballscrew.budget import BudgetError, check_memory, format_bytes, memory_budget, parse_bytes
from ballscrew.case import with_overrides
from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.sweep.axes import SweepAxis
from ballscrew.sweep.spec import check_sweep_size

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
runner = CliRunner()


def _unreachable(*args, **kwargs):
    raise AssertionError("allocation reached: the budget check must come first")


@pytest.fixture(autouse=True)
def fixed_budget(monkeypatch):
    """A fixed 2 GiB budget, whatever the machine has."""
    monkeypatch.setenv(budget.MEMORY_ENV, "2 GiB")


@pytest.fixture(scope="module")
def gao():
    return bs.load_case(EXAMPLES / "gao2019_tcr.toml")


@pytest.mark.parametrize(
    ("text", "size"),
    [("4 GiB", 4 * 2**30), ("500 MB", 500 * 10**6), ("123456", 123456), ("1.5e3 kB", 1_500_000)],
)
def test_parse_bytes(text, size):
    assert parse_bytes(text) == size


@pytest.mark.parametrize("text", ["9**9**9", "4 parsecs", "-1 GiB", "0", "GiB", "1e999 B"])
def test_a_bad_budget_is_refused(monkeypatch, text):
    monkeypatch.setenv(budget.MEMORY_ENV, text)
    with pytest.raises(InputError, match=budget.MEMORY_ENV):
        memory_budget()


def test_default_budget_is_a_share_of_the_physical_memory(monkeypatch):
    monkeypatch.delenv(budget.MEMORY_ENV)
    ram = budget._physical_memory()
    assert memory_budget() == int(budget.RAM_SHARE * ram)
    monkeypatch.setattr(budget.os, "sysconf", _unreachable_sysconf)
    assert memory_budget() == int(budget.RAM_SHARE * budget.FALLBACK_RAM)


def _unreachable_sysconf(name):
    raise ValueError(name)


def test_refusal_names_field_estimate_and_limit():
    with pytest.raises(BudgetError) as info:
        check_memory("numerics.cells", [8192, 8192], 13 * 2**30, "the grid")
    message = str(info.value)
    assert message.startswith("numerics.cells = [8192, 8192] is not allowed")
    assert "13 GiB" in message and "2 GiB" in message and budget.MEMORY_ENV in message
    assert format_bytes(1.1 * 2**40) == "1.1 TiB"


@pytest.mark.parametrize(
    ("overrides", "field"),
    [
        ({"numerics.cells": [8192, 8192]}, "numerics.cells"),
        ({"numerics.cells_across": 4096}, "numerics.cells_across"),
    ],
)
def test_contact_grid_refused_before_allocation(monkeypatch, gao, overrides, field):
    from ballscrew.contact import grid

    monkeypatch.setattr(grid, "cell_centres", _unreachable)
    start = time.perf_counter()
    with pytest.raises(BudgetError, match=rf"^{field} = .* GiB of memory, more than the budget"):
        solve_ball_contacts(with_overrides(gao, overrides))
    assert time.perf_counter() - start < 2.0


def test_tcr_rebinning_refused_before_allocation(monkeypatch):
    from ballscrew.contact_resistance import aggregation

    monkeypatch.setattr(aggregation, "_overlap_weights", _unreachable)
    pressure = np.ones((128, 128))
    with pytest.raises(BudgetError, match=r"^tcr.cell_size = 1e-09 .* TiB of memory"):
        aggregation.rebin_forces(pressure, 1e-5, 1e-5, 1e-9)


def test_wear_grid_refused_before_allocation(monkeypatch):
    from ballscrew.analyses import wear

    monkeypatch.setattr(wear, "gap_function", _unreachable)
    case = bs.load_case(EXAMPLES / "wear_step_stress.toml", {"wear.grid": [1024, 4096]})
    start = time.perf_counter()
    with pytest.raises(BudgetError, match=r"^wear.grid = \[1024, 4096\] .*BALLSCREW_MAX_WORK"):
        wear.wear_life(case)
    monkeypatch.setenv(budget.MEMORY_ENV, "1 GiB")
    with pytest.raises(BudgetError, match=r"^wear.grid = .*1024 × 4096 wear grid needs about"):
        wear.wear_life(case)
    assert time.perf_counter() - start < 3.0


@pytest.fixture(scope="module")
def thermal_case(gao):
    fast = {"thermal.mesh.size": "5 mm", "thermal.transient.time_step": "300 s"}
    case = with_overrides(gao, fast)
    return case, bs.screw_tcr(case, variant=None)


@pytest.mark.parametrize(
    ("model", "overrides", "builder"),
    [
        ("axisymmetric", {"thermal.mesh.size": "10 um"}, "build_axisymmetric"),
        ("3d", {"thermal.mesh.size_3d": "20 um"}, "build_threed"),
        ("network", {"thermal.mesh.network_cell": "1 nm"}, "build_network"),
    ],
)
def test_fine_thermal_mesh_refused_before_meshing(
    monkeypatch, thermal_case, model, overrides, builder
):
    import importlib

    module = {"build_axisymmetric": "axisymmetric", "build_threed": "threed"}.get(
        builder, "network"
    )
    monkeypatch.setattr(
        importlib.import_module(f"ballscrew.thermal.{module}"), builder, _unreachable
    )
    case, tcr = thermal_case
    field = next(iter(overrides))
    with pytest.raises(BudgetError, match=rf"^{field} = .* unknowns needs about"):
        bs.thermal_field(with_overrides(case, overrides), model, tcr=tcr)


def test_billion_time_steps_refused_before_any_work(monkeypatch, thermal_case):
    from ballscrew.analyses import thermal as field

    monkeypatch.setattr(field, "build_problem", _unreachable)
    case, tcr = thermal_case
    case = with_overrides(case, {"thermal.transient.time_step": 5400 / 1e9})
    with pytest.raises(BudgetError, match=r"^thermal.transient.time_step = .* about 1e\+09"):
        bs.thermal_field(case, tcr=tcr)


def test_transient_history_memory_refused(monkeypatch, thermal_case):
    import importlib

    simulate = importlib.import_module("ballscrew.thermal.simulate")
    case, tcr = thermal_case
    monkeypatch.setenv(budget.STEPS_ENV, str(10**7))
    monkeypatch.setenv(budget.MEMORY_ENV, "100 MiB")
    monkeypatch.setattr(simulate, "implicit_euler", _unreachable)
    case = with_overrides(case, {"thermal.transient.time_step": 5400 / 5e6})
    with pytest.raises(BudgetError, match=r"^thermal.transient.time_step = .*history of 5e\+06"):
        # the point's own transient: the [[duty]] cycle's 2.7e7 steps are refused first
        bs.thermal_field(case, "network", tcr=tcr, duty=False)


def test_sweep_of_millions_of_points_refused():
    axes = (
        SweepAxis("surface.D", tuple(np.linspace(1.4, 1.7, 5000))),
        SweepAxis("surface.G", tuple(np.linspace(1e-10, 2e-10, 4000))),
    )
    with pytest.raises(BudgetError, match=r"^--vary = '5000 \(surface.D\) × 4000 .*2e\+07"):
        check_sweep_size(axes)


def test_cli_refuses_and_writes_nothing(tmp_path, gao):
    case = tmp_path / "case.toml"
    case.write_text((EXAMPLES / "gao2019_tcr.toml").read_text())
    runs = [
        ["contact", str(case)],
        [
            "sweep",
            str(case),
            "--vary",
            "surface.D=1.4:1.7:5000",
            "--vary",
            "surface.G=1e-10:2e-10:4000",
        ],
    ]
    text = case.read_text()
    assert "[numerics]\n" in text
    case.write_text(text.replace("[numerics]\n", "[numerics]\ncells = [8192, 8192]\n", 1))
    for args in runs:
        out = tmp_path / "out"
        result = runner.invoke(app, [*args, "--out", str(out)])
        assert result.exit_code == 2, result.output
        assert result.output.startswith("error: ")
        assert "budget" in result.output or "limit" in result.output
        assert not out.exists()


def test_contact_batch_counts_its_window_check(monkeypatch):
    """A batch of 32 contacts on 1024² grids: the budget between the solves' own memory (the old
    estimate) and that plus the window check's run refuses it, naming the field, both in
    :func:`check_memory` and in the batched solver itself."""
    from ballscrew.budget import CHECK_BYTES_PER_CELL, contact_batch_bytes, contact_grid_bytes

    cells = 1024 * 1024
    solves = 32 * contact_grid_bytes(1024, 1024)
    estimate = contact_batch_bytes(32, 1024, 1024)
    assert estimate == solves + CHECK_BYTES_PER_CELL * cells  # one contact's check at a time
    monkeypatch.setenv(budget.MEMORY_ENV, str(int(solves + 0.5 * (estimate - solves))))
    check_memory("numerics.cells", [1024, 1024], solves, "old estimate")
    refused = r"^numerics.cells = \[1024, 1024\] .* 32 contacts needs .* more than the"
    with pytest.raises(BudgetError, match=refused):
        check_memory("numerics.cells", [1024, 1024], estimate, "32 contacts")
    # the batched solver counts it too: refused before any work (a broadcast view holds no cells)
    gaps = np.broadcast_to(np.full((1, 1, 1), 1e-6), (32, 1024, 1024))
    with pytest.raises(
        BudgetError,
        match=r"^gaps = 'array of shape \(32, 1024, 1024\)' .* 32 normal .* more than the budget",
    ):
        bs.contact.solve_normal_batch(gaps, 1e-6, 1e-6, 1e11, 1.0)
