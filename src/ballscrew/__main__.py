"""``python -m ballscrew``: the same command line as the ``ballscrew`` entry point."""

from ballscrew.cli import app

if __name__ == "__main__":  # importing the module (pydoc, doctests) runs nothing
    app(prog_name="ballscrew")
