"""``ballscrew index``: one page over several results folders."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import command, log


@command
def index(
    folder: Annotated[
        Path, typer.Argument(help="folder holding results folders", metavar="FOLDER")
    ],
    title: Annotated[str, typer.Option(help="page title", metavar="TEXT")] = "ballscrew results",
) -> None:
    """Write FOLDER/index.html: headline numbers, a figure and a link per results folder."""
    from ballscrew.errors import InputError
    from ballscrew.results.index import write_index

    page = folder / "index.html"
    if os.path.lexists(page) and not _written_by_ballscrew(page):
        raise InputError("folder", str(folder), "a folder without an index.html of your own")
    log.info("wrote %s", write_index(folder, title))


def _written_by_ballscrew(page: Path) -> bool:
    """True if ``page`` is a regular file that an earlier ``ballscrew index`` wrote."""
    if page.is_symlink() or not page.is_file():
        return False
    with page.open("rb") as fh:
        head = fh.read(4096).decode("utf-8", "replace")
    return "<p class='meta'>" in head and " · ballscrew " in head
