"""Wang–Komvopoulos ψ(D), equation (F10), against its table and the element example at D = 1.59."""

import itertools
import math

import pytest

from ballscrew.errors import InputError
from ballscrew.fractal import domain_extension_factor, size_distribution_constant

# (F10) table
PSI_TABLE = [
    (1.1, 2.44346),
    (1.3, 2.18371),
    (1.475, 2.02055),
    (1.5, 2.00071),
    (1.59, 1.93509),
    (1.7, 1.86540),
    (1.9, 1.76158),
]


@pytest.mark.parametrize(("D", "psi"), PSI_TABLE)
def test_psi_matches_doc_table(D: float, psi: float) -> None:
    assert domain_extension_factor(D) == pytest.approx(psi, rel=1e-5)


@pytest.mark.parametrize(("D", "_psi"), PSI_TABLE)
def test_psi_satisfies_f10(D: float, _psi: float) -> None:
    # residual of (F10) written out independently of the implementation
    psi = domain_extension_factor(D)
    k = (2 - D) / D
    lhs = (psi ** ((2 - D) / 2) - (1 + psi ** (-D / 2)) ** (-k)) / k
    assert lhs == pytest.approx(1.0, abs=1e-13)
    assert psi > 1.0


def test_size_distribution_constant_t_mb1() -> None:
    # D = 1.59 example: ψ^((2−D)/2) = 1.14492 at D = 1.59
    assert size_distribution_constant(1.59) == pytest.approx(1.14492, rel=1e-5)


def test_psi_decreases_with_d() -> None:
    values = [domain_extension_factor(1.0 + 0.01 * i) for i in range(2, 99)]
    assert all(a > b for a, b in itertools.pairwise(values))


@pytest.mark.parametrize("D", [1.0, 2.0, 0.5, 2.5, math.nan, math.inf])
def test_psi_rejects_bad_dimension(D: float) -> None:
    with pytest.raises(InputError, match="1 < D < 2"):
        domain_extension_factor(D)
