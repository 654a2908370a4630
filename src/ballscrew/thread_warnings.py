"""Warnings recorded per thread.

``warnings.catch_warnings(record=True)`` swaps the process's warning hook and filters, so two
threads that record at once (the points of a Dask worker with several threads) take each other's
warnings, and the one that leaves first takes the other's recording away. :func:`record_warnings`
swaps them once for all the threads that record (the first in installs, the last out restores)
and hands each warning to the innermost recording of the thread that raised it; a thread that
records nothing reaches the hook that was there before.
"""

from __future__ import annotations

import threading
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

__all__ = ["record_warnings"]

_lock = threading.Lock()
_local = threading.local()
_guard: list[warnings.catch_warnings] = []  # the installed hook's restorer while any records
_active = 0
_outer: Any = warnings.showwarning  # the hook that was there before the first recording


def _show(
    message: Any, category: Any, filename: str, lineno: int, file: Any = None, line: Any = None
) -> None:
    recordings = getattr(_local, "recordings", None)
    if recordings:
        recordings[-1].append(
            warnings.WarningMessage(message, category, filename, lineno, file, line)
        )
    else:
        _outer(message, category, filename, lineno, file, line)


@contextmanager
def record_warnings() -> Iterator[list[warnings.WarningMessage]]:
    """Record every warning this thread raises inside the block, each time it is raised (the
    ``always`` action: ``catch_warnings(record=True)`` with ``simplefilter("always")``)."""
    global _active, _outer
    with _lock:
        if _active == 0:
            guard = warnings.catch_warnings()
            guard.__enter__()
            warnings.simplefilter("always")
            _outer, warnings.showwarning = warnings.showwarning, _show
            _guard.append(guard)
        _active += 1
    recordings = _local.__dict__.setdefault("recordings", [])
    caught: list[warnings.WarningMessage] = []
    recordings.append(caught)
    try:
        yield caught
    finally:
        recordings.pop()
        with _lock:
            _active -= 1
            if _active == 0:
                _guard.pop().__exit__(None, None, None)
