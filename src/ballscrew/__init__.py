"""ballscrew: precision ball-screw simulation.

Raceway geometry, non-Hertzian ball–raceway contact, ball loads in preloaded double nuts, fractal
thermal contact resistance and parameter sweeps, in SI units throughout.

1. ``case = ballscrew.load_case("examples/gao2019_tcr.toml")`` reads and validates a case.
2. ``ballscrew.geometry``, ``ballscrew.contact``, ``ballscrew.loads``, ``ballscrew.fractal`` and
   ``ballscrew.thermal`` hold the physical models as plain functions.
3. ``ballscrew.screw_tcr(case)`` and the other analyses compose them; ``ballscrew.results``
   writes results folders; ``ballscrew.sweep`` runs them over parameter grids on Dask.

The public names are imported on first use (PEP 562 module ``__getattr__``), so
``import ballscrew`` and the command line start without the unit, array and solver libraries.
A new public name goes into :data:`_PUBLIC`, :data:`__all__` and the ``TYPE_CHECKING`` block.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

if TYPE_CHECKING:  # what IDEs and type checkers see; at run time __getattr__ imports them
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

#: Each public name and the module it comes from (a subpackage is its own module).
_PUBLIC: dict[str, str] = {
    "ball_kinematics": "ballscrew.analyses.kinematics",
    "ball_loads": "ballscrew.analyses.ball_loads",
    "calibrate": "ballscrew.calibration",
    "calibrate_joint": "ballscrew.calibration",
    "case": "ballscrew.case",
    "contact": "ballscrew.contact",
    "contact_resistance": "ballscrew.contact_resistance",
    "design_check": "ballscrew.analyses.design_check",
    "drag_torque": "ballscrew.analyses.kinematics",
    "errors": "ballscrew.errors",
    "fractal": "ballscrew.fractal",
    "friction_torque": "ballscrew.analyses.friction",
    "geometry": "ballscrew.geometry",
    "load_case": "ballscrew.case",
    "loads": "ballscrew.loads",
    "nut_forces": "ballscrew.loads",
    "operating_point": "ballscrew.analyses.operating_point",
    "screw_tcr": "ballscrew.analyses.screw_tcr",
    "thermal": "ballscrew.thermal",
    "thermal_field": "ballscrew.analyses.thermal",
    "units": "ballscrew.units",
    "wear_life": "ballscrew.analyses.wear",
}

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


def __getattr__(name: str) -> Any:
    """The public name ``name``, or the subpackage ``ballscrew.<name>``, imported on first use
    and kept as a module attribute (PEP 562)."""
    if name in _PUBLIC:
        module = import_module(_PUBLIC[name])
        value = module if module.__name__ == f"{__name__}.{name}" else getattr(module, name)
    elif not name.startswith("_"):
        try:
            value = import_module(f"{__name__}.{name}")
        except ModuleNotFoundError as exc:
            if exc.name != f"{__name__}.{name}":
                raise
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}") from None
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    """The module's names with the public ones not imported yet (tab completion)."""
    return sorted({*globals(), *__all__})
