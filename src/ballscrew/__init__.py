"""ballscrew: precision ball-screw simulation.

Raceway geometry, non-Hertzian ball–raceway contact, ball loads in preloaded double nuts, fractal
thermal contact resistance and parameter sweeps, in SI units throughout.

1. ``case = ballscrew.load_case("examples/gao2019_tcr.toml")`` reads and validates a case.
2. ``ballscrew.geometry``, ``ballscrew.contact``, ``ballscrew.loads``, ``ballscrew.fractal`` and
   ``ballscrew.thermal`` hold the physical models as plain functions.
3. ``ballscrew.screw_tcr(case)`` and the other analyses compose them; ``ballscrew.results``
   writes results folders; ``ballscrew.sweep`` runs them over parameter grids on Dask.
"""

__version__ = "0.1.0"

from ballscrew import (
    case,
    contact,
    contact_resistance,
    errors,
    fractal,
    geometry,
    loads,
    thermal,
    units,
)
from ballscrew.analyses.ball_loads import ball_loads
from ballscrew.analyses.design_check import design_check
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.kinematics import ball_kinematics, drag_torque
from ballscrew.analyses.operating_point import operating_point
from ballscrew.analyses.screw_tcr import screw_tcr
from ballscrew.analyses.thermal import thermal_field
from ballscrew.analyses.wear import wear_life
from ballscrew.calibration import calibrate, calibrate_joint
from ballscrew.case import load_case
from ballscrew.loads import nut_forces

__all__ = [
    "__version__",
    "ball_kinematics",
    "ball_loads",
    "calibrate",
    "calibrate_joint",
    "case",
    "contact",
    "contact_resistance",
    "design_check",
    "drag_torque",
    "errors",
    "fractal",
    "friction_torque",
    "geometry",
    "load_case",
    "loads",
    "nut_forces",
    "operating_point",
    "screw_tcr",
    "thermal",
    "thermal_field",
    "units",
    "wear_life",
]
