"""The command line as a new user meets it: help texts, --set, --export, console output."""

from __future__ import annotations

import errno
import json
import re
from pathlib import Path

import pytest
import typer
from typer.testing import CliRunner

import ballscrew
from ballscrew.cli import app
from ballscrew.results import writer
from ballscrew.results.headlines import headline_keys
from quick_cases import QUICK, write_case

GROUP = typer.main.get_command(app)  # the click group of the app
COMMANDS = sorted(GROUP.commands)
BRACKETED = re.compile(r"\S*\[[^\]\s]+\]+\S*")
#: Spellings the console must not use: ASCII micro, other torque dots, raw float exponents.
BAD_SPELLINGS = re.compile(r"\d um\b|N m\b|N\*m|\d[eE][+-]?\d|rad/s")


def run(*args: object):
    return CliRunner().invoke(app, [str(a) for a in args])


def flat(text: str) -> str:
    return " ".join(text.split())


def _help_texts(command) -> list[str]:
    return [command.help or "", *(getattr(p, "help", None) or "" for p in command.params)]


def test_the_command_list_keeps_every_word():
    result = run("--help")
    assert result.exit_code == 0
    text = flat(result.output)
    for name in COMMANDS:
        first_line = (GROUP.commands[name].help or "").split("\n")[0]
        assert flat(first_line) in text, name
    assert "(needs [thermal])" in text and "over the [[duty]] cycle" in text
    assert "<bool>" not in text


@pytest.mark.parametrize("name", COMMANDS)
def test_help_of_every_command_keeps_its_bracketed_words_and_shows_flags_as_flags(name):
    command = GROUP.commands[name]
    result = run(name, "--help")
    assert result.exit_code == 0, result.output
    text = flat(result.output)
    words = [w for t in _help_texts(command) for w in BRACKETED.findall(t)]
    for word in words:
        assert word in text, f"ballscrew {name} --help lost {word!r}"
    assert "<bool>" not in text
    for param in command.params:
        if getattr(param, "is_flag", False):
            line = next(ln for ln in result.output.splitlines() if param.opts[0] in ln)
            assert "<" not in line, line  # a flag takes no value


def test_the_known_bracketed_words_survive():
    assert "[thermal]" in flat(run("thermal", "--help").output)
    assert "'wear_depth [µm]'" in flat(run("calibrate", "--help").output)
    assert "[sweep] table" in flat(run("sweep", "--help").output)
    assert "[design]" in flat(run("check", "--help").output)


#: Every command that reads a case file.
CASE_COMMANDS = [
    "calibrate", "check", "contact", "duty", "kinematics", "operating-point", "sweep", "tcr",
    "thermal", "wear",
]  # fmt: skip


@pytest.mark.parametrize("name", CASE_COMMANDS)
def test_every_case_command_takes_set_and_export(name):
    opts = {o for p in GROUP.commands[name].params for o in getattr(p, "opts", ())}
    assert {"--set", "--export", "--quiet", "--verbose", "-q", "-v"} <= opts


def test_surface_takes_export_too():
    opts = {o for p in GROUP.commands["surface"].params for o in getattr(p, "opts", ())}
    assert {"--export", "--quiet"} <= opts


@pytest.fixture
def quick_case(tmp_path) -> Path:
    return write_case(tmp_path, "gao2019_tcr.toml", QUICK)


@pytest.fixture
def quiet_case(tmp_path) -> Path:
    """The quick case with a film thick enough (Λ ≈ 2) that the operating point warns nothing."""
    return write_case(tmp_path, "gao2019_tcr.toml", {**QUICK, "medium.viscosity": "0.2 Pa*s"})


@pytest.mark.parametrize(
    ("setting", "message"),
    [
        ("operating.speed=fast", "operating.speed"),
        ("operating.preload=-2 kN", "operating.preload = '-2 kN' is not allowed"),
        ("nut.preload=2 kN", "nut.preload: unknown key"),
        ("operating.speed", "--set 'operating.speed': expected KEY=VALUE"),
        ("screw.lead=10", "did you mean '10 mm'?"),
    ],
)
def test_a_bad_set_is_one_line_naming_the_key(tmp_path, quick_case, setting, message):
    out = tmp_path / "out"
    result = run("operating-point", quick_case, "--out", out, "--set", setting)
    assert result.exit_code == 2
    assert message in result.output
    assert len(result.output.strip().splitlines()) == 1
    assert not out.exists()


@pytest.fixture
def fake_export(monkeypatch):
    """The exporter of the results writer replaced by one recording its calls."""
    calls: list[tuple[Path, tuple[str, ...]]] = []

    def export_results(folder, formats):
        calls.append((Path(folder), tuple(formats)))
        return []

    monkeypatch.setattr(writer, "export_results", export_results)
    return calls


@pytest.mark.parametrize("formats", ["csv,pdf", "", ",", "netcdf"])
def test_an_unknown_export_format_is_one_line_exit_2_before_any_work(
    tmp_path, quick_case, fake_export, formats
):
    out = tmp_path / "out"
    result = run("operating-point", quick_case, "--out", out, "--export", formats)
    assert result.exit_code == 2
    assert result.output.startswith("error: --export = ")
    assert "csv, xlsx, mat" in result.output
    assert len(result.output.strip().splitlines()) == 1
    assert not out.exists() and not fake_export


def test_a_run_with_set_export_and_a_warning(tmp_path, quick_case, fake_export):
    """One run shows it all: --set with units applied before validation, the headline numbers
    in engineering units, an implausible bare number warned about on the console, in
    summary.json and in the report, export_results called with the folder, the folder last."""
    out = tmp_path / "out"
    result = run(
        "operating-point", quick_case, "--out", out,
        "--set", "operating.axial_load=2 kN", "--set", "friction.model=ball_model",
        "--set", "screw.lead=0.5", "--export", "CSV, xlsx,csv,mat",
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    inputs = json.loads((out / "inputs.json").read_text())
    assert inputs["operating"]["axial_load"] == {"value": 2000.0, "unit": "N"}
    assert inputs["friction"]["model"] == "ball_model"
    assert inputs["screw"]["lead"] == {"value": 0.5, "unit": "m"}

    lines = result.output.strip().splitlines()
    assert lines[-1] == f"results: {out.resolve()}"
    assert re.search(r"^  friction torque +\d+(\.\d+)? N·m$", result.output, re.M)
    assert re.search(r"^  nut temperature +\d+(\.\d+)? °C$", result.output, re.M)
    assert not BAD_SPELLINGS.search(result.output)
    headlines = len(headline_keys("operating-point"))  # one line each, and the folder
    assert len([ln for ln in lines if not ln.startswith("warning: ")]) <= headlines + 1

    expected = "screw.lead = 0.5 m is longer than the pitch circle"
    assert f"warning: {quick_case}: {expected}" in result.output
    assert "did you mean '0.5 mm'?" in result.output
    summary = json.loads((out / "summary.json").read_text())
    assert any(w.startswith(expected) for w in summary["warnings"])
    assert expected in (out / "report.html").read_text()

    # exported inside the atomic write: into the scratch folder that then becomes the folder
    [(folder, formats)] = fake_export
    assert formats == ("csv", "xlsx", "mat")
    assert folder.parent == out.resolve().parent and folder.name.startswith(".out.partial-")


def test_a_failing_export_writes_nothing_and_keeps_the_previous_folder(
    tmp_path, quiet_case, monkeypatch
):
    """An export that fails (here: a full disk) is one line and exit status 2; the folder of
    the earlier run stays as it was and a new folder is not written at all."""
    out = tmp_path / "out"
    assert run("operating-point", quiet_case, "-q", "--out", out).exit_code == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}

    def full_disk(folder, formats):
        (Path(folder) / "summary.csv").write_text("key,value,unit\n")  # half written
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(writer, "export_results", full_disk)
    for folder in (out, tmp_path / "new"):
        result = run("operating-point", quiet_case, "--out", folder, "--export", "csv")
        assert result.exit_code == 2
        assert result.output.strip().splitlines() == [
            f"error: cannot write the results {folder.resolve()}: No space left on device"
        ]
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert not (tmp_path / "new").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([quiet_case.name, "out"])


def test_quiet_after_the_command_prints_only_the_folder(tmp_path, quiet_case):
    out = tmp_path / "out"
    result = run("operating-point", quiet_case, "-q", "--out", out)
    assert result.exit_code == 0, result.output
    assert result.output.strip() == f"results: {out.resolve()}"


def test_the_examples_raise_no_plausibility_warning():
    from ballscrew.case.plausibility import implausible_values
    from quick_cases import EXAMPLES

    for path in sorted(EXAMPLES.glob("*.toml")):
        assert implausible_values(ballscrew.load_case(path)) == [], path.name


def test_every_command_list_line_is_a_whole_sentence():
    """The list read 'Fit the wear model (…) to one measured history, or' (cut mid-sentence)."""
    for name in COMMANDS:
        first_line = (GROUP.commands[name].help or "").split("\n")[0].strip()
        assert first_line.endswith("."), name


def test_sweep_help_names_the_analyses_and_options_their_units():
    from ballscrew.sweep.registry import SWEEPABLE

    text = flat(run("sweep", "--help").output)
    assert all(name in text for name in SWEEPABLE)
    assert '"2 kN" or 2000 (N)' in flat(run("operating-point", "--help").output)
    surface = flat(run("surface", "--help").output)
    assert "(a bare number is in m)" in surface and "(default: the spacing)" in surface
