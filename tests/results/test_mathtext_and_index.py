"""User text in figures is never parsed as mathtext; ``index`` survives bad folder content."""

from __future__ import annotations

import json
import warnings
from dataclasses import replace
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import pytest
from typer.testing import CliRunner

from ballscrew.analyses.surface_report import profile_plot
from ballscrew.calibration import fit_wear_coefficient, measured_history
from ballscrew.case import load_case, with_overrides
from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.plotting import plain
from ballscrew.results import write_results
from ballscrew.results.index import SkippedFolderWarning, write_index
from ballscrew.surface.profile import Profile
from calibration.conftest import MEASURED_AT, SyntheticModel, exact

WEAR_EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "wear_step_stress.toml"
NASTY = [r"$\bad{$", "a $^$ b", r"$x_$", "5$ and 6$", r"back\slash $\alpha", "<b>&amp;"]


@pytest.mark.parametrize("text", NASTY)
def test_plain_text_is_drawn_literally(tmp_path, text):
    fig, ax = plt.subplots()
    ax.set_title(plain(text))
    ax.plot([0, 1], label=plain(text))
    ax.legend()
    fig.savefig(tmp_path / "t.png")
    plt.close(fig)
    assert fig.axes[0].title.get_text().replace(r"\$", "$") == text


@pytest.mark.parametrize("name", NASTY[:3])
def test_calibration_report_with_mathtext_in_case_and_csv_names(tmp_path, name):
    depth = exact(2.0e-4, MEASURED_AT).max_wear_depth
    data = measured_history(MEASURED_AT, depth, "wear_depth", source=f"{name}.csv")
    case = with_overrides(load_case(WEAR_EXAMPLE), {"name": f"{name} <b>"})
    result = replace(fit_wear_coefficient(SyntheticModel(), data), case=case)
    folder = write_results(result, tmp_path / "out")
    assert (folder / "fit.png").is_file()
    report = (folder / "report.html").read_text()
    assert "&lt;b&gt;" in report
    assert "<b>" not in report


def test_profile_plot_with_mathtext_in_the_file_name(tmp_path):
    profile = Profile(np.sin(np.arange(64.0)) * 1e-6, 1e-6, source=r"/data/$\frac$.sdf")
    assert profile_plot(profile, tmp_path / "p.png").is_file()


def make_folder(root: Path, name: str, summary: object, report: bool = True) -> Path:
    folder = root / name
    folder.mkdir()
    text = summary if isinstance(summary, str | bytes) else json.dumps(summary)
    target = folder / "summary.json"
    target.write_bytes(text) if isinstance(text, bytes) else target.write_text(text)
    if report:
        (folder / "report.html").write_text("<html></html>")
    return folder


GOOD = {"analysis": "tcr", "case": "c", "resistance": {"value": 0.0195, "unit": "K/W"}}


@pytest.mark.parametrize(
    "summary",
    ["{not json", b"\xff\xfe\x00binary", "[1, 2]", "null", '"text"', "[" * 100_000],
    ids=["not-json", "binary", "list", "null", "string", "deep"],
)
def test_index_skips_unreadable_summaries_with_a_warning(tmp_path, summary):
    make_folder(tmp_path, "good", GOOD)
    make_folder(tmp_path, "bad", summary)
    with pytest.warns(SkippedFolderWarning, match="bad: left out of the index"):
        text = write_index(tmp_path).read_text()
    assert "resistance = 0.0195 K/W" in text
    assert "bad" not in text.split("<h2>Results</h2>")[1].split("</table>")[0]


@pytest.mark.parametrize(
    "summary",
    [
        {},
        {"analysis": 5, "case": ["x"], "axes": 7},
        {"analysis": "sweep", "axes": "surface.D"},
        {"analysis": "tcr", "resistance": {"value": "high", "unit": 3}},
        {"analysis": "tcr", "resistance": {"value": 10**400, "unit": "K/W"}},
        {"analysis": "wear", "final_preload": None, "revolutions": [1, 2]},
    ],
    ids=["empty", "wrong-types", "axes-string", "non-numeric", "huge-int", "null-values"],
)
def test_index_tolerates_summaries_of_the_wrong_shape(tmp_path, summary):
    make_folder(tmp_path, "odd", summary)
    assert "odd" in write_index(tmp_path).read_text()


def test_index_lists_a_folder_without_report_or_figures_without_a_link(tmp_path):
    make_folder(tmp_path, "bare", GOOD, report=False)
    (tmp_path / "bare" / "tcr_nut1_screw.png").symlink_to(tmp_path / "missing.png")
    text = write_index(tmp_path).read_text()
    assert "no report.html" in text
    assert 'href="bare/report.html"' not in text


def test_index_skips_a_folder_of_unreadable_files(tmp_path, monkeypatch):
    make_folder(tmp_path, "good", GOOD)
    locked = make_folder(tmp_path, "locked", GOOD)
    (locked / "fig.png").write_bytes(b"png")
    read_text, read_bytes = Path.read_text, Path.read_bytes

    def denied(original):
        def read(self, *args, **kwargs):
            if self.parent == locked:
                raise PermissionError(13, "Permission denied", str(self))
            return original(self, *args, **kwargs)

        return read

    monkeypatch.setattr(Path, "read_text", denied(read_text))
    monkeypatch.setattr(Path, "read_bytes", denied(read_bytes))
    with pytest.warns(SkippedFolderWarning, match="locked: .*cannot read"):
        text = write_index(tmp_path).read_text()
    assert "resistance = 0.0195 K/W" in text
    assert "locked" not in text


def loop(tmp_path: Path) -> Path:
    (tmp_path / "a").symlink_to(tmp_path / "b")
    (tmp_path / "b").symlink_to(tmp_path / "a")
    return tmp_path / "a"


@pytest.mark.parametrize(
    "make_root",
    [
        lambda p: p / "missing",
        lambda p: (p / "file.txt").write_text("x") and p / "file.txt",
        lambda p: p,
        loop,
        lambda p: make_folder(p, "only", "{broken") and p,
    ],
    ids=["missing", "a-file", "empty", "symlink-loop", "nothing-readable"],
)
def test_index_of_a_bad_root_is_one_line_exit_2(tmp_path, make_root):
    root = make_root(tmp_path)
    with pytest.raises(InputError, match="folder"), warnings.catch_warnings():
        warnings.simplefilter("ignore", SkippedFolderWarning)
        write_index(root)
    result = CliRunner().invoke(app, ["index", str(root)])
    assert result.exit_code == 2, result.output
    assert "error: folder" in result.output
    assert "Traceback" not in result.output


def test_index_ignores_a_symlink_loop_beside_results(tmp_path):
    make_folder(tmp_path, "good", GOOD)
    loop(tmp_path)
    assert "resistance = 0.0195 K/W" in write_index(tmp_path).read_text()
