"""What each analysis computed and how, in two sentences, with its page of the theory manual.

Every report shows this paragraph after the warnings, linked to the documentation site
(``make docs`` builds it into ``site/``; ``BALLSCREW_DOCS_URL`` points reports at a published
copy instead).
"""

from __future__ import annotations

import os
from pathlib import Path

__all__ = ["ABOUT", "theory_link"]

#: analysis → (what was computed and how, theory manual page under docs/theory/).
ABOUT: dict[str, tuple[str, str]] = {
    "contact": (
        "The normal pressure of the ball–screw and ball–nut contacts, solved on a grid with the "
        "Polonsky–Keer conjugate-gradient method and Love's influence coefficients on DC-FFT, "
        "from the exact raceway gap; the Hertz solution is drawn for comparison.",
        "contact.md",
    ),
    "tcr": (
        "The thermal contact resistance of every ball contact: the numerical pressure is "
        "re-binned to fractal cells (Majumdar–Bhushan asperities), each cell's resistance is "
        "computed and the cells, contacts and nuts are combined in series and parallel.",
        "contact-resistance.md",
    ),
    "thermal": (
        "The temperature field of screw and nut (network, axisymmetric or 3-D finite-element "
        "model) from the friction and bearing heat, convection and the contact conductance, "
        "steady and over time at the operating point, and the resulting thermal elongation of "
        "the screw; a case's [[duty]] cycle is followed as well, as by the duty analysis.",
        "thermal.md",
    ),
    "operating-point": (
        "The friction torque, heat and temperatures of one operating point, iterated until the "
        "lubricant viscosity at the computed temperature reproduces the heat that set it.",
        "operating-point.md",
    ),
    "duty": (
        "The temperatures and thermal elongation over the case's duty cycle: each segment's "
        "friction heat from its operating point, fed to the thermal model in time.",
        "thermal.md",
    ),
    "check": (
        "The makers' design formulas: rating life from the cube-mean load of the spectrum, "
        "static safety, critical speed, buckling load, dn value and the axial stiffness of the "
        "drive (nut, shaft and supports in series).",
        "loads.md",
    ),
    "kinematics": (
        "The motion of a ball (orbital, spin and rolling speeds), its quasi-static balance at "
        "the chosen level, the sliding field over each contact and the drag torque.",
        "kinematics.md",
    ),
    "wear": (
        "The fractal adhesive wear of the raceway over the programme: wear per strip across the "
        "groove, the worn gap fed back into the contact, and the preload and friction torque "
        "that follow, step by step.",
        "wear.md",
    ),
    "calibrate": (
        "A nonlinear least-squares fit of the wear coefficient (and the drag-torque scale and "
        "offset) to the measured history, or to several histories of the screw together, each "
        "trial running the wear model; standard errors by the delta method.",
        "wear.md",
    ),
    "surface": (
        "The fractal parameters D and G of a measured or synthetic profile from its power "
        "spectrum and its structure function, each fitted over the range where it is a power "
        "law.",
        "surface.md",
    ),
    "sweep": (
        "The analysis run at every point of the grid of swept case values, in parallel on Dask; "
        "each point is cached so an interrupted sweep resumes.",
        "index.md",
    ),
}

_REPO = Path(__file__).resolve().parents[3]


def theory_link(page: str) -> str:
    """URL of the theory manual ``page`` (``thermal.md``): the published site when
    ``BALLSCREW_DOCS_URL`` is set, else the local site built by ``make docs``, else the
    Markdown page in the repository."""
    stem = page.removesuffix(".md")
    path = "theory/" if stem == "index" else f"theory/{stem}/"
    base = os.environ.get("BALLSCREW_DOCS_URL")
    if base:
        return base.rstrip("/") + "/" + path
    built = _REPO / "site" / path / "index.html"
    if built.is_file():
        return built.as_uri()
    return (_REPO / "docs" / "theory" / page).as_uri()
