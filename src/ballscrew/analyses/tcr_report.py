"""What the TCR analysis shows: its summary, fields, figures and report sections."""

from __future__ import annotations

from functools import partial
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from ballscrew import plotting as plots
from ballscrew.analyses.parameters import SIDES
from ballscrew.analyses.result import Figure, Section, Table
from ballscrew.analyses.result import quantity as value
from ballscrew.analyses.roughness import roughness_summary, roughness_text

if TYPE_CHECKING:
    from ballscrew.analyses.screw_tcr import NutTCR, RacewayTCR, ScrewTCR
    from ballscrew.analyses.tcr_film import NutHeatPath

_LABEL = {"screw": "ball–screw contact", "nut": "ball–nut contact"}

HEADLINE = (
    "R (resistance) and R″ = R·S (resistance_per_area) are the headline: the micro TCR (the "
    "quantity Gao, Wang & Liu (2019) define) by the headline_model, the asperity spots and the "
    "gap between them inside each Hertz patch. The macro-constriction of the patches and the "
    "lubricant film around the balls lie outside the patches, so neither is in R, and "
    "tcr.film_path leaves R unchanged. The screw-to-nut path through the balls is "
    "ball_path_without_film (micro TCR plus macro-constriction, in every run) and, with "
    "tcr.film_path, ball_path_with_film (the film beside each patch); heat_path_resistance is the"
    " one of the two that the thermal model takes."
)
"""Which number is the headline and why the film path does not change it (summary, report)."""

CELL_OPTION = (
    "Gao, Wang & Liu's own model, the fractal element model V2 on Δ_f cells (tcr.cell_size), is "
    'the paper\'s option: [tcr] headline = "V2" (or --variant V2). Its value follows the cell '
    "size (R″ ∝ Δ_f^0.53), so it is not the default; every model is listed under models."
)
"""Where the paper's cell model went (summary and report of every run)."""


def headline_model_text(result: ScrewTCR) -> str:
    """Which model the headline is, whether it has a cell size, and the paper's cell option."""
    name = result.headline
    what = result.models[name].description if name in result.models else name
    if result.cell_size is not None and name == result.variant:
        cells = f"{1e6 * result.cell_size:g} µm cells: it follows the cell size"
        return f"The headline model is {name} ({what}) on {cells}. {CELL_OPTION}"
    if name == result.variant:
        return f"The headline model is {name} ({what}) on the solver grid's cells. {CELL_OPTION}"
    return (
        f"The headline model is {name} ({what}). It has no fractal cell size: R does not "
        f"depend on tcr.cell_size and converges with the solver grid. {CELL_OPTION}"
    )


def console_line(result: ScrewTCR) -> str:
    """The console's line on the headline: its model, whether it has a cell size, and how to
    get the paper's cell model."""
    name = result.headline
    if name == result.variant:
        return (
            f"  headline model: {name} on {_cells_text(result)}, the paper's cell model (it "
            "follows tcr.cell_size)"
        )
    return (
        f"  headline model: {name}, no fractal cell size (the paper's cell model: --variant V2 "
        'or [tcr] headline = "V2")'
    )


def fractal_cell_centres(coord: np.ndarray, count: int, cell: float) -> np.ndarray:
    """Centres of ``count`` fractal cells of side ``cell`` centred on the solver grid ``coord``."""
    centre = 0.5 * (coord[0] + coord[-1])
    return centre + (np.arange(count) - 0.5 * (count - 1)) * cell


def _cells_text(result: ScrewTCR) -> str:
    if result.headline.endswith("/patch"):
        return "the whole Hertz patch"
    if result.cell_size is None:
        return "the solver grid's cells"
    return f"{1e6 * result.cell_size:g} µm fractal cells"


def _contact_summary(r: RacewayTCR) -> dict[str, Any]:
    return {
        "resistance": value(r.resistance, "K/W"),
        "apparent_area": value(r.apparent_area, "m^2"),
        "resistance_per_area": value(r.resistance * r.apparent_area, "m^2*K/W"),
        "element_resistance": value(r.tcr.resistance, "K/W"),
        "loaded_cells": r.tcr.loaded_cells,
        "peak_pressure": value(r.contact.solution.peak_pressure, "Pa"),
        "approach": value(r.contact.solution.approach, "m"),
        "solver_iterations": r.contact.solution.iterations,
    }


def _path_summary(path: NutHeatPath) -> dict[str, Any]:
    """A nut's ball path: its micro TCR, macro-constriction and the path without and with film."""
    with_film = path.ball_path_with_film
    return {
        "micro_resistance": value(path.micro, "K/W"),
        "constriction": value(path.constriction, "K/W"),
        "ball_path_without_film": value(path.ball_path_without_film, "K/W"),
        "ball_path_with_film": None if with_film is None else value(with_film, "K/W"),
    }


def _nut_summary(nut: NutTCR, path: NutHeatPath) -> dict[str, Any]:
    return {
        "force": value(nut.force, "N"),
        "ball_load": value(nut.ball_load, "N"),
        "balls": nut.balls,
        "ball_resistance": value(nut.ball_resistance, "K/W"),
        "resistance": value(nut.resistance, "K/W"),
        "apparent_area": value(nut.apparent_area, "m^2"),
        "axial_deflection": value(nut.axial_deflection, "m"),
        "axial_stiffness": value(nut.axial_stiffness, "N/m"),
        "contacts": {side: _contact_summary(getattr(nut, side)) for side in SIDES},
        **_path_summary(path),
    } | ({} if nut.load_spread == 1.0 else {"ball_load_spread": nut.load_spread})


def _spread_summary(result: ScrewTCR) -> dict[str, Any] | None:
    spread = result.uncertainty
    if spread is None:
        return None
    return {
        "low": value(spread.low, "m^2*K/W"),
        "high": value(spread.high, "m^2*K/W"),
        "ratio": spread.ratio,
        "models": list(spread.models),
    }


def _roughness_summary(case: Any) -> dict[str, Any]:
    tcr = case.tcr
    if tcr.rms_roughness is not None:
        return {"sigma": value(tcr.rms_roughness, "m"), "slope": tcr.rms_slope}
    return {
        "from": "D, G",
        "sampling_length": value(tcr.sampling_length, "m"),
        "cutoff_length": value(tcr.cutoff_length, "m"),
    }


def summary(result: ScrewTCR) -> dict[str, Any]:
    """Scalars of the whole screw, per nut and per contact, with the options that produced them."""
    case = result.case
    paths = {p.index: p for p in result.heat_paths()}
    with_film = result.ball_path_with_film
    return {
        "case": result.case_name,
        "headline": HEADLINE,
        "headline_model": result.headline,
        "headline_model_note": headline_model_text(result),
        "resistance": value(result.resistance, "K/W"),
        "resistance_per_area": value(result.resistance_per_area, "m^2*K/W"),
        "apparent_area": value(result.apparent_area, "m^2"),
        "ball_path_without_film": value(result.ball_path_without_film, "K/W"),
        "ball_path_with_film": None if with_film is None else value(with_film, "K/W"),
        "heat_path_resistance": value(result.heat_path_resistance, "K/W"),
        "nut_forces": [value(f, "N") for f in result.nut_forces],
        "nuts": {f"nut{n.index}": _nut_summary(n, paths[n.index]) for n in result.nuts},
        "models": {
            name: {
                "resistance": value(m.resistance, "K/W"),
                "resistance_per_area": value(m.resistance_per_area, "m^2*K/W"),
            }
            for name, m in result.models.items()
        },
        "uncertainty": _spread_summary(result),
        "film_path": _film_summary(result),
        "options": {
            "headline": result.headline,
            "variant": result.variant,
            "cell_size": value(result.cell_size, "m") if result.cell_size else "solver grid",
            "gap_model": case.tcr.gap_model,
            "gap_factor": case.tcr.gap_factor,
            "cutoff_area": value(case.tcr.cutoff_area, "m^2"),
            "load_threshold": case.tcr.load_threshold,
            "surface": roughness_summary(case, "profile"),
            "correlation_roughness": _roughness_summary(case),
            "medium_conductivity": value(case.medium.thermal_conductivity, "W/(m*K)"),
            "contact_gap_model": case.numerics.gap_model,
            "film_path": case.tcr.film_path,
        },
    }


def _film_summary(result: ScrewTCR) -> dict[str, Any] | None:
    """With ``[tcr] film_path``: each nut's films and its ball path with and without them, a
    lifted-off nut's included (``resistance`` is the screw's ball path with film)."""
    if not result.films:
        return None
    paths = {p.index: p for p in result.heat_paths()}
    return {
        "resistance": value(result.heat_path_resistance, "K/W"),
        "nuts": {
            f"nut{f.index}": {
                "loaded": f.loaded,
                "film_conductance": value(f.conductance, "W/K"),
                "contacts": {
                    side: {
                        "conductance": value(getattr(f, side).conductance, "W/K"),
                        "h0": value(getattr(f, side).h0, "m"),
                        "h_max": value(getattr(f, side).h_max, "m"),
                    }
                    for side in SIDES
                },
                **_path_summary(paths[f.index]),
                # older names of ball_path_without_film and ball_path_with_film (kept)
                "resistance_without_film": value(paths[f.index].without_film, "K/W"),
                "resistance": value(paths[f.index].resistance, "K/W"),
            }
            for f in result.films
        },
    }


def fields(result: ScrewTCR) -> xr.Dataset:
    """Pressure (solver grid) and element TCR (fractal cells) of every contact, with units."""
    variables: dict[str, Any] = {}
    coords: dict[str, Any] = {}
    for nut, side, tag in _contacts(result):
        r: RacewayTCR = getattr(nut, side)
        c = r.contact
        px, py = f"{tag}_x", f"{tag}_y"
        coords[px] = (px, c.x, {"units": "m", "long_name": "rolling direction"})
        coords[py] = (py, c.y, {"units": "m", "long_name": "across the groove"})
        variables[f"{tag}_pressure"] = (
            (px, py),
            np.asarray(c.solution.pressure),
            {"units": "Pa", "long_name": f"nut {nut.index}, {_LABEL[side]}: pressure"},
        )
        rmap = r.tcr.cell_resistance
        fx, fy = f"{tag}_fx", f"{tag}_fy"
        coords[fx] = (
            fx,
            fractal_cell_centres(c.x, rmap.shape[0], r.tcr.cell_size[0]),
            {"units": "m", "long_name": "fractal cell centre, rolling direction"},
        )
        coords[fy] = (
            fy,
            fractal_cell_centres(c.y, rmap.shape[1], r.tcr.cell_size[1]),
            {"units": "m", "long_name": "fractal cell centre, across the groove"},
        )
        variables[f"{tag}_element_resistance"] = (
            (fx, fy),
            np.where(np.isfinite(rmap), rmap, np.nan),
            {
                "units": "K/W",
                "long_name": f"nut {nut.index}, {_LABEL[side]}: element TCR (NaN = unloaded)",
            },
        )
    return xr.Dataset(
        variables,
        coords=coords,
        attrs={
            "case": result.case_name,
            "headline": result.headline,
            "variant": result.variant,
            # no re-binning (tcr.rebin = false): the solver's cells, and no attribute
            **({} if result.cell_size is None else {"cell_size_m": result.cell_size}),
        },
    )


def _contacts(result: ScrewTCR) -> list[tuple[NutTCR, str, str]]:
    """(nut, side, tag) of every contact, tag = ``nut<i>_<side>``."""
    return [(n, side, f"nut{n.index}_{side}") for n in result.nuts for side in SIDES]


def figures(result: ScrewTCR) -> list[Figure]:
    """Pressure map and element-TCR map of every contact."""
    out = []
    for nut, side, tag in _contacts(result):
        r: RacewayTCR = getattr(nut, side)
        c = r.contact
        rmap = r.tcr.cell_resistance
        label = f"nut {nut.index}, {_LABEL[side]}"
        out += [
            Figure(
                f"pressure_{tag}",
                f"Pressure, {label}, Hertz ellipse dashed.",
                partial(
                    plots.pressure_map,
                    c.x,
                    c.y,
                    c.solution.pressure,
                    (c.hertz.a, c.hertz.b),
                    f"{label}: Q = {c.load:.1f} N",
                ),
            ),
            Figure(
                f"tcr_{tag}",
                f"Element TCR of the fractal model {result.variant} on {_cells_text(result)}"
                + ("." if result.headline == result.variant else " (details, not the headline)."),
                partial(
                    plots.resistance_map,
                    fractal_cell_centres(c.x, rmap.shape[0], r.tcr.cell_size[0]),
                    fractal_cell_centres(c.y, rmap.shape[1], r.tcr.cell_size[1]),
                    rmap,
                    r.tcr.cell_size,
                    f"{label}: R_c = {r.tcr.resistance:.3g} K/W",
                ),
            ),
        ]
    return out


def _single_nut_note(screw: Any) -> tuple[str, ...]:
    """For a preloaded single nut: "nut 1" and "nut 2" of the tables are its two flanks."""
    method = screw.resolved_preload_method
    if screw.nuts != 1 or method == "spacer":
        return ()
    what = {
        "oversized_balls": "the two contact pairs of the same balls (four-point contact), "
        "in parallel into the one nut body",
        "offset_lead": "its two halves (half the balls each), in parallel into the one nut body",
    }[method]
    return (
        f"A single nut preloaded by {method.replace('_', ' ')}: 'nut 1' and 'nut 2' below are "
        f"its two loaded flanks, {what} (nut 2 is absent when it is lifted off or without "
        "preload).",
    )


def sections(result: ScrewTCR) -> list[Section]:
    """The report section: the screw's resistance, then each nut's."""
    case = result.case
    paths = {p.index: p for p in result.heat_paths()}
    rows = tuple(
        (
            f"nut {n.index}",
            n.force,
            n.ball_load,
            n.screw.resistance,
            n.nut.resistance,
            n.ball_resistance,
            n.resistance,
            paths[n.index].constriction,
            paths[n.index].ball_path_without_film,
            n.axial_stiffness * 1e-6,
        )
        for n in result.nuts
    )
    with_film = result.ball_path_with_film
    return [
        Section(
            "Thermal contact resistance of the screw",
            paragraphs=(
                headline_model_text(result),
                f"{roughness_text(case, 'profile')}, λ_f = "
                f"{case.medium.thermal_conductivity:g} W/mK. Screw and nut contact in series "
                "per ball, all loaded balls of both nuts in parallel (Gao, Wang & Liu 2019).",
                HEADLINE,
                *_single_nut_note(case.screw),
                *(
                    (
                        "Elastic ball-load distribution: every ball of a nut is taken at the most "
                        "loaded ball's load (largest / mean: "
                        + ", ".join(f"nut {n.index} {n.load_spread:.3f}" for n in result.nuts)
                        + "), a bound on the resistance from below.",
                    )
                    if case.loads.distribution == "elastic"
                    else ()
                ),
            ),
            tables=(
                Table(
                    ("quantity", "value"),
                    (
                        ("R, whole screw [K/W]", result.resistance),
                        ("S, apparent area [mm²]", result.apparent_area * 1e6),
                        ("R″ = R·S [m²K/W]", result.resistance_per_area),
                        (
                            "ball path without film, micro + constriction [K/W]",
                            result.ball_path_without_film,
                        ),
                        *(() if with_film is None else (("ball path with film [K/W]", with_film),)),
                        (
                            "F1, F2 [N]",
                            f"{result.nut_forces[0]:.1f}, {result.nut_forces[1]:.1f}",
                        ),
                    ),
                ),
                Table(
                    (
                        "nut",
                        "force [N]",
                        "ball load [N]",
                        "R_sb [K/W]",
                        "R_bn [K/W]",
                        "R_sbn [K/W]",
                        "R nut [K/W]",
                        "R_cons [K/W]",
                        "ball path without film [K/W]",
                        "stiffness [N/µm]",
                    ),
                    rows,
                ),
            ),
            figures=tuple(
                f"{kind}_{tag}" for _, _, tag in _contacts(result) for kind in ("pressure", "tcr")
            ),
        ),
        *_models_section(result),
        *_film_section(result),
    ]


def _film_section(result: ScrewTCR) -> list[Section]:
    """With ``[tcr] film_path``: the films around the balls and the ball path with them."""
    if not result.films:
        return []
    paths = {p.index: p for p in result.heat_paths()}
    rows = tuple(
        (
            f"nut {f.index}" + ("" if f.loaded else " (lifted off)"),
            f.screw.conductance,
            f.nut.conductance,
            f.screw.h0 * 1e6,
            f.screw.h_max * 1e6,
            paths[f.index].micro,
            paths[f.index].constriction,
            paths[f.index].ball_path_without_film,
            paths[f.index].resistance,
        )
        for f in result.films
    )
    text = (
        "The lubricant film around each ball outside its Hertz patch conducts in parallel with "
        "the patch path (micro TCR plus macro-constriction), a lifted-off nut's balls through "
        f"their films alone. Screw to nut through all balls: {result.heat_path_resistance:.4g} "
        "K/W with the film path (theory manual: Film path around the ball)."
    )
    return [
        Section(
            "Film path around the balls",
            paragraphs=(text,),
            tables=(
                Table(
                    (
                        "nut",
                        "G_f screw [W/K]",
                        "G_f nut [W/K]",
                        "h0 [µm]",
                        "h_max [µm]",
                        "R micro [K/W]",
                        "R_cons [K/W]",
                        "ball path without film [K/W]",
                        "ball path with film [K/W]",
                    ),
                    rows,
                ),
            ),
        )
    ]


def _models_section(result: ScrewTCR) -> list[Section]:
    """Every model of ``[tcr] models`` on the same contacts, and their spread."""
    if not result.models:
        return []
    spread = result.uncertainty
    text = (
        f"The same solved contacts evaluated by every model (headline: {result.headline}): the "
        "fractal element variants on the paper's Δ_f cells and on the whole Hertz patch "
        "(/patch, no cell size), the Gaussian correlations integrated over the pressure field "
        "(no cell size; σ and m from D and G over the stated wavelength band unless measured "
        "values are given). "
    )
    if spread is not None:
        text += (
            f"R″ spans {spread.low:.3g} … {spread.high:.3g} m²K/W (a factor "
            f"{spread.ratio:.3g}): the modelling uncertainty of the TCR."
        )
    return [
        Section(
            "Rival models of the contact resistance",
            paragraphs=(text,),
            tables=(
                Table(
                    ("model", "R [K/W]", "R″ [m²K/W]", "what it is"),
                    tuple(
                        (
                            f"{name} (headline)" if name == result.headline else name,
                            m.resistance,
                            m.resistance_per_area,
                            m.description,
                        )
                        for name, m in result.models.items()
                    ),
                ),
            ),
        )
    ]
