"""An index page over several results folders (what ``make demo`` opens)."""

from __future__ import annotations

import html
import json
from pathlib import Path
from typing import Any

from ballscrew.errors import InputError
from ballscrew.results.folder import SUMMARY_NAME
from ballscrew.results.report import Section, write_report

HEADLINES = 6
"""Scalars shown per results folder when its analysis has no entry in :data:`KEY_QUANTITIES`."""

KEY_QUANTITIES: dict[str, tuple[str, ...]] = {
    "contact": (
        "ball_load",
        "contacts.screw.numerical.peak_pressure",
        "contacts.screw.relative_difference_to_hertz.peak_pressure",
    ),
    "tcr": ("resistance", "resistance_per_area", "apparent_area"),
    "thermal": ("steady.max_temperature_rise", "steady.elongation", "heat_balance.heat_input"),
    "kinematics": (
        "nuts.nut1.orbital_speed",
        "nuts.nut1.spin_screw",
        "nuts.nut1.asperity_share",
        "nuts.nut1.film_thickness_central",
        "drag_torque.ball_model",
        "drag_torque.catalogue",
    ),
    "wear": (
        "revolutions",
        "max_wear_depth",
        "final_preload",
        "final_torque",
        "ellipse_major_axis",
    ),
    "surface": ("recommended.D", "recommended.G"),
    "calibration": (
        "wear_coefficient",
        "wear_coefficient_standard_error",
        "torque_scale",
        "rms_residual",
    ),
}
"""Dotted summary.json paths of the numbers an index shows per analysis."""

KEY_FIGURES: dict[str, str] = {
    "contact": "pressure_screw.png",
    "tcr": "tcr_nut1_screw.png",
    "thermal": "temperature_map.png",
    "kinematics": "sliding_high_speed.png",
    "wear": "torque_preload.png",
    "surface": "psd.png",
    "sweep": "sweep_resistance_per_area.png",
}
"""The figure an index shows per analysis (else the folder's first PNG)."""


def _format(name: str, entry: Any) -> str | None:
    if isinstance(entry, dict) and set(entry) == {"value", "unit"}:
        entry, unit = entry["value"], entry["unit"]
    else:
        unit = ""
    if isinstance(entry, int | float) and not isinstance(entry, bool):
        return f"{name} = {entry:.4g} {unit}".rstrip()
    return None


def _lookup(summary: dict[str, Any], dotted: str) -> Any:
    node: Any = summary
    for key in dotted.split("."):
        if not isinstance(node, dict) or key not in node:
            return None
        node = node[key]
    return node


def _headlines(summary: dict[str, Any], analysis: str) -> list[str]:
    """'name = value unit' for the analysis' key quantities (or its first top-level scalars)."""
    if analysis in KEY_QUANTITIES:
        pairs = [
            (".".join(p.split(".")[-2:]), _lookup(summary, p)) for p in KEY_QUANTITIES[analysis]
        ]
    else:
        pairs = list(summary.items())
    lines = [line for name, entry in pairs if (line := _format(name, entry))]
    return lines[:HEADLINES]


def results_folders(root: Path) -> list[Path]:
    """Sub-folders of ``root`` holding a finished results folder, in name order."""
    return sorted(p for p in root.iterdir() if (p / SUMMARY_NAME).is_file() and p.is_dir())


def write_index(root: str | Path, title: str = "ballscrew results") -> Path:
    """Write ``root/index.html``: per results folder its analysis, case, headline numbers, its
    first figure and a link to its own report. Returns the path."""
    root = Path(root).resolve()
    if not root.is_dir():
        raise InputError("folder", str(root), "an existing folder of results folders")
    folders = results_folders(root)
    if not folders:
        raise InputError("folder", str(root), "a folder holding results folders (summary.json)")
    rows, sections = [], []
    for folder in folders:
        summary = json.loads((folder / SUMMARY_NAME).read_text())
        analysis = kind = summary.get("analysis", "?")
        if "axes" in summary:
            kind = "sweep"
            analysis = f"sweep of {analysis} over {', '.join(summary['axes'])}"
        case = summary.get("case") or summary.get("source", "")
        link = f"{folder.name}/report.html"
        rows.append([folder.name, analysis, case, "; ".join(_headlines(summary, kind))])
        key = folder / KEY_FIGURES.get(kind, "")
        figures = [key] if key.is_file() else sorted(folder.glob("*.png"))[:1]
        sections.append(
            Section(
                f"{folder.name}: {analysis}",
                paragraphs=[f"Case {case}. Full report: {link}"],
                figures=[(f, f"{folder.name}: {f.stem}") for f in figures],
            )
        )
    overview = Section("Results", tables=[(["folder", "analysis", "case", "headline"], rows)])
    path = write_report(
        root / "index.html", title, f"{len(folders)} results folders", [overview, *sections]
    )
    _link_reports(path, folders)
    return path


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
