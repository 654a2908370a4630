"""``summary.json``: scalar results, each with its unit."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np


def value(number: float, unit: str) -> dict[str, Any]:
    """A JSON-ready scalar with its SI unit, e.g. ``{"value": 1.35e9, "unit": "Pa"}``."""
    number = float(number)
    return {"value": number if math.isfinite(number) else None, "unit": unit}


def _plain(obj: Any) -> Any:
    """Convert NumPy scalars and arrays to JSON-serialisable Python objects."""
    if isinstance(obj, dict):
        return {str(k): _plain(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [_plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return _plain(obj.tolist())
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


def write_summary(path: str | Path, summary: dict[str, Any]) -> Path:
    """Write ``summary`` as indented JSON and return the path."""
    path = Path(path)
    path.write_text(json.dumps(_plain(summary), indent=2, ensure_ascii=False) + "\n")
    return path
