"""One case gives one answer: the Python API returns the numbers the CLI writes to summary.json.

Every case below sets options away from their built-in defaults, so an API function that
ignores the case (and falls back to its own default) gives a different number than the CLI.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import xarray as xr

import ballscrew
from ballscrew.analyses.ball_contact import solve_ball_contacts
from ballscrew.analyses.kinematics import run_kinematics
from ballscrew.analyses.screw_tcr import screw_tcr
from ballscrew.analyses.thermal import thermal_field
from ballscrew.calibration import calibrate, read_measured
from ballscrew.surface import fractal_parameters, read_profile
from quick_cases import EXAMPLES, QUICK, QUICK_WEAR, SPEED_100_RPM, run_cli, write_case

GAO, WEAR = "gao2019_tcr.toml", "wear_step_stress.toml"
PROFILE = EXAMPLES / "profiles" / "synthetic_wm_D1.59_G9e-10.sdf"
#: Every option differs from its built-in default.
GAO_OPTIONS = QUICK | {
    "numerics.gap_model": "quadratic",
    "operating.axial_load": 2500.0,
    "tcr.headline": "MT",
    "thermal.model": "network",
    "kinematics.level": 1,
}
WEAR_OPTIONS = QUICK | QUICK_WEAR | {"wear.model": "C", "wear.coefficient": 2.0e-4}
#: Calibration starts from K = 3e-4 with a torque scale of 1.1 (Model A) ...
CALIBRATION_OPTIONS = QUICK | {
    "wear.coefficient": 3.0e-4,
    "wear.torque_scale": 1.1,
    "wear.grid": [8, 32],
    "wear.max_depth_step": "0.5 um",
    "wear.torque_sampling": 1.0e4,
    "wear.programme": [{"axial_load": 3000.0, "speed": SPEED_100_RPM, "revolutions": 4.0e4}],
}
#: ... and its synthetic history is made with this K.
K_MEASURED = 1.5e-4


def lookup(summary: dict[str, Any], dotted: str) -> Any:
    """The number at ``dotted`` in a summary, unwrapping ``{"value": ..., "unit": ...}``."""
    node: Any = summary
    for key in dotted.split("."):
        node = node[int(key)] if isinstance(node, list) else node[key]
    return node["value"] if isinstance(node, dict) and "value" in node else node


#: API entry point (case file -> Python result) -> {summary key: number of the result}
Checks = dict[Callable[[Path], Any], dict[str, Callable[[Any], float]]]


@dataclass(frozen=True)
class Parity:
    """One CLI analysis: its case, its command line and the API numbers per summary key."""

    example: str | None
    overrides: dict[str, Any]
    command: Callable[[Path, Path], list[object]]  # (case or input, out) -> argv
    checks: Checks
    options: dict[str, Any] = field(default_factory=dict)  # summary key -> expected option


def on_case(function: Callable[..., Any]) -> Callable[[Path], Any]:
    """``function(case)`` on the case file's case, every option left to the case."""
    return lambda path: function(ballscrew.load_case(path))


def gao(command: str, checks: Checks, options: dict[str, Any]) -> Parity:
    """``ballscrew COMMAND`` on the Gao screw with :data:`GAO_OPTIONS`."""
    return Parity(
        GAO, GAO_OPTIONS, lambda case, out: [command, case, "--out", out], checks, options
    )


def _side(side: str, attr: str) -> Callable[[Any], float]:
    return lambda r: getattr(r.contact(side).solution, attr)


CONTACT = gao(
    "contact",
    {
        on_case(solve_ball_contacts): {
            "ball_load": lambda r: r.ball_load,
            "nut_force": lambda r: r.nut_force,
            "lead_angle": lambda r: r.geometry.lead_angle,
            "contacts.screw.numerical.peak_pressure": _side("screw", "peak_pressure"),
            "contacts.screw.numerical.approach": _side("screw", "approach"),
            "contacts.nut.numerical.peak_pressure": _side("nut", "peak_pressure"),
            "contacts.nut.numerical.contact_area": _side("nut", "contact_area"),
            "contacts.screw.hertz.peak_pressure": lambda r: r.contact("screw").hertz.p0,
        }
    },
    {"gap_model": "quadratic"},
)

TCR_NUMBERS: dict[str, Callable[[Any], float]] = {
    "resistance": lambda r: r.resistance,
    "resistance_per_area": lambda r: r.resistance_per_area,
    "apparent_area": lambda r: r.apparent_area,
    "nut_forces.1": lambda r: r.nut_forces[1],
    "nuts.nut1.resistance": lambda r: r.nuts[0].resistance,
    "nuts.nut2.ball_resistance": lambda r: r.nuts[1].ball_resistance,
}

TCR = gao(
    "tcr",
    {on_case(screw_tcr): TCR_NUMBERS, on_case(ballscrew.screw_tcr): TCR_NUMBERS},
    {"options.headline": "MT", "options.variant": "MT", "options.contact_gap_model": "quadratic"},
)

THERMAL_NUMBERS: dict[str, Callable[[Any], float]] = {
    "unknowns": lambda r: r.unknowns,
    "steady.max_temperature": lambda r: r.max_temperature,
    "steady.max_temperature_rise": lambda r: r.max_temperature_rise,
    "steady.elongation": lambda r: r.elongation,
    "heat_balance.heat_input": lambda r: r.heat_input,
    "contact.0.resistance": lambda r: r.interfaces[0].resistance,
    "sensors.0.steady": lambda r: r.sensors[0].steady,
    "transient.final_elongation": lambda r: r.solution.transient.elongation[-1],
    # the example's [[duty]] cycle, followed by `ballscrew thermal` and thermal_field alike
    "duty.peak_elongation": lambda r: r.duty.elongation.max(),
    "duty.final_elongation": lambda r: r.duty.elongation[-1],
    "duty.peak_temperature": lambda r: r.duty.max_temperature.max(),
    "duty.final_contact_temperature": lambda r: r.duty.contact_temperature[-1],
    "duty.heat_in": lambda r: r.duty.heat_in,
}

THERMAL = gao(
    "thermal",
    {on_case(thermal_field): THERMAL_NUMBERS, on_case(ballscrew.thermal_field): THERMAL_NUMBERS},
    {"model": "network"},
)

#: The balls' heat from the coupled operating point with an oil whose viscosity follows the
#: temperature and the ball-model friction (the thermal parity above runs the catalogue torque).
COUPLED_OPTIONS = GAO_OPTIONS | {
    "medium": {"name": "ISO VG 68", "thermal_conductivity": 0.14},  # viscosities: the library's
    "kinematics.lubricant": "iso_vg_68",
    "friction.model": "ball_model",
    "thermal.drag_torque.source": "operating_point",
}
COUPLED_NUMBERS = THERMAL_NUMBERS | {
    "operating_point.contact_temperature": lambda r: r.coupling.contact_temperature,
    "operating_point.viscosity": lambda r: r.coupling.viscosity,
    "operating_point.heat": lambda r: r.coupling.heat,
}
THERMAL_COUPLED = Parity(
    GAO,
    COUPLED_OPTIONS,
    lambda case, out: ["thermal", case, "--out", out],
    {on_case(thermal_field): COUPLED_NUMBERS, on_case(ballscrew.thermal_field): COUPLED_NUMBERS},
    {"model": "network", "operating_point.friction_model": "ball_model"},
)


def _nut1(attr: str) -> Callable[[Any], float]:
    return lambda r: getattr(r.states[1], attr)


KINEMATICS_NUMBERS: dict[str, Callable[[Any], float]] = {
    "speed": lambda r: r.speed,
    "nuts.nut1.ball_speed": _nut1("ball_speed"),
    "nuts.nut1.load_screw": _nut1("load_screw"),
    "nuts.nut1.angle_screw": _nut1("angle_screw"),
    "nuts.nut1.angle_nut": _nut1("angle_nut"),
    "nuts.nut2.load_nut": lambda r: r.states[2].load_nut,
    "drag_torque.contact_losses": lambda r: r.model_torque,
    "drag_torque.catalogue": lambda r: r.catalogue_torque,
}

BALL_STATE = ("ball_speed", "orbital_speed", "load_screw", "load_nut", "angle_screw", "angle_nut")

KINEMATICS = gao(
    "kinematics",
    {
        on_case(run_kinematics): KINEMATICS_NUMBERS,
        on_case(lambda case: {n: ballscrew.ball_kinematics(case, nut=n) for n in (1, 2)}): {
            f"nuts.nut{n}.{attr}": (lambda r, n=n, attr=attr: getattr(r[n], attr))
            for n in (1, 2)
            for attr in BALL_STATE
        },
    },
    {"level": 1},
)

WEAR_RUN = Parity(
    WEAR,
    WEAR_OPTIONS,
    lambda case, out: ["wear", case, "--out", out],
    {
        on_case(ballscrew.wear_life): {
            "revolutions": lambda r: r.revolutions[-1],
            "max_wear_depth": lambda r: r.max_wear_depth[-1],
            "final_preload": lambda r: r.preload[-1],
            "final_torque": lambda r: r.friction_torque[-1],
            "ellipse_major_axis": lambda r: r.ellipse_major_axis,
            "worn_band_width": lambda r: r.worn_band_width,
            "levels.0.max_wear_depth": lambda r: np.interp(
                r.level_boundaries[0], r.revolutions, r.max_wear_depth
            ),
            "wear_coefficient": lambda r: r.coefficient,
        }
    },
    {"options.model": "C", "wear_coefficient": 2.0e-4},
)


def _measured_history(folder: Path) -> Path:
    """A friction-torque history made by the wear model itself at K = K_MEASURED."""
    scratch = folder / "history"
    scratch.mkdir()
    case = ballscrew.load_case(
        write_case(scratch, WEAR, CALIBRATION_OPTIONS | {"wear.coefficient": K_MEASURED})
    )
    life = ballscrew.wear_life(case)
    at = np.linspace(0.0, life.revolutions[-1], 5)
    torque = np.interp(at, life.revolutions, life.friction_torque)
    path = folder / "measured.csv"
    rows = "".join(f"{float(n)!r},{float(t)!r}\n" for n, t in zip(at, torque, strict=True))
    path.write_text("revolutions,friction_torque\n" + rows)
    return path


CALIBRATE = Parity(
    WEAR,
    CALIBRATION_OPTIONS,
    lambda case, out: [
        "calibrate",
        case,
        "--measured",
        out.parent / "measured.csv",
        "--fit",
        "wear_coefficient",
        "--out",
        out,
    ],
    {
        lambda path: calibrate(
            ballscrew.load_case(path),
            read_measured(path.parent / "measured.csv", min_points=2),
            fit=("wear_coefficient",),
        ): {
            "wear_coefficient": lambda r: r.wear_coefficient,
            "wear_coefficient_standard_error": lambda r: r.standard_error,
            "torque_scale": lambda r: r.torque_scale,
            "rms_residual": lambda r: r.rms_residual,
            "fit.model_evaluations": lambda r: r.evaluations,
        }
    },
    {"options.wear_model": "A", "torque_scale": 1.1},
)

SURFACE = Parity(
    None,
    {},
    lambda _, out: ["surface", PROFILE, "--gamma", 1.6, "--resolution", "1 um", "--out", out],
    {
        lambda _: fractal_parameters(read_profile(PROFILE), gamma=1.6, resolution=1e-6): {
            "recommended.D": lambda r: r.D,
            "recommended.G": lambda r: r.G,
            "methods.psd.D": lambda r: r.psd.D,
            "methods.psd.G": lambda r: r.psd.G,
            "methods.structure_function.D": lambda r: r.structure_function.D,
            "methods.structure_function.r_squared": lambda r: r.structure_function.r_squared,
        }
    },
    {"gamma": 1.6},
)

ANALYSES = {
    "contact": CONTACT,
    "tcr": TCR,
    "thermal": THERMAL,
    "thermal_coupled": THERMAL_COUPLED,
    "kinematics": KINEMATICS,
    "wear": WEAR_RUN,
    "calibrate": CALIBRATE,
    "surface": SURFACE,
}


@pytest.mark.parametrize("name", list(ANALYSES))
def test_api_gives_the_numbers_of_the_cli(tmp_path, name):
    parity = ANALYSES[name]
    case = write_case(tmp_path, parity.example, parity.overrides) if parity.example else None
    if name == "calibrate":
        _measured_history(tmp_path)
    summary = run_cli(*parity.command(case, tmp_path / "cli"))
    for key, expected in parity.options.items():
        assert lookup(summary, key) == expected, key
    for api, numbers in parity.checks.items():
        result = api(case)
        for key, number in numbers.items():
            cli = lookup(summary, key)
            assert float(number(result)) == pytest.approx(cli, rel=1e-12, abs=0), key


@pytest.mark.parametrize(
    ("default", "number"),
    [
        ({"tcr.headline": "CMY"}, lambda c: screw_tcr(c).resistance),
        ({"thermal.model": "axisymmetric"}, lambda c: thermal_field(c).max_temperature_rise),
        ({"kinematics.level": 0}, lambda c: ballscrew.ball_kinematics(c).angle_screw),
        ({"numerics.gap_model": "exact"}, lambda c: solve_ball_contacts(c).screw.solution.approach),
    ],
    ids=["tcr.headline", "thermal.model", "kinematics.level", "numerics.gap_model"],
)
def test_the_non_default_options_change_the_answer(tmp_path, default, number):
    """Guard of the parity test: its options are not defaults and each one moves the numbers."""
    ours = ballscrew.load_case(write_case(tmp_path, GAO, GAO_OPTIONS))
    builtin = ballscrew.load_case(write_case(tmp_path, GAO, GAO_OPTIONS | default))
    assert number(ours) != pytest.approx(number(builtin), rel=1e-9)


def test_sweep_points_equal_the_api_at_each_point(tmp_path):
    """``ballscrew sweep`` (its own process pool) against the composer at every point."""
    case = write_case(tmp_path, GAO, GAO_OPTIONS)
    loads = (0.0, 5000.0)
    out = tmp_path / "sweep"
    axis = "operating.axial_load=" + ",".join(str(f) for f in loads)
    summary = run_cli(
        "sweep", case, "--vary", axis, "--analysis", "tcr", "--workers", 1, "--out", out
    )
    assert summary["failed"] == 0
    assert summary["axes"]["operating.axial_load"]["values"] == list(loads)
    with xr.open_dataset(out / "sweep.nc", engine="h5netcdf") as ds:
        for i, load in enumerate(loads):
            api = screw_tcr(ballscrew.load_case(case, {"operating.axial_load": load}))
            point = ds.isel({"operating.axial_load": i})
            assert api.headline == api.variant == "MT"
            for key, value in (
                ("resistance", api.resistance),
                ("resistance_per_area", api.resistance_per_area),
                ("F1", api.nut_forces[0]),
                ("F2", api.nut_forces[1]),
            ):
                assert float(point[key]) == pytest.approx(value, rel=1e-12, abs=0), (load, key)


def test_set_on_the_command_line_gives_the_numbers_of_python_overrides(tmp_path):
    """``--set KEY=VALUE`` (units included) is ``load_case(path, {KEY: VALUE})`` in Python."""
    from ballscrew.analyses.operating_point import operating_point

    case = write_case(tmp_path, GAO, QUICK)
    sets = {
        "operating.speed": "1500 rpm",
        "operating.axial_load": "2 kN",
        "friction.model": "ball_model",
    }
    argv = [word for key, text in sets.items() for word in ("--set", f"{key}={text}")]
    summary = run_cli("operating-point", case, *argv, "--out", tmp_path / "cli")
    api = operating_point(ballscrew.load_case(case, sets))
    # the case runs at 1000 rpm, 0 N and the catalogue friction model: --set changed all three
    assert summary["speed"]["value"] == pytest.approx(1500 * np.pi / 30, rel=1e-12)
    assert summary["axial_load"]["value"] == 2000.0
    assert summary["inputs"]["friction"]["model"] == "ball_model"
    for key in ("friction_torque", "heat", "nut_temperature", "screw_temperature", "axial_load"):
        assert getattr(api, key) == pytest.approx(lookup(summary, key), rel=1e-12, abs=0), key
