"""An index page over several results folders (what ``make demo`` opens)."""

from __future__ import annotations

import html
import json
import os
import warnings
from pathlib import Path
from typing import Any

from ballscrew.analyses.catalog import ANALYSES
from ballscrew.analyses.result import Analysis
from ballscrew.errors import InputError
from ballscrew.files import atomic_file
from ballscrew.results.folder import SUMMARY_NAME
from ballscrew.results.headlines import headline_label, headline_rows
from ballscrew.results.report import Section, write_report

HEADLINES = 6
"""Scalars shown per results folder when its analysis names no headlines."""

SWEEP = Analysis(
    "sweep",
    "an analysis over a grid of case values",
    headlines=("points", "computed_now", "failed"),
    key_figure="sweep_resistance_per_area.png",
)
"""What the index shows of a sweep folder (its figures are ``sweep_<scalar>.png``)."""


def _descriptor(kind: str) -> Analysis | None:
    """The descriptor of the analysis ``kind`` of a results folder (None if unknown)."""
    if kind == SWEEP.name:
        return SWEEP
    return ANALYSES[kind] if kind in ANALYSES.names else None


def _headlines(summary: dict[str, Any], analysis: str) -> list[str]:
    """'label = value unit' for the analysis' headlines (or its first top-level numbers)."""
    descriptor = _descriptor(analysis)
    keys = descriptor.headlines if descriptor is not None else ()
    rows = headline_rows(summary, keys, HEADLINES, headline_label(analysis))
    return [f"{label} = {text}" for label, text in rows]


class SkippedFolderWarning(UserWarning):
    """A sub-folder looked like a results folder but could not be read; the index leaves it out."""


def _is_results_folder(path: Path) -> bool:
    try:
        return path.is_dir() and (path / SUMMARY_NAME).is_file()
    except OSError:  # unreadable, or a symlink loop
        return False


def results_folders(root: Path) -> list[Path]:
    """Sub-folders of ``root`` holding a finished results folder, in name order."""
    try:
        entries = list(root.iterdir())
    except OSError as exc:
        raise InputError("folder", str(root), f"a readable folder ({exc.strerror})") from None
    return sorted(p for p in entries if _is_results_folder(p))


def _read_summary(folder: Path) -> dict[str, Any] | None:
    """The folder's summary as a JSON object, or None (with a warning) when it is unusable."""
    try:
        summary = json.loads((folder / SUMMARY_NAME).read_text(encoding="utf-8"))
    except OSError as exc:
        reason = f"cannot read {SUMMARY_NAME} ({exc.strerror})"
    except (ValueError, RecursionError):  # not UTF-8, not JSON, or absurd numbers or nesting
        reason = f"{SUMMARY_NAME} is not JSON"
    else:
        if isinstance(summary, dict):
            return summary
        reason = f"{SUMMARY_NAME} holds a {type(summary).__name__}, not an object"
    message = f"{folder.name}: left out of the index: {reason}"
    warnings.warn(message, SkippedFolderWarning, stacklevel=3)
    return None


def _text(value: Any, default: str = "") -> str:
    """A summary entry shown as text: strings as they are, anything else as ``default``."""
    return value if isinstance(value, str) else default


def _describe(summary: dict[str, Any]) -> tuple[str, str, str]:
    """(analysis kind, analysis text, case) of a summary, whatever shape its entries have."""
    analysis = kind = _text(summary.get("analysis"), "?")
    axes = summary.get("axes")
    if isinstance(axes, dict):
        kind = "sweep"
        analysis = f"sweep of {analysis} over {', '.join(map(str, axes))}"
    case = _text(summary.get("case")) or _text(summary.get("source"))
    return kind, analysis, case


def _figure_of(folder: Path, kind: str) -> list[Path]:
    """The folder's key figure (else its first PNG) if it is a readable file; else none."""
    descriptor = _descriptor(kind)
    key = folder / ((descriptor and descriptor.key_figure) or "")
    try:
        figures = [key] if key.is_file() else sorted(folder.glob("*.png"))[:1]
        return [f for f in figures if f.is_file() and os.access(f, os.R_OK)]
    except OSError:
        return []


def write_index(root: str | Path, title: str = "ballscrew results") -> Path:
    """Write ``root/index.html``: per results folder its analysis, case, headline numbers, its
    first figure and a link to its own report. Returns the path.

    Sub-folders whose summary.json is unreadable or not a JSON object are left out with a
    :class:`SkippedFolderWarning`; a folder without report.html is listed without a link.
    """
    root = _checked_root(root)
    rows, sections, linked = [], [], []
    for folder in results_folders(root):
        summary = _read_summary(folder)
        if summary is None:
            continue
        kind, analysis, case = _describe(summary)
        has_report = (folder / "report.html").is_file()
        link = f"{folder.name}/report.html" if has_report else "none (no report.html)"
        linked += [folder] if has_report else []
        rows.append([folder.name, analysis, case, "; ".join(_headlines(summary, kind))])
        sections.append(
            Section(
                f"{folder.name}: {analysis}",
                paragraphs=[f"Case {case}. Full report: {link}"],
                figures=[(f, f"{folder.name}: {f.stem}") for f in _figure_of(folder, kind)],
            )
        )
    if not rows:
        raise InputError("folder", str(root), "a folder holding readable results folders")
    overview = Section("Results", tables=[(["folder", "analysis", "case", "headline"], rows)])
    path = root / "index.html"
    try:
        with atomic_file(path) as tmp:  # a reader never sees a half-written index
            write_report(tmp, title, f"{len(rows)} results folders", [overview, *sections])
            _link_reports(tmp, linked)
    except OSError as exc:
        raise InputError("folder", str(root), f"a writable folder ({exc.strerror})") from None
    return path


def _checked_root(root: str | Path) -> Path:
    """``root`` resolved, if it is an existing folder holding at least one results folder."""
    try:
        resolved = Path(root).resolve(strict=True)
    except (OSError, RuntimeError):  # missing, or a symlink loop
        raise InputError("folder", str(root), "an existing folder of results folders") from None
    if not resolved.is_dir():
        raise InputError("folder", str(root), "an existing folder of results folders")
    if not results_folders(resolved):
        raise InputError("folder", str(root), "a folder holding results folders (summary.json)")
    return resolved


def _link_reports(path: Path, folders: list[Path]) -> None:
    """Turn the 'Full report: X' texts into links (relative, so the folder can be moved)."""
    text = path.read_text(encoding="utf-8")
    for folder in folders:
        target = f"{folder.name}/report.html"
        escaped = html.escape(target)
        text = text.replace(
            f"Full report: {escaped}", f'Full report: <a href="{escaped}">{escaped}</a>'
        )
    path.write_text(text, encoding="utf-8")
