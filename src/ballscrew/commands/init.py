"""``ballscrew init``: a complete, commented case file from a catalogue sheet, on stdout."""

from __future__ import annotations

from typing import Annotated

import typer

from ballscrew.commands._common import user_errors_exit_2


def _si(
    option: str, text: str, kind: str, bare_unit: str, scale: float, zero: bool = False
) -> float:
    """``text`` in SI: a bare number is in ``bare_unit`` (× ``scale``), else a unit string;
    > 0 (≥ 0 where ``zero``)."""
    from ballscrew.errors import InputError
    from ballscrew.units import to_si

    try:
        value = float(text) * scale
    except ValueError:
        try:
            value = to_si(text, kind)
        except ValueError:
            raise InputError(option, text, f"a number in {bare_unit} or e.g. '40 mm'") from None
    if not (value >= 0.0 if zero else value > 0.0) or value == float("inf"):
        bound = ">= 0" if zero else "> 0"
        raise InputError(option, text, f"a finite value {bound} (a bare number is in {bare_unit})")
    return value


_MM = "mm (or a unit string)"


@user_errors_exit_2
def init(
    d0: Annotated[str, typer.Option("--d0", help=f"nominal diameter, {_MM}")],
    lead: Annotated[str, typer.Option(help=f"lead, {_MM}")],
    ball: Annotated[str, typer.Option(help=f"ball diameter, {_MM}")],
    turns: Annotated[
        str, typer.Option(help="turns per circuit x circuits per nut, e.g. 2.5x2 or 1x4")
    ],
    nuts: Annotated[int, typer.Option(help="1 (single nut) or 2 (preloaded double nut)")] = 2,
    preload: Annotated[
        str | None,
        typer.Option(
            help="preload in N (or '2 kN'); default 5 % (double nut) or 2 % (single nut) of "
            "the geometric C_a [GUESS]; 0 for a single nut without preload"
        ),
    ] = None,
    length: Annotated[str, typer.Option(help=f"screw shaft length, {_MM}")] = "1000",
    nut_length: Annotated[
        str | None,
        typer.Option(help=f"length of each nut, {_MM}; default the loaded turns + 2 leads"),
    ] = None,
    dp: Annotated[
        str | None,
        typer.Option(
            "--dp", help=f"ball-centre (pitch circle) diameter d_m, {_MM}; default d0 [ASSUMED]"
        ),
    ] = None,
    root: Annotated[
        str | None,
        typer.Option(help=f"thread root (minor) diameter, {_MM}; default the groove bottom"),
    ] = None,
    preload_method: Annotated[
        str | None,
        typer.Option(
            help="spacer (2 nuts), oversized_balls or offset_lead (1 nut); default spacer for "
            "2 nuts, oversized_balls for 1"
        ),
    ] = None,
    name: Annotated[str, typer.Option(help="case name")] = "my_screw",
) -> None:
    """Print a complete case (TOML) for a screw from a maker's table; redirect it to a file."""
    from ballscrew.case.starter import CatalogueSheet, parse_turns, starter_case
    from ballscrew.errors import InputError
    from ballscrew.loads import preload_methods

    def optional_mm(option: str, text: str | None) -> float | None:
        return None if text is None else _si(option, text, "length", _MM, 1e-3)

    if nuts not in (1, 2):
        raise InputError("--nuts", nuts, "1 or 2")
    methods = preload_methods(nuts)
    if preload_method is not None and preload_method not in methods:
        raise InputError(
            "--preload-method", preload_method, f"{' or '.join(methods)} for {nuts} nut(s)"
        )
    t, circuits = parse_turns(turns)
    sheet = CatalogueSheet(
        nominal_diameter=_si("--d0", d0, "length", _MM, 1e-3),
        lead=_si("--lead", lead, "length", _MM, 1e-3),
        ball_diameter=_si("--ball", ball, "length", _MM, 1e-3),
        turns=t,
        circuits=circuits,
        nuts=nuts,
        preload=None if preload is None else _si("--preload", preload, "force", "N", 1.0, True),
        length=_si("--length", length, "length", _MM, 1e-3),
        nut_length=optional_mm("--nut-length", nut_length),
        pitch_diameter=optional_mm("--dp", dp),
        root_diameter=optional_mm("--root", root),
        preload_method=preload_method,
    )
    typer.echo(starter_case(sheet, name), nl=False)
