"""Case section ``[kinematics]``: ball kinematics and the quasi-static ball balance."""

from __future__ import annotations

from ballscrew.case.base import Model


class KinematicsSpec(Model):
    """Options of the kinematics model (to be completed)."""
