"""Rebuild the shipped table of the monotonic curves: ``python -m torsional_contact.curves``."""

from ._precompute.build_table import main

main()
