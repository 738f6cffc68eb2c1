"""A module loaded on first use: a job imports only what its scene needs (sympy, numba, pandas cost 0.1-0.3 s
each at start-up, paid by every one of the pipeline's jobs otherwise)."""

from __future__ import annotations

import importlib.util
import sys


def lazy_module(name: str):
    """The module `name`, executed on its first attribute access (the LazyLoader recipe of importlib's
    docs)."""
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.find_spec(name)
    loader = importlib.util.LazyLoader(spec.loader)
    spec.loader = loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    loader.exec_module(module)
    return module
