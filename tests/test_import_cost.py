"""Importing the command line leaves the costly plotting library for the first figure."""

import os
import subprocess
import sys
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"


def test_importing_the_cli_does_not_import_matplotlib():
    code = "import sys, ballscrew.cli; print(sorted(m for m in sys.modules if 'matplotlib' in m))"
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env
    ).stdout
    assert out.strip() == "[]"


def test_the_first_figure_draws_with_the_agg_backend():
    from ballscrew.plotting import pyplot

    assert pyplot().get_backend().lower() == "agg"
