"""The lubricant film around a ball as a heat path (P1)–(P3): closed form against quadrature,
limits, the deformed Hertz gap, and the composition of the reference screw."""

from __future__ import annotations

import math
import warnings
from functools import cache
from pathlib import Path

import pytest
from scipy.integrate import dblquad

from ballscrew.analyses.screw_tcr import ScrewTCR, screw_tcr
from ballscrew.analyses.tcr_film import conductivities, contact_constriction
from ballscrew.analyses.thermal_setup import build_problem
from ballscrew.case import load_case, with_overrides
from ballscrew.contact.hertz import hertz
from ballscrew.contact_resistance.film_path import (
    ellipse_gap_conductance,
    groove_clearance,
    hertz_separation,
    loaded_film_conductance,
    meniscus_thickness,
    with_film_path,
)
from ballscrew.errors import InputError

RX, RY = 2.82e-3, 82.55e-3  # reference screw, screw contact [m]
E_STAR = 115e9  # Pa
OIL = 0.14  # W/(m K)


def _quadrature(lam: float, rx: float, ry: float, h0: float, h_max: float, m: float) -> float:
    """∫∫ λ/(h + M) dA over h = h0 + x²/2R_x + y²/2R_y ≤ h_max, Cartesian (scipy dblquad)."""
    x_max = math.sqrt(2.0 * rx * (h_max - h0))

    def y_max(x: float) -> float:
        return math.sqrt(max(2.0 * ry * (h_max - h0 - x * x / (2.0 * rx)), 0.0))

    value, _ = dblquad(
        lambda y, x: lam / (h0 + x * x / (2 * rx) + y * y / (2 * ry) + m),
        -x_max,
        x_max,
        lambda x: -y_max(x),
        y_max,
        epsrel=1e-10,
    )
    return value


@pytest.mark.parametrize("rarefaction", [0.0, 2.7e-7])
def test_closed_form_equals_quadrature(rarefaction: float) -> None:
    """(P2) against a 2-D quadrature of λ_f/(h + M) over the wetted ellipse (liquid and air)."""
    args = (OIL, RX, RY, 0.3e-6, 37e-6)
    closed = ellipse_gap_conductance(*args, rarefaction)
    assert closed == pytest.approx(_quadrature(*args, rarefaction), rel=1e-6)


def test_limits_and_scaling() -> None:
    """h_max → h0 gives 0 (and ≈ 2πλ√(R_xR_y)ε just above); a sphere on a flat gives
    2πλR ln(h_max/h0); linear in λ_f; a gas with h ≪ M reaches the free-molecular λ_f A_w/M."""
    assert ellipse_gap_conductance(OIL, RX, RY, 1e-6, 1e-6) == 0.0
    assert ellipse_gap_conductance(OIL, RX, RY, 1e-6, 0.5e-6) == 0.0
    eps = 1e-6
    near = ellipse_gap_conductance(OIL, RX, RY, 1e-6, 1e-6 * (1 + eps))
    assert near == pytest.approx(2 * math.pi * OIL * math.sqrt(RX * RY) * eps, rel=1e-5)
    radius = 3.175e-3
    sphere = ellipse_gap_conductance(OIL, radius, radius, 1e-7, 1e-5)
    assert sphere == pytest.approx(2 * math.pi * OIL * radius * math.log(100.0), rel=1e-12)
    g = ellipse_gap_conductance(OIL, RX, RY, 1e-7, 1e-5)
    assert ellipse_gap_conductance(3 * OIL, RX, RY, 1e-7, 1e-5) == pytest.approx(3 * g)
    h0, h_max, m = 1e-9, 2e-9, 1e-3  # every gap far below M
    wetted = 2 * math.pi * math.sqrt(RX * RY) * (h_max - h0)  # area of the wetted ellipse
    gas = ellipse_gap_conductance(0.026, RX, RY, h0, h_max, m)
    assert gas == pytest.approx(0.026 * wetted / m, rel=1e-5)


def test_hertz_separation_of_a_sphere_is_johnsons() -> None:
    """R_x = R_y: the gap outside the circle is r²/2R − a²/R + [(2a² − r²) asin(a/r) +
    a√(r² − a²)]/(πR) (Johnson 1985, (3.42) for the two bodies); 0 inside and on the edge."""
    radius = 3.0e-3
    h = hertz(radius, radius, E_STAR, 40.0)
    a = h.a
    for r in (1.001 * a, 1.3 * a, 2.0 * a, 5.0 * a):
        johnson = (
            r * r / (2 * radius)
            - a * a / radius
            + ((2 * a * a - r * r) * math.asin(a / r) + a * math.sqrt(r * r - a * a))
            / (math.pi * radius)
        )
        assert hertz_separation(r, 0.0, h, radius, radius) == pytest.approx(johnson, rel=1e-7)
    assert hertz_separation(0.5 * a, 0.3 * a, h, radius, radius) == 0.0
    assert hertz_separation(a, 0.0, h, radius, radius) == pytest.approx(0.0, abs=1e-15)


def test_elliptic_gap_opens_as_three_halves_and_tends_to_the_rigid_gap() -> None:
    """The loaded elliptic gap grows as (s − 1)^{3/2} at the edge (a step of 4 in s − 1 gives 8
    in h) and approaches the paraboloid less δ far away (the displacement decays as 1/r)."""
    h = hertz(RX, RY, E_STAR, 40.0)
    edge = [hertz_separation(h.a * (1 + e), 0.0, h, RX, RY) for e in (1e-5, 4e-5)]
    assert edge[1] / edge[0] == pytest.approx(8.0, rel=1e-3)
    far = 60.0 * h.a
    rigid = far * far / (2 * RX) - h.approach
    gap = hertz_separation(far, 0.0, h, RX, RY)
    assert rigid < gap < rigid + 0.05 * h.approach + 0.01 * rigid


def test_loaded_film_lies_between_its_bounds_and_tends_to_the_unloaded() -> None:
    """The deformed gap is narrower than the paraboloid (G_f above (P2), here by 25 %) and wider
    than the rigid paraboloid less δ (a strict upper bound); a vanishing load gives (P2)."""
    h0, h_max = 0.3e-6, 37e-6
    h = hertz(RX, RY, E_STAR, 40.0)
    loaded = loaded_film_conductance(OIL, RX, RY, h, h0, h_max)
    assert ellipse_gap_conductance(OIL, RX, RY, h0, h_max) < loaded
    # upper bound: the rigid gap h0 + max(P − δ, 0) outside the patch (u ≥ 0), which is (P2)
    # plus the ring between the patch and the rigid interference ellipse at h0
    ring = 2 * math.pi * math.sqrt(RX * RY) * h.approach - math.pi * h.a * h.b
    upper = ellipse_gap_conductance(OIL, RX, RY, h0, h_max) + OIL * ring / h0
    assert loaded < upper
    tiny = hertz(RX, RY, E_STAR, 1e-9)
    assert loaded_film_conductance(OIL, RX, RY, tiny, h0, h_max) == pytest.approx(
        ellipse_gap_conductance(OIL, RX, RY, h0, h_max), rel=1e-3
    )
    assert loaded_film_conductance(OIL, RX, RY, h, h0, h0) == 0.0


def test_parallel_combination() -> None:
    """(P3): 1/R = 1/R_patch + G_f; no patch leaves the film, no film the patch."""
    assert with_film_path(2.0, 0.25) == pytest.approx(1.0 / (0.5 + 0.25))
    assert with_film_path(math.inf, 0.25) == pytest.approx(4.0)
    assert with_film_path(2.0, 0.0) == 2.0
    assert with_film_path(math.inf, 0.0) == math.inf


def test_meniscus_and_groove_clearance() -> None:
    """The meniscus on the patch edge (m = 1) leaves the film h0; the gothic-arch clearance is
    (r_g − r_b)(1 − cos β); bad inputs name the field."""
    h = hertz(RX, RY, E_STAR, 40.0)
    assert meniscus_thickness(h, RX, RY, 1.0, 0.3e-6) == pytest.approx(0.3e-6, abs=1e-15)
    assert meniscus_thickness(h, RX, RY, 3.0, 0.3e-6) > meniscus_thickness(h, RX, RY, 2.0, 0.3e-6)
    assert groove_clearance(3.175e-3, 3.302e-3, math.pi / 4) == pytest.approx(
        0.127e-3 * (1 - math.sqrt(0.5))
    )
    with pytest.raises(InputError, match=r"lubrication\.inlet_ratio"):
        meniscus_thickness(h, RX, RY, 0.5, 0.3e-6)
    with pytest.raises(InputError, match="groove_radius"):
        groove_clearance(3.175e-3, 3.0e-3, 0.7)
    with pytest.raises(InputError, match="h0"):
        ellipse_gap_conductance(OIL, RX, RY, 0.0, 1e-6)


COARSE = {"numerics.cells_across": 24}
PAPER_CELLS = {"tcr.headline": "V2"}
"""The micro TCR of the film-path numbers (theory manual's table): Gao et al.'s V2 on 8 µm cells."""
EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"


@cache
def _tcr(axial_load: float, film_path: str) -> ScrewTCR:
    case = load_case(
        EXAMPLE,
        {**COARSE, **PAPER_CELLS, "operating.axial_load": axial_load, "tcr.film_path": film_path},
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return screw_tcr(case)


def test_option_off_keeps_the_chain() -> None:
    """film_path = "none" (default) adds nothing: same R, no films, the ball paths without
    film (they were empty, and heat_path_resistance NaN, before both modes were given them)."""
    off, on = _tcr(0.0, "none"), _tcr(0.0, "meniscus")
    assert off.films == () and [p.film for p in off.heat_paths()] == [False, False]
    assert off.ball_path_without_film < math.inf
    assert off.heat_path_resistance == pytest.approx(off.ball_path_without_film, rel=1e-12)
    assert on.resistance == off.resistance  # the micro TCR is not touched
    # at 0 kN both nuts carry their patch: each one's film lowers that nut's own path
    paths = on.heat_paths()
    assert len(paths) == 2 and all(p.resistance < p.without_film for p in paths)
    assert with_film_path(paths[0].without_film, 0.0) == paths[0].without_film


def test_lifted_off_nut_conducts_through_its_films_only() -> None:
    """After lift-off nut 2 has no patch: its path is the two films of each ball in series,
    balls in parallel, each film with the spreading from its wetted ellipse."""
    result = _tcr(5000.0, "meniscus")
    assert [n.index for n in result.nuts] == [1]
    film = {f.index: f for f in result.films}[2]
    path = {p.index: p for p in result.heat_paths(constriction=False)}[2]
    assert not film.loaded and math.isinf(path.micro) and path.constriction == 0.0
    per_ball = 1 / film.screw.conductance + 1 / film.nut.conductance
    assert path.resistance == pytest.approx(per_ball / film.balls)
    with_spreading = {p.index: p for p in result.heat_paths()}[2]
    assert path.resistance < with_spreading.resistance < math.inf


def test_thermal_model_gets_the_film_path() -> None:
    """The smeared interfaces of the thermal model take (P3); a lifted-off nut conducts."""
    result = _tcr(5000.0, "meniscus")
    given = {"thermal.drag_torque.source": "given", "thermal.drag_torque.torque": 0.2}
    case = with_overrides(result.case, given)
    _, _, _, interfaces, _ = build_problem(case, result)
    paths = {p.index: p.resistance for p in result.heat_paths()}
    assert interfaces[0].resistance == pytest.approx(paths[1])
    assert interfaces[1].resistance == pytest.approx(paths[2])
    assert interfaces[1].conductance_per_area > 0.0
    lam = conductivities(case)
    nut = result.nuts[0]
    cons = (contact_constriction(nut.screw, lam) + contact_constriction(nut.nut, lam)) / nut.balls
    assert interfaces[0].constriction_resistance == pytest.approx(cons)


def test_results_report_both_paths() -> None:
    """summary() and the report carry the ball path with and without the films."""
    result = _tcr(5000.0, "meniscus")
    film = result.summary()["film_path"]
    assert film["nuts"]["nut2"]["loaded"] is False
    assert [s.title for s in result.report()][-1] == "Film path around the balls"
    assert _tcr(0.0, "none").summary()["film_path"] is None


@pytest.mark.parametrize(
    ("field", "args"),
    [("rx", (OIL, 0.0, RY, 1e-7, 1e-5)), ("h_max", (OIL, RX, RY, 1e-7, math.inf))],
)
def test_bad_film_inputs_are_refused(field: str, args: tuple[float, ...]) -> None:
    """A non-positive radius or an infinite film edge is an InputError naming it, not a hang."""
    h = hertz(RX, RY, E_STAR, 40.0)
    with pytest.raises(InputError, match=field):
        ellipse_gap_conductance(*args)
    lam, rx, ry, h0, h_max = args
    with pytest.raises(InputError, match=field):
        loaded_film_conductance(lam, rx, ry, h, h0, h_max)


def test_film_floor_is_the_ehl_film_when_thicker_than_the_roughness() -> None:
    """h0 = max(σ, central EHL film at the case's speed): 0.06 Pa s at 1000 rpm gives 0.27 µm
    < σ = 0.302 µm; ten times the viscosity lifts h0 to the Hamrock–Dowson film (∝ η^0.67,
    0.271 µm × 10^0.67 at the rolling speed of contact A, E2.8); a standing screw keeps σ."""
    sigma = _tcr(0.0, "meniscus").films[0].screw.h0
    assert sigma == pytest.approx(0.302e-6, rel=0.01)
    thick = load_case(EXAMPLE, {**COARSE, "tcr.film_path": "meniscus", "medium.viscosity": 0.6})
    h0 = screw_tcr(thick).films[0].screw.h0
    assert h0 == pytest.approx(0.2712e-6 * 10**0.67, rel=0.02)
    still = load_case(EXAMPLE, {**COARSE, "tcr.film_path": "meniscus", "operating.speed": 0.0})
    assert screw_tcr(still).films[0].screw.h0 == pytest.approx(sigma)


def test_loaded_film_of_a_sphere_equals_the_radial_integral_of_johnsons_gap() -> None:
    """An independent reference for (P1) around a loaded patch: on a sphere the gap outside the
    Hertz circle is Johnson's closed form (1985, eq. 3.42b),
    h(r) = r²/2R − δ + (a²/πR)[(2 − r²/a²) asin(a/r) + √(r²/a² − 1)], δ = a²/R, and the film
    conductance the radial integral ∫ 2πr λ/(h0 + h) dr from a to h(r) = h_max − h0."""
    from scipy.integrate import quad
    from scipy.optimize import brentq

    radius, lam, h0, h_max = 5e-3, 0.14, 0.3e-6, 20e-6
    contact = hertz(radius, radius, 115e9, 40.0)
    a = contact.a

    def gap(r: float) -> float:
        ratio = r / a
        shape = (2.0 - ratio**2) * math.asin(1.0 / ratio) + math.sqrt(ratio**2 - 1.0)
        return r * r / (2.0 * radius) - a * a / radius + a * a / (math.pi * radius) * shape

    outer = brentq(lambda r: h0 + gap(r) - h_max, a * (1 + 1e-12), 10.0 * radius)
    reference, _ = quad(lambda r: 2.0 * math.pi * r * lam / (h0 + gap(r)), a, outer, limit=200)
    found = loaded_film_conductance(lam, radius, radius, contact, h0, h_max)
    assert found == pytest.approx(reference, rel=1e-6)


def test_layer_fed_track_is_wetted_out_to_the_layer() -> None:
    """A track fed by a known oil layer (lubrication.inlet_layer) is wetted where the gap has
    closed to the layer: h_max = max(h0, h_oil) at every loaded contact, below the flooded edge."""
    layer = 2e-6
    case = load_case(
        EXAMPLE,
        {
            **COARSE,
            **PAPER_CELLS,
            "tcr.film_path": "meniscus",
            "lubrication.supply": "starved",
            "lubrication.inlet_layer": layer,
        },
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fed = screw_tcr(case)
    flooded = _tcr(0.0, "meniscus")
    pairs = [(f, g) for f in fed.films for g in flooded.films if f.index == g.index and f.loaded]
    assert pairs
    for f, g in pairs:
        for side in ("screw", "nut"):
            path, wide = getattr(f, side), getattr(g, side)
            assert path.h_max == pytest.approx(max(path.h0, layer), rel=1e-12)
            assert path.h_max < wide.h_max and path.conductance < wide.conductance
