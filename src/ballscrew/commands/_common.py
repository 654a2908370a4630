"""Options and error handling shared by every subcommand."""

from __future__ import annotations

import logging
from collections.abc import Callable
from functools import wraps
from pathlib import Path
from typing import Annotated, Any

import typer

from ballscrew.errors import BallscrewError

CaseArg = Annotated[
    Path, typer.Argument(help="case file (TOML)", dir_okay=False, show_default=False)
]
OutOpt = Annotated[Path, typer.Option("--out", "-o", help="results folder to write")]
ForceOpt = Annotated[
    bool,
    typer.Option(
        "--force",
        help="replace a results folder of another command or ballscrew version "
        "(a file ballscrew did not write is never replaced)",
    ),
]

log = logging.getLogger("ballscrew")


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
