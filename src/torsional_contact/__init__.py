"""Frictional torsional contact of two elastically similar flat-ended cylinders.

The public surface: ``solve`` returns a ``Solution`` with the stick radius b/a, the torque
T* = 2T/(f F a), the rigid rotation omega (f p0 / mu), the regime and the fields;
``histories`` applies the memory rules to a torque history; ``Specimen`` speaks physical
units (pint at the boundary) and ``fit_loop`` turns a measured torque-twist loop into a
friction coefficient and a shear modulus.  Conventions, units, the Python API and the
command line are in docs/conventions.md; the warning categories (``TorsionalContactWarning``
and its subclasses, exported here) in ``diagnostics``.

Submodules are imported lazily, on first use of a name, so that ``import torsional_contact``
is cheap and a workflow script depends only on the modules it really uses.
"""

from __future__ import annotations

import importlib
from importlib import metadata as _metadata

try:
    __version__ = _metadata.version("torsional_contact")
except _metadata.PackageNotFoundError:  # pragma: no cover - running from a source tree without install
    __version__ = "0+unknown"

#: public name -> submodule that defines it
_EXPORTS = {
    "solve": "dispatch",
    "Solution": "solution",
    "torque_curve": "solution",
    "METHODS": "backends",
    "DEFAULT_METHOD": "backends",
    "DEFAULT_N_TERMS": "backends",
    "history": "histories",
    "Specimen": "specimen",
    "HalfSpace": "half_space.pressure_model",
    "fit_loop": "fitting",
    "SLIP_ONSET_TORQUE": "criteria",
    "GROSS_SLIP_TORQUE": "criteria",
    # every warning category of ``diagnostics`` (the README tells users to filter them by name)
    "TorsionalContactWarning": "diagnostics",
    "AccuracyWarning": "diagnostics",
    "IllConditioningWarning": "diagnostics",
    "ResolutionWarning": "diagnostics",
    "TruncationWarning": "diagnostics",
    "UnphysicalResultWarning": "diagnostics",
    "NoiseLimitedFitWarning": "diagnostics",
}

__all__ = [*_EXPORTS, "__version__"]


def __getattr__(name):
    if name in _EXPORTS:
        module = importlib.import_module(f".{_EXPORTS[name]}", __name__)
        value = getattr(module, name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(__all__))
