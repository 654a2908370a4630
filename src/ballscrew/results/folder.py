"""Results folders that appear complete or not at all.

A run writes into a hidden sibling folder and renames it into place only when every file is
written, so a failed run never leaves a half-written folder that looks complete.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from ballscrew.errors import InputError

#: The file whose presence marks a folder as a finished ballscrew results folder.
SUMMARY_NAME = "summary.json"


def check_output_folder(out: str | Path) -> Path:
    """Resolve ``out`` and make sure a results folder can be written there.

    Allowed: a folder that does not exist yet (its parent is created), an empty folder, or an
    earlier ballscrew results folder (it is replaced). Anything else raises :class:`InputError`.
    """
    out = Path(out).expanduser().resolve()
    if out.exists():
        if not out.is_dir():
            raise InputError("--out", str(out), "a folder path, not an existing file")
        if any(out.iterdir()) and not (out / SUMMARY_NAME).is_file():
            raise InputError(
                "--out", str(out), "a new or empty folder, or an earlier ballscrew results folder"
            )
    parent = out.parent
    try:
        parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError("--out", str(out), f"a writable location ({exc.strerror})") from None
    if not os.access(parent, os.W_OK | os.X_OK):
        raise InputError("--out", str(out), f"a folder inside a writable directory ({parent})")
    return out


@contextmanager
def results_folder(out: str | Path) -> Iterator[Path]:
    """Context manager yielding a scratch folder that becomes ``out`` on success.

    On an exception the scratch folder is removed and ``out`` is left as it was.
    """
    out = check_output_folder(out)
    scratch = Path(tempfile.mkdtemp(prefix=f".{out.name}.partial-", dir=out.parent))
    try:
        yield scratch
    except BaseException:
        shutil.rmtree(scratch, ignore_errors=True)
        raise
    if out.exists():
        shutil.rmtree(out)
    scratch.chmod(0o755)
    scratch.rename(out)
