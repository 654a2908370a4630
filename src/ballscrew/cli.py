"""Command-line interface: a thin shell over the library.

Each command reads a case, runs one analysis and writes a results folder. Errors the user can
fix (bad input, unwritable output, a solver that did not converge) are one line on stderr and
exit status 2, never a traceback.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from functools import wraps
from pathlib import Path
from typing import Annotated, Any

import typer

from ballscrew import __version__
from ballscrew.errors import BallscrewError

app = typer.Typer(
    name="ballscrew",
    help="Precision ball-screw simulation: contact, thermal contact resistance, temperatures, "
    "kinematics and wear.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    add_completion=False,
)

CaseArg = Annotated[
    Path, typer.Argument(help="case file (TOML)", exists=False, dir_okay=False, show_default=False)
]
OutOpt = Annotated[Path, typer.Option("--out", "-o", help="results folder to write")]

log = logging.getLogger("ballscrew")


def _version(show: bool) -> None:
    if show:
        typer.echo(f"ballscrew {__version__}")
        raise typer.Exit()


@app.callback()
def main(
    verbose: Annotated[bool, typer.Option("--verbose", "-v", help="more log output")] = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="errors only")] = False,
    version: Annotated[
        bool, typer.Option("--version", callback=_version, is_eager=True, help="show version")
    ] = False,
) -> None:
    """Set up logging to stderr (data and reports go to files)."""
    level = logging.DEBUG if verbose else logging.WARNING if quiet else logging.INFO
    logging.basicConfig(level=level, format="%(message)s", force=True)


def user_errors_exit_2(command: Callable[..., Any]) -> Callable[..., Any]:
    """Turn :class:`BallscrewError` into a message on stderr and exit status 2."""

    @wraps(command)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return command(*args, **kwargs)
        except BallscrewError as exc:
            for line in str(exc).splitlines():
                typer.echo(f"error: {line}", err=True)
            raise typer.Exit(2) from None

    return wrapper


@app.command()
@user_errors_exit_2
def contact(case_file: CaseArg, out: OutOpt = Path("results/contact")) -> None:
    """Solve the screw-side and nut-side contact of one ball of the loaded nut."""
    from ballscrew.analyses.ball_contact import solve_ball_contacts
    from ballscrew.case import load_case
    from ballscrew.results import check_output_folder
    from ballscrew.results.contact_report import write_ball_contacts

    case = load_case(case_file)
    check_output_folder(out)
    result = solve_ball_contacts(case)
    folder = write_ball_contacts(result, out)
    log.info("wrote %s", folder / "report.html")


@app.command()
@user_errors_exit_2
def sweep(
    case_file: CaseArg,
    vary: Annotated[
        list[str],
        typer.Option(help="KEY=START:STOP:NUM or KEY=V1,V2,... (repeat for a grid)"),
    ],
    analysis: Annotated[str, typer.Option(help="analysis run at each point")] = "tcr",
    out: OutOpt = Path("results/sweep"),
    scheduler: Annotated[
        str | None, typer.Option(help="address of a running Dask scheduler (default: local)")
    ] = None,
    workers: Annotated[int, typer.Option(min=1, help="local cluster workers")] = 2,
) -> None:
    """Run an analysis over a grid of case values on Dask; re-runs skip finished points."""
    from ballscrew.case import load_case
    from ballscrew.results.sweep_report import write_sweep
    from ballscrew.sweep import parse_axis, run_sweep
    from ballscrew.sweep.registry import get_analysis

    case = load_case(case_file)
    axes = [parse_axis(text) for text in vary]
    function = get_analysis(analysis)
    folder = check_sweep_folder(out)

    def progress(done: int, total: int) -> None:
        log.info("sweep: %d/%d points done", done, total)

    dataset, computed = run_sweep(
        case, axes, function, analysis, folder, scheduler, workers, progress
    )
    write_sweep(dataset, folder, computed)
    log.info("wrote %s", folder / "report.html")


def check_sweep_folder(out: Path) -> Path:
    """A sweep writes in place (to resume): the folder must be new, empty or an earlier sweep."""
    from ballscrew.errors import InputError
    from ballscrew.results import check_output_folder

    out = out.expanduser().resolve()
    if (out / "points").is_dir():
        return out
    out = check_output_folder(out)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError("--out", str(out), f"a writable folder ({exc.strerror})") from None
    return out


if __name__ == "__main__":  # pragma: no cover
    app()
