"""The optional parts of the package and the packages each needs (``pip install 'torsional_contact[extra]'``).

The core (``solve``, ``history``, ``Specimen``, ``fit_loop`` and the command-line subcommands
``solve``, ``history`` and ``fit``) needs numpy, scipy and pint only.  The extras:

* ``reference``: mpmath and python-flint, the arbitrary-precision verification wing
  (``verification``; subcommands ``reference`` and ``errata``);
* ``fem``: scikit-fem, the finite-element check (``verification.finite_element``);
* ``progress``: tqdm, progress bars of long computations (without it they run silently);
* ``workflow``: everything the Snakemake workflow needs (environment.txt pins the versions).

``require`` checks an extra before the work starts; ``extra_for`` names the extra that holds
a missing module, so that the command line can say what to install.
"""

from __future__ import annotations

import importlib.util

__all__ = ["EXTRAS", "MissingExtraError", "require", "extra_for", "install_hint"]

#: extra -> the modules it provides (import names; the distributions are in pyproject.toml).
EXTRAS = {
    "reference": ("mpmath", "flint"),
    "fem": ("skfem",),
    "progress": ("tqdm",),
}


class MissingExtraError(ImportError):
    """An optional package is not installed; the message names the extra that installs it."""


def install_hint(extra: str) -> str:
    """The pip command that installs ``extra``."""
    return f"pip install 'torsional_contact[{extra}]'"


def extra_for(module: str) -> str | None:
    """The extra whose packages include the top-level module of ``module`` (dotted), or None."""
    top = module.split(".")[0]
    return next((extra for extra, modules in EXTRAS.items() if top in modules), None)


def require(extra: str, what: str) -> None:
    """Raise ``MissingExtraError`` naming ``what`` and the install command unless every module of ``extra`` imports."""
    missing = [name for name in EXTRAS[extra] if importlib.util.find_spec(name) is None]
    if missing:
        raise MissingExtraError(f"{what} needs the optional package(s) {', '.join(missing)}, not installed: "
                                f"{install_hint(extra)}")
