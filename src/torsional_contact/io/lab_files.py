"""Laboratory CSV files: columns whose header names their units in brackets, read into SI arrays.

A lab file looks like::

    # any comment lines (test conditions, the rig, ...)
    time [s],torque [N m],twist [mrad]
    0.000,0.0000,0.00000
    0.005,0.0471,0.02010
    ...

* The first line that is neither blank nor a comment (``#``) is the header; every column the
  caller asks for must be named there as ``name [unit]`` (or ``name (unit)``), names in any
  case.  Units are read by pint (``units``): "N m", "N*m", "N·m", "Nm", "kN m", "N mm",
  "rad", "mrad", "urad", "deg", "s", "ms"...  Other columns are ignored.
* Fields are separated by commas (or semicolons, or tabs, as the header shows).
* Every row holds a finite number in every column read; a time column must increase
  strictly from row to row.

Any violation is a ValueError naming the file, the line and the column, before anything is
computed or written.  Only the standard library's csv module is used.
"""

from __future__ import annotations

import csv
import math
import os
import re

import numpy as np

from .. import units

__all__ = ["read_lab_columns", "LAB_COLUMN_KINDS"]

#: Column names a lab file may carry, and the kind of quantity each is.
LAB_COLUMN_KINDS = {"time": "time", "torque": "torque", "twist": "angle"}

_HEADER_CELL = re.compile(r"^\s*([A-Za-z_][\w ]*?)\s*(?:\[(.*)\]|\((.*)\))?\s*$")


def _delimiter(line: str) -> str:
    for candidate in (",", ";", "\t"):
        if candidate in line:
            return candidate
    return ","


def read_lab_columns(path, required, optional=(), *, label: str | None = None, min_rows: int = 1) -> dict:
    """The columns ``required`` (and those of ``optional`` present) of a lab CSV, in SI units.

    Parameters
    ----------
    path : str or path
    required, optional : sequences of column names (keys of ``LAB_COLUMN_KINDS``)
    label : str
        How the file is named in error messages (default: its path).
    min_rows : int
        Fewest data rows accepted.

    Returns
    -------
    dict
        name -> float array in SI units (s, N m, rad), plus ``"units"``: name -> unit as written.

    Raises
    ------
    ValueError
        Unreadable file; no header (the first line is numbers); a required column missing or
        without a unit; a unit pint cannot read or of the wrong dimension; a cell that is not
        a finite number; a time that does not increase; fewer than ``min_rows`` rows.
    """
    path = os.fspath(path)
    label = label or path
    try:
        with open(path, encoding="utf-8-sig", newline="") as handle:
            lines = handle.read().splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        raise ValueError(f"{label}: cannot read ({getattr(exc, 'strerror', None) or exc})") from None
    content = [(n, line) for n, line in enumerate(lines, start=1) if line.strip() and not line.lstrip().startswith("#")]
    if not content:
        raise ValueError(f"{label}: no header and no data (expected a header such as 'time [s],torque [N m]')")
    header_line, header = content[0]
    delimiter = _delimiter(header)
    cells = next(csv.reader([header], delimiter=delimiter))
    if all(_is_number(c) for c in cells):
        raise ValueError(f"{label} line {header_line}: no header: the first line holds numbers; name the columns "
                         f"with their units, e.g. 'time [s],torque [N m]'")
    columns = {}
    for j, cell in enumerate(cells):
        match = _HEADER_CELL.match(cell)
        if not match:
            continue
        name = match.group(1).strip().lower()
        unit = match.group(2) if match.group(2) is not None else match.group(3)
        if name in columns:
            raise ValueError(f"{label} line {header_line}: column {name!r} appears twice")
        columns[name] = (j, unit)
    wanted = [(name, True) for name in required] + [(name, False) for name in optional]
    chosen = {}
    for name, needed in wanted:
        if name not in columns:
            if needed:
                raise ValueError(f"{label} line {header_line}: no column {name!r} (the header names "
                                 f"{', '.join(repr(c) for c in cells)}; expected e.g. "
                                 f"'{name} [{units.si_unit(LAB_COLUMN_KINDS[name])}]')")
            continue
        j, unit = columns[name]
        if unit is None or not unit.strip():
            raise ValueError(f"{label} line {header_line}: column {name!r} has no unit: write it in brackets, e.g. "
                             f"'{name} [{units.si_unit(LAB_COLUMN_KINDS[name])}]'")
        factor = units.parse_unit(f"{label} line {header_line}: column {name!r} unit", unit,
                                  LAB_COLUMN_KINDS[name])
        chosen[name] = (j, factor, unit.strip())
    rows = content[1:]
    if len(rows) < min_rows:
        raise ValueError(f"{label}: {len(rows)} data rows, at least {min_rows} needed")
    out = {name: np.empty(len(rows)) for name in chosen}
    for r, (n, line) in enumerate(rows):
        fields = next(csv.reader([line], delimiter=delimiter))
        for name, (j, factor, _) in chosen.items():
            text = fields[j].strip() if j < len(fields) else ""
            try:
                value = float(text)
            except ValueError:
                raise ValueError(f"{label} line {n}: column {name!r}: {text[:40]!r} is not a number") from None
            if not math.isfinite(value):
                raise ValueError(f"{label} line {n}: column {name!r}: {text!r} is not a finite number")
            out[name][r] = value * factor
    if "time" in out and out["time"].size > 1:
        step = np.diff(out["time"])
        if np.any(step <= 0):
            r = int(np.argmax(step <= 0)) + 1
            raise ValueError(f"{label} line {rows[r][0]}: time {float(out['time'][r]):.9g} s does not increase "
                             f"(previous {float(out['time'][r - 1]):.9g} s): samples must be in time order")
    out["units"] = {name: unit for name, (_, _, unit) in chosen.items()}
    return out


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True
