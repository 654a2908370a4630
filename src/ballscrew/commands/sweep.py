"""``ballscrew sweep``: an analysis over a grid of case values, on Dask."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import Output, finish, writes_results
from ballscrew.errors import InputError

#: The analyses a sweep can run, as ``--help`` lists them: those of
#: ``ballscrew.sweep.registry.SWEEPABLE`` (a test holds the two equal), written out so that
#: ``--help`` does not import every analysis.
SWEEPABLE_HELP = (
    "contact",
    "tcr",
    "thermal",
    "thermal-network",
    "thermal-fe",
    "operating-point",
    "duty",
    "check",
)

SweepCaseArg = Annotated[
    Path,
    typer.Argument(
        help="case file, or sweep file with a [sweep] table",
        dir_okay=False,
        metavar="CASE_FILE",
    ),
]
VaryOpt = Annotated[
    list[str] | None,
    typer.Option(
        help="KEY=START:STOP:NUM or KEY=V1,V2,... with or without units, e.g. "
        "--vary 'operating.speed=500 rpm:3000 rpm:6' (repeat for a grid)",
        metavar="KEY=RANGE",
    ),
]
AnalysisOpt = Annotated[
    str | None,
    typer.Option(
        help=f"analysis run at each point: {', '.join(SWEEPABLE_HELP)} (default: tcr)",
        metavar="NAME",
    ),
]
SchedulerOpt = Annotated[
    str | None,
    typer.Option(help="address of a running Dask scheduler (default: local)", metavar="ADDRESS"),
]
WorkersOpt = Annotated[int, typer.Option(min=1, help="local cluster workers", metavar="N")]
RetryFailedOpt = Annotated[
    bool, typer.Option(help="recompute points that failed in an earlier run")
]


#: Failed points named on the console; summary.json and the report list them all.
SHOWN_FAILURES = 10


def console_warnings(warnings: list[str], failed: int) -> list[str]:
    """The sweep's warnings for the console: the first :data:`SHOWN_FAILURES` of the ``failed``
    points (which lead ``warnings``) and a count of the rest, then the points' own warnings."""
    shown = warnings[: min(failed, SHOWN_FAILURES)]
    if failed > SHOWN_FAILURES:
        more = failed - SHOWN_FAILURES
        shown.append(f"… and {more} more failed points (see summary.json / report.html)")
    return shown + warnings[failed:]


#: Arguments of :func:`ballscrew.sweep.run_sweep` that the command takes as options.
OPTIONS = ("scheduler", "workers")


def as_option(error: InputError) -> InputError:
    """``error`` naming the command's option (``--scheduler``) where Python names the argument."""
    if error.field not in OPTIONS:
        return error
    return InputError(f"--{error.field}", error.value, error.allowed)


@writes_results
def sweep(
    case_file: SweepCaseArg,
    vary: VaryOpt = None,
    analysis: AnalysisOpt = None,
    scheduler: SchedulerOpt = None,
    workers: WorkersOpt = 2,
    retry_failed: RetryFailedOpt = False,
    *,
    output: Output,
) -> None:
    """Run an analysis over a grid of case values on Dask; re-runs skip finished points."""
    from ballscrew.case import CaseError, with_overrides
    from ballscrew.progress import advance
    from ballscrew.results.folder import prepare_sweep_folder
    from ballscrew.results.sweep_report import write_sweep
    from ballscrew.sweep import parse_axis, run_sweep
    from ballscrew.sweep.cluster import check_workers
    from ballscrew.sweep.registry import get_analysis
    from ballscrew.sweep.spec import check_sweep_size, is_sweep_file, load_sweep, merge_axes

    extra = [parse_axis(text) for text in vary or []]
    if is_sweep_file(case_file):
        spec = load_sweep(case_file)
        case, axes = with_overrides(spec.case, output.overrides), merge_axes(spec.axes, extra)
        name = analysis if analysis is not None else spec.analysis or "tcr"
    else:
        case, axes = output.load_case(case_file), tuple(extra)
        name = "tcr" if analysis is None else analysis
    if not axes:
        raise CaseError(["nothing to sweep: give --vary KEY=START:STOP:NUM"], "sweep")
    check_sweep_size(axes)
    if not scheduler:
        check_workers(workers)
    function = get_analysis(name)

    def progress(done: int, total: int) -> None:
        advance("sweep points", done, total)

    with output.claim(case_file) as folder:
        prepare_sweep_folder(folder)
        try:
            dataset, computed = run_sweep(
                case, axes, function, name, folder, scheduler, workers, progress, retry_failed
            )
        except InputError as error:
            raise as_option(error) from None
        written = write_sweep(dataset, folder, computed, case, axes, export=output.formats)
        summary = json.loads((written / "summary.json").read_text(encoding="utf-8"))
        for message in console_warnings(summary["warnings"], summary["failed"]):
            typer.echo(f"warning: {message}", err=True)
        finish(written)
