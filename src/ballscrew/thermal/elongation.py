"""Thermal elongation of the screw: ΔL = α∫ΔT dz (Q7) and an axisymmetric thermo-elastic check.

For a body free of tractions except a frictionless axial support at z = 0, the area-mean axial
displacement of the end face is exactly α∫θ dV/A (Betti's theorem with a uniform axial stress:
the self-equilibrated thermal stresses integrate to zero). The FE thermo-elastic solve tests
the α∫θ̄ dz bookkeeping; a 3-D clamped thermo-elastic run gave 104.8 µm against 104.7 µm.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ballscrew.errors import InputError
from ballscrew.thermal.discretisation import Discretisation


def thermal_elongation(
    z: NDArray[np.float64], mean_rise: NDArray[np.float64], expansion: float
) -> float:
    """ΔL = α ∫ θ̄(z) dz, trapezoidal over the stations ``z`` [m] (Q7).

    Example: a uniform 5 K over 0.5 m with α = 11.5e-6 /K gives 28.75 µm.
    """
    z, theta = np.asarray(z, dtype=float), np.asarray(mean_rise, dtype=float)
    return float(expansion * np.trapezoid(theta, z, axis=-1))


def displacement_profile(
    z: NDArray[np.float64], mean_rise: NDArray[np.float64], expansion: float, fixed: float = 0.0
) -> NDArray[np.float64]:
    """Axial thermal displacement u(z) = α ∫_{z_fixed}^{z} θ̄ dz along the shaft [m].

    ``fixed`` is where the shaft is held axially (the fixed bearing): the positioning error of
    a nut at z is u(z). Works on the last axis of ``mean_rise`` (time histories too).
    """
    z, theta = np.asarray(z, dtype=float), np.asarray(mean_rise, dtype=float)
    mid = 0.5 * (theta[..., 1:] + theta[..., :-1]) * np.diff(z)
    u = np.concatenate([np.zeros((*theta.shape[:-1], 1)), np.cumsum(mid, axis=-1)], axis=-1)
    u_fixed = np.apply_along_axis(lambda row: np.interp(fixed, z, row), -1, u)
    return expansion * (u - u_fixed[..., None])


def shaft_displacement(
    z: NDArray[np.float64],
    mean_rise: NDArray[np.float64],
    expansion: float,
    length: float,
    fixed: float = 0.0,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(stations, u): :func:`displacement_profile` from the shaft's start z = 0 to its end face
    z = ``length``, so the end face moves by the elongation α∫θ̄ dz over the whole shaft.

    Stations that stop short of the ends (the network's cell centres) get the two end faces
    added, θ̄ held at the outer stations' values out to them (a network cell has one temperature
    up to its faces): then u(length) equals the network's elongation Σ α θ̄_i Δz_i exactly on
    uniform cells and to second order in the cell-size change otherwise, and the FE model's
    α/A ∫θ dV to its quadrature.
    """
    z, theta = np.asarray(z, dtype=float), np.asarray(mean_rise, dtype=float)
    tol = 1e-9 * length
    if z[0] > tol:
        z, theta = np.concatenate([[0.0], z]), np.concatenate([theta[..., :1], theta], axis=-1)
    if z[-1] < length - tol:
        z = np.concatenate([z, [length]])
        theta = np.concatenate([theta, theta[..., -1:]], axis=-1)
    return z, displacement_profile(z, theta, expansion, fixed)


def thermoelastic_elongation(
    disc: Discretisation, theta: NDArray[np.float64], youngs_modulus: float, poisson: float
) -> float:
    """Mean axial end-face displacement of the shaft from axisymmetric thermo-elasticity [m].

    Linear elasticity of the shaft alone (vector Lagrange elements of the thermal mesh), strains
    (∂u_r/∂r, ∂u_z/∂z, u_r/r, ∂u_r/∂z + ∂u_z/∂r), thermal strain αθ in the three normal
    directions, u_z = 0 on z = 0 (frictionless), u_r = 0 on the axis, all else free; weight 2πr.
    """
    if disc.model != "axisymmetric":
        raise InputError("model", disc.model, "'axisymmetric' (the check needs the FE mesh)")
    if not (youngs_modulus > 0.0 and 0.0 < poisson < 0.5):
        raise InputError("materials.screw", (youngs_modulus, poisson), "E > 0 and 0 < ν < 0.5")
    from skfem import Basis, BilinearForm, ElementVector, FacetBasis, LinearForm, asm, condense
    from skfem import solve as fe_solve

    problem = disc.problem
    am = disc.extra["mesh"]
    mesh = am.mesh
    intorder = disc.extra["intorder"]
    shaft_elements = np.nonzero(am.body == 0)[0]
    vector = Basis(
        mesh, ElementVector(disc.extra["element"]), elements=shaft_elements, intorder=intorder
    )
    scalar = disc.extra["shaft_basis"]
    lam = youngs_modulus * poisson / ((1 + poisson) * (1 - 2 * poisson))
    mu = youngs_modulus / (2 * (1 + poisson))
    alpha = problem.expansion
    two_pi = 2.0 * math.pi

    def strains(u, r):
        g = u.grad
        return g[0][0], g[1][1], np.asarray(u)[0] / r, g[0][1] + g[1][0]

    @BilinearForm
    def stiffness(u, v, w):
        r = w.x[0]
        er, ez, et, gu = strains(u, r)
        vr, vz, vt, gv = strains(v, r)
        trace = lam * (er + ez + et) * (vr + vz + vt)
        return (trace + 2 * mu * (er * vr + ez * vz + et * vt) + mu * gu * gv) * two_pi * r

    @LinearForm
    def thermal_load(v, w):
        r = w.x[0]
        vr, vz, vt, _ = strains(v, r)
        return (3 * lam + 2 * mu) * alpha * w.theta * (vr + vz + vt) * two_pi * r

    k = asm(stiffness, vector)
    f = asm(thermal_load, vector, theta=scalar.interpolate(theta[: scalar.N]))
    shaft_dofs = np.unique(vector.element_dofs)
    tol = 1e-9 * problem.shaft_length
    fixed_z = vector.get_dofs(lambda x: np.abs(x[1]) < tol).all(["u^2"])
    axis_r = vector.get_dofs(lambda x: np.abs(x[0]) < tol).all(["u^1"])
    free = np.setdiff1d(shaft_dofs, np.concatenate([fixed_z, axis_r]))
    u = fe_solve(*condense(k, f, I=free))
    end_facets = am.facets["shaft_ends"]
    tip = end_facets[mesh.p[1, mesh.facets[0, end_facets]] > 0.5 * problem.shaft_length]
    fb = FacetBasis(mesh, ElementVector(disc.extra["element"]), facets=tip, intorder=intorder)

    @LinearForm
    def axial_mean(v, w):
        return np.asarray(v)[1] * two_pi * w.x[0] / problem.section_area

    return float(asm(axial_mean, fb) @ u)
