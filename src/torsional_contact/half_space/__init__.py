"""Two elastically similar half-spaces under the same uniform pressure: the comparison model.

``solve(..., model="half-space")`` and ``history(..., model="half-space")`` return the same
state classes as the cylinder model, in the same units (docs/conventions.md).  The
derivation (Jaeger's superposition of Reissner-Sagoci rigid-disc rotations) and the closed
forms (H1)-(H14) are in ``half_space.closed_form`` (the interface fields (H7)-(H9) in
``half_space.interface``); the fields in the bodies (a verified
quadrature of the superposition) in ``half_space.fields``; the state classes and the
contact model (``UniformHalfSpace``, entry "half-space" of ``models.MODELS``) in ``half_space.model``.
"""

from . import closed_form
from .model import MODEL, UNIFORM_HALF_SPACE, HalfSpaceSolution, HalfSpaceState, UniformHalfSpace

__all__ = ["MODEL", "closed_form", "UNIFORM_HALF_SPACE", "UniformHalfSpace", "HalfSpaceSolution", "HalfSpaceState"]
