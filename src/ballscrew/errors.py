"""Exceptions raised by ballscrew.

Every error a user can cause derives from :class:`BallscrewError`, so the CLI can turn it into a
one-line message and exit status 2 instead of a traceback.
"""

from __future__ import annotations


class BallscrewError(Exception):
    """Base class of all errors that ballscrew raises on purpose."""


class InputError(BallscrewError, ValueError):
    """A value given by the user is outside its physical or allowed range.

    The message names the field, the value and the allowed range.
    """

    def __init__(self, field: str, value: object, allowed: str) -> None:
        self.field = field
        self.value = value
        self.allowed = allowed
        super().__init__(f"{field} = {value!r} is not allowed: {allowed}")


class ConvergenceError(BallscrewError, RuntimeError):
    """An iterative solver stopped before reaching its tolerance."""

    def __init__(
        self, solver: str, iterations: int, residual: float, tolerance: float, hint: str = ""
    ) -> None:
        self.solver = solver
        self.iterations = iterations
        self.residual = residual
        self.tolerance = tolerance
        super().__init__(
            f"{solver} did not converge: residual {residual:.3e} > tolerance {tolerance:.1e} "
            f"after {iterations} iterations" + (f"; {hint}" if hint else "")
        )


class ImplausibleValueWarning(UserWarning):
    """A value is valid but physically implausible (a unit is likely missing)."""
