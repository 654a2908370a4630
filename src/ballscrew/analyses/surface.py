"""Fractal D and G of a measured profile: the ``ballscrew surface`` analysis.

Composes :mod:`ballscrew.surface` (profile reading, power-spectrum and structure-function fits)
into a result that presents itself; it has no case, its inputs are the profile file, its size
and spacing and the options of the fit.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any, ClassVar

from ballscrew.analyses import surface_report
from ballscrew.analyses.result import Presented, quantity, recorded_warnings
from ballscrew.surface import fractal_parameters, read_profile
from ballscrew.surface.fit import SurfaceFit
from ballscrew.surface.profile import Profile

__all__ = ["SurfaceCharacterisation", "surface_characterisation"]


@dataclass(frozen=True)
class SurfaceCharacterisation(Presented):
    """The fractal fits of a profile with the profile and the options they used."""

    profile_file: str
    """The profile file as given."""
    profile: Profile
    fit: SurfaceFit
    gamma: float
    """W–M frequency ratio γ of the fit."""
    resolution: float | None = None
    """Instrument lateral resolution [m] (None: the sampling interval)."""
    warnings: tuple[str, ...] = ()
    """Warnings raised while reading and fitting (one line each)."""

    analysis: ClassVar[str] = "surface"
    presentation: ClassVar[ModuleType] = surface_report

    @property
    def title(self) -> str:
        return f"Surface characterisation: {Path(self.profile.source).name}"

    @property
    def inputs(self) -> dict[str, Any]:
        p = self.profile
        return {
            "profile_file": self.profile_file,
            "format": p.metadata.get("format", ""),
            "profiles": p.n_profiles,
            "points_per_profile": p.n_points,
            "spacing": quantity(p.spacing, "m"),
            "sampling_length": quantity(p.length, "m"),
            "gamma": self.gamma,
            "resolution": None if self.resolution is None else quantity(self.resolution, "m"),
        }


def surface_characterisation(
    profile_file: str | Path,
    *,
    spacing: str | float | None = None,
    resolution: float | None = None,
    gamma: float = 1.5,
) -> SurfaceCharacterisation:
    """Read a profile file and fit its fractal D and G by power spectrum and structure function.

    Args:
        profile_file: CSV/text (x, z or z only) or ISO 25178-71/BCR SDF.
        spacing: sampling interval of a one-column text file (m, or text such as ``"0.5 um"``).
        resolution: instrument lateral resolution [m] if coarser than the spacing.
        gamma: W–M frequency ratio γ.
    """
    with recorded_warnings() as messages:
        profile = read_profile(profile_file, spacing=spacing)
        fit = fractal_parameters(profile, gamma=gamma, resolution=resolution)
    return SurfaceCharacterisation(
        str(profile_file), profile, fit, gamma, resolution, tuple(messages)
    )
