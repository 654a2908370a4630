"""Every file in ``examples/`` runs, with quick numerics, through the code it is an example of.

Files are found by glob: a new example without a runner below fails the test, naming the file.
"""

from __future__ import annotations

import fnmatch
import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.ball_contact import solve_ball_contacts
from ballscrew.analyses.kinematics import run_kinematics
from ballscrew.calibration import read_measured
from ballscrew.case import with_overrides
from ballscrew.surface import fractal_parameters, read_profile
from ballscrew.sweep.axes import SweepAxis, grid_points, validate_points
from ballscrew.sweep.registry import get_analysis
from ballscrew.sweep.runner import assemble, run_point
from ballscrew.sweep.spec import load_sweep
from quick_cases import EXAMPLES, quick_overrides


def finite(*numbers: float) -> bool:
    return all(math.isfinite(float(n)) for n in numbers)


def run_case(path: Path) -> None:
    """Every analysis the case has a section for: contact, TCR, kinematics, thermal, wear."""
    case = ballscrew.load_case(path)
    case = with_overrides(case, quick_overrides(case))
    contacts = solve_ball_contacts(case)
    assert finite(contacts.screw.solution.peak_pressure, contacts.nut.solution.peak_pressure)
    tcr = ballscrew.screw_tcr(case)
    assert tcr.resistance > 0 and tcr.variant == case.tcr.variant
    kinematics = run_kinematics(case)
    assert finite(kinematics.states[1].ball_speed, kinematics.model_torque)
    if case.thermal is not None:
        field = ballscrew.thermal_field(case)
        assert field.model == case.thermal.model
        assert field.max_temperature_rise > 0 and finite(field.elongation)
    if case.wear is not None:
        life = ballscrew.wear_life(case)
        assert life.complete and life.max_wear_depth[-1] > 0
        assert 0 < life.preload[-1] < life.preload[0]


def run_sweep_file(path: Path) -> None:
    """The ends of every swept axis through the sweep machinery (in-process, no Dask cluster)."""
    spec = load_sweep(path)
    assert spec.axes, f"{path.name}: no swept axis"
    base = with_overrides(spec.case, quick_overrides(spec.case))
    ends = [SweepAxis(a.key, (a.values[0], a.values[-1])) for a in spec.axes]
    points = grid_points(ends)
    name = spec.analysis or "tcr"
    records = [
        run_point(get_analysis(name), case, point)
        for case, point in zip(validate_points(base, points), points, strict=True)
    ]
    dataset = assemble(ends, records, name, base)
    assert not dataset["failed"].any(), dataset["error"].values
    for variable in set(dataset.data_vars) - {
        "error",
        "failed",
        "warnings",
    }:  # NaN: e.g. a lifted-off nut
        assert np.isfinite(dataset[variable].values).any(), variable


def run_measured(path: Path) -> None:
    """A measured history for ``ballscrew calibrate``, within the wear example's programme."""
    data = read_measured(path, min_points=3)
    assert len(data) >= 3 and finite(*data.values)
    programme = ballscrew.load_case(EXAMPLES / "wear_step_stress.toml").wear.programme
    assert data.revolutions[-1] <= sum(level.revolutions for level in programme)


def run_profile(path: Path) -> None:
    """A measured profile through the reader and both fractal fits."""
    fit = fractal_parameters(read_profile(path))
    assert 1.0 < fit.D < 2.0 and fit.G > 0
    assert fit.psd is not None and fit.structure_function is not None


#: glob (relative to examples/) -> runner; the first match wins.
RUNNERS: dict[str, Callable[[Path], None]] = {
    "*.toml": run_case,
    "sweeps/*.toml": run_sweep_file,
    "measured/*.csv": run_measured,
    "profiles/*": run_profile,
}


def runner_of(relative: str) -> Callable[[Path], None] | None:
    matches = [
        run
        for pattern, run in RUNNERS.items()
        if fnmatch.fnmatch(relative, pattern) and relative.count("/") == pattern.count("/")
    ]
    return matches[0] if matches else None


EXAMPLE_FILES = sorted(
    p.relative_to(EXAMPLES).as_posix()
    for p in EXAMPLES.rglob("*")
    if p.is_file() and not any(part.startswith(".") for part in p.relative_to(EXAMPLES).parts)
)


def test_there_are_examples_of_every_kind():
    kinds = {
        pattern for pattern in RUNNERS for f in EXAMPLE_FILES if runner_of(f) is RUNNERS[pattern]
    }
    assert kinds == set(RUNNERS)


@pytest.mark.parametrize("relative", EXAMPLE_FILES)
def test_example_runs(relative):
    run = runner_of(relative)
    if run is None:
        pytest.fail(f"examples/{relative} has no runner in tests/test_examples.py (RUNNERS)")
    run(EXAMPLES / relative)
