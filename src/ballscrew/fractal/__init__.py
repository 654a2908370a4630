"""Fractal rough-surface contact: Majumdar–Bhushan with the Wang–Komvopoulos extension.

Theory manual: ``docs/theory/fractal-contact.md`` (equations F5–F15) and ``docs/theory/surface.md``
(F3).
"""

from ballscrew.fractal.domain_extension import (
    domain_extension_factor,
    size_distribution_constant,
    validate_dimension,
)
from ballscrew.fractal.majumdar_bhushan import (
    asperity_elastic_load,
    asperity_interference,
    asperity_plastic_load,
    asperity_tip_radius,
    critical_area,
    elastic_load,
    largest_spot_area,
    plastic_load,
    profile_rms_roughness,
    real_contact_area,
    size_distribution,
    total_load,
)

__all__ = [
    "asperity_elastic_load",
    "asperity_interference",
    "asperity_plastic_load",
    "asperity_tip_radius",
    "critical_area",
    "domain_extension_factor",
    "elastic_load",
    "largest_spot_area",
    "plastic_load",
    "profile_rms_roughness",
    "real_contact_area",
    "size_distribution",
    "size_distribution_constant",
    "total_load",
    "validate_dimension",
]
