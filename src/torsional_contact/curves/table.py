"""The shipped table of the monotonic curves (``monotonic_curves.json``): where it is and how it is read.

Units: b in a; T* = 2T/(f F a); omega in f p0 / mu; W_mono in (f p0)^2 a^3 / mu.

The table holds piecewise Chebyshev coefficients of T*(b), 4/3 - T*(b), omega(b) and W_mono(b)
on panels in b that are geometric toward both ends, and of b, omega and W_mono by torque.
It is built (a few minutes of Abel-Fredholm solves) by ``curves._precompute.build_table``,
which documents its layout and tolerances, and rebuilt with ``python -m torsional_contact.curves``;
``curves.interpolant`` evaluates it.  Its accuracy at points that are not nodes is measured by
tests/test_curves.py and by workflow/scripts/curve_accuracy.py.
"""

from __future__ import annotations

import json
import os

__all__ = ["TABLE_PATH", "FORMAT", "read_table"]

#: The shipped table.
TABLE_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "monotonic_curves.json")
#: Format number of the table file (``read_table`` refuses others).
FORMAT = 1


def read_table(path: str = TABLE_PATH) -> dict:
    """The table as written by ``_precompute.build_table.write_table``.

    Raises FileNotFoundError or ValueError (another format) if it is unusable.
    """
    with open(path, encoding="utf-8") as handle:
        table = json.load(handle)
    if table.get("format") != FORMAT:
        raise ValueError(f"{path}: curve table format {table.get('format')!r}, expected {FORMAT}")
    return table
