"""Load ratings from the geometry (Lundberg–Palmgren C_a, ISO 76 C_0a) against five makers'
catalogue ratings: HIWIN FDC double nuts (12 sizes), NBS VFI single nuts (12 sizes), Bosch
Rexroth FDM double nuts (24 sizes), THK BNFN double nuts (16 sizes) and TBI SFNU/SFU single nuts
(11 sizes).

HIWIN, NBS, Rexroth and TBI print nominal diameter, lead, ball diameter and circuit (or turn) count
next to C_a and C_0a; none prints conformity or pitch diameter, so the same assumptions serve all
(below). THK prints the pitch (ball centre-to-centre) diameter and "rows × turns" of its
return-tube circuits but no ball diameter, which is assigned from the printed ball-centre offset
(:data:`THK_GEOMETRY_ASSUMPTIONS`).

* HIWIN: C_a −10 %…−1 %, C_0a −17 %…−1 %. The double-nut table prints C_0a = 16.42 kN for
  R20-05K4 (1.10 C_a, a third of its neighbours' ratio); the same catalogue's single-nut table
  (Table 6.4, p. 48) prints 36.4 kN for that size, and the two tables print the same C_a and
  C_0a for each of the 31 other sizes compared: a misprint, so the row takes 36.4 kN (−10.8 %;
  +97.7 % against the misprint).
* NBS rates the same geometry about 20 % lower than HIWIN (its 40 x 10 nut with 4 circuits has
  C_a = 39.1 kN, HIWIN's with 5 circuits 63.4 kN), so every NBS row is a known miss at the
  HIWIN-like conformity 0.53 (C_a +24…+59 %, C_0a +35…+54 %); conformity ≈ 0.55 would remove
  most of it, which the catalogue does not state.
* Rexroth computes its ratings "according to DIN 69051 part 4 or ISO 3408" (catalogue p. 98).
  C_a is met within −13…+2 % on every row. C_0a is 45…60 % above Rexroth's on every row (known
  misses): Rexroth's C_0 is 0.63-0.69 of the Hertz 4200 MPa load at conformity 0.53 with the
  same ball count, so either its grooves are more open or its static criterion is stricter than
  ISO 76's. Rexroth's C grows as i^0.90 with the turns i (40 x 10: 4 → 6 turns, 50.0 → 72.1 kN;
  20 x 5: 4 → 5 turns, 14.3 → 17.5 kN), faster than the i^0.7 of this model: the model is
  −5 % at 4 turns and −12 % at 6.
* THK rates the same geometry below HIWIN (BNFN 2005-5, two 2.5-turn circuits: C_a = 15.1 kN;
  HIWIN R20-05K4, four one-turn circuits: 14.9 kN). C_a: +11…+19 % on the two- and three-circuit
  halves, +31 % on the one-circuit halves (misses; THK's C_a grows as rows^0.86, 4010: 29.0 →
  52.7 kN from one to two circuits), −1 % and −10 % on the two 9.525 mm-ball rows. C_0a: +25…+39
  % (misses) but −9 % and −6 % on the 9.525 mm-ball rows, whose assigned ball is the least sure.
* TBI prints ball diameter and circuits (ratings in kgf, ×9.80665): C_a −9…−3 %, C_0a −20…−5 %,
  with HIWIN (its 20 x 5 with four circuits: 15.2 / 38.0 kN, HIWIN's 14.9 / 36.4 kN); Palmgren's
  C_0a −28…−22 % (every row a miss). The table was read in a transcription (see the data file).

The rival static model ``palmgren`` (``static_load_rating(..., model="palmgren")``: Palmgren's
permanent deformation δ_s = 1.3·10⁻⁷ Q² Σρ_I Σρ_II / D_w [mm, N] set to the makers' 10⁻⁴ D_w,
Harris & Kotzalas 2006) is compared with the same rows (``<maker>_C0a_palmgren_<model>``): it is
12–19 % below the 4200 MPa rating at these ball-screw contacts, so it meets 10 of 12 NBS rows
(+15…+37 %), moves Rexroth from +45…+60 % to +26…+33 % (every row still a miss) and HIWIN from
−17…−1 % to −26…−18 % (half its rows then miss). The makers disagree with one another by more than
either reading separates: for the same geometry Rexroth's C_0 is 0.60 of HIWIN's (model errors
+54 % and −7 %, medians) while their C agree within 5 % (−10 % and −5 %).
"""

from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from ballscrew import design
from ballscrew.contact.elastic import composite_modulus
from ballscrew.geometry import ScrewGeometry

MM = 1e-3
CONFORMITY = 0.53
E_STAR = composite_modulus(206e9, 0.3, 206e9, 0.3)

HIWIN_SOURCE = "HIWIN Ballscrews & Accessories BS-08-2-EN-1704-K, Table 6.5 (pp. 50-51)"
NBS_SOURCE = "NBS (Italcuscinetti) Components for linear motion, ch. 4, table VFI (p. 127)"
REXROTH_SOURCE = "Bosch Rexroth R310RU 3301 (2006.02), double nuts FDM-E-S/-C (p. 108)"
THK_SOURCE = "THK General Catalog, Preload Type of Precision Ball Screw, model BNFN (B-652…B-684)"
TBI_SOURCE = "TBI MOTION Ball Screw catalogue, SFNU/SFU (DIN 69051 Form B) table (pp. C46-C48)"
KGF = 9.80665  # N

ASSUMPTIONS = (
    "pitch diameter = nominal diameter d0 (ASSUMED: no table prints it)",
    "n circuits (Rexroth: i turns) of one turn each; balls per circuit floor(π d_m/(D_w cos λ))"
    " − 1 (ASSUMED: one ball space for the deflector)",
    f"conformity {CONFORMITY} on screw and nut, contact angle 45° (ASSUMED: typical Gothic-arch "
    "values; 0.52 → +17 % C_a, +28 % C_0a; 0.55 → −18 % C_a, −27 % C_0a)",
    "steel E = 206 GPa, ν = 0.3 for balls, screw and nut (ASSUMED)",
    "no hardness or accuracy factor (the makers state HRC 58-62, their ratings' precondition)",
)

THK_BALLS = {0.5: 2.381, 0.75: 3.175, 1.0: 3.969, 1.25: 4.7625, 1.75: 6.35, 2.0: 7.144,
             2.25: 7.9375, 2.7: 9.525}  # fmt: skip
"""THK's ball-centre offset d_p − d [mm] → ball diameter D_w [mm] (ASSUMED, see
:data:`THK_GEOMETRY_ASSUMPTIONS`)."""

THK_GEOMETRY_ASSUMPTIONS = (
    "pitch diameter = the printed ball centre-to-centre diameter d_p",
    "ball diameter ASSUMED (no THK table prints it): the printed offsets d_p − d take eight "
    "values, 0.5, 0.75, 1.0, 1.25, 1.75, 2.0, 2.25, 2.7 mm, matched in order to the eight "
    "standard balls 2.381, 3.175, 3.969, 4.763, 6.35, 7.144, 7.938, 9.525 mm (d_p − d = "
    "0.21…0.28 D_w, the printed thread depth d_p − d_c = 1.03…1.20 D_w)",
    "'rows × turns' per nut half = circuits × turns of one return-tube circuit; balls per circuit "
    "floor(turns π d_p/(D_w cos λ)) − 1 (ASSUMED: one ball space for the tube pick-up)",
)


def tbi_newtons(row: dict[str, Any]) -> dict[str, Any]:
    """A TBI row with its ratings printed in kgf also in newtons (1 kgf = 9.80665 N)."""
    return row | {"Ca_N": row["Ca_kgf"] * KGF, "C0a_N": row["C0a_kgf"] * KGF}


def thk_geometry(row: dict[str, Any]) -> dict[str, Any]:
    """A THK row with the pitch diameter ``d0_mm`` = d_p and the assumed ``ball_mm``."""
    offset = round(row["dp_mm"] - row["d_mm"], 2)
    return row | {"d0_mm": row["dp_mm"], "ball_mm": THK_BALLS[offset]}


TOLERANCE = 0.20
TOLERANCE_BASIS = (
    "the assumed conformity alone moves the prediction by about ±18 % (C_a) between 0.52 and "
    "0.55, hence ±20 %"
)


def _models(file: str, key: str) -> list[str]:
    with (Path(__file__).parent / "data" / f"{file}.toml").open("rb") as fh:
        return [row[0] for row in tomllib.load(fh)[key]["rows"]]


KNOWN_MISSES = {
    *(("nbs", rating, row) for rating in ("Ca", "C0a") for row in (
        "VFI 1605", "VFI 1610", "VFI 2005", "VFI 205T", "VFI 2505", "VFI 3205", "VFI 3210",
        "VFI 4005", "VFI 4010", "VFI 5010", "VFI 6310", "VFI 8010",
    )),
    *(("rexroth", "C0a", row) for row in _models("design_check", "rexroth_fdm_rigidity")),
    *(("hiwin", "C0a_palmgren", row) for row in (
        "R20-05K4-FDC", "R25-10K4-FDC", "R32-10K5-FDC", "R40-10K5-FDC", "R50-10K5-FDC",
        "R50-20K4-FDC (Dw 9.525)",
    )),
    *(("nbs", "C0a_palmgren", row) for row in ("VFI 1605", "VFI 1610")),
    *(("rexroth", "C0a_palmgren", row)
      for row in _models("design_check", "rexroth_fdm_rigidity")),
    *(("thk", "Ca", row) for row in (
        "BNFN1605-2.5", "BNFN2005-2.5", "BNFN4010-2.5", "BNFN4010-3",
    )),
    *(("thk", "C0a", row) for row in _models("design_check", "thk_bnfn_rigidity")
      if row not in ("BNFN5020-2.5", "BNFN6320-5")),
    ("thk", "C0a_palmgren", "BNFN5020-2.5"),
    *(("tbi", "C0a_palmgren", row) for row in _models("load_ratings", "tbi_sfnu")),
}  # fmt: skip
"""Strict xfails: NBS C_a +24…+59 %, C_0a +35…+54 %; Rexroth C_0a
+45…+60 % (every row); THK C_a of the one-circuit halves +31.0…+31.6 % and of 4010-3 (two
1.5-turn circuits) +27.7 %, THK C_0a +25.4…+38.8 % (every row but the two 9.525 mm-ball ones).
Palmgren's C_0a: HIWIN −26…−22 % (six rows), TBI −28…−22 % (every row), NBS VFI 1605 +20.0 % and VFI
1610 +37 %, Rexroth +26…+33 % (every row), THK 5020-2.5 −20.5 %."""


def _rows(dataset, file: str, key: str) -> tuple[list[dict[str, Any]], dict[str, Any]]:
    data = dataset(file, key)
    rows = [dict(zip(data["columns"], r, strict=True)) for r in data["rows"]]
    return rows, {k: v for k, v in data.items() if k not in ("rows", "columns")}


def predicted_ratings(
    d0: float,
    lead: float,
    ball: float,
    circuits: int,
    static_model: str = "iso76",
    turns: float = 1.0,
) -> tuple[float, float]:
    """(C_a, C_0a) [N] of one nut of ``circuits`` circuits of ``turns`` turns each (millimetre
    inputs), C_0a by the rival ``static_model`` of :data:`ballscrew.design.STATIC_RATING_MODELS`."""
    geometry = ScrewGeometry(
        d0 * MM, lead * MM, ball * MM, CONFORMITY, CONFORMITY, math.radians(45.0)
    )
    balls = circuits * design.circuit_ball_count(d0 * MM, ball * MM, lead * MM, turns=turns)
    return (
        design.dynamic_load_rating(geometry, balls),
        design.static_load_rating(geometry, balls, (E_STAR, E_STAR), model=static_model),
    )


MAKERS = {
    "hiwin": ("design_check", "hiwin_fdc_rigidity", HIWIN_SOURCE, "circuits_per_nut"),
    "nbs": ("load_ratings", "nbs_vfi", NBS_SOURCE, "circuits"),
    "rexroth": ("design_check", "rexroth_fdm_rigidity", REXROTH_SOURCE, "circuits_per_nut"),
    "thk": ("design_check", "thk_bnfn_rigidity", THK_SOURCE, "circuits_per_nut"),
    "tbi": ("load_ratings", "tbi_sfnu", TBI_SOURCE, "circuits"),
}

ROW_GEOMETRY = {"thk": thk_geometry, "tbi": tbi_newtons}
"""Completion of a maker's row with ``d0_mm`` and ``ball_mm`` where the table lacks them."""

MAKER_ASSUMPTIONS = {
    "thk": (
        *THK_GEOMETRY_ASSUMPTIONS,
        *ASSUMPTIONS[2:4],
        "no hardness or accuracy factor (THK's ratings hold for its hardened raceways)",
    )
}


CASES = [(maker, model) for maker, (f, k, *_) in MAKERS.items() for model in _models(f, k)]


RATINGS = {
    # id: (static model or None for C_a, model description)
    "Ca": (None, "dynamic_load_rating (Lundberg-Palmgren, i^0.7 over the turns)"),
    "C0a": ("iso76", "static_load_rating (Hertz 4200 MPa, ISO 76)"),
    "C0a_palmgren": (
        "palmgren",
        "static_load_rating, model 'palmgren' (permanent deformation 1e-4 D_w by Palmgren's "
        "formula, Harris & Kotzalas 2006)",
    ),
}


@pytest.mark.parametrize("rating", RATINGS)
@pytest.mark.parametrize(("maker", "model"), CASES)
def test_load_rating_against_catalogue(validation, dataset, maker, model, rating) -> None:
    file, key, source, circuits = MAKERS[maker]
    rows, reference = _rows(dataset, file, key)
    row = ROW_GEOMETRY.get(maker, dict)(next(r for r in rows if r["model"] == model))
    static_model, description = RATINGS[rating]
    ca, c0a = predicted_ratings(
        row["d0_mm"],
        row["lead_mm"],
        row["ball_mm"],
        row[circuits],
        static_model or "iso76",
        row.get("turns_per_circuit", 1.0),
    )
    static = static_model is not None
    correction = reference.get("corrections", {}).get(model) if static else None
    validation.check(
        f"{maker}_{rating}_" + re.sub(r"[^\w.-]+", "_", model).strip("_"),
        kind="comparison with a maker's calculation",
        model=description,
        source=f"{source}; {correction}" if correction else source,
        reference=reference | {"row": row},
        quantity=f"{'static' if static else 'dynamic'} axial load rating of {model}",
        unit="kN",
        measured=row["C0a_N" if static else "Ca_N"] * 1e-3,
        predicted=(c0a if static else ca) * 1e-3,
        tolerance=TOLERANCE,
        relative=True,
        tolerance_basis=TOLERANCE_BASIS,
        assumptions=MAKER_ASSUMPTIONS.get(maker, ASSUMPTIONS),
        known_miss=(maker, rating, model) in KNOWN_MISSES,
    )


def _ratings_at(row: dict[str, Any], circuits: str, conformity: float) -> tuple[float, float]:
    """(C_a, C_0a at 4200 MPa) [N] of a maker's row at ``conformity`` on screw and nut."""
    d0, lead, ball = row["d0_mm"] * MM, row["lead_mm"] * MM, row["ball_mm"] * MM
    geometry = ScrewGeometry(d0, lead, ball, conformity, conformity, math.radians(45.0))
    turns = row.get("turns_per_circuit", 1.0)
    balls = row[circuits] * design.circuit_ball_count(d0, ball, lead, turns=turns)
    return (
        design.dynamic_load_rating(geometry, balls),
        design.static_load_rating(geometry, balls, (E_STAR, E_STAR)),
    )


def implied_static_pressures(dataset, maker: str) -> list[float]:
    """Per row of a maker: the Hertz peak pressure [Pa] at which the model's C_0a equals the
    maker's, at the conformity that makes the model's C_a equal the maker's (so the ball count,
    ball and conformity a maker uses drop out as far as its C_a shows them)."""
    from scipy.optimize import brentq

    file, key, _, circuits = MAKERS[maker]
    rows, _ = _rows(dataset, file, key)
    pressures = []

    def dynamic_gap(conformity: float, row: dict[str, Any]) -> float:
        return _ratings_at(row, circuits, conformity)[0] - row["Ca_N"]

    for raw in rows:
        row = ROW_GEOMETRY.get(maker, dict)(raw)
        f = brentq(dynamic_gap, 0.5005, 0.7, args=(row,))
        c0a = _ratings_at(row, circuits, f)[1]
        pressures.append(design.STATIC_CONTACT_PRESSURE * (row["C0a_N"] / c0a) ** (1.0 / 3.0))
    return pressures


def test_the_static_rating_convention_of_each_maker(dataset) -> None:
    """Is the C_0a gap a maker's convention? Back out each row's static limit at the conformity
    its own C_a implies: HIWIN, THK, NBS and TBI rate C_0a at a median 4190-4270 MPa, ISO 76's
    4200 MPa (their C_0a misses at 0.53 go with their C_a: a more open groove, or THK's assigned
    ball); Rexroth at 3370-3660 MPa on every one of its 24 sizes, median 3450 MPa (C_0a 0.55 of
    the 4200 MPa load): a static criterion of its own (docs/theory/load-ratings.md)."""
    medians = {}
    for maker in MAKERS:
        pressures = implied_static_pressures(dataset, maker)
        medians[maker] = float(np.median(pressures))
        if maker == "rexroth":
            assert max(pressures) < 3.7e9 and min(pressures) > 3.3e9
    for maker in ("hiwin", "thk", "nbs", "tbi"):
        assert medians[maker] == pytest.approx(4.2e9, rel=0.03), maker
    assert medians["rexroth"] == pytest.approx(3.45e9, rel=0.02)
