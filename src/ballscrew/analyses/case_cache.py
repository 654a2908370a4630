"""A small thread-safe cache of results keyed by the case inputs they depend on.

The key is the JSON of the case fields an analysis reads (``include``) or of all but those it
does not read (``exclude``, fixed or a function of the case where what is read depends on the
case's options); a too-small key would hand one case the result of another, so a cache names
every section its computation reads, through every function it calls.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any, Generic, TypeAlias, TypeVar

from ballscrew.case import Case

__all__ = ["CaseCache", "Fields"]

T = TypeVar("T")
Fields: TypeAlias = set[str] | dict[str, Any]
"""Case fields as pydantic's ``include``/``exclude``: section names, or a section → its fields
(``True`` for the whole section)."""


class CaseCache(Generic[T]):
    """At most ``size`` results of ``compute(case)``, the oldest evicted first.

    ``include``/``exclude`` select the case fields of the key (as ``Case.model_dump_json``);
    ``exclude`` may be a function of the case (the fields that case's computation never reads).
    The result is computed outside the lock (two threads may compute the same key once each).
    """

    def __init__(
        self,
        compute: Callable[[Case], T],
        size: int,
        *,
        include: Fields | None = None,
        exclude: Fields | Callable[[Case], Fields] | None = None,
    ) -> None:
        self.compute = compute
        self.size = size
        self.include = include
        self.exclude = exclude
        self._lock = threading.Lock()
        self._store: dict[str, T] = {}

    def key(self, case: Case) -> str:
        """The JSON of the fields the result depends on."""
        exclude = self.exclude(case) if callable(self.exclude) else self.exclude
        return case.model_dump_json(include=self.include, exclude=exclude)

    def __call__(self, case: Case) -> T:
        key = self.key(case)
        with self._lock:
            if key in self._store:
                return self._store[key]
        value = self.compute(case)
        with self._lock:
            while len(self._store) >= self.size:
                self._store.pop(next(iter(self._store)), None)
            self._store[key] = value
        return value

    def clear(self) -> None:
        """Forget every result."""
        with self._lock:
            self._store.clear()
