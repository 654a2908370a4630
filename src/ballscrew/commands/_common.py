"""Options, console output and error handling shared by every subcommand.

Every command function is decorated with :func:`command`, which adds ``-q/--quiet`` and
``-v/--verbose``, shows one progress bar (with ETA) for long work, prints the headline numbers
and the results folder, and turns :class:`~ballscrew.errors.BallscrewError` into one line on
stderr and exit status 2.
"""

from __future__ import annotations

import inspect
import json
import logging
import sys
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from functools import wraps
from pathlib import Path
from typing import Annotated, Any

import typer

from ballscrew.errors import BallscrewError, InputError

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
EXPORT_FORMATS = ("csv", "xlsx", "mat")
"""Formats ``--export`` accepts (besides the NetCDF and JSON every results folder holds)."""
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


def command(function: Callable[..., Any]) -> Callable[..., Any]:
    """A subcommand: ``function`` with ``-q/--quiet`` and ``-v/--verbose`` added, a progress
    bar for long work, and user errors as one line and exit status 2.

    The options also work before the command name (``ballscrew -q wear …``).
    """
    signature = inspect.signature(function, eval_str=True)
    extra = [
        inspect.Parameter(
            "verbose", inspect.Parameter.KEYWORD_ONLY, default=False, annotation=VerboseOpt
        ),
        inspect.Parameter(
            "quiet", inspect.Parameter.KEYWORD_ONLY, default=False, annotation=QuietOpt
        ),
    ]
    parameters = [*signature.parameters.values(), *extra]

    @user_errors_exit_2
    @wraps(function)
    def wrapper(*args: Any, verbose: bool = False, quiet: bool = False, **kwargs: Any) -> Any:
        if verbose or quiet:
            set_verbosity(verbose, quiet)
        with progress_bar():
            return function(*args, **kwargs)

    wrapper.__signature__ = signature.replace(parameters=parameters)  # type: ignore[attr-defined]
    wrapper.__annotations__ = {p.name: p.annotation for p in parameters}
    return wrapper


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
    """The formats of ``--export`` (``"csv,xlsx"``), each once; :class:`InputError` for others."""
    if text is None:
        return ()
    formats = tuple(dict.fromkeys(f.strip().lower() for f in text.split(",") if f.strip()))
    unknown = [f for f in formats if f not in EXPORT_FORMATS]
    if unknown or not formats:
        allowed = f"a comma-separated list of {', '.join(EXPORT_FORMATS)}"
        raise InputError("--export", text, allowed)
    return formats


def analyse(
    name: str,
    case_file: Path,
    out: Path,
    options: tuple[bool, list[str] | None, str | None],
    run: Callable[[Any], Any],
) -> None:
    """The flow of a command on one case: read it with the ``--set`` values, ``run(case)``,
    write the results folder of the result, export it and print its headlines.

    ``options``: the command's ``(--force, --set, --export)``.
    """
    from ballscrew.case import load_case
    from ballscrew.results import claim_output, write_results

    force, sets, export = options
    formats = export_formats(export)
    case = load_case(case_file, parse_sets(sets))
    with claim_output(out, command=name, force=force, inputs=[case_file]):
        folder = write_results(run(case), out, case_file)
        finish(folder, formats)


def quantity_option(option: str, text: str | None, kind: str) -> float | None:
    """The SI value of an option given with or without a unit (``--speed "1500 rpm"``)."""
    from ballscrew.units import to_si

    if text is None:
        return None
    try:
        return to_si(text, kind)
    except ValueError as exc:
        raise InputError(option, text, str(exc)) from None


def finish(folder: Path, formats: Sequence[str] = ()) -> None:
    """After a results folder is written: the exports, the headline numbers and the folder.

    The headlines are those of ``summary.json`` in engineering units (the index page shows the
    same numbers); with ``--quiet`` only the folder is printed.
    """
    if formats:
        from ballscrew.results.export import export_results

        export_results(folder, formats)
    for bar in _BARS:
        bar.stop()  # the work is done: the bar leaves the terminal to the numbers
    if not is_quiet():
        for line in headline_lines(folder):
            typer.echo(line)
    typer.echo(f"results: {folder}")


def headline_lines(folder: Path) -> list[str]:
    """'  label   value unit' lines of the headline numbers of the results folder ``folder``."""
    from ballscrew.results.headlines import headline_keys, headline_rows
    from ballscrew.results.index import SWEEP

    summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    is_sweep = isinstance(summary.get("axes"), dict)
    keys = SWEEP.headlines if is_sweep else headline_keys(str(summary.get("analysis", "")))
    rows = headline_rows(summary, keys)
    width = max((len(label) for label, _ in rows), default=0)
    return [f"  {label:<{width}}  {text}" for label, text in rows]
