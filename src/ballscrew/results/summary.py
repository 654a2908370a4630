"""``summary.json``: scalar results, each with its unit."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from ballscrew.analyses.result import json_ready
from ballscrew.analyses.result import quantity as value

__all__ = ["value", "write_summary"]


def write_summary(path: str | Path, summary: dict[str, Any]) -> Path:
    """Write ``summary`` as indented JSON (plain types, no NaN) and return the path."""
    path = Path(path)
    text = json.dumps(json_ready(summary), indent=2, ensure_ascii=False, allow_nan=False)
    path.write_text(text + "\n", encoding="utf-8")
    return path
