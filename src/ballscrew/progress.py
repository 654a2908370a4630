"""Progress of long work (thermal transients, wear runs, sweeps), told to whoever listens.

A long loop calls :func:`advance` with what it has done of its total; a listener installed
with :func:`listening` (the command line's progress bar) hears it. Without a listener
:func:`advance` does nothing, so library users and tests pay nothing.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar

__all__ = ["Listener", "advance", "listening"]

Listener = Callable[[str, float, float], None]
"""``listener(task, done, total)``: ``done`` of ``total`` units of ``task`` are finished."""

_LISTENER: ContextVar[Listener | None] = ContextVar("ballscrew_progress", default=None)


def advance(task: str, done: float, total: float) -> None:
    """Tell the listener, if any, that ``done`` of ``total`` units of ``task`` are finished."""
    listener = _LISTENER.get()
    if listener is not None:
        listener(task, float(done), float(total))


@contextmanager
def listening(listener: Listener) -> Iterator[None]:
    """Within the block, :func:`advance` calls ``listener``."""
    token = _LISTENER.set(listener)
    try:
        yield
    finally:
        _LISTENER.reset(token)
