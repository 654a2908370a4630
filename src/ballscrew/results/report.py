"""Self-contained HTML reports: tables and embedded PNG figures in one file."""

from __future__ import annotations

import base64
import html
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import numpy as np

from ballscrew import __version__
from ballscrew.case.inputs import input_rows
from ballscrew.results.about import ABOUT, theory_link
from ballscrew.results.display import engineering, engineering_array
from ballscrew.units import format_number

_STYLE = """
body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;margin:2rem auto;
max-width:70rem;color:#1d2733;line-height:1.45;padding:0 1rem}
h1{font-size:1.6rem;margin-bottom:.2rem}h2{font-size:1.2rem;margin-top:2rem;
border-bottom:1px solid #d5dbe3;padding-bottom:.2rem}
.meta{color:#5b6878;font-size:.9rem}table{border-collapse:collapse;margin:.6rem 0;
font-size:.92rem}th,td{border:1px solid #d5dbe3;padding:.25rem .6rem;text-align:right}
th{background:#eef2f6}td:first-child,th:first-child{text-align:left}
figure{display:inline-block;margin:.5rem 1rem .5rem 0;vertical-align:top}
figure img{max-width:32rem;border:1px solid #e3e7ec}figcaption{font-size:.85rem;color:#5b6878}
p.note{background:#f6f8fa;border-left:3px solid #8aa4c0;padding:.4rem .8rem}
"""


@dataclass
class Section:
    """One report section: a heading, paragraphs, tables and figures (in that order)."""

    title: str
    paragraphs: list[str] = field(default_factory=list)
    tables: list[tuple[Sequence[str], Sequence[Sequence[object]]]] = field(default_factory=list)
    figures: list[tuple[Path, str]] = field(default_factory=list)
    links: list[tuple[str, str]] = field(default_factory=list)
    """(text, URL) links shown after the paragraphs."""


def _input_row(key: str, value: Any, unit: str) -> list[object]:
    if isinstance(value, list) and value and all(_is_number(v) for v in value):
        shown, shown_unit = engineering_array(np.asarray(value, dtype=float), unit, key)
        return [key, ", ".join(format_number(v) for v in shown), shown_unit]
    shown, shown_unit = engineering(value, unit, key)
    return [key, shown, shown_unit]


def _is_number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def inputs_warnings_sections(
    inputs: Mapping[str, Any],
    warnings: Sequence[str],
    analysis: str | None = None,
    guesses: Mapping[str, str] | None = None,
) -> list[Section]:
    """The first sections of every report: the inputs as they ran, the warnings, the
    ``guesses`` (dotted input key → description, :func:`ballscrew.case.inputs.guessed_defaults`)
    and, for a known ``analysis``, what was computed and how (linked to the theory manual)."""
    rows = [_input_row(key, value, unit) for key, value, unit in input_rows(dict(inputs))]
    sections = [
        Section(
            "Inputs",
            paragraphs=[
                "The case as it ran: every value, defaults included, in engineering units "
                "(summary.json and inputs.json keep SI)."
            ],
            tables=[(["input", "value", "unit"], rows)],
        ),
        Section("Warnings", paragraphs=list(warnings) or ["No warnings."]),
    ]
    if guesses:
        guessed = [[*row, guesses[row[0]]] for row in rows if row[0] in guesses]
        shown = {row[0] for row in guessed}
        guessed += [
            [key, "by its rule", "", text] for key, text in guesses.items() if key not in shown
        ]
        sections.append(
            Section(
                "Defaults that are guesses",
                paragraphs=[
                    "Inputs this analysis reads that the case left at a default that is only a "
                    "guess (GUESS or ASSUMED in its description) or lists in its [assumed] "
                    "table; each counts only where the analysis uses it. Write the value into "
                    "the case when it is known."
                ],
                tables=[(["input", "value", "unit", "what and why"], guessed)],
            )
        )
    if analysis in ABOUT:
        text, page = ABOUT[analysis]
        title = page.removesuffix(".md").replace("-", " ")
        sections.append(
            Section(
                "What was computed and how",
                paragraphs=[text],
                links=[(f"Theory manual: {title}", theory_link(page))],
            )
        )
    return sections


def _cell(item: object) -> str:
    if isinstance(item, float):
        return format_number(item)  # four significant figures
    return html.escape(str(item))


def _table(header: Sequence[str], rows: Iterable[Sequence[object]]) -> str:
    head = "".join(f"<th>{html.escape(h)}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td>{_cell(c)}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _figure(path: Path, caption: str) -> str:
    data = base64.b64encode(Path(path).read_bytes()).decode("ascii")
    return (
        f'<figure><img alt="{html.escape(caption)}" src="data:image/png;base64,{data}">'
        f"<figcaption>{html.escape(caption)}</figcaption></figure>"
    )


def write_report(path: str | Path, title: str, subtitle: str, sections: list[Section]) -> Path:
    """Write a self-contained ``report.html`` (figures embedded as base64 PNG)."""
    stamp = datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC")
    parts = [
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
        f"<title>{html.escape(title)}</title><style>{_STYLE}</style></head><body>",
        f"<h1>{html.escape(title)}</h1>",
        f"<p class='meta'>{html.escape(subtitle)} · ballscrew {__version__} · {stamp}</p>",
    ]
    for section in sections:
        parts.append(f"<h2>{html.escape(section.title)}</h2>")
        parts += [f"<p>{html.escape(p)}</p>" for p in section.paragraphs]
        parts += [
            f"<p class='note'><a href=\"{html.escape(url)}\">{html.escape(text)}</a></p>"
            for text, url in section.links
        ]
        parts += [_table(h, r) for h, r in section.tables]
        parts += [_figure(p, c) for p, c in section.figures]
    parts.append("</body></html>")
    path = Path(path)
    path.write_text("\n".join(parts), encoding="utf-8")
    return path
