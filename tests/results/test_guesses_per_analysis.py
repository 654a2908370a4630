"""Each analysis lists only the guessed defaults of the inputs it reads (every analysis used to
list every guess of the case: a design check listed the friction and wear guesses it never
used).

The table of what each analysis reads (:data:`ballscrew.analyses.case_reads.CASE_READS`) is held
to the fields the analysis really reads, recorded while it runs: no guess it reads is left out,
and every guess it lists is one it reads in one of the cases tried.
"""

from __future__ import annotations

import gc
import json
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest
from pydantic import BaseModel
from tests.quick_cases import EXAMPLES, QUICK, QUICK_WEAR, write_case
from typer.testing import CliRunner

from ballscrew import load_case
from ballscrew.analyses.case_cache import CaseCache
from ballscrew.analyses.case_reads import CASE_READS
from ballscrew.analyses.catalog import ANALYSES
from ballscrew.case import Case
from ballscrew.case.base import Model
from ballscrew.case.inputs import guessed_defaults
from ballscrew.cli import app

#: A second configuration that reaches the guesses the example leaves unused: an oil given by
#: its viscosities (its density at 15 °C), the elastic load sharing (the nut body), the ball
#: model of friction with the return push (the ball-train guesses).
VARIANT: dict[str, Any] = {
    "medium.viscosity": None,
    "medium.viscosity_40": "68e-6 m^2/s",
    "medium.viscosity_100": "8.7e-6 m^2/s",
    "loads.distribution": "elastic",
    "friction.model": "ball_model",
    "friction.ball_train": "return_push",
}
#: An input the case declares assumed: listed wherever the screw is read.
ASSUMED = {"assumed": {"screw.lead": "read off a drawing"}}

#: Pure field reads of these modules are bookkeeping, not physics (the resolved inputs, the
#: guesses themselves, the copy of a case with overrides).
_BOOKKEEPING = ("case/inputs.py", "case/plausibility.py", "case/loader.py")


def _runs() -> dict[str, Callable[[Case], Any]]:
    from ballscrew import screw_tcr, thermal_field, wear_life
    from ballscrew.analyses.ball_contact import solve_ball_contacts
    from ballscrew.analyses.design_check import design_check
    from ballscrew.analyses.duty_thermal import thermal_duty
    from ballscrew.analyses.kinematics import run_kinematics
    from ballscrew.analyses.operating_point import operating_point

    return {
        "check": design_check,
        "contact": solve_ball_contacts,
        "tcr": screw_tcr,
        "kinematics": run_kinematics,
        "operating-point": operating_point,
        "thermal": thermal_field,
        "duty": lambda case: thermal_duty(case, None),
        "wear": wear_life,
    }


def _owners(model: BaseModel, prefix: str = "") -> Iterator[tuple[str, type, str]]:
    """(dotted key, owning class, field name) of every field of a case."""
    for name in type(model).model_fields:
        key, value = prefix + name, getattr(model, name)
        yield key, type(model), name
        if isinstance(value, BaseModel):
            yield from _owners(value, key + ".")
        elif isinstance(value, list | tuple):
            for k, item in enumerate(value):
                if isinstance(item, BaseModel):
                    yield from _owners(item, f"{key}[{k}].")


@contextmanager
def _recorded_reads() -> Iterator[set[tuple[type, str]]]:
    """The (class, field) pairs of the case sections read inside the block."""
    import sys

    reads: set[tuple[type, str]] = set()
    plain = BaseModel.__getattribute__

    def recording(self: BaseModel, name: str) -> Any:
        cls = plain(self, "__class__")
        if isinstance(self, Model) and name in cls.model_fields:
            if not sys._getframe(1).f_code.co_filename.endswith(_BOOKKEEPING):
                reads.add((cls, name))
        return plain(self, name)

    for cache in [o for o in gc.get_objects() if isinstance(o, CaseCache)]:
        cache.clear()  # a cached result reads nothing
    BaseModel.__getattribute__ = recording  # type: ignore[method-assign]
    try:
        yield reads
    finally:
        BaseModel.__getattribute__ = plain  # type: ignore[method-assign]


def _case(name: str, variant: dict[str, Any]) -> Case:
    example, quick = (
        ("wear_step_stress.toml", QUICK | QUICK_WEAR)
        if name == "wear"
        else ("gao2019_tcr.toml", QUICK)
    )
    return load_case(EXAMPLES / example, quick | variant | ASSUMED)


def test_every_analysis_declares_what_it_reads():
    assert set(ANALYSES) <= set(CASE_READS)


@pytest.mark.parametrize("name", sorted(_runs()))
def test_an_analysis_lists_the_guesses_it_reads_and_no_other(name):
    run = _runs()[name]
    read_any: set[str] = set()
    listed_any: set[str] = set()
    for variant in ({}, VARIANT):
        case = _case(name, variant)
        with _recorded_reads() as reads:
            run(case)
        read = {key for key, cls, field in _owners(case) if (cls, field) in reads}
        every = guessed_defaults(case)
        listed = guessed_defaults(case, reads=CASE_READS[name])
        missing = {key for key in every if key in read} - set(listed)
        assert not missing, f"{name} reads these guesses but does not list them: {missing}"
        assert list(listed) == [k for k in every if k in listed]  # order kept
        read_any |= read
        listed_any |= set(listed)
    unread = listed_any - read_any
    assert not unread, f"{name} lists guesses it never read: {unread}"
    assert "screw.lead" in listed_any  # the [assumed] table follows the same filter


def _guesses_of(tmp_path: Path, command: str, example: str, overrides: dict[str, Any]) -> set:
    case_file = write_case(tmp_path, example, overrides)
    out = tmp_path / command
    result = CliRunner().invoke(app, [command, str(case_file), "--out", str(out), "-q"])
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    report = (out / "report.html").read_text(encoding="utf-8")
    for key in summary["guessed_defaults"]:
        assert f"<td>{key}</td>" in report
    return set(summary["guessed_defaults"])


@pytest.mark.parametrize(
    ("command", "example", "kept", "gone"),
    [
        (
            "check",
            "gao2019_tcr.toml",
            {"loads.nut_outer_diameter"},
            {"friction.", "thermal.", "kinematics."},
        ),
        ("tcr", "gao2019_tcr.toml", {"loads.nut_outer_diameter"}, {"friction.", "thermal."}),
        (
            "operating-point",
            "gao2019_tcr.toml",
            {"friction.seal_force", "lubrication.inlet_ratio"},
            {"wear."},
        ),
        (
            "thermal",
            "gao2019_tcr.toml",
            {"friction.circuits", "kinematics.boundary_friction"},
            {"wear."},
        ),
        (
            "wear",
            "wear_step_stress.toml",
            {"medium.density_15"},
            {"friction.", "thermal.", "kinematics."},
        ),
    ],
)
def test_the_command_lists_only_its_guesses(tmp_path, command, example, kept, gone):
    quick = QUICK | QUICK_WEAR if command == "wear" else QUICK
    guesses = _guesses_of(tmp_path, command, example, quick)
    assert kept <= guesses
    assert not [key for key in guesses if key.startswith(tuple(gone))]


def test_a_sweep_lists_the_guesses_of_its_analysis(tmp_path):
    from ballscrew.results.sweep_report import write_sweep
    from ballscrew.sweep import PointRecord, assemble, parse_axis

    case = load_case(EXAMPLES / "gao2019_tcr.toml")
    axis = parse_axis("operating.preload=1000 N,2000 N")
    records = [
        PointRecord({axis.key: v}, {"resistance": (v, "K/W")}, None, 0.0) for v in axis.values
    ]
    folder = tmp_path / "sweep"
    folder.mkdir()
    write_sweep(assemble([axis], records, "tcr", case), folder, 2, case, [axis])
    guessed = json.loads((folder / "summary.json").read_text(encoding="utf-8"))["guessed_defaults"]
    assert "case.loads.nut_outer_diameter" in guessed
    assert not [key for key in guessed if key.startswith(("case.friction.", "case.kinematics."))]
