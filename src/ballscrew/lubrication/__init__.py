"""Lubrication of the ball contacts: EHL film, rolling resistance and mixed-lubrication sharing.

1. :func:`hamrock_dowson`: central and minimum film thickness of an elliptical EHL contact
   (Hamrock & Dowson 1977; theory manual ``docs/theory/lubrication.md``).
2. :func:`ehl_rolling_resistance`: hydrodynamic rolling force (Harris & Kotzalas 2006; (E3.4)).
3. :func:`share_load`: Johnson–Greenwood–Poon (1972) split of the normal load between the film
   and the fractal asperities of :mod:`ballscrew.fractal.yan_komvopoulos` ((E6.1)–(E6.5)), and
   :func:`asperity_pressure` for the per-cell asperity pressure ψ p; :func:`film_parameter`
   Λ = h/σ_Λ on the one roughness of :func:`composite_roughness` and its :func:`regime`.
4. :data:`LUBRICANTS` / :func:`lubricant`: named oils and greases with their sources.
"""

from ballscrew.lubrication.film import (
    FILM_MODELS,
    FilmThickness,
    dimensionless_groups,
    hamrock_dowson,
)
from ballscrew.lubrication.load_sharing import (
    BOUNDARY_FILM_PARAMETER,
    AsperitySurface,
    LoadSharing,
    asperity_pressure,
    composite_roughness,
    film_parameter,
    load_sharing_residual,
    regime,
    share_load,
    share_loads,
)
from ballscrew.lubrication.lubricants import LUBRICANTS, Lubricant, lubricant
from ballscrew.lubrication.rolling_resistance import ehl_rolling_resistance

__all__ = [
    "BOUNDARY_FILM_PARAMETER",
    "FILM_MODELS",
    "LUBRICANTS",
    "AsperitySurface",
    "FilmThickness",
    "LoadSharing",
    "Lubricant",
    "asperity_pressure",
    "composite_roughness",
    "dimensionless_groups",
    "ehl_rolling_resistance",
    "film_parameter",
    "hamrock_dowson",
    "load_sharing_residual",
    "lubricant",
    "regime",
    "share_load",
    "share_loads",
]
