"""The contact models and the one place that dispatches on them.

* ``cylinder`` (default): two elastically similar flat-ended cylinders of radius a, the
  paper's problem (``solution``, methods ``fast``, ``complete``, ``published``).
* ``half-space``: two elastically similar half-spaces pressed together over the disc
  r < a by the same uniform pressure (``half_space``; closed-form, no method).

``validated`` checks a model name against its options; ``monotonic_model`` returns the
monotonic solution of a model as the memory rules of ``histories`` use it: an object with
``model``, ``method``, ``n_terms`` and

    point(tau)    -> (b, omega_m, W_mono)      at one torque 0 <= tau <= 4/3,
    points(tau)   -> arrays b, omega_m, W_mono  for an array of torques,
    solution(tau) -> the monotonic ``Solution`` mono(tau) (cached),

(``histories.monotonic.CylinderMonotonic``, ``half_space.HalfSpaceMonotonic``).  ``solve``
dispatches its own call (``solution.solve``).
"""

from __future__ import annotations

import functools

from . import validation

__all__ = ["CYLINDER", "HALF_SPACE", "MODELS", "DEFAULT_MODEL", "validated", "monotonic_model"]

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


def monotonic_model(model=None, method=None, n_terms=None):
    """The monotonic solution of ``model`` for the memory rules (see the module docstring).

    ``method`` and ``n_terms`` as for ``history`` (cylinder only); the objects are shared
    (cached) per resolved (model, method, n_terms).

    Raises
    ------
    ValueError
        For an unknown model, a method or n_terms with the half-space model, or a bad
        method / n_terms of the cylinder model.
    """
    model = validated(model, method, n_terms)
    if model == HALF_SPACE:
        return _half_space()
    from .histories.monotonic import resolve

    return _cylinder(*resolve(method, n_terms))


@functools.lru_cache(maxsize=1)
def _half_space():
    from .half_space import HalfSpaceMonotonic

    return HalfSpaceMonotonic()


@functools.lru_cache(maxsize=64)
def _cylinder(method: str, n_terms):
    from .histories.monotonic import CylinderMonotonic

    return CylinderMonotonic(method, n_terms)
