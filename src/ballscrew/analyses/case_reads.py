"""Which case inputs each analysis reads, so that its results list only the guesses it used.

:data:`CASE_READS` maps an analysis name (:data:`~ballscrew.analyses.result.ANALYSES`) to the
dotted prefixes of the case inputs it reads, in any configuration of the case (a section,
``"thermal"``, or one input of a section it reads only in part, ``"friction.traction"``). The
writer keeps the guessed defaults and the ``[assumed]`` entries under these prefixes
(:func:`ballscrew.case.inputs.guessed_defaults`); ``tests/results/test_guesses_per_analysis.py``
records the fields each analysis really reads and holds this table to them both ways.
"""

from __future__ import annotations

__all__ = ["CASE_READS", "case_reads"]

#: Read by every analysis of the physics (through ``ScrewParameters.from_case``).
_PARAMETERS = (
    "screw",
    "materials",
    "surface",
    "medium",
    "operating",
    "numerics",
    "kinematics.lubricant",
    "lubrication.supply",
    "lubrication.thermal",
)
_LOADED = (*_PARAMETERS, "loads")
#: The coupled operating point and the temperature fields: every section but ``[wear]``.
_COUPLED = (
    *_LOADED,
    "kinematics",
    "lubrication",
    "friction",
    "thermal",
    "tcr",
    "design",
    "duty",
    "duty_repeat",
)
_WEAR = (*_LOADED, "wear", "duty")

CASE_READS: dict[str, tuple[str, ...]] = {
    "contact": _LOADED,
    "tcr": (*_LOADED, "tcr"),
    "check": (*_LOADED, "design", "duty"),
    "kinematics": (
        *_PARAMETERS,
        "kinematics",
        "friction.boundary_friction",
        "friction.traction",
        "design",
    ),
    "operating-point": _COUPLED,
    "thermal": _COUPLED,
    "thermal-network": _COUPLED,
    "thermal-fe": _COUPLED,
    "duty": _COUPLED,
    "wear": _WEAR,
    "calibrate": _WEAR,
    "surface": ("surface",),
}


def case_reads(analysis: str) -> tuple[str, ...] | None:
    """The prefixes of the inputs ``analysis`` reads; None (every input) for one not listed."""
    return CASE_READS.get(analysis)
