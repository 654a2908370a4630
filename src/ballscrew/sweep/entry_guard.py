"""Refuse a local cluster started from a script's top level outside its ``__main__`` guard.

Dask starts its local workers with the ``spawn`` method of :mod:`multiprocessing`: each worker
process runs the user's main script again (as ``__mp_main__``) before it starts. A script that
calls :func:`ballscrew.sweep.run_sweep` at its top level, without
``if __name__ == "__main__":``, would start a cluster again in every worker; multiprocessing
refuses that ("before the current process has finished its bootstrapping phase") and Dask logs
pages of "Nanny failed to start". This check finds the case before any process is started.
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path
from types import FrameType

from ballscrew.errors import BallscrewError

__all__ = ["UnguardedScriptError", "check_entry_guard", "is_guarded"]


class UnguardedScriptError(BallscrewError, RuntimeError):
    """A script starts a local Dask cluster outside its ``if __name__ == "__main__":`` block."""

    def __init__(self, script: str, line: int) -> None:
        self.script = script
        self.line = line
        super().__init__(
            f"{script}:{line} starts a local Dask cluster outside "
            "'if __name__ == \"__main__\":', and each worker process runs the script again: "
            "put the sweep under that guard, or pass scheduler='tcp://HOST:PORT' of a running "
            "Dask scheduler"
        )


def _is_main_test(test: ast.expr) -> bool:
    """``__name__ == "__main__"`` either way round."""
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1):
        return False
    if not isinstance(test.ops[0], ast.Eq):
        return False
    sides = [test.left, test.comparators[0]]
    named = any(isinstance(s, ast.Name) and s.id == "__name__" for s in sides)
    main = any(isinstance(s, ast.Constant) and s.value == "__main__" for s in sides)
    return named and main


def _span(node: ast.AST) -> tuple[int, int]:
    start = getattr(node, "lineno", 0)
    return start, getattr(node, "end_lineno", None) or start


def _guarded(nodes: list[ast.AST], line: int) -> bool:
    for node in nodes:
        start, end = _span(node)
        if not start <= line <= end:
            continue
        if isinstance(node, ast.If) and _is_main_test(node.test):
            return _span(node.body[0])[0] <= line <= _span(node.body[-1])[1]
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
            return True
        inner = [
            child
            for child in ast.iter_child_nodes(node)
            if isinstance(child, ast.stmt | ast.excepthandler | ast.match_case)
        ]
        return _guarded(inner, line)
    return False


def is_guarded(source: str, line: int) -> bool:
    """Whether ``line`` of the module ``source`` runs only in the script itself: in the body of
    ``if __name__ == "__main__":``, or of a function or class (which a re-run only defines).
    A source that does not parse is taken as guarded."""
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError):
        return True
    return _guarded(list(tree.body), line)


def _main_frame() -> FrameType | None:
    """The frame running the main module's top-level code, if it is on the stack."""
    main = sys.modules.get("__main__")
    if main is None:
        return None
    frame = sys._getframe(1)
    while frame is not None:
        if frame.f_globals is vars(main) and frame.f_code.co_name == "<module>":
            return frame
        frame = frame.f_back
    return None


def _rerun_by_spawn() -> bool:
    """Whether a spawned process runs the main module again (as :mod:`multiprocessing` does:
    by its path, or by its module name unless that is a package's ``__main__``)."""
    main = sys.modules.get("__main__")
    spec = getattr(main, "__spec__", None)
    if spec is not None:
        return not (spec.name == "__main__" or spec.name.endswith(".__main__"))
    return getattr(main, "__file__", None) is not None


def check_entry_guard() -> None:
    """Raise :class:`UnguardedScriptError` if a local cluster started now would be started again
    by each of its worker processes (see the module's docstring)."""
    import dask

    if dask.config.get("distributed.worker.multiprocessing-method", "spawn") == "fork":
        return
    frame = _main_frame()
    if frame is None or not _rerun_by_spawn():
        return
    path = Path(frame.f_code.co_filename)
    try:
        source = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return
    if not is_guarded(source, frame.f_lineno):
        raise UnguardedScriptError(str(path), frame.f_lineno)
