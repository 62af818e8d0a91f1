"""The optional parts of the package and the packages each needs (``pip install 'torsional_contact[extra]'``).

The core (``solve``, ``history``, ``Specimen``, ``fit_loop`` and the command-line subcommands
``solve``, ``history`` and ``fit``) needs numpy, scipy and pint only.  The extras:

* ``reference``: mpmath and python-flint, the arbitrary-precision verification wing
  (``verification``; subcommands ``reference`` and ``errata``);
* ``fem``: scikit-fem, the finite-element check (``verification.finite_element``);
* ``progress``: tqdm, progress bars of long computations (without it they run silently);
* ``plots``: matplotlib, the figures (the workflow's, and ``fit --plot``);
* ``workflow``: everything the Snakemake workflow needs (environment.txt pins the versions).

``require`` checks an extra before the work starts; ``extra_for`` names the extra that holds
a missing module, so that the command line can say what to install.  Messages name the packages as
PyPI (and pip) knows them (python-flint, scikit-fem), not their import names (flint, skfem).
"""

from __future__ import annotations

import importlib.util

__all__ = ["EXTRAS", "DISTRIBUTIONS", "MissingExtraError", "require", "extra_for", "install_hint", "distribution",
           "missing_message"]

#: extra -> the modules it provides (import names; the distributions are in pyproject.toml).
EXTRAS = {
    "reference": ("mpmath", "flint"),
    "fem": ("skfem",),
    "progress": ("tqdm",),
    "plots": ("matplotlib",),
}

#: import name -> the package's name on PyPI, where they differ.
DISTRIBUTIONS = {"flint": "python-flint", "skfem": "scikit-fem"}


class MissingExtraError(ImportError):
    """An optional package is not installed; the message names the extra that installs it."""


def install_hint(extra: str) -> str:
    """The pip command that installs ``extra``."""
    return f"pip install 'torsional_contact[{extra}]'"


def distribution(module: str) -> str:
    """The PyPI name of the package that provides the top-level module of ``module``."""
    top = module.split(".")[0]
    return DISTRIBUTIONS.get(top, top)


def missing_message(what: str, modules, extra: str) -> str:
    """One line: ``what`` needs the packages of ``modules`` (PyPI names), and the pip command of ``extra``."""
    names = ", ".join(distribution(m) for m in modules)
    return f"{what} needs the optional package(s) {names}, not installed: {install_hint(extra)}"


def extra_for(module: str) -> str | None:
    """The extra whose packages include the top-level module of ``module`` (dotted), or None."""
    top = module.split(".")[0]
    return next((extra for extra, modules in EXTRAS.items() if top in modules), None)


def require(extra: str, what: str) -> None:
    """Raise ``MissingExtraError`` naming ``what`` and the install command unless every module of ``extra`` imports."""
    missing = [name for name in EXTRAS[extra] if importlib.util.find_spec(name) is None]
    if missing:
        raise MissingExtraError(missing_message(what, missing, extra))
