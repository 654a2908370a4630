"""``ballscrew surface``: fractal D and G of a measured profile (CSV/text or SDF)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ballscrew.commands._common import ExportOpt, ForceOpt, OutOpt, command, export_formats, finish

ProfileArg = Annotated[
    Path,
    typer.Argument(
        help="measured profile: CSV/text (x, z or z only) or ISO 25178-71/BCR SDF",
        dir_okay=False,
        show_default=False,
        metavar="PROFILE_FILE",
    ),
]


def _length(text: str | None, option: str) -> float | None:
    from ballscrew.errors import InputError
    from ballscrew.units import to_si

    if text is None:
        return None
    try:
        return to_si(text, "length")
    except ValueError as exc:
        raise InputError(option, text, f"a length such as '0.5 µm' ({exc})") from None


@command
def surface(
    profile_file: ProfileArg,
    out: OutOpt = Path("results/surface"),
    spacing: Annotated[
        str | None,
        typer.Option(
            help="sampling interval of a one-column text file, e.g. '0.5 µm'", metavar="LENGTH"
        ),
    ] = None,
    resolution: Annotated[
        str | None,
        typer.Option(
            help="instrument lateral resolution if coarser than the spacing", metavar="LENGTH"
        ),
    ] = None,
    gamma: Annotated[float, typer.Option(help="W-M frequency ratio γ", metavar="NUMBER")] = 1.5,
    force: ForceOpt = False,
    export: ExportOpt = None,
) -> None:
    """Fractal dimension D and roughness G by power spectrum and structure function."""
    from ballscrew.analyses.surface import surface_characterisation
    from ballscrew.results import claim_output, write_results

    formats = export_formats(export)
    with claim_output(out, command="surface", force=force, inputs=[profile_file]):
        result = surface_characterisation(
            profile_file,
            spacing=spacing,
            resolution=_length(resolution, "--resolution"),
            gamma=gamma,
        )
        folder = write_results(result, out)
        finish(folder, formats)
