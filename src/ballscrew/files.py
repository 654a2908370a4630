"""Writing files safely: a unique temporary file, renamed into place only when complete."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

__all__ = ["UMASK", "atomic_file"]

UMASK = os.umask(0o022)
"""The process umask (read once: ``os.umask`` can only be read by setting it)."""
os.umask(UMASK)


@contextmanager
def atomic_file(path: Path) -> Iterator[Path]:
    """Yield a unique temporary path beside ``path`` that replaces ``path`` on success.

    The temporary file is created with ``O_EXCL`` (never through a planted link) and removed on
    failure; the final rename replaces a link at ``path`` instead of writing through it.
    """
    hidden = path.name if path.name.startswith(".") else f".{path.name}"
    fd, name = tempfile.mkstemp(prefix=f"{hidden}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    tmp = Path(name)
    try:
        yield tmp
        tmp.chmod(0o666 & ~UMASK)  # as an ordinary new file, not mkstemp's 0600
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
