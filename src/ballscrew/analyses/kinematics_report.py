"""What the kinematics analysis shows: its summary, fields, figures and report sections."""

from __future__ import annotations

import math
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.result import Figure, Section, Table
from ballscrew.analyses.result import quantity as value
from ballscrew.analyses.roughness import roughness_summary, roughness_text
from ballscrew.kinematics.balance import BallState
from ballscrew.kinematics.torque import BallDrag
from ballscrew.plotting import legend_outside, plain, pyplot, save_figure, zero_noise

if TYPE_CHECKING:
    from ballscrew.analyses.kinematics import ContactFields, KinematicsRun

__all__ = [
    "fields",
    "figures",
    "sections",
    "sliding_map",
    "summary",
]

_RPM = 60.0 / (2.0 * math.pi)


def _state_summary(
    state: BallState, drag: BallDrag, balls: int, fields: ContactFields | None
) -> dict[str, Any]:
    out: dict[str, Any] = {
        "flank": state.flank,
        "nut_force": value(state.nut_force, "N"),
        "ball_speed": value(state.ball_speed, "m/s"),
        "orbital_speed": value(state.orbital_speed, "rad/s"),
        "spin_screw": value(state.spin_screw, "rad/s"),
        "spin_nut": value(state.spin_nut, "rad/s"),
        "load_screw": value(state.load_screw, "N"),
        "load_nut": value(state.load_nut, "N"),
        "angle_screw": value(state.angle_screw, "rad"),
        "angle_nut": value(state.angle_nut, "rad"),
        # the ball contacts' losses of this nut: sliding at A and EHL rolling at A and B
        "contact_losses": value(balls * drag.dissipation_torque, "N*m"),
        "asperity_share": drag.psi,
        "solver_iterations": state.iterations,
    }
    if state.level == 2:
        out["traction_coefficient_nut"] = state.traction_coefficient_nut
    if fields is not None:
        out["asperity_share"] = fields.sharing.psi
        out["separation"] = value(
            fields.sharing.separation if fields.sharing.film else math.nan, "m"
        )
        out["peak_pressure"] = value(fields.contact.solution.peak_pressure, "Pa")
    return out


def summary(run: KinematicsRun) -> dict[str, Any]:
    """Scalars at the case speed, the curves versus speed and the options used."""
    case = run.case
    balls = ScrewParameters.from_case(case).flanks.balls  # per loaded flank
    nuts = {}
    for number, state in run.states.items():
        fields = run.fields if number == 1 else None
        entry = _state_summary(state, run.drags[number], balls, fields)
        nuts[f"nut{number}"] = entry
    film, nut_film = run.films
    nuts["nut1"] |= {
        "film_thickness_central": value(film.central if film else math.nan, "m"),
        "film_thickness_minimum": value(film.minimum if film else math.nan, "m"),
        "film_contact": "screw contact A at its whole ball load",
        "film_parameter": value(run.film_parameter, ""),
        "film_thickness_central_nut": value(nut_film.central if nut_film else math.nan, "m"),
        "film_thickness_minimum_nut": value(nut_film.minimum if nut_film else math.nan, "m"),
        "entrainment_speed_screw": value(run.entrainment[0], "m/s"),
        "entrainment_speed_nut": value(run.entrainment[1], "m/s"),
    }
    sweep = run.sweep
    return {
        "case": run.case_name,
        "level": run.level,
        "speed": value(run.speed, "rad/s"),
        "viscosity": value(run.viscosity, "Pa*s"),
        "viscosity_source": run.viscosity_source,
        "nuts": nuts,
        "drag_torque": {
            "catalogue": value(run.catalogue_torque, "N*m"),
            "contact_losses": value(run.model_torque, "N*m"),
            "heat": value(run.model_torque * run.speed, "W"),
        },
        "curves": {
            "speed": {"value": sweep.speed, "unit": "rad/s"},
            "load_screw": {"value": sweep.load_screw, "unit": "N"},
            "load_nut": {"value": sweep.load_nut, "unit": "N"},
            "angle_screw": {"value": sweep.angle_screw, "unit": "rad"},
            "angle_nut": {"value": sweep.angle_nut, "unit": "rad"},
            "ball_speed": {"value": sweep.ball_speed, "unit": "m/s"},
            "asperity_share": {"value": sweep.asperity_share, "unit": ""},
            "drag_torque_operating": {"value": sweep.model_torque, "unit": "N*m"},
            "drag_torque_no_load": {"value": run.no_load_torque, "unit": "N*m"},
            "preload": {"value": run.preloads, "unit": "N"},
            "drag_torque_catalogue_vs_preload": {"value": run.preload_catalogue, "unit": "N*m"},
            "drag_torque_model_vs_preload": {"value": run.preload_model, "unit": "N*m"},
        },
        "options": {
            "traction": case.friction.traction,
            "boundary_friction": (
                case.kinematics.boundary_friction
                if case.friction.boundary_friction is None
                else case.friction.boundary_friction
            ),
            "limiting_shear": case.kinematics.limiting_shear,
            "micro_contact_size": value(case.kinematics.micro_contact_size, "m"),
            "film_roughness": value(run.roughness, "m"),
            "surface": {**roughness_summary(case, "surface"), "Ds": case.surface.D + 1.0},
            "lubricated": run.lubricated,
        },
    }


def fields(run: KinematicsRun) -> xr.Dataset:
    """Pressure, sliding (exact and closed form), ‖Δv‖ and asperity pressure at A, nut 1."""
    f = run.fields
    x, y = np.asarray(f.contact.x), np.asarray(f.contact.y)
    dims = ("x", "y")

    def var(data: np.ndarray, unit: str, name: str) -> tuple:
        return dims, np.asarray(data, dtype=float), {"units": unit, "long_name": name}

    return xr.Dataset(
        {
            "pressure": var(f.contact.solution.pressure, "Pa", "contact pressure at A"),
            "sliding_x": var(f.sliding.along_x, "m/s", "sliding velocity along X_A (E2.6)"),
            "sliding_y": var(f.sliding.along_y, "m/s", "sliding velocity along Y_A (E2.6)"),
            "sliding_speed": var(f.sliding.speed, "m/s", "sliding speed |Δv| (E2.6)"),
            "sliding_x_closed_form": var(f.closed_form.along_x, "m/s", "Δv_X, closed form E2.7"),
            "sliding_y_closed_form": var(f.closed_form.along_y, "m/s", "Δv_Y, closed form E2.7"),
            "asperity_pressure": var(f.asperity_pressure, "Pa", "asperity pressure ψ p (E6.5)"),
        },
        coords={
            "x": ("x", x, {"units": "m", "long_name": "rolling direction X_A"}),
            "y": ("y", y, {"units": "m", "long_name": "across the groove Y_A"}),
        },
        attrs={
            "case": run.case_name,
            "level": run.level,
            "screw_speed_rad_s": f.state.screw_speed,
            "load_screw_N": f.state.load_screw,
            "angle_screw_rad": f.state.angle_screw,
            "flank": f.state.flank,
            "asperity_share": f.sharing.psi,
        },
    )


def sliding_map(fields: ContactFields, title: str, path: str | Path, arrows: int = 14) -> Path:
    """Sliding-velocity arrows over the pressure map, like Figure 4 of the wear paper."""
    from matplotlib.patches import Ellipse

    plt = pyplot()
    x, y = np.asarray(fields.contact.x), np.asarray(fields.contact.y)
    pressure = np.asarray(fields.contact.solution.pressure)
    fig, ax = plt.subplots(figsize=(6.6, 4.4), layout="constrained")
    extent = (y[0] * 1e6, y[-1] * 1e6, x[0] * 1e6, x[-1] * 1e6)
    image = ax.imshow(pressure * 1e-9, origin="lower", extent=extent, aspect="auto", cmap="inferno")
    fig.colorbar(image, ax=ax, label="contact pressure [GPa]")
    ix = np.linspace(0, x.size - 1, arrows).round().astype(int)
    iy = np.linspace(0, y.size - 1, 2 * arrows).round().astype(int)
    sub = np.ix_(ix, iy)
    loaded = pressure[sub] > 0
    yy, xx = np.meshgrid(y[iy], x[ix])
    u = np.where(loaded, fields.sliding.along_y[sub], np.nan)
    v = np.where(loaded, fields.sliding.along_x[sub], np.nan)
    ax.quiver(yy * 1e6, xx * 1e6, u, v, color="cyan", angles="xy", pivot="mid", width=0.003)
    hertz = fields.contact.hertz
    ax.add_patch(
        Ellipse((0, 0), 2e6 * hertz.b, 2e6 * hertz.a, fill=False, color="white", linestyle="--")
    )
    ax.set_xlabel("y along Y_A, across the groove [µm] (axes not to scale)")
    ax.set_ylabel("x along X_A, rolling direction [µm]")
    ax.set_title(plain(title), fontsize=10)
    return save_figure(fig, path)


def _loads_angles(run: KinematicsRun, path: Path) -> Path:
    plt = pyplot()
    s = run.sweep
    rpm = s.speed * _RPM
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.4), layout="constrained")
    axes[0].plot(rpm, s.load_screw, "o-", ms=3, label="Q_A (screw)")
    axes[0].plot(rpm, s.load_nut, "s--", ms=3, label="Q_B (nut)")
    axes[0].set_ylabel("normal ball load [N]")
    axes[1].plot(rpm, np.degrees(s.angle_screw), "o-", ms=3, label="β_A (screw)")
    axes[1].plot(rpm, np.degrees(s.angle_nut), "s--", ms=3, label="β_B (nut)")
    axes[1].set_ylabel("contact angle [deg]")
    for ax in axes:
        ax.set_xlabel("screw speed [rpm]")
        legend_outside(ax, fontsize=8)
    fig.suptitle(f"Ball of nut 1 versus speed (level {run.level})", fontsize=10)
    return save_figure(fig, path)


def _torques(run: KinematicsRun, path: Path) -> Path:
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(9.0, 3.4), layout="constrained")
    rpm = run.drag_speeds * _RPM
    axes[0].plot(rpm, run.no_load_torque, "o-", ms=3, label="ball contacts' losses (E3.7), F_a = 0")
    axes[0].axhline(run.catalogue_torque, color="k", ls="--", label="catalogue (E9.1)")
    axes[0].set_xlabel("screw speed [rpm]")
    axes[1].plot(
        run.preloads, run.preload_model, "o-", ms=3, label="ball contacts' losses (E3.7), F_a = 0"
    )
    axes[1].plot(run.preloads, run.preload_catalogue, "k--", label="catalogue (E9.1)")
    axes[1].set_xlabel("preload [N]")
    for ax in axes:
        ax.set_ylabel("drag torque [N·m]")
        ax.set_ylim(bottom=0)
        legend_outside(ax, fontsize=8)
    return save_figure(fig, path)


NOISE = 1e-9
"""Speeds below this fraction of the screw speed are solver round-off, shown as 0 [-]."""


def _state_rows(run: KinematicsRun) -> tuple[tuple[object, ...], ...]:
    rows = []
    for number, st in run.states.items():
        orbital, spin_a, spin_b = zero_noise(
            np.array([st.orbital_speed, st.spin_screw, st.spin_nut]) * _RPM,
            NOISE * abs(run.speed) * _RPM,
        )
        rows.append(
            (
                f"nut {number} (s = {st.flank:+d})",
                st.nut_force,
                st.ball_speed,
                orbital,
                spin_a,
                spin_b,
                st.load_screw,
                st.load_nut,
                math.degrees(st.angle_screw),
                math.degrees(st.angle_nut),
            )
        )
    return tuple(rows)


def _why_speed(run: KinematicsRun, speed: float) -> str:
    """Why a sliding map is drawn at ``speed`` [rad/s]: the case speed or the top of the curves
    vs speed (``kinematics.speed_range``, else the speed of the d·n limit)."""
    if math.isclose(speed, run.speed):
        return "the case speed"
    if not math.isclose(speed, float(run.sweep.speed.max())):
        return "the lowest speed of the curves (the case speed is 0)"
    spec = run.case.kinematics
    if spec.speed_range is not None:
        return "the top of the curves vs speed (kinematics.speed_range)"
    return (
        f"the top of the curves vs speed: the d·n limit {spec.dn_limit:.0f} mm·rpm / d_m = "
        f"{1e3 * run.case.screw.pitch_diameter:.4g} mm (kinematics.dn_limit)"
    )


def figures(run: KinematicsRun) -> list[Figure]:
    """Sliding maps at the low and high speed, loads and angles versus speed, drag torques."""
    out = []
    for tag, f in (("low", run.low), ("high", run.high)):
        rpm = f.state.screw_speed * _RPM
        out.append(
            Figure(
                f"sliding_{tag}_speed",
                f"Sliding velocity of the ball relative to the screw over the pressure at A, "
                f"{rpm:.0f} rpm, {_why_speed(run, f.state.screw_speed)} (arrow length ∝ |Δv|, "
                "per figure).",
                partial(
                    sliding_map,
                    f,
                    f"{tag} speed {rpm:.0f} rpm: Q_A = {f.state.load_screw:.2f} N, "
                    f"β_A = {math.degrees(f.state.angle_screw):.2f}°",
                ),
            )
        )
    return [
        *out,
        Figure("loads_angles_vs_speed", "Q_A, Q_B, β_A, β_B.", partial(_loads_angles, run)),
        Figure(
            "drag_torque",
            "Drag torque: the ball contacts' losses of the ball model and the catalogue value.",
            partial(_torques, run),
        ),
    ]


def sections(run: KinematicsRun) -> list[Section]:
    """The report sections: ball state and loads, lubrication at A, drag torque."""
    case = run.case
    film, nut_film = run.films
    sharing = run.fields.sharing
    return [
        Section(
            "Ball kinematics and loads at the case speed",
            paragraphs=(
                f"Level {run.level} ball balance at ω_s = {run.speed:.4g} rad/s "
                f"({run.speed * _RPM:.4g} rpm). Nut-raceway control: no spin and no slip at "
                "the nut contact B; pure rolling along t at the centre of A (Level 0/1) or "
                "the full quasi-static balance (Level 2). Spins are relative to the raceway, "
                "about the contact normals pointing into the ball.",
            ),
            tables=(
                Table(
                    (
                        "nut",
                        "F [N]",
                        "V [m/s]",
                        "ω_c [rpm]",
                        "spin A [rpm]",
                        "spin B [rpm]",
                        "Q_A [N]",
                        "Q_B [N]",
                        "β_A [°]",
                        "β_B [°]",
                    ),
                    _state_rows(run),
                ),
            ),
        ),
        Section(
            "Lubrication at A and B (nut 1)",
            paragraphs=(
                "Hamrock–Dowson films at the whole ball loads, the films of the film parameter "
                "Λ = h_c/σ_Λ; Johnson–Greenwood–Poon load sharing at A with the "
                "Yan–Komvopoulos fractal asperities (Ds = D + 1, "
                f"{roughness_text(case, 'surface')}, cell "
                f"{case.kinematics.micro_contact_size * 1e6:g} µm) whose heights have the "
                "same σ_Λ: the surfaces separate by h, the film of the film-borne load (1 − ψ) Q, "
                "and the asperities carry ψ Q."
                if run.lubricated
                else "No lubricant data: dry contact, asperity share ψ = 1.",
            ),
            tables=(
                Table(
                    ("quantity", "value"),
                    (
                        ("lubricant viscosity η₀ [mPa·s]", run.viscosity * 1e3),
                        ("viscosity from", run.viscosity_source),
                        ("u_e at A [m/s]", run.entrainment[0]),
                        ("h_c at A [nm]", film.central * 1e9 if film else "—"),
                        ("h_min at A [nm]", film.minimum * 1e9 if film else "—"),
                        ("u_e at B [m/s]", run.entrainment[1]),
                        ("h_c at B [nm]", nut_film.central * 1e9 if nut_film else "—"),
                        ("h_min at B [nm]", nut_film.minimum * 1e9 if nut_film else "—"),
                        ("σ_Λ of Λ and of the asperity heights [nm]", run.roughness * 1e9),
                        ("film parameter Λ = h_c/σ_Λ at A", run.film_parameter),
                        ("asperity share ψ at A (JGP)", sharing.psi),
                        (
                            "separation h at A (JGP) [nm]",
                            sharing.separation * 1e9 if sharing.film else "—",
                        ),
                    ),
                ),
            ),
        ),
        Section(
            "Drag torque",
            paragraphs=(
                "Catalogue preload drag torque (E9.1) and the ball contacts' losses T_c of the "
                "ball model: power dissipated by sliding at A (traction E3.3) and EHL rolling "
                "resistance (E3.4) over ω_s, which equals the screw torque of the ball forces "
                "(E3.7) when the balance includes the traction (level 2). T_c leaves out the "
                "ball–ball friction, viscous drag, hysteresis, seals and ball returns: the "
                'friction torque of `operating-point` with friction.model = "ball_model" '
                "adds them and is larger. The external load's reversible torque is excluded. "
                "The curves are at F_a = 0 (no-load drag torque).",
            ),
            tables=(
                Table(
                    ("quantity", "value"),
                    (
                        ("catalogue T_p [N m]", run.catalogue_torque),
                        ("ball contacts' losses T_c at the case load [N m]", run.model_torque),
                        ("their heat T_c·ω_s [W]", run.model_torque * run.speed),
                    ),
                ),
            ),
            figures=tuple(f.name for f in figures(run)),
        ),
    ]
