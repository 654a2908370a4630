"""The README works as written: its Python tour runs and prints the numbers its comments state,
its ``ballscrew`` command lines parse, and its error example is the CLI's message.
"""

from __future__ import annotations

import ast
import io
import os
import re
import shlex
import tokenize
import tomllib
from decimal import Decimal
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from typer.testing import CliRunner

import ballscrew
from ballscrew import load_case
from ballscrew.case.loader import apply_overrides
from ballscrew.cli import app
from quick_cases import EXAMPLES, REPO, dump_toml, quick_overrides, write_case

README = (REPO / "README.md").read_text(encoding="utf-8")
NUMBER = re.compile(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w.])")
ATTRIBUTE = re.compile(r"(?<![\w.])\.([A-Za-z_]\w*)")


def blocks(language: str) -> list[str]:
    """The README's fenced code blocks of ``language`` ("" = no language)."""
    found, current, fence = [], [], None
    for line in README.splitlines():
        if line.startswith("```"):
            if fence is None:
                fence, current = line[3:].strip(), []
            else:
                if fence == language:
                    found.append("\n".join(current) + "\n")
                fence = None
        elif fence is not None:
            current.append(line)
    return found


SNIPPET = "\n".join(blocks("python"))


def statements() -> list[tuple[ast.stmt, str, str]]:
    """(statement, its source, its end-of-line comment) of the Python snippet."""
    comments = {
        tok.start[0]: tok.string.lstrip("# ")
        for tok in tokenize.generate_tokens(io.StringIO(SNIPPET).readline)
        if tok.type == tokenize.COMMENT
    }
    return [
        (node, ast.get_source_segment(SNIPPET, node) or "", comments.get(node.end_lineno, ""))
        for node in ast.parse(SNIPPET).body
    ]


STATEMENTS = statements()
#: Expressions whose comment states numbers: the README claims these values.
CLAIMS = [(s, src, c) for s, src, c in STATEMENTS if isinstance(s, ast.Expr) and NUMBER.search(c)]
#: Assignments whose comment names attributes of the result (``# .resistance [K/W]``).
ATTRIBUTES = [
    (s.targets[0].id, name, src)
    for s, src, c in STATEMENTS
    if isinstance(s, ast.Assign) and isinstance(s.targets[0], ast.Name)
    for name in ATTRIBUTE.findall(c)
]


@pytest.fixture(scope="module")
def tour(tmp_path_factory) -> dict[str, Any]:
    """Run the snippet as written in a fresh folder that sees the examples; keep the values."""
    folder = tmp_path_factory.mktemp("readme")
    (folder / "examples").symlink_to(EXAMPLES, target_is_directory=True)
    namespace: dict[str, Any] = {"__name__": "__readme__"}
    values: dict[str, Any] = {}
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        for node, source, _ in STATEMENTS:
            if isinstance(node, ast.Expr):
                values[source] = eval(
                    compile(ast.Expression(node.value), "README", "eval"), namespace
                )
            else:
                exec(compile(ast.Module([node], []), "README", "exec"), namespace)
    finally:
        os.chdir(cwd)
    return {"namespace": namespace, "values": values}


def test_the_readme_has_a_python_tour_with_numbers():
    assert SNIPPET and len(CLAIMS) >= 3 and ATTRIBUTES and ERRORS


def flat(value: Any) -> list[float]:
    """The numbers of a result: a scalar or a (named) tuple of scalars."""
    return [float(v) for v in np.ravel(np.asarray(value, dtype=float))]


@pytest.mark.parametrize(("node", "source", "comment"), CLAIMS, ids=[s for _, s, _ in CLAIMS])
def test_the_tour_prints_the_numbers_of_its_comments(tour, node, source, comment):
    actual = flat(tour["values"][source])
    stated = NUMBER.findall(comment)[: len(actual)]  # later numbers are context ("after 1.44e6")
    assert len(stated) == len(actual), f"{source}: {comment!r} states {stated} for {actual}"
    for text, number in zip(stated, actual, strict=True):
        half_digit = Decimal(5) * Decimal(10) ** (Decimal(text).as_tuple().exponent - 1)
        assert abs(Decimal(number) - Decimal(text)) <= half_digit, (
            f"README says {text}, the code gives {number:.6g}: {source}"
        )


@pytest.mark.parametrize(("name", "attribute", "source"), ATTRIBUTES)
def test_the_tour_results_have_the_attributes_its_comments_name(tour, name, attribute, source):
    assert hasattr(tour["namespace"][name], attribute), source


def command_lines() -> list[list[str]]:
    """Every ``ballscrew ...`` line of the README's bash blocks, continuations joined."""
    text = "\n".join(blocks("bash")).replace("\\\n", " ")
    return [
        shlex.split(line, comments=True)[1:]
        for line in text.splitlines()
        if line.strip().startswith("ballscrew ")
    ]


COMMANDS = command_lines()


def test_the_readme_shows_every_subcommand():
    shown = {argv[0] for argv in COMMANDS}
    assert {"contact", "tcr", "sweep", "thermal", "kinematics", "wear", "calibrate"} <= shown
    assert "surface" in shown


@pytest.mark.parametrize("argv", COMMANDS, ids=[" ".join(a[:2]) for a in COMMANDS])
def test_every_readme_command_line_parses(argv):
    """Options and arguments are those of the CLI (--help stops before any work)."""
    for word in argv:
        if word.startswith("examples/"):
            assert (REPO / word).is_file(), f"the README names a missing file: {word}"
    result = CliRunner().invoke(app, [*argv, "--help"])
    assert result.exit_code == 0, f"ballscrew {' '.join(argv)}:\n{result.output}"
    assert "Usage:" in result.output


#: A calibration fits the measured history of the whole programme: only its numerics are coarse.
QUICK_FOR = {"calibrate": {"wear.grid": [12, 48], "wear.max_depth_step": "0.4 um"}}


def quick_argv(argv: list[str], folder: Path) -> list[str]:
    """``argv`` with its case files made quick (coarse grids, short runs) and ``--out`` in
    ``folder``; the other files are the repository's."""
    quick = []
    for k, word in enumerate(argv):
        if k and argv[k - 1] == "--out":
            word = str(folder / word)
        elif word.startswith("examples/") and word.endswith(".toml") and "/" not in word[9:]:
            overrides = QUICK_FOR.get(argv[0]) or quick_overrides(ballscrew.load_case(REPO / word))
            word = str(write_case(folder, Path(word).name, overrides))
        elif word.startswith("examples/"):
            word = str(REPO / word)
        quick.append(word)
    return quick


#: The README's commands that run here; a sweep starts a Dask cluster (its machinery runs in
#: tests/sweep and tests/test_examples.py), so it is only parsed.
RUNNABLE = [argv for argv in COMMANDS if argv[0] not in ("sweep", "init") and "my.toml" not in argv]
#: The catalogue-sheet walk-through: ``init ... > my.toml``, then commands on my.toml.
SHEET = [argv for argv in COMMANDS if argv[0] == "init" or "my.toml" in argv]


@pytest.mark.parametrize("argv", RUNNABLE, ids=[" ".join(a[:2]) for a in RUNNABLE])
def test_every_readme_command_runs_and_writes_its_report(tmp_path, argv):
    """As written, but on quick numerics: exit 0 and a results folder with its report."""
    result = CliRunner().invoke(app, quick_argv(argv, tmp_path))
    assert result.exit_code == 0, f"ballscrew {' '.join(argv)}:\n{result.output}"
    out = tmp_path / argv[argv.index("--out") + 1]
    assert (out / "report.html").is_file() and (out / "summary.json").is_file()


def test_the_catalogue_sheet_walk_through_runs(tmp_path):
    """``init`` as written prints a case; every README command on it runs (quick numerics)."""
    (init,) = [argv for argv in SHEET if argv[0] == "init"]
    made = CliRunner().invoke(app, init[: init.index(">")])
    assert made.exit_code == 0, made.output
    full = tmp_path / "full.toml"
    full.write_text(made.stdout, encoding="utf-8")
    raw = apply_overrides(tomllib.loads(made.stdout), quick_overrides(load_case(full)), "my.toml")
    quick = tmp_path / "my.toml"
    quick.write_text(dump_toml(raw), encoding="utf-8")
    for argv in (a for a in SHEET if a[0] != "init"):
        argv = [str(quick) if w == "my.toml" else w for w in argv]
        argv[argv.index("--out") + 1] = str(tmp_path / argv[argv.index("--out") + 1])
        result = CliRunner().invoke(app, argv)
        assert result.exit_code == 0, f"ballscrew {' '.join(argv)}:\n{result.output}"
        assert (Path(argv[argv.index("--out") + 1]) / "report.html").is_file()


def test_the_readme_calibration_fits_the_torque_scale():
    (argv,) = [a for a in COMMANDS if a[0] == "calibrate"]
    assert "--fit-torque-scale" in argv


ERROR = re.compile(r"^\$ ballscrew (.+)\n(error: (\S+): (\S+) = (\S+) is not allowed.*)$", re.M)


ERRORS = ERROR.findall("\n".join(blocks("")))
#: README error lines that are out of date today -> what the CLI prints instead.
STALE = {
    "error: bad.toml: screw.screw_conformity = 0.5 is not allowed: allowed range is (0.5, 1)": (
        "error: bad.toml: screw.screw_conformity = 0.5 is not allowed: allowed range is (0.5, 1) "
        "(screw groove radius / ball diameter f_s)"
    ),
}


def _error_param(example: tuple[str, ...]) -> Any:
    stale = STALE.get(example[1])
    if stale is None:
        return example
    reason = f"README error example is out of date: the CLI prints {stale!r}"
    return pytest.param(example, marks=pytest.mark.xfail(strict=True, reason=reason))


@pytest.mark.parametrize("example", [_error_param(e) for e in ERRORS])
def test_the_readme_error_example_is_the_cli_message(tmp_path, monkeypatch, example):
    command, message, file, key, value = example
    monkeypatch.chdir(tmp_path)
    write_case(tmp_path, "gao2019_tcr.toml", {key: float(value)}).rename(file)
    result = CliRunner().invoke(app, shlex.split(command))
    assert result.exit_code == 2
    assert result.output.strip() == message
    assert not (tmp_path / "results").exists()


def test_the_readme_case_snippet_is_the_example_case():
    """The README's TOML excerpt parses and each of its values is the example file's."""
    import tomllib

    (snippet,) = blocks("toml")
    example = tomllib.loads((EXAMPLES / "gao2019_tcr.toml").read_text(encoding="utf-8"))
    for section, values in tomllib.loads(snippet).items():
        for key, value in values.items():
            assert example[section][key] == value, f"README [{section}] {key} = {value!r}"
