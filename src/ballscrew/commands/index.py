"""``ballscrew index``: one page over several results folders."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import log, user_errors_exit_2


@user_errors_exit_2
def index(
    folder: Annotated[Path, typer.Argument(help="folder holding results folders")],
    title: Annotated[str, typer.Option(help="page title")] = "ballscrew results",
) -> None:
    """Write FOLDER/index.html: headline numbers, a figure and a link per results folder."""
    from ballscrew.results.index import write_index

    log.info("wrote %s", write_index(folder, title))
