"""End to end: the thermal field heated by the ball model under the ``skf`` traction law.

The example screw at 1000 rpm runs in full film (Λ ≈ 7 at the screw contact, theory manual
*Friction*, breakdown table), where the SKF weighting φ_bl (F3c) is ~0 and the cell shear is
capped at μ_EHL = 0.05 instead of the film law's 0.07: less sliding heat, the rolling and drag
parts unchanged in kind. The field is solved with a cooled bore and the table as a heat mass,
so the heat leaves by every path the model has.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.thermal import thermal_field

#: the ball model's preload torque is below the catalogue's here (a known warning)
pytestmark = pytest.mark.filterwarnings(
    "ignore::ballscrew.analyses.operating_point.OperatingPointWarning"
)
EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
CASE = {
    "numerics.cells_across": 16,
    "friction.model": "ball_model",
    "thermal.transient.duration": "20 min",
    "thermal.transient.time_step": "120 s",
    "thermal.shaft_coolant.bore_diameter": "12 mm",
    "thermal.shaft_coolant.flow_rate": "0.5 L/min",
    "thermal.mounting.table_heat_capacity": "20 kJ/K",
}


def _case(law: str):
    return ballscrew.load_case(EXAMPLE, CASE | {"friction.traction": law})


@pytest.fixture(scope="module")
def fields():
    return {law: thermal_field(_case(law), "network") for law in ("film", "skf")}


def test_the_skf_heat_is_the_friction_torque_times_the_speed_split_between_screw_and_nut(
    fields,
):
    field = fields["skf"]
    case, coupling = field.case, field.coupling
    assert coupling is not None and coupling.friction_model == "ball_model"
    omega = case.operating.speed
    work = case.operating.axial_load * case.screw.lead / (2 * math.pi) * omega
    assert coupling.heat == pytest.approx(coupling.friction_torque * omega - work, rel=1e-12)
    balls = [s for s in field.sources if "balls" in s.name]
    assert sum(s.heat for s in balls) == pytest.approx(coupling.heat, rel=1e-9)
    assert sum(s.into_screw for s in balls) == pytest.approx(coupling.heat_to_screw, rel=1e-9)
    for s in balls:
        assert s.into_screw + s.into_nut == pytest.approx(s.heat, rel=1e-12)
        assert 0.0 < s.into_screw < s.heat
    entering = sum(s.into_screw + s.into_nut for s in field.sources)  # bearings: their shaft part
    assert field.heat_input == pytest.approx(entering, rel=1e-12)


def test_the_skf_field_sends_the_generated_heat_to_ambient_coolant_and_table(fields):
    """Steady: generated = convected + coolant outflow W θ_out + table G_t θ_t; transient:
    ∫Q dt = stored + lost. The coolant enters at ambient, so the heat input is the friction's.

    The heat to ground is taken from the matrix's row sums (the conductances to ambient and from
    the table, the internal links summing to zero in each row; the upwind coolant leaves W in the
    inlet's row only), not its column sums, which balance the heat input by construction: a
    coolant transport that did not conserve W θ would break the sum."""
    field = fields["skf"]
    sol = field.solution
    disc = sol.discretisation
    problem = field.problem
    w = problem.shaft_coolant.capacity_rate
    channel = disc.extra["coolant"]
    coolant = w * sol.steady[channel[-1]]
    table = problem.table.conductance * sol.steady[disc.extra["table"]]
    a, _ = disc.assemble(disc.grid.weights)
    to_ground = np.asarray(a.sum(axis=1)).ravel()
    assert to_ground[channel[0]] == pytest.approx(w, rel=1e-12)
    to_ground[channel[0]] -= w
    ambient = to_ground @ sol.steady - table
    assert 0.05 * field.heat_input < coolant < field.heat_input
    assert 0.0 < table < field.heat_input and ambient > 0.0
    assert ambient + coolant + table == pytest.approx(field.heat_input, rel=1e-9)
    assert field.heat_balance_error < 1e-9
    assert field.transient_heat_balance_error < 1e-9


def test_skf_makes_less_heat_than_the_film_law_in_full_film(fields):
    film, skf = fields["film"], fields["skf"]
    regime = friction_torque(_case("skf"), viscosity=skf.coupling.viscosity)
    # full film in the traction (ψ ≈ 0): SKF's μ_EHL 0.05 < the film law's cap 0.07
    assert regime.traction_coefficient == pytest.approx(0.05, abs=0.002)
    ratio = skf.coupling.heat / film.coupling.heat
    assert 0.7 < ratio < 0.97  # the sliding parts only, a third to a half of the torque
    assert skf.max_temperature_rise < film.max_temperature_rise
