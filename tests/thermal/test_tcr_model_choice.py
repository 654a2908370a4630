"""``[thermal.contact] tcr_model``: the balls' micro TCR from one of screw_tcr's rival models."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import ballscrew as bs
from ballscrew.case import CaseError, with_overrides

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
FAST = {"thermal.mesh.size": "5 mm", "thermal.transient.time_step": "300 s"}
MICRO_ONLY = {"thermal.contact.constriction": False}
"""Without the macro-constriction (10× the micro TCR) the micro model's effect is plain."""


@pytest.fixture(scope="module")
def case():
    return bs.load_case(EXAMPLE, FAST | MICRO_ONLY)


@pytest.fixture(scope="module")
def tcr(case):
    return bs.screw_tcr(case)


@pytest.fixture(scope="module")
def fields(case, tcr):
    """Steady network results: the default (the headline, CMY) and the paper's V2 cell model
    (lower R) and MT (lowest R) choices."""
    out = {None: bs.thermal_field(case, "network", tcr=tcr, transient=False)}
    for name in ("V2", "MT"):
        chosen = with_overrides(case, {"thermal.contact.tcr_model": name})
        out[name] = bs.thermal_field(chosen, "network", tcr=tcr, transient=False)
    return out


def test_chosen_model_sets_the_micro_resistance(tcr, fields):
    """Each nut's micro R is the chosen model's R of that nut; the nuts in parallel give the
    model's R of the screw (A3)."""
    for name in ("V2", "MT"):
        model = tcr.models[name]
        micro = [i.micro_resistance for i in fields[name].interfaces]
        assert micro == pytest.approx(list(model.nut_resistances.values()), rel=1e-12)
        assert 1 / sum(1 / r for r in micro) == pytest.approx(model.resistance, rel=1e-12)


def _heat_across_nut_1(field) -> float:
    """Heat from screw to nut 1 through its balls, mean(T_shaft surface − T_bore)/R [W]."""
    ds = field.to_xarray()
    z = ds.ring_z.values
    surface = np.interp(z, ds.axis_z.values, ds.shaft_surface_temperature_steady.values)
    nut_1 = z < 0.495  # nut 1 spans 435–495 mm (60 mm nut, 10 mm spacer, centred at 500 mm)
    jump = surface[nut_1] - ds.ring_bore_temperature_steady.values[nut_1]
    return float(np.mean(jump)) / field.interfaces[0].micro_resistance


def test_higher_resistance_passes_less_heat(fields):
    """Heat crosses the balls from screw to nut here (the nut sits on the cooled table).
    The default CMY (R above V2's) passes less of it than V2, MT (R below) more: hotter screw,
    cooler nut with CMY."""
    r = {k: fields[k].interfaces[0].micro_resistance for k in fields}
    assert r["MT"] < r["V2"] < r[None]
    q = {k: _heat_across_nut_1(f) for k, f in fields.items()}
    assert 0 < q[None] < q["V2"] < q["MT"]
    steady = {k: {s.name: s.steady for s in f.sensors} for k, f in fields.items()}
    assert steady[None]["screw"] > steady["V2"]["screw"] > steady["MT"]["screw"]
    assert steady[None]["nut 1"] < steady["V2"]["nut 1"] < steady["MT"]["nut 1"]


def test_default_keeps_the_headline_model(case, tcr, fields):
    """No tcr_model: the headline model's R per nut (``[tcr] headline``, CMY); naming the
    headline model gives the same numbers."""
    default = fields[None]
    for nut, i in zip(tcr.nuts, default.interfaces, strict=True):
        assert i.micro_resistance == pytest.approx(nut.resistance, rel=1e-12)
    same = bs.thermal_field(
        with_overrides(case, {"thermal.contact.tcr_model": case.tcr.headline}),
        "network",
        tcr=tcr,
        transient=False,
    )
    assert same.max_temperature_rise == pytest.approx(default.max_temperature_rise, rel=1e-12)


def test_model_outside_the_case_list_is_computed(case):
    """A model not in ``[tcr] models`` (here the patch variant of a dropped V1) is solved on
    demand."""
    narrow = with_overrides(
        case, {"tcr.models": ["V2", "CMY"], "thermal.contact.tcr_model": "V1/patch"}
    )
    r = bs.thermal_field(narrow, "network", transient=False)
    assert all(0 < i.micro_resistance < float("inf") for i in r.interfaces)


def test_bad_model_name_lists_the_names(case):
    with pytest.raises(CaseError, match=r"thermal.contact.tcr_model.*V2.*CMY.*Mikic.*V2/patch"):
        with_overrides(case, {"thermal.contact.tcr_model": "Holm"})
    with pytest.raises(CaseError, match=r"tcr_model = 'CMY' needs source = 'tcr'"):
        with_overrides(
            case,
            {
                "thermal.contact.source": "given",
                "thermal.contact.resistance_per_area": 1e-4,
                "thermal.contact.tcr_model": "CMY",
            },
        )
