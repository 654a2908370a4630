"""A nut body that does not enclose its balls is refused when the case is read.

A ``loads.nut_outer_diameter`` within a few tenths of a millimetre of the groove bottom used to
pass the case and stop deep in the elastic load distribution with a ConvergenceError of its
Newton solve (below the groove bottom, only when an analysis ran).
"""

from __future__ import annotations

import pytest
from tests.quick_cases import EXAMPLES, write_case
from typer.testing import CliRunner

import ballscrew
from ballscrew.analyses.ball_loads import ball_loads
from ballscrew.case.loader import CaseError
from ballscrew.case.nut_body import least_nut_outer_diameter
from ballscrew.cli import app

EXAMPLE = EXAMPLES / "gao2019_tcr.toml"
ELASTIC = {"loads.distribution": "elastic"}
#: d_m = 40 mm, D_b = 6.35 mm: groove bottom 46.35 mm, least nut body 52.7 mm.
LEAST = 0.0527


def test_the_least_nut_is_the_groove_bottom_and_half_a_ball_of_wall():
    assert least_nut_outer_diameter(0.040, 0.00635) == pytest.approx(LEAST)


@pytest.mark.parametrize("diameter", ["46.35 mm", "46.65 mm", "52.6 mm", "30 mm"])
def test_a_nut_at_its_groove_is_one_line_exit_2_and_nothing_written(tmp_path, diameter):
    """46.65 mm (0.3 mm over the groove bottom) was the ConvergenceError of the report."""
    case_file = write_case(tmp_path, "gao2019_tcr.toml", {"loads.nut_outer_diameter": diameter})
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["contact", str(case_file), "--out", str(out)])
    assert result.exit_code == 2, result.output
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ")
    assert "loads.nut_outer_diameter" in lines[0] and "0.0527 m" in lines[0]
    assert "Traceback" not in result.output and not out.exists()


def test_set_on_the_command_line_is_checked_too(tmp_path):
    out = tmp_path / "out"
    args = ["tcr", str(EXAMPLE), "--out", str(out), "--set", "loads.nut_outer_diameter=47 mm"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2 and "loads.nut_outer_diameter" in result.output
    assert not out.exists()


def test_the_least_nut_is_accepted_and_its_ball_loads_converge():
    """At the bound the elastic distribution solves, even under a high preload and load."""
    case = ballscrew.load_case(
        EXAMPLE, ELASTIC | {"loads.nut_outer_diameter": LEAST, "operating.preload": "20 kN"}
    )
    loads = ball_loads(case, axial_load=20_000.0)
    assert loads.loads.min() >= 0.0 and loads.loads.max() > 0.0
    with pytest.raises(CaseError, match="nut_outer_diameter"):
        ballscrew.load_case(EXAMPLE, ELASTIC | {"loads.nut_outer_diameter": LEAST - 1e-5})
