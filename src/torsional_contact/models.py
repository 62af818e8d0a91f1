"""The contact models: their names and the check of a model's options.

* ``cylinder`` (default): two elastically similar flat-ended cylinders of radius a, the
  paper's problem (``solution.solve_cylinder``, methods ``backends.METHODS``).
* ``half-space``: two elastically similar half-spaces pressed together over the disc
  r < a by the same uniform pressure (``half_space``; closed-form, no method).

``validated`` checks a model name against its options.  The dispatch on the model (``solve``,
``monotonic_model``) is in ``dispatch``, above both models; this module imports neither.
"""

from __future__ import annotations

from . import validation

__all__ = ["CYLINDER", "HALF_SPACE", "MODELS", "DEFAULT_MODEL", "validated"]

CYLINDER = "cylinder"
HALF_SPACE = "half-space"
#: Every model ``solve`` and ``history`` accept; the first is the default.
MODELS = (CYLINDER, HALF_SPACE)
DEFAULT_MODEL = CYLINDER


def validated(model, method=None, n_terms=None) -> str:
    """The model name (default ``cylinder``), or ValueError naming it (and ``method``/``n_terms``,
    which apply to the cylinder model only)."""
    model = validation.choice("model", DEFAULT_MODEL if model is None else model, MODELS)
    if model != CYLINDER:
        for name, value in (("method", method), ("n_terms", n_terms)):
            if value is not None:
                raise ValueError(f"{name}={value!r} applies to model='cylinder' only; model={model!r} is closed-form "
                                 f"(omit {name})")
    return model
