"""Results folders: written only by ballscrew, replaced atomically, one writer at a time.

A run *claims* its ``--out`` folder: it checks that the folder is new, empty or a results folder
this tool wrote (the marker file :data:`MARKER_NAME` names the command, the version and every
file written), takes an exclusive lock beside it for the whole run and tidies what killed runs
left behind. Results are written into a hidden scratch folder in the same parent and swapped in
only when complete, so the final name holds the old or the new complete folder at every moment.
A file ballscrew did not write is never deleted or overwritten.
"""

from __future__ import annotations

import ctypes
import errno
import json
import os
import shutil
import tempfile
from collections.abc import Iterable, Iterator, Sequence
from contextlib import contextmanager, nullcontext
from dataclasses import dataclass
from fnmatch import fnmatchcase
from glob import escape
from pathlib import Path
from typing import Any

from filelock import FileLock, Timeout

from ballscrew import __version__
from ballscrew.errors import BallscrewError, InputError
from ballscrew.files import atomic_file

#: The file whose presence marks a folder as a finished ballscrew results folder.
SUMMARY_NAME = "summary.json"
#: The file naming the command, the version and the files of a folder ballscrew wrote.
MARKER_NAME = ".ballscrew-results.json"
#: Files a sweep writes in place into its folder (besides those its marker lists).
SWEEP_PATTERNS = (
    "points/*.json",
    "points/.*.tmp",
    ".*.tmp",
    "sweep.nc",
    "sweep_*.png",
    SUMMARY_NAME,
    "report.html",
)


class ResultsWriteError(BallscrewError):
    """Results could not be written (disk full, quota, read-only); nothing half-written stays."""

    def __init__(self, out: Path, exc: OSError) -> None:
        super().__init__(f"cannot write the results {out}: {exc.strerror or exc}")


IN_MEMORY_BYTES = 256 << 20
"""Largest dataset written to NetCDF through memory rather than by HDF5 on the disk [B]."""


@dataclass(frozen=True)
class _Claim:
    command: str | None
    force: bool


_claims: dict[Path, _Claim] = {}


def _resolve(out: str | Path) -> Path:
    if not str(out).strip():
        raise InputError("--out", str(out), "a folder name, not an empty string")
    return Path(out).expanduser().resolve()


def lock_path(out: str | Path) -> Path:
    """The lock file of a run writing to ``out``: ``.<name>.lock`` beside the folder."""
    out = Path(out).expanduser().resolve()
    return out.parent / f".{out.name}.lock"


def _files(folder: Path) -> list[str]:
    """Every entry but directories under ``folder`` (symbolic links included, not followed)."""
    found = []
    for root, dirs, names in os.walk(folder):
        here = Path(root)
        links = [d for d in dirs if (here / d).is_symlink()]
        found += [(here / n).relative_to(folder).as_posix() for n in [*names, *links]]
    return sorted(found)


def _read_marker(folder: Path) -> dict[str, Any] | None:
    path = folder / MARKER_NAME
    if path.is_symlink() or not path.is_file():
        return None
    try:
        marker = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        return None
    if not isinstance(marker, dict) or not isinstance(marker.get("files"), list):
        return None
    return marker


def _owned(name: str, marker: dict[str, Any]) -> bool:
    patterns = [p for p in marker.get("patterns", []) if isinstance(p, str)]
    return (
        name == MARKER_NAME
        or name in marker["files"]
        or any(fnmatchcase(name, p) for p in patterns)
    )


def write_marker(folder: Path, command: str | None, patterns: Sequence[str] = ()) -> None:
    """Write the marker of ``folder``: the command, the version and the files written (those
    ``patterns`` match are owned without being listed)."""
    names = [
        f
        for f in _files(folder)
        if f != MARKER_NAME and not any(fnmatchcase(f, p) for p in patterns)
    ]
    marker = {
        "command": command,
        "version": __version__,
        "files": sorted(set(names)),
        "patterns": list(patterns),
    }
    with atomic_file(folder / MARKER_NAME) as tmp:
        tmp.write_text(json.dumps(marker, indent=1) + "\n", encoding="utf-8")


def _check_location(raw: str | Path, out: Path, inputs: Iterable[str | Path]) -> None:
    cwd = Path.cwd().resolve()
    if out == cwd or out in cwd.parents:
        raise InputError("--out", str(raw), "a folder other than the current one or its parents")
    for item in inputs:
        path = Path(item).expanduser().resolve()
        if out == path or out in path.parents:
            raise InputError("--out", str(raw), f"a folder that does not hold the input {path}")


def _check_replaceable(out: Path, command: str | None, force: bool) -> None:
    """Refuse unless ``out`` is absent, empty or wholly a results folder ballscrew wrote."""
    if not os.path.lexists(out):
        return
    if not out.is_dir():
        raise InputError("--out", str(out), "a folder path, not an existing file")
    if not any(out.iterdir()):
        return
    marker = _read_marker(out)
    if marker is None:
        raise InputError(
            "--out",
            str(out),
            f"a new or empty folder, or a results folder ballscrew wrote (with {MARKER_NAME}); "
            "this one is not, so nothing in it is replaced",
        )
    foreign = [name for name in _files(out) if not _owned(name, marker)]
    if foreign:
        raise InputError(
            "--out",
            str(out),
            f"a results folder holding only files ballscrew wrote; move away "
            f"{len(foreign)} other file(s), e.g. {foreign[0]!r}",
        )
    if command is None or force:
        return
    if marker.get("command") != command or marker.get("version") != __version__:
        raise InputError(
            "--out",
            str(out),
            f"a folder of `ballscrew {command}` {__version__} results; it holds results of "
            f"`ballscrew {marker.get('command')}` {marker.get('version')} (--force replaces them)",
        )


def check_output_folder(
    out: str | Path,
    *,
    command: str | None = None,
    force: bool = False,
    inputs: Iterable[str | Path] = (),
) -> Path:
    """Resolve ``out`` and make sure a results folder may be written there; nothing is created.

    Allowed: a folder that does not exist yet, an empty folder, or a results folder ballscrew
    wrote that holds no other file (it is replaced; one of another command or version only with
    ``force``). Refused: an empty name, the current folder or a parent of it, a folder holding
    one of ``inputs``. Raises :class:`InputError`.
    """
    path = _resolve(out)
    _check_location(out, path, inputs)
    _check_replaceable(path, command, force)
    if path in _claims:
        return path
    parent = next(p for p in (path.parent, *path.parent.parents) if p.exists())
    if not parent.is_dir() or not os.access(parent, os.W_OK | os.X_OK):
        raise InputError("--out", str(path), f"a folder inside a writable directory ({parent})")
    return path


def _make_parents(folder: Path) -> list[Path]:
    """Create ``folder`` and missing parents; return those created, deepest first."""
    missing = [p for p in (folder, *folder.parents) if not p.exists()]
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        _remove_empty(missing)
        raise InputError("--out", str(folder), f"a writable location ({exc.strerror})") from None
    return missing


def _remove_empty(folders: Iterable[Path]) -> None:
    for folder in folders:
        try:
            folder.rmdir()
        except OSError:
            return


def _tidy(out: Path) -> None:
    """Remove what killed runs into ``out`` left (call under the lock): scratch folders, temp
    files, and an old folder set aside during a swap (put back if ``out`` is missing)."""
    stem = f".{escape(out.name)}."
    for scratch in out.parent.glob(stem + "partial-*"):
        shutil.rmtree(scratch, ignore_errors=True)
    for temp in out.parent.glob(stem + "*.tmp"):
        if temp.is_file() or temp.is_symlink():
            temp.unlink(missing_ok=True)
    for aside in sorted(out.parent.glob(stem + "old-*")):
        if not os.path.lexists(out) and _read_marker(aside) is not None:
            aside.rename(out)
        else:
            shutil.rmtree(aside, ignore_errors=True)


def _lock_refusal(lock: Path) -> str:
    """Why the lock file ``lock`` could not be taken: held by another run, or not creatable
    (filelock reports both as a timeout)."""
    try:
        os.close(os.open(lock, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644))
    except FileExistsError:
        return f"a folder no other ballscrew run is writing (another run holds {lock})"
    except OSError as exc:
        return f"a folder that can be created and written (cannot create {lock}: {exc.strerror})"
    lock.unlink(missing_ok=True)  # released meanwhile
    return f"a folder no other ballscrew run is writing (another run held {lock})"


@contextmanager
def claim_output(
    out: str | Path,
    *,
    command: str | None = None,
    force: bool = False,
    inputs: Iterable[str | Path] = (),
) -> Iterator[Path]:
    """Hold ``out`` for a whole run: checked, locked against other writers, tidied.

    Yields the resolved path. A second run claiming the same folder meanwhile is refused with
    :class:`InputError`. On leaving, parents created here and left empty are removed again.
    """
    inputs = list(inputs)
    path = check_output_folder(out, command=command, force=force, inputs=inputs)
    if path in _claims:
        yield path
        return
    created = _make_parents(path.parent)
    lock = FileLock(lock_path(path), blocking=False)
    try:
        lock.acquire()
    except Timeout:
        _remove_empty(created)
        raise InputError("--out", str(path), _lock_refusal(lock_path(path))) from None
    except OSError as exc:
        _remove_empty(created)
        raise InputError("--out", str(path), f"a writable location ({exc.strerror})") from None
    existed = os.path.lexists(path)
    try:
        _tidy(path)
        _check_replaceable(path, command, force)
        _claims[path] = _Claim(command, force)
        yield path
    finally:
        _claims.pop(path, None)
        if not existed and path.is_dir() and not set(_files(path)) - {MARKER_NAME}:
            shutil.rmtree(path, ignore_errors=True)  # a run that wrote nothing leaves nothing
        lock_path(path).unlink(missing_ok=True)  # still held: no waiter can own this inode
        lock.release()
        _remove_empty(created)


@contextmanager
def writing(out: Path) -> Iterator[None]:
    """Turn a failed write (disk full, quota, read-only) into :class:`ResultsWriteError`."""
    try:
        yield
    except ResultsWriteError:
        raise
    except OSError as exc:
        raise ResultsWriteError(out, exc) from None


def write_netcdf(dataset: Any, path: Path) -> Path:
    """Write an xarray Dataset to ``path`` (NetCDF-4/HDF5) through a temporary file.

    HDF5 writing to a full disk can crash the process, so a file of up to
    :data:`IN_MEMORY_BYTES` is built in memory and written with plain file I/O (which raises
    :class:`OSError`); a larger one is written by HDF5 only if the disk has twice its size free.
    """
    with atomic_file(path) as tmp:
        if dataset.nbytes <= IN_MEMORY_BYTES:
            tmp.write_bytes(dataset.to_netcdf(engine="h5netcdf"))
        elif shutil.disk_usage(path.parent).free < 2 * dataset.nbytes:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))
        else:
            dataset.to_netcdf(tmp, engine="h5netcdf")
    return path


_RENAME_EXCHANGE = 2
_AT_FDCWD = -100


def _exchange(a: Path, b: Path) -> bool:
    """Swap two paths in one step (Linux ``renameat2``); False where unsupported."""
    try:
        renameat2 = ctypes.CDLL(None, use_errno=True).renameat2
    except (AttributeError, OSError):
        return False
    done = renameat2(
        _AT_FDCWD, os.fsencode(a), _AT_FDCWD, os.fsencode(b), ctypes.c_uint(_RENAME_EXCHANGE)
    )
    return done == 0


def _swap_in(new: Path, out: Path) -> None:
    """Put the complete folder ``new`` at ``out``; the old one, if any, is removed afterwards."""
    if not os.path.lexists(out):
        new.rename(out)
        return
    if _exchange(new, out):
        shutil.rmtree(new, ignore_errors=True)  # now the old folder
        return
    aside = Path(tempfile.mkdtemp(prefix=f".{out.name}.old-", dir=out.parent))
    out.rename(aside)
    try:
        new.rename(out)
    except BaseException:
        aside.rename(out)
        raise
    shutil.rmtree(aside, ignore_errors=True)


@contextmanager
def results_folder(out: str | Path) -> Iterator[Path]:
    """Context manager yielding a scratch folder that becomes ``out`` on success.

    On an exception the scratch folder is removed and ``out`` is left as it was; a failed write
    raises :class:`ResultsWriteError`. ``out`` is claimed here unless the caller claimed it.
    """
    path = _resolve(out)
    held = path in _claims
    with nullcontext(path) if held else claim_output(out) as path:
        claim = _claims[path]
        scratch = Path(tempfile.mkdtemp(prefix=f".{path.name}.partial-", dir=path.parent))
        try:
            with writing(path):
                yield scratch
                write_marker(scratch, claim.command or _analysis(scratch))
                scratch.chmod(0o755)
                _check_replaceable(path, claim.command, claim.force)
                _swap_in(scratch, path)
        finally:
            shutil.rmtree(scratch, ignore_errors=True)


def _analysis(folder: Path) -> str | None:
    try:
        return json.loads((folder / SUMMARY_NAME).read_text()).get("analysis")
    except (OSError, ValueError, AttributeError):
        return None


def prepare_sweep_folder(out: Path) -> None:
    """Make the claimed ``out`` ready for a sweep written in place (results of another command
    or version, allowed by ``--force``, are removed; the point cache of this version is kept)."""
    marker = _read_marker(out)
    if marker is not None and (
        marker.get("command") != "sweep" or marker.get("version") != __version__
    ):
        for name in _files(out):
            if _owned(name, marker):
                (out / name).unlink()
        marker = None
    with writing(out):
        (out / "points").mkdir(parents=True, exist_ok=True)
        if marker is None:
            write_marker(out, "sweep", SWEEP_PATTERNS)
        for temp in [*out.glob(".*.tmp"), *out.glob("points/.*.tmp")]:
            temp.unlink(missing_ok=True)
