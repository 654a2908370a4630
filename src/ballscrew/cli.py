"""Command-line interface: a thin shell over the library.

Each subcommand is one module ``ballscrew.commands.<name>`` with a function ``<name>`` (found
here, so a new command is one module); it reads a case, runs one analysis and writes a results
folder. Errors the user can fix (bad input, unwritable output, a solver that
did not converge) are one line on stderr and exit status 2, never a traceback.
"""

from __future__ import annotations

import inspect
import logging
import pkgutil
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from importlib import import_module
from typing import Annotated, Any, TextIO

import typer
from typer.core import TyperGroup

try:  # newer typer carries its own copy of click
    from typer._click import Context, exceptions
except ImportError:  # pragma: no cover - typer on the installed click
    from click import Context, exceptions

from ballscrew import __version__, commands
from ballscrew.commands._common import QuietOpt, VerboseOpt, set_verbosity


class _OneLineUsageError(exceptions.ClickException):
    """A command line click cannot parse (a wrong option value, a missing argument), shown as
    one ``error:`` line with exit status 2 like every other bad input."""

    exit_code = 2

    def show(self, file: TextIO | None = None) -> None:
        typer.echo(f"error: {self.format_message()}", err=True)


@contextmanager
def _one_line_usage_errors() -> Iterator[None]:
    try:
        yield
    except exceptions.NoArgsIsHelpError:
        raise
    except exceptions.UsageError as exc:
        raise _OneLineUsageError(exc.format_message()) from None


class _Commands(TyperGroup):
    """The subcommands, with their usage errors as one line instead of click's usage box."""

    def make_context(self, *args: Any, **kwargs: Any) -> Context:
        with _one_line_usage_errors():
            return super().make_context(*args, **kwargs)

    def invoke(self, ctx: Context) -> Any:
        with _one_line_usage_errors():
            return super().invoke(ctx)


app = typer.Typer(
    name="ballscrew",
    cls=_Commands,
    help="Precision ball-screw simulation: contact, thermal contact resistance, temperatures, "
    "kinematics and wear.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    add_completion=False,
    rich_markup_mode=None,  # help texts as written: rich markup would eat "[thermal]"
)


def _version(show: bool) -> None:
    if show:
        typer.echo(f"ballscrew {__version__}")
        raise typer.Exit()


@app.callback()
def main(
    verbose: VerboseOpt = False,
    quiet: QuietOpt = False,
    version: Annotated[
        bool, typer.Option("--version", callback=_version, is_eager=True, help="show version")
    ] = False,
) -> None:
    """Set up logging to stderr (data and reports go to files)."""
    logging.basicConfig(level=logging.WARNING, format="%(message)s", force=True)
    set_verbosity(verbose, quiet)
    warnings.showwarning = _show_warning


def _show_warning(
    message: Warning | str,
    category: type[Warning],
    filename: str,
    lineno: int,
    file: TextIO | None = None,
    line: str | None = None,
) -> None:
    """Warnings on the command line: one line each, without the source line."""
    typer.echo(f"warning: {message}", err=True)


def _short_help(function: object) -> str:
    """The first line of a command's docstring, shown whole in the list of commands."""
    return (inspect.getdoc(function) or "").split("\n", 1)[0]


# Every module ballscrew.commands.<name> (not _private) is the subcommand <name>.
for _module in pkgutil.iter_modules(commands.__path__):
    if not _module.name.startswith("_"):
        _name = _module.name
        _function = getattr(import_module(f"ballscrew.commands.{_name}"), _name)
        app.command(short_help=_short_help(_function))(_function)

if __name__ == "__main__":  # pragma: no cover
    app()
