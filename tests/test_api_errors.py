"""Public API calls with wrong-type, out-of-range, non-finite or complex arguments raise
:class:`InputError` naming the argument, never a bare Python or numpy error (nor a silently
dropped imaginary part)."""

from __future__ import annotations

import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

import ballscrew as bs
from ballscrew import contact as C
from ballscrew import fractal as F
from ballscrew import geometry as G
from ballscrew import loads as L
from ballscrew import lubrication as U
from ballscrew import surface as S
from ballscrew import wear as W
from ballscrew.errors import InputError

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "gao2019_tcr.toml"
CASE = bs.load_case(EXAMPLE)
BALL_CASE = bs.load_case(EXAMPLE, {"friction.model": "ball_model"})
GEOMETRY = G.as_geometry(CASE)
X = np.linspace(-1e-4, 1e-4, 5)
GAP = np.full((8, 8), 1e-6)
HEIGHTS = np.sin(np.arange(64.0)) * 1e-6

CASES: dict[str, tuple[Callable[[], object], str]] = {
    "complex gap x": (lambda: G.gap_exact(GEOMETRY, "screw", X + 1e-6j, X), "x"),
    "complex quadratic gap": (lambda: G.gap_quadratic(GEOMETRY, "nut", X, X * 1j), "y"),
    "text helix angle": (lambda: G.helix_point(GEOMETRY, "a"), "theta"),
    "complex helix angle": (lambda: G.contact_direction(GEOMETRY, 1j), "theta"),
    "mismatched raceway shapes": (
        lambda: G.raceway_surface(GEOMETRY, "screw", np.ones(3), np.ones(4)),
        "theta, phi",
    ),
    "complex gap grid": (lambda: C.solve_normal(GAP + 1e-7j, 1e-5, 1e-5, 1e11, 10.0), "gap"),
    "text gap grid": (lambda: C.solve_normal("gap", 1e-5, 1e-5, 1e11, 10.0), "gap"),
    "complex displacement gap": (
        lambda: C.solve_normal_displacement(GAP + 1e-7j, 1e-5, 1e-5, 1e11, 1e-6),
        "gap",
    ),
    "text load": (lambda: C.hertz(0.01, 0.001, 1e11, "100"), "load"),
    "boolean load": (lambda: C.hertz(0.01, 0.001, 1e11, True), "load"),
    "zero influence grid": (lambda: C.wraparound_kernel(0, 0, 1e-5, 1e-5, 1e11), "nx"),
    "fractional cell count": (lambda: C.love_coefficients(4.5, 4, 1e-5, 1e-5, 1e11), "nx"),
    "negative cell count": (lambda: C.cell_centres(-3, 1e-5), "n"),
    "complex pressure": (lambda: C.direct_convolution(GAP + 1j, 1e-5, 1e-5, 1e11), "pressure"),
    "gap not a function": (lambda: C.solve_contact(5, 0.01, 0.001, 1e11, 10.0), "gap_function"),
    "complex fractal dimension": (lambda: F.domain_extension_factor(1.5 + 1j), "D"),
    "text fractal dimension": (lambda: F.validate_dimension("1.5"), "D"),
    "complex spot areas": (lambda: F.real_contact_area(np.array([1e-9 + 1j]), D=1.5), "a_l"),
    "complex axial force": (lambda: L.ball_load(100 + 1j, 20, 0.78, 0.05), "axial_force"),
    "text axial force": (lambda: L.ball_load("100", 20, 0.78, 0.05), "axial_force"),
    "complex wear depth": (
        lambda: L.preload_after_wear(1500.0, 3.7e-8, np.array([1e-6 + 1j]), 0.78, 0.05),
        "max_wear_depth",
    ),
    "mismatched stiffness shapes": (
        lambda: L.preloaded_axial_stiffness(np.ones(3), np.ones(4)),
        "force, axial_deflection",
    ),
    "mismatched approaches": (
        lambda: L.axial_deflection_from_approaches(np.ones(3), np.ones(4), 0.78, 0.05),
        "delta_a, delta_b",
    ),
    "complex film pressure": (
        lambda: U.asperity_pressure(np.array([1e9 + 1j]), 0.5),
        "pressure",
    ),
    "complex asperity share": (lambda: U.asperity_pressure(np.array([1e9]), 0.5j), "psi"),
    "complex nominal gap": (lambda: W.worn_gap(np.ones((2, 3)) + 1j, np.ones(3)), "nominal"),
    "1-D nominal gap": (lambda: W.worn_gap(np.ones(3), np.ones(3)), "nominal"),
    "NaN wear depth": (lambda: W.worn_gap(np.ones((2, 3)), [np.nan, 0, 0]), "wear depth"),
    "complex cell rates": (
        lambda: W.strip_wear_speed(np.ones((3, 3)) + 1j, 1e-5),
        "cell_rates",
    ),
    "mismatched reciprocating rates": (
        lambda: W.reciprocating_rate(np.ones(3), np.ones(4)),
        "rate_loaded, rate_unloaded",
    ),
    "screw_tcr of a number": (lambda: bs.screw_tcr(5), "case"),
    "thermal_field of a number": (lambda: bs.thermal_field(5), "case"),
    "ball_kinematics of a number": (lambda: bs.ball_kinematics(5), "case"),
    "drag_torque of a number": (lambda: bs.drag_torque(None), "case"),
    "friction_torque of a number": (lambda: bs.friction_torque(5), "case"),
    "friction_torque complex speed": (lambda: bs.friction_torque(CASE, speed=1j), "speed"),
    "friction_torque text load": (
        lambda: bs.friction_torque(CASE, axial_load="1 kN"),
        "axial_load",
    ),
    "friction_torque NaN viscosity": (
        lambda: bs.friction_torque(BALL_CASE, viscosity=np.nan),
        "viscosity",
    ),
    "complex profile": (lambda: S.Profile(HEIGHTS + 1j, 1e-6), "heights"),
    "text profile": (lambda: S.Profile("abc", 1e-6), "heights"),
    "infinite profile height": (lambda: S.Profile(np.r_[HEIGHTS, np.inf], 1e-6), "heights"),
    "complex heights for the PSD": (lambda: S.power_spectrum(HEIGHTS + 1j, 1e-6), "heights"),
    "unknown window": (lambda: S.power_spectrum(HEIGHTS, 1e-6, window="bogus"), "window"),
    "fractional max_lag": (lambda: S.structure_function(HEIGHTS, 1e-6, max_lag=3.5), "max_lag"),
    "complex W-M frequency": (lambda: S.wm_power_spectrum([1.0 + 1j], 1.5, 1e-10), "frequency"),
    "text seed": (
        lambda: S.weierstrass_mandelbrot_profile(1.5, 1e-10, 1e-3, 1e-6, seed="x"),
        "seed",
    ),
    "mismatched spectrum shapes": (
        lambda: S.log_smoothed_spectrum(np.ones(3), np.ones(4), np.ones(2), 0.1),
        "frequency, psd",
    ),
    "complex heights to fit": (
        lambda: S.fractal_parameters(HEIGHTS + 1j, 1e-6),
        "heights",
    ),
    "profile path None": (lambda: S.read_profile(None), "path"),
    "write a bare array": (lambda: S.write_sdf("x.sdf", np.ones(3)), "profile"),
}


@pytest.mark.parametrize("name", list(CASES))
def test_bad_argument_raises_input_error_naming_it(name):
    call, field = CASES[name]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a ComplexWarning would mean a dropped imaginary part
        with pytest.raises(InputError) as info:
            call()
    assert info.value.field == field


@pytest.mark.parametrize(
    ("overrides", "field"),
    [
        ({"operating.preload": 1e7}, "screw.ball_diameter"),
        ({"screw.ball_diameter": 1e-5}, "screw.ball_diameter"),
    ],
)
def test_case_errors_name_the_case_field_not_an_internal_symbol(overrides, field):
    case = bs.load_case(EXAMPLE, {**overrides, "numerics.cells_across": 8})
    with pytest.raises(InputError) as info:
        bs.screw_tcr(case)
    message = str(info.value)
    assert field in message
    assert "r_b" not in message
    assert "lambda" not in message
