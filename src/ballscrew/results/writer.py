"""The one writer of results folders: any :class:`~ballscrew.analyses.result.AnalysisResult`.

A results folder holds

* ``summary.json`` — the result's scalars (SI, each with its unit), its warnings, the keys of
  the inputs it reads (:mod:`ballscrew.analyses.case_reads`) left at a default that is only a
  guess (``guessed_defaults``) and the resolved inputs;
* ``<dataset_name>.nc`` — the result's xarray dataset (NetCDF, ``units`` attributes;
  ``fields.nc`` unless the result names it);
* ``<figure>.png`` — its figures;
* ``report.html`` — one self-contained page: the inputs, the warnings, then the result's own
  sections with their figures embedded;
* ``summary.csv``, ``results.xlsx``, ``<stem>.mat`` … — the exports asked for
  (:mod:`ballscrew.results.export`);
* ``case.toml`` — the case file as the user gave it (when there is one) and ``inputs.json``,
  the case as resolved (every default filled in, SI values with units).

The folder appears complete or not at all (:func:`~ballscrew.results.folder.results_folder`).
"""

from __future__ import annotations

import json
import shutil
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from ballscrew.analyses.case_reads import case_reads
from ballscrew.analyses.result import AnalysisResult
from ballscrew.case import Case
from ballscrew.case.inputs import guessed_defaults
from ballscrew.case.plausibility import implausible_values
from ballscrew.results.export import export_results, parse_formats
from ballscrew.results.folder import results_folder, write_netcdf
from ballscrew.results.report import Section, inputs_warnings_sections, write_report
from ballscrew.results.summary import write_summary

__all__ = ["result_warnings", "write_results"]


def result_warnings(result: AnalysisResult) -> list[str]:
    """The warnings of ``result``, after those about implausible values of its case."""
    case = getattr(result, "case", None)
    implausible = implausible_values(case) if isinstance(case, Case) else []
    return list(dict.fromkeys([*implausible, *result.warnings]))


def _headline_section(summary: dict[str, Any]) -> list[Section]:
    """The report's table of headline numbers in engineering units (as on the console)."""
    from ballscrew.results.headlines import headline_keys, headline_label, headline_rows

    analysis = str(summary["analysis"])
    rows = headline_rows(summary, headline_keys(analysis), label=headline_label(analysis))
    if not rows:
        return []
    return [Section("Headline numbers", tables=[(["quantity", "value"], [list(r) for r in rows])])]


def write_results(
    result: AnalysisResult,
    out: str | Path,
    case_file: str | Path | None = None,
    extra_files: Mapping[str, bytes] | None = None,
    export: Sequence[str] = (),
) -> Path:
    """Write the results folder of ``result`` at ``out`` and return its path.

    ``case_file``: the case file as given, copied into the folder as ``case.toml``.
    ``extra_files``: further files of the command (file name → content), written with the rest
    so that the folder still appears complete or not at all.
    ``export``: formats of :func:`~ballscrew.results.export.export_results` (``csv``,
    ``xlsx``, ``mat``) written into the folder before it appears.
    """
    warnings = result_warnings(result)
    case = getattr(result, "case", None)
    reads = case_reads(result.analysis)
    guesses = guessed_defaults(case, reads=reads) if isinstance(case, Case) else {}
    export = parse_formats(export)
    with results_folder(out) as folder:
        summary = {
            "analysis": result.analysis,
            **result.summary(),
            "warnings": warnings,
            "guessed_defaults": sorted(guesses),
            "inputs": dict(result.inputs),
        }
        write_summary(folder / "summary.json", summary)
        (folder / "inputs.json").write_text(
            json.dumps(dict(result.inputs), indent=2, ensure_ascii=False) + "\n", encoding="utf-8"
        )
        if case_file is not None:
            shutil.copyfile(case_file, folder / "case.toml")
        dataset = result.to_xarray()
        if dataset.data_vars:  # a result with no fields or histories writes no NetCDF
            write_netcdf(dataset, folder / f"{getattr(result, 'dataset_name', 'fields')}.nc")
        drawn = {f.name: (f.draw(folder / f"{f.name}.png"), f.caption) for f in result.figures()}
        sections = inputs_warnings_sections(result.inputs, warnings, result.analysis, guesses)
        sections += _headline_section(summary)
        for s in result.report():
            sections.append(
                Section(
                    s.title,
                    paragraphs=list(s.paragraphs),
                    tables=[(list(t.header), [list(r) for r in t.rows]) for t in s.tables],
                    figures=[drawn[name] for name in s.figures],
                )
            )
        write_report(folder / "report.html", result.title, f"ballscrew {result.analysis}", sections)
        for name, content in (extra_files or {}).items():
            (folder / name).write_bytes(content)
        if export:
            export_results(folder, export)
    return Path(out).resolve()
