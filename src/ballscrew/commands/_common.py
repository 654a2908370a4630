"""Options, console output and error handling shared by every subcommand.

Every command function is decorated with :func:`command`, which adds ``-q/--quiet`` and
``-v/--verbose``, shows one progress bar (with ETA) for long work and turns
:class:`~ballscrew.errors.BallscrewError` into one line on stderr and exit status 2. A command
that writes a results folder is decorated with :func:`writes_results` instead, which also adds
``--out``, ``--force``, ``--export`` (and ``--set``) and hands the command an :class:`Output`:
it writes the folder with its exports in one atomic step and prints the headline numbers and
the folder.
"""

from __future__ import annotations

import inspect
import json
import logging
import sys
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import wraps
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from ballscrew.errors import BallscrewError, InputError

if TYPE_CHECKING:
    from ballscrew.analyses.result import AnalysisResult
    from ballscrew.case import Case

CaseArg = Annotated[
    Path,
    typer.Argument(
        help="case file (TOML)", dir_okay=False, show_default=False, metavar="CASE_FILE"
    ),
]
OutOpt = Annotated[
    Path, typer.Option("--out", "-o", help="results folder to write", metavar="FOLDER")
]
ForceOpt = Annotated[
    bool,
    typer.Option(
        "--force",
        help="replace a results folder of another command or ballscrew version "
        "(a file ballscrew did not write is never replaced)",
    ),
]
SetOpt = Annotated[
    list[str] | None,
    typer.Option(
        "--set",
        metavar="KEY=VALUE",
        help="set a case value before the case is checked, with or without a unit, e.g. "
        "--set operating.speed='1500 rpm' --set operating.preload='2 kN' (repeatable; "
        "a number without a unit is SI)",
        show_default=False,
    ),
]
ExportOpt = Annotated[
    str | None,
    typer.Option(
        "--export",
        metavar="FORMATS",
        help="also write the results as csv, xlsx and/or mat (MATLAB), comma-separated, "
        "e.g. --export csv,xlsx",
        show_default=False,
    ),
]
VerboseOpt = Annotated[
    bool, typer.Option("--verbose", "-v", help="more output: every step of long work")
]
QuietOpt = Annotated[bool, typer.Option("--quiet", "-q", help="only errors and the folder")]
SpeedOpt = Annotated[
    str | None,
    typer.Option(
        help='screw speed, e.g. "1500 rpm" or 157.1 (rad/s); default: the case\'s',
        metavar="SPEED",
    ),
]
ThermalModelOpt = Annotated[
    str | None,
    typer.Option(
        help="axisymmetric, network or 3d (default: the case's thermal.model)", metavar="NAME"
    ),
]

log = logging.getLogger("ballscrew")


def set_verbosity(verbose: bool, quiet: bool) -> None:
    """Log level of ballscrew's messages: DEBUG (verbose), WARNING (quiet) or INFO."""
    log.setLevel(logging.DEBUG if verbose else logging.WARNING if quiet else logging.INFO)
    for noisy in ("distributed", "dask"):
        logging.getLogger(noisy).setLevel(logging.DEBUG if verbose else logging.ERROR)


def is_quiet() -> bool:
    """True when only errors and the results folder are to be printed."""
    return not log.isEnabledFor(logging.INFO)


def user_errors_exit_2(function: Callable[..., Any]) -> Callable[..., Any]:
    """Turn :class:`BallscrewError` into a message on stderr and exit status 2."""

    @wraps(function)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return function(*args, **kwargs)
        except BallscrewError as exc:
            for line in str(exc).splitlines():
                typer.echo(f"error: {line}", err=True)
            raise typer.Exit(2) from None

    return wrapper


def _keyword(name: str, annotation: Any, default: Any) -> inspect.Parameter:
    return inspect.Parameter(
        name, inspect.Parameter.KEYWORD_ONLY, default=default, annotation=annotation
    )


def _with_parameters(
    wrapper: Callable[..., Any], parameters: Sequence[inspect.Parameter]
) -> Callable[..., Any]:
    """``wrapper`` showing ``parameters`` to typer (each keyword-only, so any order is valid)."""
    keyword = [p.replace(kind=inspect.Parameter.KEYWORD_ONLY) for p in parameters]
    wrapper.__signature__ = inspect.Signature(keyword)  # type: ignore[attr-defined]
    wrapper.__annotations__ = {p.name: p.annotation for p in keyword}
    return wrapper


def command(function: Callable[..., Any]) -> Callable[..., Any]:
    """A subcommand: ``function`` with ``-q/--quiet`` and ``-v/--verbose`` added, a progress
    bar for long work, and user errors as one line and exit status 2.

    The options also work before the command name (``ballscrew -q wear …``).
    """
    signature = inspect.signature(function, eval_str=True)

    @user_errors_exit_2
    @wraps(function)
    def wrapper(*args: Any, verbose: bool = False, quiet: bool = False, **kwargs: Any) -> Any:
        if verbose or quiet:
            set_verbosity(verbose, quiet)
        with progress_bar():
            return function(*args, **kwargs)

    extra = [_keyword("verbose", VerboseOpt, False), _keyword("quiet", QuietOpt, False)]
    return _with_parameters(wrapper, [*signature.parameters.values(), *extra])


@dataclass(frozen=True)
class Output:
    """Where and how a command writes its results folder: ``--out``, ``--force``, the
    ``--export`` formats and the ``--set`` case overrides of the command ``command``."""

    command: str
    out: Path
    force: bool = False
    formats: tuple[str, ...] = ()
    overrides: Mapping[str, Any] = field(default_factory=dict)

    def load_case(self, case_file: Path) -> Case:
        """The case of ``case_file`` with the ``--set`` values applied."""
        from ballscrew.case import load_case

        return load_case(case_file, self.overrides)

    @contextmanager
    def claim(self, *inputs: Path) -> Iterator[Path]:
        """Hold the results folder for the run (``ballscrew.results.claim_output``); yields its
        resolved path. ``inputs``: the files the run reads, which the folder must not hold."""
        from ballscrew.results import claim_output

        with claim_output(self.out, command=self.command, force=self.force, inputs=inputs) as path:
            yield path

    def write(
        self,
        result: AnalysisResult,
        case_file: Path | None = None,
        extra_files: Mapping[str, bytes] | None = None,
    ) -> None:
        """Write the results folder of ``result`` with its exports, complete or not at all
        (``ballscrew.results.write_results``), then print its headlines and the folder."""
        from ballscrew.results import write_results

        finish(write_results(result, self.out, case_file, extra_files, export=self.formats))

    def analyse(self, case_file: Path, run: Callable[[Case], AnalysisResult]) -> None:
        """The flow of a command on one case: read it with the ``--set`` values, claim the
        folder, ``run(case)`` and write the results."""
        case = self.load_case(case_file)
        with self.claim(case_file):
            self.write(run(case), case_file)


def writes_results(
    function: Callable[..., Any] | None = None, *, sets: bool = True
) -> Callable[..., Any]:
    """A :func:`command` that writes a results folder: ``function(…, output=Output)``.

    Adds ``--out`` (default ``results/<command>``) after the command's first parameter (its
    input file) and ``--force``, ``--set`` (unless ``sets`` is false) and ``--export`` after
    its own options; the ``--export`` and ``--set`` values are checked before any work.
    """
    if function is None:
        return lambda f: writes_results(f, sets=sets)
    name = function.__name__.replace("_", "-")
    own = [
        p
        for p in inspect.signature(function, eval_str=True).parameters.values()
        if p.name != "output"
    ]
    parameters = [
        *own[:1],
        _keyword("out", OutOpt, Path("results") / name),
        *own[1:],
        _keyword("force", ForceOpt, False),
        *([_keyword("set_", SetOpt, None)] if sets else []),
        _keyword("export", ExportOpt, None),
    ]

    @wraps(function)
    def wrapper(
        *args: Any,
        out: Path,
        force: bool = False,
        set_: list[str] | None = None,
        export: str | None = None,
        **kwargs: Any,
    ) -> Any:
        formats = export_formats(export)
        output = Output(name, out, force, formats, parse_sets(set_))
        return function(*args, output=output, **kwargs)

    return command(_with_parameters(wrapper, parameters))


@contextmanager
def progress_bar() -> Iterator[None]:
    """One rich progress bar with ETA on stderr for the :mod:`ballscrew.progress` reports of
    the block (only on a terminal, not with ``--quiet``)."""
    from rich.console import Console
    from rich.progress import (
        BarColumn,
        Progress,
        TaskProgressColumn,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    from ballscrew.progress import listening

    console = Console(file=sys.stderr)
    bar = Progress(
        TextColumn("{task.description}"),
        BarColumn(),
        TaskProgressColumn(),
        TimeElapsedColumn(),
        TextColumn("ETA"),
        TimeRemainingColumn(),
        console=console,
        transient=True,
        disable=is_quiet() or not console.is_terminal,
    )
    task = bar.add_task("", total=None, visible=False)
    state = {"task": "", "done": 0.0}

    def listener(name: str, done: float, total: float) -> None:
        if name != state["task"] or done < state["done"]:  # a new stage: the ETA starts afresh
            bar.reset(task, total=total, description=name, visible=True)
        state["task"], state["done"] = name, done
        bar.update(task, completed=done, total=total)

    with bar, listening(listener):
        _BARS.append(bar)
        try:
            yield
        finally:
            _BARS.remove(bar)


#: The progress bars shown now (finish() ends them before it prints).
_BARS: list[Any] = []


def parse_sets(texts: Sequence[str] | None) -> dict[str, Any]:
    """The ``--set KEY=VALUE`` options as case overrides (``ballscrew.case.parse_assignments``)."""
    from ballscrew.case import parse_assignments

    return parse_assignments(texts or (), "--set")


def export_formats(text: str | None) -> tuple[str, ...]:
    """The formats of ``--export`` (``"csv,xlsx"``), each once, checked by
    ``ballscrew.results.export.parse_formats``; :class:`InputError` for none or others."""
    if text is None:
        return ()
    from ballscrew.results.export import FORMATS, parse_formats

    formats = tuple(parse_formats(text))
    if not formats:
        raise InputError("--export", text, f"a comma-separated list of {', '.join(FORMATS)}")
    return formats


def quantity_option(option: str, text: str | None, kind: str) -> float | None:
    """The SI value of an option given with or without a unit (``--speed "1500 rpm"``)."""
    from ballscrew.units import to_si

    if text is None:
        return None
    try:
        return to_si(text, kind)
    except ValueError as exc:
        raise InputError(option, text, str(exc)) from None


def finish(folder: Path) -> None:
    """After a results folder is written (with its exports): its headline numbers and the
    folder.

    The headlines are those of ``summary.json`` in engineering units (the index page shows the
    same numbers); with ``--quiet`` only the folder is printed.
    """
    for bar in _BARS:
        bar.stop()  # the work is done: the bar leaves the terminal to the numbers
    if not is_quiet():
        for line in headline_lines(folder):
            typer.echo(line)
    typer.echo(f"results: {folder}")


def headline_lines(folder: Path) -> list[str]:
    """'  label   value unit' lines of the headline numbers of the results folder ``folder``."""
    from ballscrew.results.headlines import headline_keys, headline_label, headline_rows
    from ballscrew.results.index import SWEEP

    summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    is_sweep = isinstance(summary.get("axes"), dict)
    analysis = str(summary.get("analysis", ""))
    keys = SWEEP.headlines if is_sweep else headline_keys(analysis)
    rows = headline_rows(summary, keys, label=headline_label(analysis))
    width = max((len(label) for label, _ in rows), default=0)
    return [f"  {label:<{width}}  {text}" for label, text in rows]
