"""The rival discretisations of the screw's temperature field, one registry.

Each model turns the same SI :class:`~ballscrew.thermal.problem.ThermalProblem` into a
:class:`~ballscrew.thermal.discretisation.Discretisation` that :func:`~ballscrew.thermal.simulate`
solves (theory manual: *Thermal*):

* ``axisymmetric`` — 2-D axisymmetric scikit-fem model, Lagrange quadrilaterals;
* ``network`` — 1-D axial network of shaft and nut cells (milliseconds, for sweeps);
* ``3d`` — 3-D scikit-fem hexahedra with the balls as helical contact patches.

The heavy modules are imported when a model is built.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from ballscrew.registry import Registry
from ballscrew.thermal.discretisation import Discretisation
from ballscrew.thermal.problem import ThermalProblem

__all__ = ["THERMAL_MODELS", "MeshOptions", "build_model"]


@dataclass(frozen=True)
class MeshOptions:
    """Discretisation settings of all three models (SI)."""

    size: float = 0.002
    """Axisymmetric model: element size in both directions [m]."""
    order: int = 2
    """Axisymmetric model: Lagrange order, 1 or 2."""
    network_cell: float = 0.005
    """Network: axial cell length [m]."""
    size_3d: float = 0.005
    """3-D model: axial element size over the nut and its stroke [m]."""
    far_size_3d: float = 0.02
    """3-D model: axial element size of the shaft away from the nut [m]."""
    divisions_3d: int = 48
    """3-D model: circumferential divisions."""
    layers_3d: int = 4
    """3-D model: radial layers of the shaft O-grid."""


Builder = Callable[[ThermalProblem, MeshOptions, Sequence[Any] | None], Discretisation]
THERMAL_MODELS: Registry[Builder] = Registry("thermal model", "thermal.model")


@THERMAL_MODELS.register("axisymmetric", "2-D axisymmetric finite elements (scikit-fem)")
def _axisymmetric(
    problem: ThermalProblem, mesh: MeshOptions, patches: Sequence[Any] | None
) -> Discretisation:
    from ballscrew.thermal.axisymmetric import build_axisymmetric

    return build_axisymmetric(problem, mesh.size, mesh.order)


@THERMAL_MODELS.register("network", "1-D axial network of shaft and nut cells")
def _network(
    problem: ThermalProblem, mesh: MeshOptions, patches: Sequence[Any] | None
) -> Discretisation:
    from ballscrew.thermal.network import build_network

    return build_network(problem, mesh.network_cell)


@THERMAL_MODELS.register("3d", "3-D finite elements with helical ball-contact patches")
def _threed(
    problem: ThermalProblem, mesh: MeshOptions, patches: Sequence[Any] | None
) -> Discretisation:
    from ballscrew.thermal.threed import build_threed

    return build_threed(
        problem,
        mesh.size_3d,
        mesh.divisions_3d,
        mesh.layers_3d,
        mesh.far_size_3d,
        patches=patches,
    )


def build_model(
    name: str,
    problem: ThermalProblem,
    mesh: MeshOptions,
    patches: Sequence[Any] | None = None,
) -> Discretisation:
    """Discretise ``problem`` with the registered model ``name``.

    ``patches``: per ring part, the ball contact patches of the 3-D model (None elsewhere).
    """
    return THERMAL_MODELS[name](problem, mesh, patches)
