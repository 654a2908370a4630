"""Case files: pydantic models of a ball-screw case and the TOML loader."""

from ballscrew.case.assignments import parse_assignments
from ballscrew.case.loader import CaseError, case_from_dict, load_case, with_overrides
from ballscrew.case.models import (
    Case,
    FractalSurface,
    MaterialSpec,
    MediumSpec,
    NumericsSpec,
    OperatingSpec,
    ScrewSpec,
    SurfaceSpec,
    TCRSpec,
)

__all__ = [
    "Case",
    "CaseError",
    "FractalSurface",
    "MaterialSpec",
    "MediumSpec",
    "NumericsSpec",
    "OperatingSpec",
    "ScrewSpec",
    "SurfaceSpec",
    "TCRSpec",
    "case_from_dict",
    "load_case",
    "parse_assignments",
    "with_overrides",
]
