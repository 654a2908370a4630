"""What the wear analysis shows: its summary, history, figures and report sections.

Figures after the paper's: drag torque and preload versus revolutions with the level boundaries
(its Figures 11–12) and the wear profile across the groove at the end of each level (its
Figure 8).
"""

from __future__ import annotations

import math
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from ballscrew.analyses.result import Figure, Section, Table
from ballscrew.analyses.result import quantity as value
from ballscrew.analyses.roughness import roughness_summary, surface_roughness
from ballscrew.analyses.wear_film import FULL_FILM_SHARE, PartFilm
from ballscrew.case import Case
from ballscrew.case.wear_spec import WearSpec
from ballscrew.loads import preload_flanks
from ballscrew.plotting import legend_outside, pyplot, revolutions_axis, save_figure
from ballscrew.units import format_number
from ballscrew.wear.history import WearLife

if TYPE_CHECKING:
    from ballscrew.analyses.wear import WearResult

__all__ = ["figures", "history", "sections", "summary"]


def _provenance(case: Case) -> str:
    spec = case.wear
    if spec is not None and not spec.reference_calibration:
        return "case file [wear] coefficient"
    roughness = "film" if spec is None else spec.asperity_roughness
    return (
        "reference calibration: h_max = 2.43 µm at 1.44×10⁶ rev on the step-stress example screw "
        "(examples/wear_step_stress.toml: Model A, 32 × 128 grid, ΔA = 59.91 µm², S = 0.30 m) "
        f"with wear.asperity_roughness = '{roughness}'"
    )


def _member(case: Case) -> str:
    """What the two loaded members are called: "nut" (nut 1, nut 2) of a double nut, "flank"
    (flank 1, flank 2) of a preloaded single nut (two contact pairs of the same balls, or two
    halves)."""
    return "nut" if case.screw.nuts == 2 else "flank"


def _layout(case: Case) -> dict[str, Any]:
    """How the nut is preloaded and how many balls load each flank."""
    screw = case.screw
    method = screw.resolved_preload_method
    flanks = preload_flanks(method, screw.nuts, screw.balls_per_nut, case.operating.preload)
    return {"nuts": screw.nuts, "preload_method": method, "balls_per_flank": flanks.balls}


def _single_nut_note(case: Case) -> tuple[str, ...]:
    """For a preloaded single nut: what its flank 1 and flank 2 are."""
    if case.screw.nuts != 1:
        return ()
    layout = _layout(case)
    balls = layout["balls_per_flank"]
    what = {
        "oversized_balls": (
            "oversized balls",
            f"the two contact pairs of the same {balls} balls (four-point contact)",
            "ball oversize",
        ),
        "offset_lead": ("an offset lead", f"its two halves of {balls} balls each", "lead offset"),
    }[layout["preload_method"]]
    return (
        f"A single nut preloaded by {what[0]}: flank 1 and flank 2 are {what[1]}, each loaded "
        f"and worn as one nut of a double nut; the wear eats into the {what[2]} (theory manual, "
        "Wear).",
    )


def _lubrication_options(case: Case) -> dict[str, Any]:
    """Supply factor, running-in and, for a duty programme, each segment's operating point."""
    from ballscrew.analyses.wear_duty import duty_programme

    spec = case.wear or WearSpec()
    running = spec.running_in
    out: dict[str, Any] = {
        "film_factor": spec.film_factor,
        "asperity_roughness": spec.asperity_roughness,
        "surface": roughness_summary(case, "surface"),
        "running_in": None
        if running is None
        else {
            "D": running.D,
            "G": value(running.G, "m"),
            "G_surface": value(surface_roughness(case, running.D, running.G), "m"),
            "depth": value(running.depth, "m"),
        },
        "programme": "duty" if case.duty else "wear.programme",
    }
    if case.duty:
        out["segments"] = [
            {
                "speed": value(part.speed, "rad/s"),
                "axial_load": value(part.axial_load, "N"),
                "revolutions": part.revolutions,
                "contact_temperature": value(part.temperature, "K"),
                "viscosity": None if part.viscosity is None else value(part.viscosity, "Pa*s"),
            }
            for level in duty_programme(case)
            for _, part in level.parts()
        ]
    return out


def _film_scalars(film: PartFilm) -> dict[str, Any]:
    """Λ = h_c/σ_Λ of the whole ball load (the operating point's), its regime and parts, and the
    wear engine's asperity share ψ and separation h; the film entries None when dry or at rest."""

    def maybe(number: float | None, unit: str) -> dict[str, Any] | None:
        return None if number is None else value(number, unit)

    return {
        "film_parameter": maybe(film.film_parameter, ""),
        "lubrication_regime": film.regime,
        "film_thickness": maybe(film.film_thickness, "m"),
        "film_roughness": maybe(
            film.film_roughness if math.isfinite(film.film_roughness) else None, "m"
        ),
        "asperity_share": value(film.asperity_share, ""),
        "separation": maybe(film.separation, "m"),
    }


def summary(result: WearResult) -> dict[str, Any]:
    """Scalars of the run: final wear, contact width, preload, torque and the model options."""
    life, case = result.life, result.case
    return {
        "case": case.name,
        "complete": life.complete,
        "revolutions": float(life.revolutions[-1]),
        "max_wear_depth": value(float(life.max_wear_depth[-1]), "m"),
        "ellipse_major_axis": value(life.ellipse_major_axis, "m"),
        "ellipse_major_axis_unworn": value(life.ellipse_major_axis_unworn, "m"),
        "worn_band_width": value(life.worn_band_width, "m"),
        "initial_preload": value(float(life.preload[0]), "N"),
        "final_preload": value(float(life.preload[-1]), "N"),
        "initial_torque": value(float(life.friction_torque[0]), "N*m"),
        "final_torque": value(float(life.friction_torque[-1]), "N*m"),
        "final_forces": {
            name: value(float(force), "N")
            for name, force in zip(
                (f"{_member(case)} 1", f"{_member(case)} 2"), life.nut_forces[-1], strict=True
            )
        },
        "nut": _layout(case),
        "wear_coefficient": {"value": life.coefficient, "unit": "", "source": _provenance(case)},
        "lubrication": [
            {
                "part": f.name,
                "speed": value(f.speed, "rad/s"),
                "axial_load": value(f.axial_load, "N"),
                "ball_load": value(f.ball_load, "N"),
                **_film_scalars(f),
            }
            for f in result.films
        ],
        "levels": [
            {
                "axial_load": value(float(f), "N"),
                "end_revolutions": float(n),
                "max_wear_depth": value(
                    float(np.interp(n, life.revolutions, life.max_wear_depth)), "m"
                ),
                "preload": value(float(np.interp(n, life.revolutions, life.preload)), "N"),
            }
            for f, n in zip(life.level_loads, life.level_boundaries, strict=True)
        ],
        "options": {
            "model": life.model,
            "raceway_length": value(life.raceway_length, "m"),
            "compliance_constant": value(life.compliance, "m/N^(2/3)"),
            "cell_area": value(life.cell_area, "m^2"),
            "initial_psi": life.initial_psi,
            **_lubrication_options(case),
        },
        "solver": {
            "steps": life.steps,
            "contact_solves": life.contact_solves,
            "wall_time": value(life.wall_time, "s"),
        },
    }


def fields(result: WearResult) -> xr.Dataset:
    """The dataset of the results folder, ``history.nc``: :func:`history`."""
    return history(result)


def history(result: WearResult) -> xr.Dataset:
    """History over revolutions: wear profiles of both flanks, h_max, preload, forces, torque."""
    life, case = result.life, result.case
    step = np.arange(life.revolutions.size)
    member = _member(case)
    force = "nut_force" if member == "nut" else "flank_force"
    pair = "nut" if member == "nut" else "loaded_flank"
    return xr.Dataset(
        {
            "revolutions": ("step", life.revolutions, {"units": "1", "long_name": "revolutions"}),
            "max_wear_depth": ("step", life.max_wear_depth, {"units": "m"}),
            "preload": ("step", life.preload, {"units": "N", "long_name": "preload (E1.13)"}),
            "friction_torque": (
                "step",
                life.friction_torque,
                {"units": "N m", "long_name": "no-load drag torque (E9.1)"},
            ),
            force: (
                ("step", pair),
                life.nut_forces,
                {"units": "N", "long_name": f"axial force of {member} 1 and {member} 2"},
            ),
            "level": ("step", life.level, {"units": "1", "long_name": "level index (0-based)"}),
            "torque_sample": ("step", life.sampled.astype(np.int8), {"units": "1"}),
            "wear_depth": (
                ("step", "flank", "y"),
                life.profiles,
                {"units": "m", "long_name": "wear depth across the groove"},
            ),
            "level_end": ("level_index", life.level_boundaries, {"units": "1"}),
            "level_load": ("level_index", life.level_loads, {"units": "N"}),
            **_film_variables(result.films),
        },
        coords={
            "step": step,
            pair: [1, 2],
            "flank": [1, -1],
            "y": ("y", life.y, {"units": "m", "long_name": "across the groove"}),
            "level_index": np.arange(life.level_loads.size),
            "part": [f.name for f in result.films],
        },
        attrs={"case": case.name, "model": life.model, "wear_coefficient": life.coefficient},
    )


_FILM_VARIABLES = {
    "film_parameter": ("1", "film parameter h_c/σ_Λ of the whole ball load (E6.6)"),
    "film_thickness": ("m", "central EHL film h_c of the whole ball load"),
    "film_roughness": ("m", "composite RMS roughness σ_Λ (E6.6)"),
    "asperity_share": ("1", "asperity share ψ of the wear engine (E6.4)"),
    "separation": ("m", "mean-plane separation of the wear engine (E6.4)"),
}


def _film_variables(films: tuple[PartFilm, ...]) -> dict[str, Any]:
    """Per programme part at its level's start (NaN when dry or at rest): Λ = h_c/σ_Λ and its
    parts, the wear engine's ψ and separation h."""
    out = {}
    for name, (unit, long_name) in _FILM_VARIABLES.items():
        numbers = [getattr(f, name) for f in films]
        column = np.array([math.nan if v is None else v for v in numbers], dtype=float)
        out[name] = ("part", column, {"units": unit, "long_name": long_name})
    return out


def _levels(ax: Any, life: WearLife, unit: float) -> None:
    for n in life.level_boundaries[:-1]:
        ax.axvline(n / unit, color="0.6", ls=":", lw=1)


def _torque_preload(life: WearLife, path: Path) -> Path:
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.4), layout="constrained")
    n, t = life.torque_samples
    unit, label = revolutions_axis(life.revolutions)
    axes[0].plot(life.revolutions / unit, life.friction_torque, "-", lw=1)
    axes[0].plot(np.asarray(n) / unit, t, "o", ms=3, label="samples (wear.torque_sampling)")
    axes[0].set_ylabel("drag torque [N·m]")
    axes[1].plot(life.revolutions / unit, life.preload, "-", lw=1)
    axes[1].set_ylabel("preload [N]")
    for ax in axes:
        _levels(ax, life, unit)
        ax.set_xlabel(label)
        ax.set_ylim(bottom=0)
    axes[0].legend(fontsize=8, loc="lower left")
    return save_figure(fig, path)


def _profiles(life: WearLife, path: Path) -> Path:
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
    for k, end in enumerate(life.level_boundaries):
        i = int(np.argmin(np.abs(life.revolutions - end)))
        ax.plot(1e6 * life.y, 1e6 * life.profiles[i, 0], label=f"end of level {k + 1}")
    ax.set_xlabel("y, across the groove [µm]")
    ax.set_ylabel("wear depth [µm]")
    legend_outside(ax, fontsize=8)
    return save_figure(fig, path)


def _depth(life: WearLife, path: Path) -> Path:
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 3.4), layout="constrained")
    unit, label = revolutions_axis(life.revolutions)
    ax.plot(life.revolutions / unit, 1e6 * life.max_wear_depth, "o-", ms=2)
    _levels(ax, life, unit)
    ax.set_xlabel(label)
    ax.set_ylabel("largest wear depth h_max [µm]")
    return save_figure(fig, path)


def figures(result: WearResult) -> list[Figure]:
    """Torque and preload, wear profiles and the largest wear depth versus revolutions."""
    life = result.life
    return [
        Figure(
            "torque_preload",
            "Drag torque (E9.1) and preload (E1.13) versus revolutions; dotted: level ends.",
            partial(_torque_preload, life),
        ),
        Figure(
            "wear_profiles",
            "Wear depth across the groove (flank +1) at the end of each level.",
            partial(_profiles, life),
        ),
        Figure("max_wear_depth", "Largest wear depth versus revolutions.", partial(_depth, life)),
    ]


def sections(result: WearResult) -> list[Section]:
    """The report section: final wear, contact width, preload and torque, level by level."""
    life = result.life
    data = summary(result)
    member = _member(result.case)
    rows = tuple(
        (
            f"level {k + 1}",
            lv["axial_load"]["value"],
            lv["end_revolutions"],
            1e6 * lv["max_wear_depth"]["value"],
            lv["preload"]["value"],
        )
        for k, lv in enumerate(data["levels"])
    )
    return [
        Section(
            "Raceway wear and preload degradation",
            paragraphs=(
                f"Fractal wear Model {life.model}, K = {format_number(life.coefficient)} "
                f"({data['wear_coefficient']['source']}); L_w = "
                f"{life.raceway_length:.4g} m; {life.steps} steps, "
                f"{life.contact_solves} contact solutions in {life.wall_time:.1f} s.",
                "The largest wear depth sets the preload every step (E1.13); the torque is "
                "the catalogue drag torque of the preload (E9.1). The running-in drop of "
                "the measured torque is not modelled.",
                *_single_nut_note(result.case),
            ),
            tables=(
                Table(
                    ("quantity", "value"),
                    (
                        ("largest wear depth [µm]", 1e6 * float(life.max_wear_depth[-1])),
                        (
                            "contact width, worn / unworn [µm]",
                            f"{1e6 * life.ellipse_major_axis:.0f} / "
                            f"{1e6 * life.ellipse_major_axis_unworn:.0f}",
                        ),
                        ("worn band (h > 5 % of max) [µm]", 1e6 * life.worn_band_width),
                        (
                            "preload, initial / final [N]",
                            f"{life.preload[0]:.1f} / {life.preload[-1]:.1f}",
                        ),
                        (
                            "torque, initial / final [N·m]",
                            f"{life.friction_torque[0]:.4f} / {life.friction_torque[-1]:.4f}",
                        ),
                        (
                            f"axial force at the end, {member} 1 / {member} 2 [N]",
                            f"{life.nut_forces[-1, 0]:.1f} / {life.nut_forces[-1, 1]:.1f}",
                        ),
                    ),
                ),
                Table(("level", "F_a [N]", "end [rev]", "h_max [µm]", "F_p [N]"), rows),
            ),
            figures=("torque_preload", "wear_profiles", "max_wear_depth"),
        ),
        *_film_section(result),
    ]


_HEIGHTS = {
    "cell": 'from the asperities of one grid cell (wear.asperity_roughness = "cell": the σ of '
    "one cell, not σ_Λ, so ψ and Λ need not agree)",
    "film": 'from asperities of the height σ_Λ of Λ (wear.asperity_roughness = "film", as the '
    "friction model)",
}
"""Which asperities share the load with the film, by ``wear.asperity_roughness``."""


def _film_section(result: WearResult) -> list[Section]:
    """Λ, its regime and ψ of each programme part: why a level wears little or nothing."""
    if not result.films:
        return []

    def nm(number: float | None) -> str:
        return "–" if number is None else f"{1e9 * number:.3g}"

    rows = tuple(
        (
            f.name,
            f.speed * 30.0 / math.pi,
            f.axial_load,
            f.ball_load,
            "dry" if f.film_parameter is None else f"{f.film_parameter:.3g}",
            f.regime or "dry",
            f"{f.asperity_share:.3g}",
            nm(f.separation),
        )
        for f in result.films
    )
    text = (
        "The wear law acts on the asperity-borne part ψQ of the ball load Q only (Johnson, "
        "Greenwood & Poon 1972): where the EHL film separates the surfaces (ψ → 0) a level "
        "wears practically nothing, so the wear depth can stop growing from one level to the "
        "next. For the mean ball of the more loaded "
        f"{_member(result.case)} at the start of each level (the raceway worn and the preload "
        "lost by the earlier levels): Λ = h_c/σ_Λ, the central film of the whole ball load over "
        "the raceway's composite RMS roughness, as the operating point and the kinematics report "
        "it, with its regime (Hamrock 1994: below 1 boundary, 1–3 mixed, above 3 EHL); ψ and "
        "the separation h (the film of the film-borne load) as the wear engine applies them, "
        f"{_HEIGHTS[(result.case.wear or WearSpec()).asperity_roughness]}. Below ψ = "
        f"{FULL_FILM_SHARE:g} a warning says so."
    )
    table = Table(
        (
            "part",
            "speed [rpm]",
            "F_a [N]",
            "Q [N]",
            "Λ = h_c/σ_Λ [-]",
            "regime",
            "ψ [-]",
            "h, wear engine [nm]",
        ),
        rows,
    )
    return [Section("Film and asperity share by level", paragraphs=(text,), tables=(table,))]
