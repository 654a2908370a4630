"""Ball-screw raceway geometry: helix, Frenet and contact frames, curvatures and the initial gap.

Implements the theory manual's *Raceway geometry* (``docs/theory/geometry.md``), (G1)–(G18): the
ball-centre helix and its Frenet–Serret frame (Lin, Ravani & Velinsky 1994; Wei, Lin & Horng 2009),
Gothic-arch raceways swept helicoidally, the contact frames at A (screw) and B (nut), the exact gap
Hessian, Harris-type curvature sums (Harris & Kotzalas), and the exact and quadratic initial gap
h(x, y) over a contact grid.
"""

from ballscrew.geometry.curvature import (
    RacewayCurvature,
    harris_rolling_curvature,
    raceway_curvature,
    rolling_curvature,
)
from ballscrew.geometry.gap import (
    GAP_MODELS,
    RacewayPoint,
    ball_height,
    gap_exact,
    gap_function,
    gap_quadratic,
    project_onto_raceway,
)
from ballscrew.geometry.helix import frenet_frame, frenet_matrix, helix_point
from ballscrew.geometry.raceway import (
    ContactFrame,
    contact_direction,
    contact_frame,
    contact_point,
    groove_profile,
    raceway_surface,
)
from ballscrew.geometry.screw import ScrewGeometry, Side, as_geometry, lead_angle

__all__ = [
    "GAP_MODELS",
    "ContactFrame",
    "RacewayCurvature",
    "RacewayPoint",
    "ScrewGeometry",
    "Side",
    "as_geometry",
    "ball_height",
    "contact_direction",
    "contact_frame",
    "contact_point",
    "frenet_frame",
    "frenet_matrix",
    "gap_exact",
    "gap_function",
    "gap_quadratic",
    "groove_profile",
    "harris_rolling_curvature",
    "helix_point",
    "lead_angle",
    "project_onto_raceway",
    "raceway_curvature",
    "raceway_surface",
    "rolling_curvature",
]
