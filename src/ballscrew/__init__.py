"""ballscrew: precision ball-screw simulation.

Raceway geometry, non-Hertzian ball–raceway contact, fractal thermal contact resistance,
temperature field, ball kinematics and wear, in SI units throughout.

>>> import ballscrew
>>> case = ballscrew.load_case("examples/gao2019_tcr.toml")       # doctest: +SKIP
>>> ballscrew.geometry.lead_angle(case)                             # doctest: +SKIP
0.0794...
"""

__version__ = "0.1.0"

from ballscrew import case, errors, units  # noqa: E402
from ballscrew.case import load_case  # noqa: E402

__all__ = ["__version__", "case", "errors", "load_case", "units"]
