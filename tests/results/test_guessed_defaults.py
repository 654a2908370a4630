"""A default that is only a guess is reported in results: summary.json lists its key and the
report has a section with its value and why (the folder used to list it among every default,
unmarked)."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import xarray as xr

from ballscrew import load_case
from ballscrew.case import Case
from ballscrew.case.inputs import guessed_defaults, resolved_inputs
from ballscrew.results import write_results

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"


def test_guesses_are_the_defaults_labelled_so_that_the_case_left_alone():
    case = load_case(EXAMPLE)
    guesses = guessed_defaults(case)
    assert "friction.circuits" in guesses and "GUESS" in guesses["friction.circuits"]
    assert "medium.density_15" in guesses  # ASSUMED
    assert "friction.hysteresis" in guesses
    assert "friction.rolling_friction" not in guesses  # a default, but not labelled a guess
    given = load_case(EXAMPLE, {"friction.circuits": 3})
    assert "friction.circuits" not in guessed_defaults(given)


@dataclass(frozen=True)
class _Result:
    case: Case
    analysis: str = "tcr"
    title: str = "guesses"
    warnings: tuple[str, ...] = ()
    inputs: dict = field(default_factory=dict)

    def summary(self) -> dict:
        return {"resistance": {"value": 0.02, "unit": "K/W"}}

    def to_xarray(self) -> xr.Dataset:
        return xr.Dataset()

    def figures(self) -> list:
        return []

    def report(self) -> list:
        return []


def test_the_folder_reports_the_guesses(tmp_path):
    case = load_case(EXAMPLE, {"friction.circuits": 3})
    # the operating point reads [friction] (a tcr result lists no friction guess any more)
    result = _Result(case, analysis="operating-point", inputs=resolved_inputs(case))
    folder = write_results(result, tmp_path / "out")
    summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    assert "friction.seal_force" in summary["guessed_defaults"]
    assert "friction.circuits" not in summary["guessed_defaults"]
    report = (folder / "report.html").read_text(encoding="utf-8")
    assert "<h2>Defaults that are guesses</h2>" in report
    assert "<td>friction.seal_force</td><td>5</td><td>N</td>" in report


def test_a_guessed_rule_behind_none_is_a_guess_too(tmp_path):
    """The nut body d_m + 5 D_b that an unset ``loads.nut_outer_diameter`` stands for was used
    without appearing among the guesses (None counted as no value)."""
    case = load_case(EXAMPLE)
    guesses = guessed_defaults(case)
    assert case.loads.nut_outer_diameter is None and "loads.nut_outer_diameter" in guesses
    assert "thermal.shaft_diameter" not in guesses  # None = d_m: a definition, not a guess
    given = load_case(EXAMPLE, {"loads.nut_outer_diameter": "70 mm"})
    assert "loads.nut_outer_diameter" not in guessed_defaults(given)
    folder = write_results(_Result(case, inputs=resolved_inputs(case)), tmp_path / "out")
    report = (folder / "report.html").read_text(encoding="utf-8")
    assert "loads.nut_outer_diameter</td><td>by its rule" in report.replace("\n", "")


def test_overrides_keep_the_defaults_the_case_left_alone():
    """``with_overrides`` re-validated the full dump, which marked every field as written: a
    sweep's base case (always passed through it) and every analysis that resolves its case
    (coupled thermal, operating point) reported no guesses at all."""
    from ballscrew.case import with_overrides

    case = load_case(EXAMPLE)
    overridden = with_overrides(case, {"surface.D": 1.5, "friction.hysteresis": 0.01})
    assert set(guessed_defaults(overridden)) == set(guessed_defaults(case)) - {
        "friction.hysteresis"
    }
    assert overridden.surface.D == 1.5 and overridden.friction.hysteresis == 0.01
    assert set(guessed_defaults(with_overrides(overridden, {}))) == set(
        guessed_defaults(overridden)
    )
    given = with_overrides(case, {"friction": {"seal_force": 5.0, "circuits": 2}})
    assert "friction.circuits" not in guessed_defaults(given)  # a written section is written
