"""The tabulated load–approach law Q(δ) of a ball's contacts and the distribution that uses it."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.loads.contact_law import TabulatedContact
from ballscrew.loads.distribution import (
    NutBodies,
    ball_layout,
    lift_off_load,
    solve_distribution,
)

K = 1.2e-7  # Hertz constant of a ball's two contacts [m N^-2/3]
TABLE = np.geomspace(2.0, 256.0, 7)


def test_the_approach_at_a_load_inverts_the_law():
    """δ(Q) of a power-law table is K Q^(2/3) inside and beyond the table; on a table off the
    power law it is the inverse of Q(δ) between the points."""
    law = TabulatedContact.hertz(K, TABLE)
    for q in (0.1, 2.0, 7.3, 100.0, 256.0, 5000.0):
        assert law.approach(q) == pytest.approx(K * q ** (2.0 / 3.0), rel=1e-12)
    bent = TabulatedContact(TABLE, K * TABLE**0.6 * (1.0 + 0.01 * np.log(TABLE)))
    for q in (3.0, 50.0, 200.0):
        assert bent.load(bent.approach(q))[0] == pytest.approx(q, rel=1e-12)


def test_a_power_law_table_gives_the_power_law_inside_and_beyond_it():
    law = TabulatedContact.hertz(K, TABLE)
    q = np.geomspace(0.05, 2000.0, 101)
    load, slope = law.load(K * q ** (2.0 / 3.0))
    np.testing.assert_allclose(load, q, rtol=1e-12)
    np.testing.assert_allclose(slope, 1.5 * q ** (1.0 / 3.0) / K, rtol=1e-10)


QS = 256.0
"""Load [N] at which the layer's compliance equals the Hertz approach (the table's top)."""
C_LAYER = K * QS ** (-1.0 / 3.0)


def _layered(q):
    """δ = K Q^(2/3) + c Q (Hertz in series with a linear compliant layer) and its log-slope
    n = d ln δ / d ln Q = (2/3 K Q^(2/3) + c Q) / δ, rising from 2/3 to 1 (0.72 → 0.83 over the
    table)."""
    hertz, layer = K * q ** (2.0 / 3.0), C_LAYER * q
    return hertz + layer, (2.0 / 3.0 * hertz + layer) / (hertz + layer)


def test_the_law_continues_with_the_end_exponents_of_a_non_power_law():
    """The table of a Hertz contact on a compliant layer: its end exponents are the law's
    log-slopes at the table's ends (to 1e-3), not the Hertz 2/3 nor each other's."""
    law = TabulatedContact(TABLE, _layered(TABLE)[0])
    low, high = law.exponents
    assert low == pytest.approx(_layered(TABLE[0])[1], abs=1e-3)  # 0.722
    assert high == pytest.approx(_layered(TABLE[-1])[1], abs=1e-3)  # 0.833
    assert law.top == TABLE[-1]


@pytest.mark.parametrize("ratio", [1.5, 2.0, 4.0, 6.0])
def test_the_extrapolation_error_is_bounded_by_the_change_of_the_log_slope(ratio):
    """Beyond the table δ_ext = δ_end (Q/Q_end)^n_end. With the log-slope n(Q) rising
    monotonically, ln δ is convex in ln Q and its end tangent lies below it on both sides:
    ln(δ/δ_ext) = |∫ (n − n_end) d ln Q| lies between 0 and |n(Q) − n_end| ln r (r = Q/Q_end
    above, Q_end/Q below the table), up to the 1e-3 error of n_end. The bound is less than half
    the error of the other end's exponent (and, above the table, of the Hertz 2/3), so an
    extrapolation with a wrong exponent fails here."""
    law = TabulatedContact(TABLE, _layered(TABLE)[0])
    for end, q in ((TABLE[-1], TABLE[-1] * ratio), (TABLE[0], TABLE[0] / ratio)):
        exact, n_q = _layered(q)
        d_end, n_end = _layered(end)
        bound = (abs(n_q - n_end) + 1e-3) * math.log(ratio)
        error = math.log(exact / law.approach(q))
        assert abs(error) <= bound
        assert error >= -1e-3 * math.log(ratio)  # the tangent lies below
        q_back, slope = law.load(law.approach(q))
        assert q_back[()] == pytest.approx(q, rel=1e-12)
        exponent = law.exponents[1] if q > end else law.exponents[0]
        assert slope[()] == pytest.approx(q / (exponent * law.approach(q)), rel=1e-12)
        wrongs = (2.0 / 3.0, law.exponents[0]) if q > end else (law.exponents[1],)
        for wrong in wrongs:
            assert abs(math.log(exact / (d_end * (q / end) ** wrong))) > 2.0 * bound


def test_no_approach_carries_nothing_and_the_law_rises():
    law = TabulatedContact(TABLE, 1e-6 * np.array([1.0, 1.7, 2.6, 3.4, 4.1, 4.7, 5.2]))
    load, slope = law.load(np.array([-1e-6, 0.0]))
    assert np.all(load == 0.0) and np.all(slope == 0.0)
    d = np.linspace(1e-8, 8e-6, 400)
    q, s = law.load(d)
    assert np.all(np.diff(q) > 0.0) and np.all(s > 0.0)
    eps = 1e-6  # the slope is the derivative
    numeric = (law.load(d * (1 + eps))[0] - law.load(d * (1 - eps))[0]) / (2 * eps * d)
    np.testing.assert_allclose(s, numeric, rtol=1e-6)


@pytest.mark.parametrize(
    ("loads", "approaches"),
    [([1.0], [1e-6]), ([1.0, 2.0], [2e-6, 1e-6]), ([0.0, 2.0], [1e-6, 2e-6])],
)
def test_a_table_that_is_not_rising_is_refused(loads, approaches):
    with pytest.raises(InputError):
        TabulatedContact(np.array(loads), np.array(approaches))


MM = 1e-3
BETA, LEAD, D_M, D_B = math.radians(45.0), 10 * MM, 40 * MM, 6.35 * MM
ALPHA = math.atan(LEAD / (math.pi * D_M))
BODIES = NutBodies(screw_rigidity=2e8, nut_rigidity=4e8, ring_compliance=3e-12)


def _pair(**kwargs):
    layout = ball_layout(90, 2, LEAD, D_M, D_B, ALPHA, LEAD)
    args = (layout, K, BETA, ALPHA, 2000.0, 1500.0, BODIES)
    return solve_distribution(*args, **kwargs), solve_distribution(
        *args, contact=TabulatedContact.hertz(K, TABLE), **kwargs
    )


def test_a_hertz_table_gives_the_hertz_distribution():
    hertz, table = _pair(lead_error=np.linspace(0.0, 1e-6, 10))
    np.testing.assert_allclose(table.loads, hertz.loads, rtol=1e-9, atol=1e-9)
    assert table.stiffness == pytest.approx(hertz.stiffness, rel=1e-8)
    assert table.interference == pytest.approx(hertz.interference, rel=1e-9)
    balance = table.nut_forces[0] - table.nut_forces[1] - 2000.0
    assert abs(balance) < 1e-10 * 2000.0


def test_a_stiffer_law_takes_the_lift_off_later():
    layout = ball_layout(40, 2, LEAD, D_M, D_B, ALPHA, LEAD)
    hertz = lift_off_load(layout, K, BETA, ALPHA, 1000.0, rtol=1e-6)
    assert hertz == pytest.approx(2.0**1.5 * 1000.0, rel=1e-5)
    linear = TabulatedContact(TABLE, 1e-8 * TABLE)  # δ ∝ Q: lift-off at 2 F_p
    assert lift_off_load(layout, K, BETA, ALPHA, 1000.0, contact=linear) == pytest.approx(
        2000.0, rel=1e-5
    )
