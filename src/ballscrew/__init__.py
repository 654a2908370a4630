"""ballscrew: precision ball-screw simulation."""

__version__ = "0.1.0"
