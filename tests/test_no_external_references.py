"""Docstrings, comments and docs cite the theory manual or the original papers, never outside files.

Forbidden pointers: the working notes that are not in the repository (``contact-tcr.md``,
``kinematics-wear.md``, ``thermal-fe-engines.md``, anything under ``shared/``, "the physics
reference", "the physics notes", "the engine report", "the seed paper") and issue numbers.
"""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCANNED = ("src", "docs", "examples", "README.md")
FORBIDDEN = re.compile(
    r"contact-tcr|kinematics-wear|thermal-fe-engines|shared/|seed paper|physics reference"
    r"|physics notes|engine report|\bissue #?\d+",
    re.IGNORECASE,
)


def _files() -> list[Path]:
    found: list[Path] = []
    for name in SCANNED:
        path = ROOT / name
        if path.is_dir():
            found.extend(p for p in path.rglob("*") if p.is_file())
        else:
            found.append(path)
    return sorted(p for p in found if "__pycache__" not in p.parts)


def _offences() -> list[str]:
    lines = []
    for path in _files():
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:  # binary files (images) hold no citations
            continue
        rel = path.relative_to(ROOT).as_posix()
        lines += [
            f"{rel}:{number}: {line.strip()}"
            for number, line in enumerate(text.splitlines(), start=1)
            if FORBIDDEN.search(line)
        ]
    return lines


def _report(offences: list[str]) -> str:
    return f"{len(offences)} pointer(s) to files outside the repository:\n" + "\n".join(offences)


def test_no_external_references() -> None:
    offences = _offences()
    assert not offences, _report(offences)
