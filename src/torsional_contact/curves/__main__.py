"""Rebuild the shipped table of the monotonic curves: ``python -m torsional_contact.curves``."""

from .table import _main

_main()
