"""``solve`` over every model: the table of the models' solves.

The models and their names are in ``models``: ``cylinder`` (``solution.solve_cylinder``, with the
methods of ``backends.METHODS``) and ``half-space`` (``half_space.solve_half_space``, closed-form).
``MODEL_SOLVERS`` maps each name to its solve; adding a model is one entry here and one in
``histories.monotonic.MONOTONIC_MODELS`` (its monotonic solution for the memory rules).  This
module sits above both models, so that neither imports the other.
"""

from __future__ import annotations

from . import models
from .half_space import solve_half_space
from .solution import Solution, solve_cylinder

__all__ = ["solve", "MODEL_SOLVERS"]

#: model name -> its solve (same arguments as ``solve`` without ``model``).
MODEL_SOLVERS = {models.CYLINDER: solve_cylinder, models.HALF_SPACE: solve_half_space}


def solve(stick_radius=None, torque=None, *, method=None, n_terms=None, tolerance=None, model=None) -> Solution:
    """Solve the partial-slip torsion problem for a stick radius or a torque.

    Parameters
    ----------
    stick_radius : float, optional
        b/a in [0, 1] (1: the whole face sticks, T* = 1; 0: spinning, T* = 4/3).
        Gives a positive torque.
    torque : float, optional
        T* = 2T/(f F a) in [-4/3, 4/3].  Exactly one of ``stick_radius`` and
        ``torque`` must be given.
    method : {"fast", "complete", "published"}, optional
        ``solvers.abel_fredholm`` (default): the Abel-Fredholm method (the most accurate);
        ``published``: eq. (38) exactly as printed; ``complete``: the same weak form
        with the missing rigid-rotation mode.
    n_terms : int, optional
        Series methods: number of eigenfunctions, 1 to ``MAX_SERIES_TERMS`` = 10000
        (default 145, the paper's; memory ~16 N^2 bytes).  ``fast``: number of Dini terms
        for fields at z > 0, 1 to ``fields.MAX_FIELD_TERMS`` = 4096 (default: chosen per call).
    tolerance : float, optional
        Absolute accuracy of the stresses (f p0) and displacements (f p0 a / mu) off the
        interface; default 1e-12.  A figure needs ~1e-4 and sums fewer terms.
    model : {"cylinder", "half-space"}, optional
        ``cylinder`` (default): the two flat-ended cylinders.  ``half-space``: two
        elastically similar half-spaces under the same uniform pressure over r < a, in the
        same units (``half_space``; closed-form: no ``method``, no ``n_terms``); it slips
        at any torque (b < 1 for T* > 0) and ``rigid_rotation`` is the far-field rotation
        of each body, half the relative twist.

    Returns
    -------
    Solution

    Raises
    ------
    ValueError
        Naming the argument and its valid range, for non-finite or out-of-range
        numbers, |torque| > 4/3 (the cylinders spin: no static solution), both or
        neither of stick_radius/torque, n_terms outside [1, MAX_SERIES_TERMS] (weak
        forms) or [1, fields.MAX_FIELD_TERMS] (``fast``), tolerance not in [0, 1], an
        unknown method, or an inverse problem that the weak form's n_terms cannot resolve;
        an unknown model, or a method or n_terms with model="half-space".

    Warns
    -----
    AccuracyWarning (ResolutionWarning, IllConditioningWarning, TruncationWarning) and
    UnphysicalResultWarning, each naming what is lost; see the README.
    """
    model = models.validated(model, method, n_terms)
    return MODEL_SOLVERS[model](stick_radius, torque, method=method, n_terms=n_terms, tolerance=tolerance)
