"""The table of contact models: one object per model (``contact_models.base.ContactModel``), by name.

=================  ===========================================================================
name               model
=================  ===========================================================================
``cylinder``       two elastically similar flat-ended cylinders, uniform pressure (default;
                   ``contact_models.cylinder``)
``half-space``     two elastically similar half-spaces, uniform pressure (``half_space.model``)
``hertz``          two elastically similar bodies, Hertzian pressure: a sphere on a flat
                   (``half_space.pressure_model``)
``flat-punch``     a rigid flat punch on an elastic half-space (``half_space.pressure_model``)
=================  ===========================================================================

This is the only module that compares a model's name: everything else asks the model object
(``get``) for what it needs.  ``get`` also accepts a ``ContactModel`` itself (e.g. one built by
``HalfSpace(pressure=...)``, or a model of the user's own), so a model need not be in the table
to be used from Python; ``register`` puts one in the table, which makes it known by name (the
command line's ``--model`` and JSON's ``model``).  Adding a model to the package is one module
and one entry in ``_BUILT_IN`` below.
"""

from __future__ import annotations

from .contact_models.base import ContactModel
from .contact_models.cylinder import CYLINDER
from .half_space.model import UNIFORM_HALF_SPACE
from .half_space.pressure_model import FLAT_PUNCH, HERTZ

__all__ = ["MODELS", "DEFAULT_MODEL", "get", "register", "unregister", "names", "validated", "ContactModel"]

#: The models of the package, in the order the documents list them; the first is the default.
_BUILT_IN = (CYLINDER, UNIFORM_HALF_SPACE, HERTZ, FLAT_PUNCH)

#: name -> model object: every model known by name.
MODELS: dict[str, ContactModel] = {model.name: model for model in _BUILT_IN}

#: The name of the default model.
DEFAULT_MODEL = CYLINDER.name


def names() -> tuple[str, ...]:
    """The names of the models in the table, the default first."""
    return tuple(MODELS)


def get(model=None) -> ContactModel:
    """The model object for ``model``: None (the default), a name of ``MODELS`` or a ``ContactModel``.

    Raises
    ------
    ValueError
        Naming ``model`` and the names it may take.
    """
    if model is None:
        return MODELS[DEFAULT_MODEL]
    if isinstance(model, ContactModel):
        return model
    if isinstance(model, str) and model in MODELS:
        return MODELS[model]
    raise ValueError(f"model must be one of {', '.join(repr(n) for n in MODELS)} or a ContactModel, got {model!r}")


def validated(model=None, method=None, n_terms=None) -> ContactModel:
    """``get(model)``, after checking that the model takes ``method`` and ``n_terms`` (ValueError naming them)."""
    contact = get(model)
    contact.options(method, n_terms)
    return contact


def register(model: ContactModel, *, replace: bool = False) -> ContactModel:
    """Put ``model`` in the table under ``model.name``; ValueError if the name is taken (unless ``replace``)."""
    if not isinstance(model, ContactModel):
        raise ValueError(f"model must be a ContactModel, got {model!r}")
    if not isinstance(model.name, str) or not model.name.strip():
        raise ValueError(f"a registered model needs a non-empty name, got {model.name!r}")
    if model.name in MODELS and MODELS[model.name] is not model and not replace:
        raise ValueError(f"a model named {model.name!r} is already in the table (replace=True replaces it)")
    MODELS[model.name] = model
    return model


def unregister(name: str) -> None:
    """Remove the model ``name`` from the table (the package's own models stay)."""
    if any(model.name == name for model in _BUILT_IN):
        raise ValueError(f"model {name!r} is one of the package's own models and stays in the table")
    MODELS.pop(name, None)
