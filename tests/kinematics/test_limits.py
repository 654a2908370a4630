"""Speed limits: whirling speed of the shaft, d·n limit, and how the user silences the warning."""

from __future__ import annotations

import math
import warnings

import pytest

import ballscrew
from ballscrew.kinematics import SpeedLimitWarning, critical_speed, groove_root_diameter

from .conftest import RPM, updated


def test_root_diameter_of_the_gothic_arch(ref_geometry):
    # Arc of flank +1: centre at radius r_m + (r_s − r_b)cosβ, axial offset −(r_s − r_b)sinβ;
    # on the groove centre line (axial 0) its radius is centre − √(r_s² − offset²).
    r_s, r_b = 0.55 * 6.35e-3, 3.175e-3
    offset = (r_s - r_b) * math.sin(math.pi / 4)
    expected = 2 * (0.020 + (r_s - r_b) * math.cos(math.pi / 4) - math.sqrt(r_s**2 - offset**2))
    assert groove_root_diameter(ref_geometry) == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(33.478e-3, rel=1e-4)


def test_simply_supported_shaft_is_the_textbook_value():
    # ω = (π/l)² √(EI/(ρA)), I = πd⁴/64, A = πd²/4 (Euler–Bernoulli, pinned–pinned).
    d, length, e, rho = 0.0335, 1.2, 206e9, 7850.0
    textbook = (math.pi / length) ** 2 * math.sqrt(
        e * (math.pi * d**4 / 64) / (rho * math.pi * d**2 / 4)
    )
    assert critical_speed(d, length, e, rho, "supported-supported") == pytest.approx(
        textbook, rel=1e-12
    )
    # stiffer fixity, higher speed; λ₁² ratios of Blevins (1979)
    ratio = critical_speed(d, length, e, rho, "fixed-fixed") / textbook
    assert ratio == pytest.approx((4.7300 / math.pi) ** 2, rel=1e-12)


def test_dn_warning_and_its_switch(ref_case):
    fast = 3000 * RPM  # 40 mm × 3000 rpm = 120 000 > 70 000
    with pytest.warns(SpeedLimitWarning, match="d·n"):
        ballscrew.ball_kinematics(ref_case, speed=fast)
    quiet = updated(ref_case, kinematics={"speed_warnings": False})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ballscrew.ball_kinematics(quiet, speed=fast)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.filterwarnings("ignore", category=SpeedLimitWarning)
        ballscrew.ball_kinematics(ref_case, speed=fast)


def test_whirling_warning_needs_a_length(ref_case):
    long = updated(ref_case, kinematics={"unsupported_length": 3.0, "mounting": "fixed-free"})
    allowed = 0.8 * critical_speed(
        groove_root_diameter(ballscrew.geometry.ScrewGeometry.from_spec(ref_case.screw)),
        3.0,
        206e9,
        7850.0,
        "fixed-free",
    )
    with pytest.warns(SpeedLimitWarning, match="whirling"):
        ballscrew.ball_kinematics(long, speed=1.01 * allowed)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ballscrew.ball_kinematics(long, speed=0.99 * allowed)  # below both limits
        ballscrew.ball_kinematics(ref_case, speed=1.01 * allowed)  # no length, no whirling check


def test_speed_warnings_read_in_rpm(ref_case):
    """The limits were stated in rad/s ('speed 314.2 rad/s gives d·n = …'); an engineer reads rpm
    and mm."""
    with pytest.warns(SpeedLimitWarning, match=r"^speed 3000 rpm gives d·n = 120000 mm·rpm"):
        ballscrew.ball_kinematics(ref_case, speed=3000 * RPM)
    long = updated(ref_case, kinematics={"unsupported_length": 3.0, "mounting": "fixed-free"})
    with pytest.warns(SpeedLimitWarning, match=r"rpm \(fixed-free, l = 3 m, d_r = 33\.48 mm\)"):
        ballscrew.ball_kinematics(long, speed=1000 * RPM)


def test_a_speed_with_its_unit_is_read_as_the_operating_point_reads_it(ref_case):
    """ball_kinematics(case, speed="1500 rpm") is 1500 rpm = 157.08 rad/s (it was refused as
    outside [0, 100000] rad/s), and a speed in the wrong unit names the unit."""
    with_unit = ballscrew.ball_kinematics(ref_case, speed="1500 rpm")
    in_si = ballscrew.ball_kinematics(ref_case, speed=1500 * RPM)
    assert with_unit.screw_speed == pytest.approx(157.0796, rel=1e-6)
    assert with_unit.orbital_speed == in_si.orbital_speed
    with pytest.raises(ballscrew.errors.InputError, match=r"'2 m' is not an angular velocity"):
        ballscrew.ball_kinematics(ref_case, speed="2 m")


def test_the_kinematics_run_reads_a_speed_as_ball_kinematics_does(ref_case):
    """run_kinematics (the `ballscrew kinematics` analysis) takes "1000 rpm" as 104.72 rad/s and
    refuses a speed it cannot read with the one-line InputError naming ``speed``, not a bare
    ValueError of float()."""
    from ballscrew.analyses.kinematics import run_kinematics

    with_unit = run_kinematics(ref_case, speed="1000 rpm", level=0)
    assert with_unit.speed == pytest.approx(1000 * RPM, rel=1e-12)
    with pytest.raises(ballscrew.errors.InputError, match=r"^speed = 'fast'"):
        run_kinematics(ref_case, speed="fast", level=0)
