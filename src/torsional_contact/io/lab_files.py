"""Laboratory export files: the columns a computation needs, found by name, read into SI arrays.

A lab file looks like any of::

    time [s],torque [N m],twist [mrad]          Rig: torsion 3
    0.000,0.0000,0.00000                        Datum: 12.03.2025
    0.005,0.0471,0.02010                        Zeit [s];Drehmoment [N·m];Winkel [°]
    ...                                         0,000;0,0000;0,00000
                                                ...

The table itself (encoding, separator, decimal mark, metadata lines above the header) is read
by ``io.text_tables``.  Here each column the caller asks for (a *role*: ``time``, ``torque``,
``twist``) is found in the header, whose cells are ``name [unit]`` or ``name (unit)``:

* by the name given (``columns={"twist": "Winkel"}``; ``--twist-column NAME`` on the command
  line): the header cell's name or its whole text, in any case;
* else by the role's name or an unambiguous synonym (``SYNONYMS``, any case): ``twist``, ``angle``,
  ``rotation``, ``Winkel``...; ``torque``, ``moment``, ``Drehmoment``...; ``time``, ``Zeit``.  Two
  columns that could be the one asked for, or none, is a one-line ValueError naming the option
  that says which.

Units are read with the grammar of ``units`` (as a unit, never evaluated), case-insensitively
where unambiguous (``[Deg]``, ``[DEG]``, ``[RAD]``, ``[N-m]``, ``[°]``); a unit of another
dimension, or ``%`` for the twist, is refused naming the column.  Every row holds a finite number
in every column read; a time column must increase strictly from row to row.

Any violation is a ValueError naming the file, the line and the column, before anything is
computed or written.  ``read_lab_columns`` also returns the ``report`` of what it read (file
SHA-256, encoding, separator, decimal mark, skipped lines, header, rows, the columns chosen and
their units as written), for the provenance of results.
"""

from __future__ import annotations

import math
import re

import numpy as np

from .. import units
from ..units import shown_text
from .text_tables import read_text_table

__all__ = ["read_lab_columns", "LAB_COLUMN_KINDS", "SYNONYMS", "COLUMN_OPTIONS"]

#: Column roles a lab file may carry, and the kind of quantity each is.
LAB_COLUMN_KINDS = {"time": "time", "torque": "torque", "twist": "angle"}

#: Header names that mean a role (lower case; a cell's name is compared whole, blanks collapsed).
SYNONYMS = {
    "time": ("time", "zeit", "elapsed time", "test time", "temps", "tiempo"),
    "torque": ("torque", "moment", "torsional moment", "torque moment", "drehmoment", "torsionsmoment", "couple"),
    "twist": ("twist", "angle", "rotation", "twist angle", "rotation angle", "angle of twist", "torsion angle",
              "winkel", "drehwinkel", "verdrehwinkel", "torsionswinkel", "verdrehung"),
}

#: The command-line option that names each role's column.
COLUMN_OPTIONS = {role: f"--{role}-column" for role in LAB_COLUMN_KINDS}

_HEADER_CELL = re.compile(r"^\s*(.*?)\s*(?:\[([^\]]*)\]|\(([^)]*)\))?\s*$", re.DOTALL)


def _cell(text: str) -> tuple[str, str | None]:
    """(name, unit or None) of a header cell."""
    match = _HEADER_CELL.match(text)
    name = " ".join(match.group(1).split())
    unit = match.group(2) if match.group(2) is not None else match.group(3)
    return name, unit


def _choose(label: str, role: str, cells: list[tuple[str, str | None]], header: list[str], given) -> int | None:
    """The index of ``role``'s column, or None (absent); ValueError for a name that is not there or two
    candidates."""
    listed = ", ".join(shown_text(c, 40) for c in header)
    option = COLUMN_OPTIONS[role]
    if given is not None:
        wanted = " ".join(str(given).split()).casefold()
        hits = [j for j, (name, _) in enumerate(cells) if wanted in (name.casefold(), " ".join(header[j].split())
                                                                     .casefold())]
        if len(hits) != 1:
            what = "no" if not hits else f"{len(hits)}"
            raise ValueError(f"{option} {shown_text(given)}: {what} column of that name (the header names {listed})")
        return hits[0]
    hits = [j for j, (name, _) in enumerate(cells) if name.casefold() in SYNONYMS[role]]
    if len(hits) > 1:
        raise ValueError(f"{label}: columns {', '.join(shown_text(header[j], 40) for j in hits)} could each be the "
                         f"{role}: say which with {option} NAME")
    return hits[0] if hits else None


def read_lab_columns(path, required, optional=(), *, label: str | None = None, min_rows: int = 1,
                     columns: dict | None = None, encoding: str | None = None) -> dict:
    """The columns ``required`` (and those of ``optional`` present) of a lab export, in SI units.

    Parameters
    ----------
    path : str or path
    required, optional : sequences of roles (keys of ``LAB_COLUMN_KINDS``)
    label : str
        How the file is named in error messages (default: its path).
    min_rows : int
        Fewest data rows accepted.
    columns : dict, optional
        role -> the header name of its column (``--time-column``, ``--torque-column``,
        ``--twist-column``), for headers whose names are not the roles' or their synonyms.
    encoding : str, optional
        The file's text encoding (default: UTF-8, else Windows-1252).

    Returns
    -------
    dict
        role -> float array in SI units (s, N m, rad); ``"units"``: role -> unit as written;
        ``"report"``: what was read (module docstring).

    Raises
    ------
    ValueError
        Unreadable or binary file; no header (the first line is numbers); a column missing, two
        candidates for one, or one without a unit; a unit outside the grammar or of the wrong
        dimension; a row with another number of fields; a cell that is not a finite number; a
        time that does not increase; fewer than ``min_rows`` rows.
    """
    columns = dict(columns or {})
    unknown = set(columns) - set(LAB_COLUMN_KINDS)
    if unknown:
        raise ValueError(f"columns: unknown role(s) {', '.join(sorted(unknown))} "
                         f"(one of {', '.join(LAB_COLUMN_KINDS)})")
    table = read_text_table(path, label=label, encoding=encoding)
    label = table.label
    if table.header is None:
        raise ValueError(f"{label} line {table.rows[0][0]}: no header: the first line holds numbers; name the columns "
                         f"with their units, e.g. 'torque [N m],twist [rad]'")
    where = f"{label} line {table.header_line}"
    cells = [_cell(text) for text in table.header]
    wanted = [(role, True) for role in required] + [(role, False) for role in optional]
    chosen = {}
    for role, needed in wanted:
        j = _choose(label, role, cells, table.header, columns.get(role))
        if j is None:
            if needed:
                raise ValueError(f"{where}: no {role} column (the header names "
                                 f"{', '.join(shown_text(c, 40) for c in table.header)}): say which with "
                                 f"{COLUMN_OPTIONS[role]} NAME, or name it e.g. "
                                 f"'{role} [{units.si_unit(LAB_COLUMN_KINDS[role])}]'")
            continue
        if j in [k for k, _, _ in chosen.values()]:
            other = next(r for r, (k, _, _) in chosen.items() if k == j)
            raise ValueError(f"{where}: column {shown_text(table.header[j], 40)} cannot be both the {other} and the "
                             f"{role}: say which with {COLUMN_OPTIONS[role]} NAME")
        name, unit = cells[j]
        kind = LAB_COLUMN_KINDS[role]
        if unit is None or not unit.strip():
            raise ValueError(f"{where}: column {shown_text(table.header[j], 40)} ({role}) has no unit: write it in "
                             f"brackets, e.g. '{name or role} [{units.si_unit(kind)}]'")
        factor = units.parse_unit(f"{where}: column {shown_text(table.header[j], 40)} ({role}) unit", unit, kind)
        chosen[role] = (j, factor, unit.strip())
    if len(table.rows) < min_rows:
        raise ValueError(f"{label}: {len(table.rows)} data rows, at least {min_rows} needed")
    out = {}
    for role, (j, factor, _) in chosen.items():
        raw = table.column(j, table.header[j])
        bad = ~np.isfinite(raw)
        if bad.any():
            i = int(np.argmax(bad))
            raise ValueError(f"{label} line {table.rows[i][0]}: column {shown_text(table.header[j], 40)}: "
                             f"{shown_text(table.rows[i][1][j], 40)} is not a finite number")
        values = raw * factor
        big = ~np.isfinite(values) | (np.abs(values) > units.MAX_MAGNITUDE)
        if big.any():
            i = int(np.argmax(big))
            raise ValueError(f"{label} line {table.rows[i][0]}: column {shown_text(table.header[j], 40)}: "
                             f"{shown_text(table.rows[i][1][j], 40)} exceeds {units.MAX_MAGNITUDE:g} "
                             f"{units.si_unit(LAB_COLUMN_KINDS[role])} in magnitude")
        out[role] = values
    if "time" in out and out["time"].size > 1:
        step = np.diff(out["time"])
        if np.any(step <= 0):
            r = int(np.argmax(step <= 0)) + 1
            raise ValueError(f"{label} line {table.rows[r][0]}: time {float(out['time'][r]):.9g} s does not increase "
                             f"(previous {float(out['time'][r - 1]):.9g} s): samples must be in time order")
    out["units"] = {role: unit for role, (_, _, unit) in chosen.items()}
    out["report"] = {**table.report(), "columns": {
        role: {"header": table.header[j], "unit": unit, "to_si": factor if math.isfinite(factor) else None,
               "si_unit": units.si_unit(LAB_COLUMN_KINDS[role])}
        for role, (j, factor, unit) in chosen.items()}}
    return out
