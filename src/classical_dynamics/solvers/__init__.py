"""Shared numerical layer: eigen-solvers, integrators, exact references, work-precision harness."""
