"""Cell wear rates of Models A and C against worked examples ((E7.2), (E7.3), Archard limit)."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.wear import cell_wear_rate, wear_rate_model_a, wear_rate_model_c

E_STAR, H, K, DV = 1.1319e11, 7.0e9, 1e-4, 2.637e-3  # wear reference raceway
CELL = 100e-12  # ΔA = 100 µm²


def test_t7_1_model_a_cell() -> None:
    w = wear_rate_model_a(5e8, DV, CELL, 2.4, 1e-10, E_STAR, H, K)
    assert float(w) == pytest.approx(1.328e-9, rel=2e-3)


def test_t7_2_model_c_cell() -> None:
    w = wear_rate_model_c(5e8, DV, CELL, 2.4, 1e-10, E_STAR, H, K)
    assert float(w) == pytest.approx(1.381e-9, rel=2e-3)


def test_t7_3_archard_limit_fully_plastic() -> None:
    """G = 1e-8 m: a_c > a_l, every asperity plastic → w = K|Δv|p/(3H) = 6.280e-9 m/s."""
    w = wear_rate_model_a(5e8, DV, CELL, 2.4, 1e-8, E_STAR, H, K)
    assert float(w) == pytest.approx(6.280e-9, rel=1e-3)
    assert float(w) == pytest.approx(K * DV * 5e8 / (3 * H), rel=1e-9)


def test_vectorised_zero_load_and_sign_of_speed() -> None:
    p = np.array([[0.0, 5e8], [1e8, 1e9]])
    v = np.array([[DV, -DV], [DV, DV]])
    w = cell_wear_rate("A", p, v, CELL, 2.4, 1e-10, E_STAR, H, K)
    assert w.shape == (2, 2)
    assert w[0, 0] == 0.0
    assert w[0, 1] == pytest.approx(1.328e-9, rel=2e-3)
    assert w[1, 0] < w[0, 1] < w[1, 1]  # more load, more wear


def test_wear_rate_linear_in_k_and_speed() -> None:
    """w ∝ K |Δv| in both models (Archard structure of (E7.2)–(E7.3))."""
    for model in ("A", "C"):
        w1 = cell_wear_rate(model, 5e8, DV, CELL, 2.4, 1e-10, E_STAR, H, K)
        w2 = cell_wear_rate(model, 5e8, 3 * DV, CELL, 2.4, 1e-10, E_STAR, H, 2 * K)
        assert float(w2) == pytest.approx(6 * float(w1), rel=1e-12)


def test_model_c_needs_ds_below_2_5() -> None:
    with pytest.raises(InputError, match="Model C"):
        wear_rate_model_c(5e8, DV, CELL, 2.59, 1e-10, E_STAR, H, K)


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [({"coefficient": 0.0}, "coefficient"), ({"cell_area": -1.0}, "cell_area")],
)
def test_bad_input(kwargs: dict[str, float], field: str) -> None:
    args = {"cell_area": CELL, "coefficient": K} | kwargs
    with pytest.raises(InputError, match=field):
        wear_rate_model_a(5e8, DV, args["cell_area"], 2.4, 1e-10, E_STAR, H, args["coefficient"])


def test_negative_pressure_and_unknown_model_rejected() -> None:
    with pytest.raises(InputError):
        wear_rate_model_a(-1.0, DV, CELL, 2.4, 1e-10, E_STAR, H, K)
    with pytest.raises(InputError, match=r"wear\.model"):
        cell_wear_rate("B", 5e8, DV, CELL, 2.4, 1e-10, E_STAR, H, K)  # type: ignore[arg-type]
