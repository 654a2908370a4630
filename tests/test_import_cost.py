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


HEAVY = {"pint", "xarray", "scipy", "dask", "distributed", "matplotlib", "pandas"}


def _run(code: str) -> str:
    """The standard output of ``code`` in a fresh interpreter on this checkout."""
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    return done.stdout


def _heavy_modules(code: str) -> list[str]:
    """The heavy libraries in ``sys.modules`` after ``code`` ran in a fresh interpreter."""
    check = f"\nimport sys\nprint(sorted({{m.split('.')[0] for m in sys.modules}} & {HEAVY!r}))"
    return eval(_run(code + check).strip().splitlines()[-1])


def test_importing_ballscrew_imports_no_heavy_library():
    assert _heavy_modules("import ballscrew") == []


def test_version_and_every_help_of_python_m_ballscrew_import_no_heavy_library():
    """``python -m ballscrew --version``, ``--help`` and ``<command> --help`` for each command,
    one after the other in one interpreter, each with exit status 0."""
    code = (
        "import contextlib, io, pkgutil, runpy, sys\n"
        "from ballscrew import commands\n"
        "names = [m.name.replace('_', '-') for m in pkgutil.iter_modules(commands.__path__)\n"
        "         if not m.name.startswith('_')]\n"
        "for argv in [['--version'], ['--help'], *([n, '--help'] for n in names)]:\n"
        "    sys.argv = ['ballscrew', *argv]\n"
        "    with contextlib.redirect_stdout(io.StringIO()) as out:\n"
        "        try:\n"
        "            runpy.run_module('ballscrew', run_name='__main__')\n"
        "        except SystemExit as exc:\n"
        "            assert exc.code in (0, None), (argv, exc.code)\n"
        "    assert out.getvalue(), argv\n"
        "print(len(names))"
    )
    assert _heavy_modules(code) == []
    assert int(_run(code).strip()) >= 10  # every command was asked for its help


def test_every_public_name_resolves_to_what_type_checkers_see():
    """Each name of ``__all__`` resolves in a fresh interpreter to the object the
    ``TYPE_CHECKING`` imports of ``ballscrew/__init__.py`` name, and those are all of them."""
    code = (
        "import ast, ballscrew\n"
        "tree = ast.parse(open(ballscrew.__file__, encoding='utf-8').read())\n"
        "block = next(n for n in tree.body if isinstance(n, ast.If)\n"
        "             and ast.unparse(n.test) == 'TYPE_CHECKING')\n"
        "listed = set(dir(ballscrew))\n"
        "seen = {}\n"
        "exec(compile(ast.Module(block.body, []), 'stub', 'exec'), seen)\n"
        "seen.pop('__builtins__')\n"
        "public = set(ballscrew.__all__) - {'__version__'}\n"
        "assert set(seen) == public, set(seen) ^ public\n"
        "assert public <= listed, public - listed\n"
        "assert all(getattr(ballscrew, n) is seen[n] for n in sorted(public))\n"
        "from ballscrew import screw_tcr, load_case, results\n"
        "print(screw_tcr.__module__, load_case.__module__, results.__name__)"
    )
    assert _run(code).split() == [
        "ballscrew.analyses.screw_tcr",
        "ballscrew.case.loader",
        "ballscrew.results",
    ]


def test_an_unknown_name_is_an_attribute_error():
    import ballscrew

    for name in ("no_such_model", "_private", "__wrapped__"):
        assert not hasattr(ballscrew, name), name


def test_the_sweep_help_lists_exactly_the_sweepable_analyses():
    from ballscrew.commands.sweep import SWEEPABLE_HELP
    from ballscrew.sweep.registry import SWEEPABLE

    assert SWEEPABLE_HELP == SWEEPABLE
