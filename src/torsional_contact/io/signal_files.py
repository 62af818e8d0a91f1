"""Torque signals on disk: reading a text/CSV file or a ``.npy`` array, writing per-sample tables.

Units: T* = 2T/(f F a); omega in f p0 / mu; energies in (f p0)^2 a^3 / mu.

Reading is strict.  Text: blank lines and lines starting with ``#`` are skipped; the first
remaining line is a header (column names) when one of its fields is not a number; fields are
separated by commas, semicolons, tabs or blanks (the first line decides).  One column is read
as it is; of several, ``column`` chooses one (a number from 1, or a header name).  Every value
of the column must be a finite number in [-4/3, 4/3]; the first that is not is named, with its
line, in the ValueError.  ``.npy``: a 1-d array, or a 2-d one whose ``column`` is read.
Writing formats the numbers column by column with integer arithmetic (16 significant
digits, relative rounding error below 1e-15), which is an order of magnitude faster than
per-number string formatting for the 10^6-row tables of long signals.

Tables of named columns (``write_table``) take their format from the file name: ``.npz``
(one array per column, exact doubles, plus a ``metadata`` entry: the provenance as a JSON
string), ``.npy`` (one structured array, a field per column, no metadata), anything else
CSV (a header of the column names, then the rows).  The binary formats are written and read
in milliseconds for 10^6 rows and keep every bit; CSV is for people and spreadsheets.
"""

from __future__ import annotations

import os

import numpy as np

from .. import models, validation
from ..units import shown_text

__all__ = ["read_signal", "format_columns", "write_sample_table", "table_format", "write_table", "read_table"]

_EXPECTED = ("expected one torque T* in [-4/3, 4/3] per line, or a CSV column chosen with --column N|NAME; "
             "a first line of names is a header; blank lines and lines starting with # are skipped")
_DELIMITERS = (b",", b";", b"\t")


def _check_values(label: str, values: np.ndarray, where, model=None) -> np.ndarray:
    """Finite torques within the model's gross-slip torque ([-4/3, 4/3] for the cylinders; clipped by
    rounding), or ValueError naming ``where(i)``."""
    if values.size == 0:
        raise ValueError(f"{label}: no samples ({_EXPECTED})")
    contact = models.get(model)
    gross, text = contact.gross_slip_torque, contact.gross_slip_text
    limit = gross * (1.0 + validation.TORQUE_TOLERANCE)
    bad = ~(np.abs(values) <= limit)
    if bad.any():
        i = int(np.argmax(bad))
        v = float(values[i])
        problem = "is not finite" if not np.isfinite(v) else (
            f"lies outside [-{text}, {text}] (beyond {text} {contact.bodies} spin: no static solution)")
        raise ValueError(f"{label} {where(i)}: {v!r} {problem}")
    return np.clip(values, -gross, gross)


def _column_number(label: str, column, count: int, names: list[str] | None) -> int:
    """The 0-based index of ``column`` (a number from 1 or a header name) among ``count`` columns."""
    if column is None:
        if count == 1:
            return 0
        listed = ", ".join(shown_text(name, 40) for name in names) if names else f"1 to {count}"
        raise ValueError(f"{label}: {count} columns ({listed}): choose the torque with --column N|NAME "
                         "(column= in Python)")
    text = str(column).strip()
    if isinstance(column, (int, np.integer)) or text.isdigit():
        number = int(text)
        if not 1 <= number <= count:
            raise ValueError(f"--column must be a column number in [1, {count}] (columns count from 1) "
                             f"for {label}, got {column!r}")
        return number - 1
    if names is None:
        raise ValueError(f"--column {shown_text(text)} is a name, but {label} has no header line (give a number in "
                         f"[1, {count}])")
    if text not in names:
        raise ValueError(f"--column must be a column number in [1, {count}] or one of the header's names "
                         f"({', '.join(shown_text(name, 40) for name in names)}) for {label}, got {shown_text(text)}")
    return names.index(text)


def _read_npy(label: str, path: str, column=None, model=None) -> np.ndarray:
    try:
        array = np.load(path, allow_pickle=False)
    except (OSError, ValueError, EOFError) as exc:
        raise ValueError(f"{label}: cannot read a .npy array ({exc})") from None
    if array.dtype.kind not in "fiu" or array.ndim not in (1, 2):
        raise ValueError(f"{label}: expected a 1-d array of real numbers (T*) or a 2-d one with --column, got "
                         f"dtype {array.dtype} and shape {array.shape}")
    if array.ndim == 2:
        if array.shape[1] == 0:
            raise ValueError(f"{label}: no samples (shape {array.shape})")
        j = _column_number(label, column, array.shape[1], None)
        return _check_values(label, array[:, j].astype(float), lambda i: f"element [{i}, {j}]", model)
    if column is not None:
        _column_number(label, column, 1, None)
    return _check_values(label, array.astype(float), lambda i: f"element {i}", model)


def _fields(line: bytes, delimiter: bytes | None) -> list[bytes]:
    return [field.strip().strip(b'"').strip() for field in line.split(delimiter)]


def _is_number(field: bytes) -> bool:
    try:
        float(field)
    except ValueError:
        return False
    return True


def _read_text(label: str, path: str, column=None, model=None) -> np.ndarray:
    from .text_tables import read_text_bytes

    data = read_text_bytes(path, label, "not a text file of T* samples (a .npy array is read by its extension; "
                                        f"{_EXPECTED})")
    lines = data.removeprefix(b"\xef\xbb\xbf").split(b"\n")  # a UTF-8 byte-order mark is no part of a sample
    if lines and not lines[-1].strip():
        lines.pop()
    if column is None:
        try:  # every line a number: the fast path
            values = np.fromiter(map(float, lines), dtype=float, count=len(lines))
        except ValueError:  # comments, a header, several columns or a bad line: read as a table below
            values = None
        if values is not None:
            return _check_values(label, values, lambda i: f"line {i + 1}", model)
    return _read_table(label, lines, column, model)


def _read_table(label: str, lines: list[bytes], column, model=None) -> np.ndarray:
    """A table with an optional header; ValueError naming the first line that does not hold a number."""
    content = [n for n, raw in enumerate(lines) if raw.strip() and not raw.lstrip().startswith(b"#")]
    if not content:
        raise ValueError(f"{label}: no samples ({_EXPECTED})")
    first = lines[content[0]].strip()
    delimiter = next((d for d in _DELIMITERS if d in first), None)
    fields = _fields(first, delimiter)
    names = None
    if not all(_is_number(f) for f in fields):
        names = [f.decode("utf-8", errors="replace") for f in fields]
        content = content[1:]
        if not content:
            raise ValueError(f"{label}: a header line and no samples ({_EXPECTED})")
    j = _column_number(label, column, len(fields), names)
    body = [lines[n] for n in content]
    try:  # numpy's parser: fast; its message is replaced by ours, naming the line, below
        values = np.loadtxt(body, delimiter=None if delimiter is None else delimiter.decode(), usecols=j,
                            comments=None, quotechar='"', dtype=float, ndmin=1)
    except ValueError:
        values = None
    if values is None or values.size != len(body):
        values = np.empty(len(body))
        for k, n in enumerate(content):
            row = _fields(lines[n].strip(), delimiter)
            where = f"{label} line {n + 1}"
            if j >= len(row):
                raise ValueError(f"{where}: {len(row)} field(s), column {j + 1} wanted ({_EXPECTED})")
            try:
                values[k] = float(row[j])
            except ValueError:
                shown = row[j].decode("utf-8", errors="replace")
                raise ValueError(f"{where}: {shown[:40]!r} is not a number ({_EXPECTED})") from None
    return _check_values(label, values, lambda i: f"line {content[i] + 1}", model)


def read_signal(path, label: str | None = None, column=None, model=None) -> np.ndarray:
    """The T* samples of ``path``: a ``.npy`` array, or text with one number per line or a CSV column.

    ``column``: which column of a table (a number from 1, or a name of its header line);
    needed only when the file has several columns.  ``model``: the contact model whose gross-slip
    torque bounds the samples (default the cylinders: [-4/3, 4/3]).

    Raises
    ------
    ValueError
        Naming the file and the line (text) or element (``.npy``) of the first sample that
        is not a finite number in [-4/3, 4/3]; for an unreadable or empty file, a table of
        several columns without ``column``, or a ``column`` it does not have.
    """
    path = os.fspath(path)
    label = label or path
    if "\0" in path:  # open() would say only "embedded null byte"
        shown = label.replace("\0", "\\0")
        raise ValueError(f"{shown}: cannot read (the path contains a NUL character)")
    if path.endswith(".npy"):
        return _read_npy(label, path, column, model)
    return _read_text(label, path, column, model)


# --------------------------------------------------------------------------- writing
def _digits(values: np.ndarray, width: int) -> np.ndarray:
    """ASCII digits of non-negative integers, right-aligned in ``width`` columns, leading zeros as 0 bytes."""
    out = np.zeros((values.size, width), dtype=np.uint8)
    rest = values.astype(np.int64).copy()
    for j in range(width - 1, -1, -1):
        out[:, j] = np.where((rest > 0) | (j == width - 1), 48 + rest % 10, 0)
        rest //= 10
    return out


def _integers(values) -> np.ndarray:
    values = np.asarray(values, dtype=np.int64)
    width = max(1, len(str(int(np.max(np.abs(values))))) if values.size else 1)
    body = _digits(np.abs(values), width)
    sign = np.where(values < 0, ord("-"), 0).astype(np.uint8)[:, None]
    return np.hstack([sign, body])


def _floats(values) -> np.ndarray:
    """d.ddddddddddddddde+XX with 16 significant digits; inf, -inf, nan spelled out (bytes, 0 = nothing)."""
    x = np.asarray(values, dtype=float)
    n = x.size
    finite = np.isfinite(x) & (x != 0)
    magnitude = np.where(finite, np.abs(x), 1.0)
    exponent = np.floor(np.log10(magnitude)).astype(np.int64)
    mantissa = np.rint(magnitude / 10.0 ** exponent.astype(float) * 1e15).astype(np.int64)
    high = mantissa >= 10**16  # rounding up to 10.000...: renormalise
    mantissa = np.where(high, mantissa // 10, mantissa)
    exponent = np.where(high, exponent + 1, exponent)
    low = mantissa < 10**15
    mantissa = np.where(low, np.rint(magnitude / 10.0 ** (exponent - 1).astype(float) * 1e15).astype(np.int64),
                        mantissa)
    exponent = np.where(low, exponent - 1, exponent)
    mantissa = np.where(finite, mantissa, 0)
    exponent = np.where(finite, exponent, 0)
    digits = _digits(mantissa, 16)
    out = np.zeros((n, 24), dtype=np.uint8)
    out[:, 0] = np.where(np.signbit(x) & ~np.isnan(x), ord("-"), 0)
    out[:, 1] = digits[:, 0]
    out[:, 2] = ord(".")
    out[:, 3:18] = digits[:, 1:]
    out[:, 18] = ord("e")
    out[:, 19] = np.where(exponent < 0, ord("-"), ord("+"))
    e = np.abs(exponent)
    out[:, 20] = np.where(e >= 100, 48 + e // 100, 0)
    out[:, 21] = 48 + (e // 10) % 10
    out[:, 22] = 48 + e % 10
    for mask, word in ((x == 0, b"0"), (np.isnan(x), b"nan"), (np.isinf(x), b"inf")):
        if mask.any():
            out[mask, 1:] = 0
            out[np.ix_(mask, range(1, 1 + len(word)))] = np.frombuffer(word, dtype=np.uint8)
    return out


def format_columns(columns, integer_columns=()) -> bytes:
    """CSV rows (no header) of equal-length numeric ``columns``; columns in ``integer_columns`` as integers."""
    blocks = []
    for j, column in enumerate(columns):
        blocks.append(_integers(column) if j in integer_columns else _floats(column))
        end = ord("\n") if j == len(columns) - 1 else ord(",")
        blocks.append(np.full((blocks[-1].shape[0], 1), end, dtype=np.uint8))
    table = np.hstack(blocks).ravel()
    return table[table != 0].tobytes()


def write_sample_table(path, header: str, columns, integer_columns=(), chunk: int = 200_000, progress=None, *,
                       label: str = "path", inputs=(), parents: bool = False) -> None:
    """Write ``header`` and the CSV rows of ``columns`` to ``path``, ``chunk`` rows at a time, through the one
    writer (``output.open_output``: atomic for a regular file, in place for a FIFO or device; ``label``,
    ``inputs`` and ``parents`` as there)."""
    from ..output import open_output

    columns = [np.asarray(c) for c in columns]
    rows = columns[0].size
    with open_output(path, "wb", label=label, inputs=inputs, parents=parents) as handle:
        handle.write(header.encode() + b"\n")
        for start in range(0, rows, chunk):
            handle.write(format_columns([c[start : start + chunk] for c in columns], integer_columns))
            if progress is not None:
                progress(min(chunk, rows - start))


# --------------------------------------------------------------------------- tables of named columns
def table_format(path) -> str:
    """"npz", "npy" or "csv": the format ``write_table`` uses for ``path`` (by its extension)."""
    extension = os.path.splitext(os.fspath(path))[1].lower()
    return {".npz": "npz", ".npy": "npy"}.get(extension, "csv")


def write_table(path, columns: dict, *, metadata: dict | None = None, progress=None, label: str = "path", inputs=(),
                parents: bool = False) -> None:
    """Write equal-length named ``columns`` to ``path`` through the one writer, in the format of its extension.

    ``.npz``: one array per column and ``metadata`` (``provenance`` of ``metadata``, a JSON
    string); ``.npy``: a structured array with one field per column; otherwise CSV with a
    header of the column names (integer columns as integers, ``write_sample_table``).
    ``progress(rows)`` is called as CSV rows are written.  ``label``, ``inputs``, ``parents``: as
    for ``output.open_output`` (the option named in errors, files never to overwrite, whether
    to create missing directories).
    """
    import json

    from ..output import open_output
    from ..provenance import provenance

    names = list(columns)
    arrays = [np.asarray(columns[name]) for name in names]
    kind = table_format(path)
    if kind == "csv":
        integer_columns = tuple(j for j, a in enumerate(arrays) if a.dtype.kind in "iub")
        write_sample_table(path, ",".join(names), arrays, integer_columns=integer_columns, progress=progress,
                           label=label, inputs=inputs, parents=parents)
        return
    with open_output(path, "wb", label=label, inputs=inputs, parents=parents) as handle:
        if kind == "npz":
            record = provenance(**(metadata or {}))
            np.savez(handle, **dict(zip(names, arrays, strict=True)), metadata=np.array(json.dumps(record)))
        else:
            table = np.empty(arrays[0].size, dtype=[(name, a.dtype) for name, a in zip(names, arrays, strict=True)])
            for name, a in zip(names, arrays, strict=True):
                table[name] = a
            np.save(handle, table, allow_pickle=False)
    if progress is not None:
        progress(arrays[0].size)


def read_table(path) -> dict:
    """The columns of a table written by ``write_table`` (and ``metadata`` of an ``.npz``, a dict)."""
    import json

    kind = table_format(path)
    if kind == "npz":
        with np.load(path, allow_pickle=False) as data:
            out = {name: data[name] for name in data.files if name != "metadata"}
            if "metadata" in data.files:
                out["metadata"] = json.loads(str(data["metadata"]))
            return out
    if kind == "npy":
        table = np.load(path, allow_pickle=False)
        return {name: table[name] for name in table.dtype.names}
    with open(path, encoding="utf-8") as handle:
        names = handle.readline().strip().split(",")
    rows = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: rows[:, j] for j, name in enumerate(names)}
