"""Analyses: compose geometry, loads and physics models into the runs the CLI offers."""
