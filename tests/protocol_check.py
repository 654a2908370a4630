"""The check every analysis result passes: the protocol and the folder of the generic writer."""

from __future__ import annotations

import json
from pathlib import Path

from ballscrew.analyses.result import AnalysisResult


def assert_protocol_folder(result: object, folder: Path, case_file: bool = True) -> dict:
    """``result`` is an :class:`AnalysisResult` and ``folder`` its complete results folder;
    returns the folder's summary.json."""
    assert isinstance(result, AnalysisResult)
    summary = json.loads((folder / "summary.json").read_text())
    assert {"analysis", "warnings", "inputs"} <= summary.keys()
    assert summary["analysis"] == result.analysis
    assert summary["warnings"] == list(result.warnings)
    assert json.loads((folder / "inputs.json").read_text()) == summary["inputs"]
    assert (folder / "case.toml").is_file() == case_file
    report = (folder / "report.html").read_text()
    assert "<h2>Inputs</h2>" in report and "<h2>Warnings</h2>" in report
    return summary
