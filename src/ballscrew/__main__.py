"""``python -m ballscrew``: the same command line as the ``ballscrew`` entry point."""

from ballscrew.cli import app

app(prog_name="ballscrew")
