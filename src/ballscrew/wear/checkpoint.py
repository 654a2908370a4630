"""Checkpoint files of a wear run: written atomically, read back only when sound.

A checkpoint is an ``.npz`` archive of named arrays plus a JSON ``meta`` record. It is written
to a uniquely named temporary file beside it (created with ``O_EXCL``, so never through a
planted link) and renamed over it, which replaces a link at the path instead of following it.
Reading never follows a link either; a checkpoint that cannot be read is reported with a
:class:`CheckpointWarning` and ignored, so the run starts afresh.
"""

from __future__ import annotations

import json
import os
import warnings
import zipfile
from pathlib import Path
from typing import Any

import numpy as np

from ballscrew.files import atomic_file


class CheckpointWarning(UserWarning):
    """A wear checkpoint was unusable and is ignored: the run starts afresh."""


def save_checkpoint(path: Path, meta: dict[str, Any], arrays: dict[str, Any]) -> None:
    """Write ``meta`` and ``arrays`` to ``path`` atomically."""
    with atomic_file(path) as tmp, tmp.open("wb") as fh:
        np.savez(fh, meta=np.array(json.dumps(meta)), **arrays)


def load_checkpoint(path: Path) -> tuple[dict[str, Any], dict[str, np.ndarray]] | None:
    """``(meta, arrays)`` of the checkpoint at ``path``; None if there is none or it is unusable.

    An unusable one (a link, empty, truncated, not an archive, no ``meta``) gives a warning.
    """
    if not os.path.lexists(path):
        return None
    if path.is_symlink() or not path.is_file():
        return ignore_checkpoint(path, "it is not a regular file")
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
        with os.fdopen(fd, "rb") as fh, np.load(fh, allow_pickle=False) as data:
            arrays = {name: np.array(data[name]) for name in data.files}
        meta = json.loads(str(arrays.pop("meta")))
    except (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile) as exc:
        return ignore_checkpoint(path, f"it cannot be read ({type(exc).__name__})")
    if not isinstance(meta, dict):
        return ignore_checkpoint(path, "its meta record is not a table")
    return meta, arrays


def ignore_checkpoint(path: Path, reason: str) -> None:
    """Warn that the checkpoint at ``path`` is ignored and the run starts afresh."""
    warnings.warn(
        f"the wear checkpoint {path} is ignored ({reason}); starting afresh",
        CheckpointWarning,
        stacklevel=3,
    )
