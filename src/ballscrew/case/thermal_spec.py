"""Case section ``[thermal]``: what the temperature-field model needs beyond the screw."""

from __future__ import annotations

from ballscrew.case.base import Model


class ThermalSpec(Model):
    """Thermal model of screw shaft, nuts, spacer and bearings (to be completed)."""
