"""``solve`` over every contact model: the model object of ``models.get`` solves.

The models are in the table ``models.MODELS`` (``contact_models``): ``cylinder`` (the default, with
the methods of ``backends.METHODS``), ``half-space`` and the others listed there.  This module sits
above every model, so that no model imports another.
"""

from __future__ import annotations

from . import models
from .solution import Solution

__all__ = ["solve"]


def solve(stick_radius=None, torque=None, *, method=None, n_terms=None, tolerance=None, model=None) -> Solution:
    """Solve the partial-slip torsion problem for a stick radius or a torque.

    Parameters
    ----------
    stick_radius : float, optional
        b/a in [0, 1] (1: the whole face sticks; 0: spinning).  Gives a positive torque.
    torque : float, optional
        T* = 2T/(f F a) in [-T*_gs, T*_gs], T*_gs the model's gross-slip torque (4/3 for the
        cylinders).  Exactly one of ``stick_radius`` and ``torque`` must be given.
    method : {"fast", "complete", "published"}, optional
        Cylinders only (``backends.METHODS``): ``fast`` (default), the Abel-Fredholm method (the most
        accurate); ``published``: eq. (38) exactly as printed; ``complete``: the same weak form
        with the missing rigid-rotation mode.  Models without methods refuse it.
    n_terms : int, optional
        Series methods: number of eigenfunctions, 1 to ``MAX_SERIES_TERMS`` = 10000
        (default 145, the paper's; memory ~16 N^2 bytes).  ``fast``: number of Dini terms for
        fields at z > 0, 1 to ``fields.MAX_FIELD_TERMS`` = 4096 (default: chosen per call).
    tolerance : float, optional
        Absolute accuracy of the stresses (f p0) and displacements (f p0 a / mu) off the
        interface; default 1e-12.  A figure needs ~1e-4 and sums fewer terms.
    model : str or ContactModel, optional
        A name of ``models.MODELS`` ("cylinder", the default: the two flat-ended cylinders;
        "half-space": two half-spaces under the same uniform pressure, ...) or a model object
        (``contact_models.base.ContactModel``).  Every model speaks the same units
        (docs/conventions.md); ``rigid_rotation`` is the rotation of one body's stick zone
        relative to its remote points.

    Returns
    -------
    Solution

    Raises
    ------
    ValueError
        Naming the argument and its valid range, for non-finite or out-of-range
        numbers, |torque| above the model's gross-slip torque (the bodies spin: no static
        solution), both or neither of stick_radius/torque, n_terms outside [1, MAX_SERIES_TERMS] (weak
        forms) or [1, fields.MAX_FIELD_TERMS] (``fast``), tolerance not in [0, 1], an
        unknown method, or an inverse problem that the weak form's n_terms cannot resolve;
        an unknown model, or a method or n_terms with a model that has no methods.

    Warns
    -----
    AccuracyWarning (ResolutionWarning, IllConditioningWarning, TruncationWarning) and
    UnphysicalResultWarning, each naming what is lost; see the README.
    """
    return models.get(model).solve(stick_radius, torque, method=method, n_terms=n_terms, tolerance=tolerance)
