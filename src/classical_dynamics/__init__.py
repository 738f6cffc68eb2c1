"""Classical rigid-body dynamics and vibrations: solvers, models, scenes, studies and the report."""

__version__ = "0.1.0"
