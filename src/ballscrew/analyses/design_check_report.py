"""What the design check shows: design values with margins, the stiffness curve, the life."""

from __future__ import annotations

import math
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from ballscrew import design
from ballscrew.analyses.ball_loads import elastic_distribution, elastic_lift_off
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.result import Figure, Section, Table
from ballscrew.loads.distribution import LIFT_OFF_SEARCH, Distribution
from ballscrew.plotting import legend_outside, pyplot, save_figure
from ballscrew.units import in_display_units

if TYPE_CHECKING:
    from ballscrew.analyses.design_check import DesignCheck, Margin

__all__ = ["ball_distribution", "fields", "figures", "sections", "stiffness_curve", "summary"]

_CURVE_POINTS = 121
_BODY_POINTS = 41

# name → (unit, label, display scale, display unit)
_VALUES: dict[str, tuple[str, str, float, str]] = {
    "dynamic_load_rating": ("N", "dynamic load rating C_a", 1e-3, "kN"),
    "static_load_rating": ("N", "static load rating C_0a", 1e-3, "kN"),
    "rating_life": ("", "rating life L", 1.0, "rev"),
    "life_hours": ("h", "rating life L_h", 1.0, "h"),
    "life_travel": ("m", "rating life as travel", 1e-3, "km"),
    "static_safety_factor": ("", "static safety factor f_s", 1.0, "-"),
    "critical_speed": ("rad/s", "critical speed (Euler beam)", 60.0 / (2.0 * math.pi), "rpm"),
    "buckling_load": ("N", "buckling load (Euler)", 1e-3, "kN"),
    "permissible_tension": ("N", "permissible tension/compression", 1e-3, "kN"),
    "dn": ("mm·rpm", "d·n at the highest speed", 1.0, "mm·rpm"),
    "contact_stiffness": ("N/m", "nut stiffness, Hertz contacts only", 1e-6, "N/µm"),
    "nut_stiffness": ("N/m", "nut stiffness, contacts and bodies", 1e-6, "N/µm"),
    "catalogue_nut_stiffness": ("N/m", "nut stiffness, catalogue 0.8 K", 1e-6, "N/µm"),
    "shaft_stiffness": ("N/m", "shaft stiffness", 1e-6, "N/µm"),
    "axial_stiffness": ("N/m", "nut + shaft stiffness (supports rigid)", 1e-6, "N/µm"),
    "drive_stiffness": ("N/m", "drive stiffness, nut + shaft + supports", 1e-6, "N/µm"),
    "preload_drag_torque": ("N*m", "preload drag torque", 1.0, "N·m"),
    "preload_drag_torque_min": ("N*m", "preload drag torque, lower end of the band", 1.0, "N·m"),
    "preload_drag_torque_max": ("N*m", "preload drag torque, upper end of the band", 1.0, "N·m"),
    "lost_motion": ("m", "lost motion at a reversal of the largest load", 1e6, "µm"),
    "nut_radial_force": ("N", "radial force on the guided nut at the largest load", 1.0, "N"),
    "nut_tilting_moment": ("N*m", "tilting moment on the guided nut, same load", 1.0, "N·m"),
    "nut_radial_displacement": ("m", "radial shift of the free nut at the largest load", 1e6, "µm"),
    "nut_tilt": ("rad", "tilt of the free nut, same load", 1e6, "µrad"),
    "thermal_elongation": ("m", "thermal elongation", 1e6, "µm"),
    "thermal_pretension": ("N", "pretension for the temperature rise", 1e-3, "kN"),
}


def _quantity(number: float | None, unit: str) -> dict[str, Any] | None:
    if number is None:
        return None
    if math.isinf(number):
        return {"value": None, "unit": unit, "note": "infinite"}
    return {"value": float(number), "unit": unit}


def summary(result: DesignCheck) -> dict[str, Any]:
    """Design values (SI) and every margin with its status."""
    values = {name: _quantity(getattr(result, name), unit) for name, (unit, *_) in _VALUES.items()}
    s = result.spectrum
    return {
        "case": result.case.name,
        **{k: v for k, v in values.items() if v is not None},
        "nut_support": result.case.loads.nut_support,
        "load_ratings_computed": list(result.computed_ratings),
        "equivalent_loads": [_quantity(f, "N") for f in result.equivalent_loads],
        "load_spectrum": {
            "source": s.source,
            "loads": [_quantity(f, "N") for f in s.loads],
            "shares": list(s.shares),
            "mean_speed": _quantity(s.mean_speed, "rad/s"),
            "max_speed": _quantity(s.max_speed, "rad/s"),
        },
        "margins": {
            m.name: {
                "demand": _quantity(m.demand, m.unit),
                "capacity": _quantity(m.capacity, m.unit),
                "ratio": None if math.isinf(m.ratio) else m.ratio,
                "status": m.status,
            }
            for m in result.margins
        },
    }


def _params(result: DesignCheck) -> ScrewParameters:
    return ScrewParameters.from_case(result.case)


def ball_distribution(result: DesignCheck, axial_load: float | None = None) -> Distribution:
    """Elastic load of every ball (contacts and bodies) at the case's preload and
    ``axial_load`` ≥ 0 [N] (None: the case's)."""
    case = result.case
    return elastic_distribution(
        _params(result), case.loads, result.root_diameter, axial_load, numerics=case.numerics
    )


def _distribution_at(result: DesignCheck, load: float) -> Distribution:
    """:func:`ball_distribution` at ``load`` ≥ 0 [N]; the one :func:`design_check` solved
    where ``load`` is the spectrum's largest |F_a| or zero."""
    if load == result.spectrum.max_load and result.largest_distribution is not None:
        return result.largest_distribution
    if load == 0.0 and result.unloaded_distribution is not None:
        return result.unloaded_distribution
    return ball_distribution(result, load)


def _largest_level(result: DesignCheck) -> float:
    """The spectrum's level of the largest |F_a|, signed (a forward one where ± tie) [N]."""
    return max(result.spectrum.loads, key=lambda f: (abs(f), f))


def _body_curve(result: DesignCheck, top: float) -> tuple[np.ndarray, ...]:
    """Axial loads, displacement and stiffness with the bodies."""
    params, spec, numerics = _params(result), result.case.loads, result.case.numerics
    fp = params.preload
    loads = np.linspace(0.0 if fp > 0 else top / _BODY_POINTS, top, _BODY_POINTS)
    interference = (  # of the preload, found at zero axial load; none without preload
        _distribution_at(result, 0.0).interference if fp > 0 else None
    )
    runs: list[Distribution] = []
    for f in loads:  # each solve starts from the one at the load before (long nuts)
        runs.append(
            elastic_distribution(
                params,
                spec,
                result.root_diameter,
                axial_load=f,
                interference=interference,
                numerics=numerics,
                start=runs[-1] if runs else None,
            )
        )
    x = np.array([r.displacement for r in runs])
    if fp > 0:  # from the preloaded state at zero load; without preload x(0) = 0 already
        x = x - x[0]
    return loads, x, np.array([r.stiffness for r in runs])


def stiffness_curve(result: DesignCheck) -> xr.Dataset:
    """Nut displacement and stiffness against the axial load: Hertz contacts only, and the
    contacts with the elastic bodies, with units. Without preload the curves start one step
    above zero load, where the unloaded contacts have no stiffness to give. A report reads it
    through :attr:`DesignCheck.stiffness_curve`, which builds it once per result."""
    fp, nuts = result.case.operating.preload, result.flanks
    lift_off = design.LIFT_OFF_FACTOR * fp if nuts == 2 else 0.0
    top = max(1.5 * lift_off, 1.2 * result.spectrum.max_load, 3.0 * fp, 1.0)
    loads = np.linspace(0.0 if fp > 0 else top / _CURVE_POINTS, top, _CURVE_POINTS)
    x, k = design.nut_load_curve(loads, fp, result.compliance, nuts)
    body_loads, body_x, body_k = _body_curve(result, top)
    return xr.Dataset(
        {
            "deflection": ("axial_load", x, {"units": "m", "long_name": "nut displacement"}),
            "stiffness": ("axial_load", k, {"units": "N/m", "long_name": "tangent stiffness"}),
            "deflection_bodies": (
                "body_load",
                body_x,
                {"units": "m", "long_name": "nut displacement, contacts and bodies"},
            ),
            "stiffness_bodies": (
                "body_load",
                body_k,
                {"units": "N/m", "long_name": "tangent stiffness, contacts and bodies"},
            ),
        },
        coords={
            "axial_load": ("axial_load", loads, {"units": "N"}),
            "body_load": ("body_load", body_loads, {"units": "N"}),
        },
        attrs={
            "lift_off_load_N": lift_off,
            "lift_off_load_bodies_N": elastic_lift_off(
                _params(result), result.case.loads, result.root_diameter, result.case.numerics
            ),
            "preload_N": fp,
            "nut_support": result.case.loads.nut_support,
            "nuts": result.case.screw.nuts,
            "flanks": nuts,
        },
    )


def fields(result: DesignCheck) -> xr.Dataset:
    """The stiffness curve (a shallow copy of the result's: its arrays, not its dataset)."""
    return result.stiffness_curve.copy()


def _stiffness_figure(result: DesignCheck, path: Path) -> Path:
    plt = pyplot()
    curve = result.stiffness_curve
    loads = curve["axial_load"].values * 1e-3
    body = curve["body_load"].values * 1e-3
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.4), layout="constrained")
    axes[0].plot(loads, curve["deflection"].values * 1e6, label="contacts only")
    axes[0].plot(body, curve["deflection_bodies"].values * 1e6, label="contacts and bodies")
    axes[0].set_ylabel("nut displacement [µm]")
    axes[1].plot(loads, curve["stiffness"].values * 1e-6, label="contacts only")
    axes[1].plot(body, curve["stiffness_bodies"].values * 1e-6, label="contacts and bodies")
    axes[1].set_ylabel("stiffness [N/µm]")
    for ax in axes:
        for key, color, text in (
            ("lift_off_load_N", "C0", "lift-off 2^1.5 F_p, contacts"),
            ("lift_off_load_bodies_N", "C1", "lift-off with bodies"),
        ):
            at = curve.attrs[key] * 1e-3
            if 0 < at <= loads.max():
                ax.axvline(at, ls="--", c=color, lw=0.8, label=text)
            elif math.isinf(at):  # a long nut's bars keep the load from nut 2
                beyond = LIFT_OFF_SEARCH * curve.attrs["preload_N"] * 1e-3
                ax.plot([], [], ls="--", c=color, lw=0.8, label=f"{text}: none to {beyond:.4g} kN")
            elif at > 0:  # a free nut's tilt keeps balls loaded far beyond: said, not drawn
                ax.plot([], [], ls="--", c=color, lw=0.8, label=f"{text} at {at:.4g} kN")
        ax.axvline(result.case.operating.axial_load * 1e-3, ls=":", c="C3", label="case")
        ax.set_xlabel("axial load [kN]")
        ax.set_ylim(bottom=0)
        ax.set_xlim(-0.04 * loads.max(), 1.02 * loads.max())  # a line at 0 kN stays visible
    legend_outside(axes[1], fontsize=8)
    return save_figure(fig, path)


def _ball_figure(result: DesignCheck, path: Path) -> Path:
    """Ball loads at the case's axial load and, where it differs, at the spectrum's largest
    level: a reverse one as the mirror image of |F_a| (ASSUMED), nut 2 the loaded one."""
    plt = pyplot()
    case_load, largest = result.case.operating.axial_load, _largest_level(result)
    levels = [case_load] + ([largest] if largest != case_load else [])
    fig, axes = plt.subplots(
        1, len(levels), figsize=(4.6 * len(levels) + 1.8, 3.4), layout="constrained", sharey=True
    )
    top = 1e-9
    for ax, level in zip(np.atleast_1d(axes), levels, strict=True):
        dist = _distribution_at(result, abs(level))
        q, z = dist.per_nut(dist.loads), dist.per_nut(dist.layout.z)
        top = max(top, float(dist.loads.max()))
        for k in range(dist.layout.nuts):
            shown = k + 1 if level >= 0.0 else 2 - k  # reverse: flank 2 carries the load
            ax.plot(z[k] * 1e3, q[k], ".-", ms=3, lw=0.8, label=f"{result.part} {shown}")
            lifted = q[k] <= 0.0
            if lifted.any():
                ax.plot(z[k][lifted] * 1e3, q[k][lifted], "x", c="k", label="lifted off")
        mirror = ", mirror image of +|F_a|" if level < 0.0 else ""
        which = "case" if level == case_load else "largest of the spectrum"
        ax.set_title(f"F_a = {level * 1e-3:.4g} kN ({which}{mirror})", fontsize=9)
        ax.set_xlabel("axial position of the ball [mm] (loaded end right)")
        ax.legend(fontsize=8, loc="lower center")
    np.atleast_1d(axes)[0].set_ylabel("normal ball load [N]")
    np.atleast_1d(axes)[0].set_ylim(0.0, 1.1 * top)
    return save_figure(fig, path)


def _life_figure(result: DesignCheck, path: Path) -> Path:
    plt = pyplot()
    spec, s = result.spec, result.spectrum
    top = max(max(result.equivalent_loads), s.max_load, 1.0) * 2.0
    loads = np.linspace(top / 100.0, top, 100)
    life = design.rating_life(result.dynamic_load_rating, loads, spec.load_factor, spec.reliability)
    fig, ax = plt.subplots(figsize=(6.4, 3.6), layout="constrained")
    ax.loglog(loads, life, label="L(F) at constant load")
    size = np.abs(s.loads)  # a reverse level at its |F_a|
    ax.scatter(
        np.maximum(size, top / 100.0),
        np.interp(size, loads, life),
        s=20 + 200 * np.asarray(s.shares),
        c="C1",
        label="spectrum (size: share)",
    )
    for k, f in enumerate(result.equivalent_loads):
        if f > 0:
            ax.axvline(f, ls="--", c=f"C{k + 2}", lw=0.8, label=f"F_bm, {result.part} {k + 1}")
    if result.rating_life is not None and math.isfinite(result.rating_life):
        both = f"both {result.part}s" if result.flanks == 2 else result.part
        ax.axhline(result.rating_life, ls=":", c="k", lw=0.8, label=f"rating life, {both}")
    ax.set_xlabel("axial load [N]")
    ax.set_ylabel("rating life [rev]")
    legend_outside(ax, fontsize=8)
    return save_figure(fig, path)


def figures(result: DesignCheck) -> list[Figure]:
    """Stiffness curve with lift-off; rating life against the load spectrum (with C_a)."""
    out = [
        Figure(
            "stiffness_curve",
            "Nut displacement and stiffness vs axial load, Hertz contacts only and with the "
            f"elastic shaft and nut body; dashed: lift-off of the second {result.part}.",
            partial(_stiffness_figure, result),
        ),
        Figure(
            "ball_loads",
            "Normal load of every ball at the case's preload and axial load and, where it "
            "differs, at the largest load of the spectrum (contacts and bodies; a reverse load "
            f"as the mirror image, {result.part} 2 the loaded one, ASSUMED); x: lifted-off balls.",
            partial(_ball_figure, result),
        ),
    ]
    if result.dynamic_load_rating is not None:
        out.append(
            Figure(
                "life_spectrum",
                "Rating life against the axial load, the spectrum's levels and F_bm.",
                partial(_life_figure, result),
            )
        )
    return out


def _value_rows(result: DesignCheck) -> tuple[tuple[object, ...], ...]:
    rows = []
    for name, (_, label, scale, unit) in _VALUES.items():
        number = getattr(result, name)
        if number is not None:
            note = " (computed from the geometry)" if name in result.computed_ratings else ""
            rows.append((f"{label}{note} [{unit}]", number * scale))
    return tuple(rows)


_METHODS = {
    "dynamic_load_rating": "C_a by Lundberg-Palmgren (Harris & Kotzalas 2006) with C_a ∝ i^0.7 "
    "over the turns (ISO 281)",
    "static_load_rating": "C_0a by model '{model}' ({description})",
}


def _ratings_note(result: DesignCheck) -> str:
    if not result.computed_ratings:
        return "Load ratings C_a and C_0a are the catalogue's."
    model = result.spec.static_rating_model
    description = design.STATIC_RATING_MODELS.entry(model).description
    methods = "; ".join(
        _METHODS[name].format(model=model, description=description)
        for name in result.computed_ratings
    )
    return (
        "Load ratings not given in [design] ("
        + ", ".join(result.computed_ratings)
        + f") are COMPUTED from the geometry: {methods}; times the hardness and accuracy factors "
        "f_H f_ac (theory manual, Load ratings). The maker's values take precedence when known."
    )


_PRELOAD_NOTES = {
    "spacer": "a double nut preloaded by a spacer",
    "oversized_balls": "a single nut preloaded by oversized balls (four-point contact: every "
    "ball loads both flanks, each flank carries all balls of the nut)",
    "offset_lead": "a single nut preloaded by an offset lead (half the balls on each flank)",
}


def _preload_note(result: DesignCheck) -> str:
    """Which preload method the loads, stiffness, life and lift-off margin assume."""
    screw = result.case.screw
    if result.flanks == 1:
        return "Preload method: none (a single nut without preload, one loaded flank). "
    method = screw.resolved_preload_method
    return f"Preload method: {method}, {_PRELOAD_NOTES[method]}. "


def _supports_note(result: DesignCheck) -> str:
    """What the drive stiffness includes: a catalogue's nut rigidity compares with the nut's."""
    text = (
        "A catalogue's nut rigidity compares with the nut stiffness alone; the shaft between "
        "the fixed bearing and the nut is in series with it"
    )
    if result.drive_stiffness is None:
        return (
            text + ". The support bearings are LEFT OUT (taken as rigid): give "
            "design.bearing_stiffness for the drive stiffness with them."
        )
    return text + ", and so are the support bearings (design.bearing_stiffness)."


def _motion_note(result: DesignCheck) -> str:
    """How the lost motion and the drag-torque band are made."""
    from ballscrew.analyses.design_check import DRAG_TORQUE_BAND

    play = (
        "; a nut without preload adds its axial play, which is not an input"
        if result.flanks == 1
        else " (no backlash below lift-off)"
    )
    band = 100 * DRAG_TORQUE_BAND
    return (
        " Lost motion: 2 (x_nut(F) + F/K_shaft [+ F/K_bearings]) at a reversal of the largest "
        f"axial load F, x_nut with contacts and bodies{play}. Preload drag torque "
        f"K F_p L/(2π) with a band of ±{band:.0f} % [ASSUMED: the makers' tolerance depends on "
        "the torque, grade and thread length]."
    )


def _support_note(result: DesignCheck) -> str:
    """What takes the balls' radial force and tilting moment (``loads.nut_support``)."""
    at = (
        "under the largest axial load (a reverse one taken as the mirror image of the forward "
        "load, ASSUMED)"
    )
    if result.case.loads.nut_support == "free":
        return (
            " Nut support free: the nut balances the net radial force and tilting moment of its "
            "balls (the helix places them unsymmetrically) and any external ones "
            "(loads.nut_radial_load, nut_tilting_moment) by shifting and tilting on its balls "
            f"relative to the screw, given {at}; the lift-off with bodies is where the last ball "
            f"of the second {result.part} lifts off (the tilt keeps a few loaded long after "
            f"that {result.part}'s force has nearly gone), with the case's lead and "
            "ball-diameter errors and external radial force and moment."
        )
    return (
        " Nut support guided: the helix places the balls unsymmetrically, and the nut's housing "
        f"takes their net radial force and tilting moment about the nut's centre, given {at}."
    )


def _margin_row(m: Margin) -> tuple[str, float, float, str, float, str]:
    """A margin's table row, demand and capacity in one engineering unit (rpm, kN; SI in, as
    ``summary.json`` keeps them)."""
    (demand, capacity), unit = in_display_units((m.demand, m.capacity), m.unit)
    return (m.label, demand, capacity, unit, m.ratio, m.status.upper())


def sections(result: DesignCheck) -> list[Section]:
    """Margins (green/amber/red), design values, stiffness curve and life."""
    margins = tuple(_margin_row(m) for m in result.margins)
    s = result.spectrum
    spectrum = tuple(
        (k + 1, f, share) for k, (f, share) in enumerate(zip(s.loads, s.shares, strict=True))
    )
    return [
        Section(
            "Margins",
            paragraphs=(
                "capacity / demand: GREEN ≥ 1.25, AMBER ≥ 1, RED < 1. Speed and buckling against "
                "the makers' 0.8 × critical speed and 0.5 × buckling load (THK, HIWIN). "
                "A preloaded nut's largest axial load against the lift-off load 2^1.5 F_p, above "
                f"which its second {result.part} runs unloaded, with backlash (HIWIN F 3.5-3.7; "
                "rigid bodies, no lead or ball-diameter errors, no radial load or moment: the "
                "stiffness figure's lift-off with bodies has the case's); "
                "a shaft fixed at both ends, pretensioned for the temperature rise, against its "
                "permissible tension (THK A-694). The amber band of every margin is a GUESS.",
            ),
            tables=(Table(("check", "demand", "capacity", "unit", "ratio", "status"), margins),),
        ),
        Section(
            "Design values",
            paragraphs=(
                _preload_note(result)
                + _ratings_note(result)
                + " Life, static safety, speed and buckling by "
                "the makers' formulas (THK General Catalog, HIWIN Ballscrews & Accessories); "
                "nut stiffness from the Hertz contacts of every ball with the elastic shaft "
                "under the nut and the nut body (theory manual, Loads). "
                + _supports_note(result)
                + _motion_note(result)
                + _support_note(result),
            ),
            tables=(Table(("quantity", "value"), _value_rows(result)),),
            figures=("stiffness_curve", "ball_loads"),
        ),
        Section(
            "Life against the load spectrum",
            paragraphs=(
                f"Load spectrum from [{s.source}]. Cube-mean equivalent loads of the loaded "
                f"flanks (preload included, HIWIN F 3.5–3.9), lives combined as "
                f"(L₁^(−10/9) + L₂^(−10/9))^(−9/10); a negative load is the reverse "
                f"direction, which loads {result.part} 2: "
                + ", ".join(f"{f:.4g} N" for f in result.equivalent_loads),
            ),
            tables=(Table(("level", "axial load [N]", "revolutions share"), spectrum),),
            figures=("life_spectrum",) if result.dynamic_load_rating is not None else (),
        ),
    ]
