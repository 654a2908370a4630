"""Case → the coolant and table inputs of the thermal problem (Q8 transient, Q10, Q11).

The hollow-shaft coolant (``[thermal.shaft_coolant]``), the inlet temperature of a cooled nut
(``[thermal.coolant]``) and the table's heat capacity (``[thermal.mounting]``), in SI for
:class:`~ballscrew.thermal.problem.ThermalProblem`.
"""

from __future__ import annotations

from ballscrew.case.thermal_spec import ThermalSpec
from ballscrew.thermal.boundary import mounting_coefficient
from ballscrew.thermal.coolant import (
    LAMINAR_LIMIT,
    NU_LAMINAR,
    TURBULENT_LIMIT,
    BoreFlow,
    Fluid,
    ShaftCoolant,
    fluid,
)
from ballscrew.thermal.problem import TableMass


def bore_flow(spec: ThermalSpec) -> BoreFlow | None:
    """The coolant flow of the shaft bore; None when the shaft is solid."""
    sc = spec.shaft_coolant
    if sc.bore_diameter is None:
        return None
    if sc.fluid == "custom":
        props = (sc.density, sc.specific_heat, sc.viscosity, sc.conductivity)
        medium = Fluid(*(float(p) for p in props if p is not None))
    else:
        medium = fluid(sc.fluid)
    return BoreFlow(sc.bore_diameter, sc.flow_rate, medium)


def bore_coefficient(spec: ThermalSpec) -> tuple[float, str] | None:
    """h of the shaft bore [W/(m² K)] and how it was found; None for a solid shaft."""
    flow = bore_flow(spec)
    return None if flow is None else _coefficient(spec, flow)


def _coefficient(spec: ThermalSpec, flow: BoreFlow) -> tuple[float, str]:
    """h of the bore ``flow`` [W/(m² K)] and how it was found (the case's override, else the
    regime of :func:`~ballscrew.thermal.coolant.bore_nusselt` at its Reynolds number)."""
    sc = spec.shaft_coolant
    if sc.coefficient is not None:
        return float(sc.coefficient), "override"
    name = "Gnielinski" if sc.correlation == "gnielinski" else "Dittus–Boelter"
    re = flow.reynolds
    if re <= LAMINAR_LIMIT:
        regime = f"laminar Nu = {NU_LAMINAR['flux']:g}"
    elif re < TURBULENT_LIMIT:
        regime = f"laminar–{name} blend"
    else:
        regime = name
    return flow.coefficient(sc.correlation), f"{regime}, Re = {re:.4g} (Q11)"


def shaft_coolant(spec: ThermalSpec) -> ShaftCoolant | None:
    """The :class:`ShaftCoolant` of the case (h from the correlation unless given)."""
    flow = bore_flow(spec)
    if flow is None:
        return None
    h, _ = _coefficient(spec, flow)
    sc = spec.shaft_coolant
    inlet = spec.ambient_temperature if sc.inlet_temperature is None else sc.inlet_temperature
    return ShaftCoolant(
        0.5 * flow.diameter, h, flow.capacity_rate, inlet - spec.ambient_temperature
    )


def nut_coolant_flux(spec: ThermalSpec, outer_area: float) -> float:
    """h_cool·(T_in − T_amb) of the cooled nut smeared over its outer area A_od [W/m²]."""
    c = spec.coolant
    if c.inlet_temperature is None or c.nut_coefficient == 0 or c.nut_channel_area == 0:
        return 0.0
    h_cool = c.nut_coefficient * c.nut_channel_area / outer_area
    return h_cool * (c.inlet_temperature - spec.ambient_temperature)


def table_mass(spec: ThermalSpec, outer_area: float) -> TableMass | None:
    """The table as a lumped mass, or None when it is quasi-steady (inside h of the nut)."""
    m = spec.mounting
    if m.kind != "table" or m.table_heat_capacity is None or m.table_conductance is None:
        return None
    contact = m.contact_fraction * outer_area if m.contact_area is None else m.contact_area
    joint = mounting_coefficient(m.contact_conductance, contact, outer_area)
    return TableMass(joint, m.table_conductance, m.table_heat_capacity)
