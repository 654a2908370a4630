"""``ballscrew surface``: fractal D and G of a measured profile (CSV/text or SDF)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import Output, quantity_option, writes_results

ProfileArg = Annotated[
    Path,
    typer.Argument(
        help="measured profile: CSV/text (x, z or z only) or ISO 25178-71/BCR SDF",
        dir_okay=False,
        show_default=False,
        metavar="PROFILE_FILE",
    ),
]
SpacingOpt = Annotated[
    str | None,
    typer.Option(
        help="sampling interval of a one-column text file, e.g. '0.5 µm' (a bare number is "
        "in m); from 1e-11 m (a tenth of an atomic distance) to 1 m / points (a record of at "
        "most 1 m); CSV with x and SDF files carry their own",
        metavar="LENGTH",
    ),
]
ResolutionOpt = Annotated[
    str | None,
    typer.Option(
        help="instrument lateral resolution if coarser than the spacing, e.g. '2 µm' "
        "(default: the spacing)",
        metavar="LENGTH",
    ),
]
GammaOpt = Annotated[
    float,
    typer.Option(
        help="W-M frequency ratio γ, 1.01 ≤ γ ≤ 10 (1.5 after Majumdar & Tien 1990): below, the "
        "spectral sub-bins ln γ/16 become too many; above, the W-M lines are more than a decade "
        "apart and too few fall inside the measured band for D and G to mean anything",
        metavar="NUMBER",
    ),
]


@writes_results(sets=False)
def surface(
    profile_file: ProfileArg,
    spacing: SpacingOpt = None,
    resolution: ResolutionOpt = None,
    gamma: GammaOpt = 1.5,
    *,
    output: Output,
) -> None:
    """Fractal dimension D and roughness G by power spectrum and structure function."""
    from ballscrew.analyses.surface import surface_characterisation

    lateral = quantity_option("--resolution", resolution, "length")
    with output.claim(profile_file):
        result = surface_characterisation(
            profile_file, spacing=spacing, resolution=lateral, gamma=gamma
        )
        output.write(result)
