"""Delimited text tables as laboratories export them, read the way a careful person would.

``read_text_table(path)`` finds, without being told:

* the encoding: UTF-8 (a byte-order mark is removed, never the first sample with it), else
  Windows-1252 (``°``, ``·``, ``µ`` of European exports); ``encoding=`` (``--encoding``) overrides;
* the separator, among ``,`` ``;`` tab and blanks: the one under which a line of names (the
  header) is followed by a line of numbers with as many fields, the most fields winning;
* the decimal mark: a comma when the separator is not a comma and the numbers carry one
  ("0,0471;0,0201"); a point otherwise.  A field holding both marks ("1.234,5") is refused, not
  guessed;
* the header: the last line of names above the first line of numbers.  Lines above it
  (the rig, the date, the operator, test conditions) are skipped and counted
  (``TextTable.skipped_lines``); blank lines and lines starting with ``#`` are skipped anywhere.

Then it is strict: every data line must hold as many fields as the header (a row with an extra
or a missing field is refused, naming its line), and a column is read only when every field of
it is a number (``TextTable.column``; the first field that is not is named, with its line).
Binary input (a NumPy ``.npz`` or ``.npy``, a spreadsheet, any file with NUL bytes) is refused
as such.  Text from the file is shown in messages only escaped (``units.shown_text``), so a
control character or a terminal escape in the file never reaches the terminal.

Only the standard library's ``csv`` (quoted fields) and ``hashlib`` (the file's SHA-256 for the
provenance of results) are used.
"""

from __future__ import annotations

import codecs
import csv
import hashlib
import os
import re
from dataclasses import dataclass

import numpy as np

from ..units import NUMBER, shown_text

__all__ = ["TextTable", "read_text_table", "read_text_bytes", "DELIMITERS", "DELIMITER_NAMES"]

#: The separators tried, in the order that breaks ties (" " stands for any run of blanks).
DELIMITERS = (",", ";", "\t", " ")
DELIMITER_NAMES = {",": "comma", ";": "semicolon", "\t": "tab", " ": "blanks"}

_NUMBER = re.compile(NUMBER)
_NOT_FINITE = {"nan", "+nan", "-nan", "inf", "+inf", "-inf", "infinity", "+infinity", "-infinity"}
#: A whole column, one field per line, every field a number (``_number`` of each is not None).
_FIELD_NUMBER = rf"(?:{NUMBER}|(?i:[+-]?(?:nan|inf|infinity)))"
_NUMBER_COLUMN = re.compile(rf"{_FIELD_NUMBER}(?:\n{_FIELD_NUMBER})*")
_LINE_BREAK = re.compile(r"\r\n|\r|\n")
#: A header field under blanks: a name with its unit in brackets ("torque [N m]") stays one field.
_BLANK_HEADER_FIELD = re.compile(r"[^\s\[(]+(?:\s*(?:\[[^\]]*\]|\([^)]*\)))?|\[[^\]]*\]|\([^)]*\)")
_BINARY_MAGIC = {b"PK\x03\x04": "a ZIP archive: a NumPy .npz or a spreadsheet (.xlsx)",
                 b"\x93NUMPY": "a NumPy .npy array", b"\xd0\xcf\x11\xe0": "an Excel .xls workbook",
                 b"%PDF": "a PDF document"}


@dataclass(frozen=True)
class TextTable:
    """A delimited text table (module docstring).  Lines are numbered from 1, as an editor shows them.

    Attributes
    ----------
    label : str
        How messages name the file (e.g. "--loop data.csv").
    path, sha256 : str
        The file and the SHA-256 of its bytes.
    encoding : str
        "utf-8", "utf-8 with BOM", "windows-1252" or the name given.
    delimiter : str
        One of ``DELIMITERS``.
    decimal_mark : str
        "." or ",".
    skipped_lines : int
        Lines above the header (metadata, comments, blanks) that were not read.
    header_line : int or None
        Line number of the header (None: the file has none, its first line holds numbers).
    header : list of str or None
    rows : list of (line number, fields)
    """

    label: str
    path: str
    sha256: str
    encoding: str
    delimiter: str
    decimal_mark: str
    skipped_lines: int
    header_line: int | None
    header: list[str] | None
    rows: list[tuple[int, list[str]]]

    def report(self) -> dict:
        """What was read, for the provenance of a result (JSON-ready)."""
        return {"path": self.path, "sha256": self.sha256, "encoding": self.encoding,
                "delimiter": DELIMITER_NAMES[self.delimiter], "decimal_mark": self.decimal_mark,
                "skipped_lines": self.skipped_lines, "header_line": self.header_line,
                "header": self.header, "rows": len(self.rows)}

    def column(self, j: int, name: str) -> np.ndarray:
        """Field ``j`` (from 0) of every row as floats; ValueError naming the line and column ``name`` for a field
        that is not a number (a number with the table's decimal mark; nan and inf are read, for the caller to
        refuse)."""
        comma = self.decimal_mark == ","
        text = "\n".join(fields[j] for _, fields in self.rows)
        # under a decimal comma a point is refused (the loop below names the field); a field with two commas
        # stays no number after the replacement and goes to the loop too
        readable = not (comma and "." in text)
        if comma and readable:
            text = text.replace(",", ".")
        if readable and _NUMBER_COLUMN.fullmatch(text):
            # every field a number (one pattern over the whole column): float() of each, as _number gives
            return np.fromiter(map(float, text.split("\n")), dtype=float, count=len(self.rows))
        out = np.empty(len(self.rows))
        for i, (line, fields) in enumerate(self.rows):
            value = _number(fields[j], comma)
            if value is None:
                hint = (" (this file writes decimal commas)" if comma and "." in fields[j] else "")
                raise ValueError(f"{self.label} line {line}: column {shown_text(name)}: {shown_text(fields[j], 40)} "
                                 f"is not a number{hint}")
            out[i] = value
        return out


def _number(text: str, comma: bool) -> float | None:
    """``text`` as a float (a decimal number, nan or inf), or None."""
    if comma:
        if "." in text:
            return None
        text = text.replace(",", ".", 1)
    if _NUMBER.fullmatch(text) or text.lower() in _NOT_FINITE:
        return float(text)
    return None


def read_text_bytes(path: str, label: str, not_text: str) -> bytes:
    """The bytes of the file ``path``; ValueError naming ``label`` when it cannot be read or is binary (then
    ``label: <what it is>, <not_text>``)."""
    if "\0" in path:
        shown = label.replace("\0", "\\0")
        raise ValueError(f"{shown}: cannot read (the path contains a NUL character)")
    try:
        with open(path, "rb") as handle:
            data = handle.read()
    except OSError as exc:
        raise ValueError(f"{label}: cannot read ({exc.strerror or exc})") from None
    kind = _binary_kind(data)
    if kind is not None:
        raise ValueError(f"{label}: {kind}, {not_text}")
    return data


def _binary_kind(data: bytes) -> str | None:
    for magic, kind in _BINARY_MAGIC.items():
        if data.startswith(magic):
            return kind
    return "a binary file (it holds NUL bytes)" if b"\0" in data[:65536] else None


def _decode(label: str, data: bytes, encoding: str | None) -> tuple[str, str]:
    """(text, encoding as reported)."""
    if encoding is not None:
        try:
            codec = codecs.lookup(encoding)
        except LookupError:
            raise ValueError(f"--encoding: unknown encoding {shown_text(encoding)} (e.g. utf-8, windows-1252, "
                             "latin-1)") from None
        try:
            text = data.decode(codec.name)
        except UnicodeDecodeError as exc:
            raise ValueError(f"{label}: not {codec.name} text (byte 0x{data[exc.start]:02x} at offset {exc.start}); "
                             "give the file's encoding with --encoding") from None
        return text.removeprefix("\ufeff"), codec.name
    if data.startswith(codecs.BOM_UTF8):
        try:
            return data[len(codecs.BOM_UTF8):].decode("utf-8"), "utf-8 with BOM"
        except UnicodeDecodeError as exc:
            raise ValueError(f"{label}: starts with a UTF-8 byte-order mark but is not UTF-8 (byte "
                             f"0x{data[exc.start]:02x} at offset {exc.start}); give the encoding with "
                             "--encoding") from None
    try:
        return data.decode("utf-8"), "utf-8"
    except UnicodeDecodeError:
        pass
    try:
        return data.decode("cp1252"), "windows-1252"
    except UnicodeDecodeError as exc:
        raise ValueError(f"{label}: neither UTF-8 nor Windows-1252 text (byte 0x{data[exc.start]:02x} at offset "
                         f"{exc.start}); give the file's encoding with --encoding") from None


def _fields(line: str, delimiter: str, header: bool = False) -> list[str] | None:
    """The fields of ``line`` (stripped), or None if the line cannot be split (a broken quote)."""
    if delimiter == " ":
        return _BLANK_HEADER_FIELD.findall(line) if header else line.split()
    try:
        return [field.strip() for field in next(csv.reader([line], delimiter=delimiter, skipinitialspace=True))]
    except (csv.Error, StopIteration):
        return None


def _numeric(fields: list[str] | None, delimiter: str) -> bool:
    """Whether every field is a number, with decimal points or (the separator not a comma) decimal commas."""
    if not fields:
        return False
    return all(_number(f, False) is not None for f in fields) or (
        delimiter != "," and all(_number(f, True) is not None for f in fields))


def _line_pattern(delimiter: str, comma: bool) -> str:
    """A line whose every field (split at ``delimiter``, stripped) is a number: ``_number(field, comma)`` of each is
    not None.  One pattern per line instead of a split and a test per field (exact for lines without quotes; the
    blanks exclude the line break, so that the pattern applies line by line to the joined lines)."""
    number = NUMBER.replace(r"\.", ",") if comma else NUMBER
    field = rf"(?:{number}|(?i:[+-]?(?:nan|inf|infinity)))"
    if delimiter == " ":
        return rf"[^\S\n]*{field}(?:[^\S\n]+{field})*[^\S\n]*"
    blank = r"[^\S\t\n]*" if delimiter == "\t" else r"[^\S\n]*"  # blanks around a field, never its separator
    return rf"{blank}{field}{blank}(?:{re.escape(delimiter)}{blank}{field}{blank})*"


#: Per separator: the lines of numbers (decimal points, or decimal commas unless the separator is a comma).
_NUMERIC_LINES = {delimiter: re.compile("^(?:" + "|".join(_line_pattern(delimiter, comma) for comma in (False, True)
                                                       if not (comma and delimiter == ",")) + ")$", re.MULTILINE)
                  for delimiter in DELIMITERS}


def _numeric_lines(content: list[tuple[int, str]], delimiter: str):
    """Indices in ``content`` of the lines whose fields are all numbers (``_numeric``), in order."""
    lines = [line for _, line in content]
    if delimiter != " " and any('"' in line for line in lines):  # quoted fields: csv's reading, line by line
        yield from (index for index, line in enumerate(lines) if _numeric(_fields(line, delimiter), delimiter))
        return
    starts = np.cumsum([0] + [len(line) + 1 for line in lines[:-1]])
    for match in _NUMERIC_LINES[delimiter].finditer("\n".join(lines)):
        yield int(np.searchsorted(starts, match.start(), side="right")) - 1


def _layout(content: list[tuple[int, str]], delimiter: str):
    """(index in ``content`` of the first data line, number of fields) under ``delimiter``, or None.

    The data start at the first line of numbers whose field count the line above it (the header) shares, or at
    the first content line when it holds numbers already (no header)."""
    for index in _numeric_lines(content, delimiter):
        fields = _fields(content[index][1], delimiter)
        if index == 0:
            return 0, len(fields)
        previous = _fields(content[index - 1][1], delimiter, header=True)
        if previous is not None and len(previous) == len(fields):
            return index, len(fields)
        if len(fields) > 1:  # numbers under a line that is no header for them: this is not the separator
            return None
    return None


def read_text_table(path, *, label: str | None = None, encoding: str | None = None) -> TextTable:
    """Read ``path`` as a delimited text table (module docstring).

    Raises
    ------
    ValueError
        Naming ``label`` (default: the path): an unreadable or binary file, an unknown or wrong
        ``encoding``, no line of numbers, a data line whose field count differs from the header's.
    """
    path = os.fspath(path)
    label = label or path
    data = read_text_bytes(path, label, "not a text table: export the record as CSV or text (a header such as "
                                        "'torque [N m],twist [rad]', then one sample per line)")
    text, used = _decode(label, data, encoding)
    lines = _LINE_BREAK.split(text)
    content = [(n, line) for n, line in enumerate(lines, start=1)
               if line.strip() and not line.lstrip().startswith("#")]
    if not content:
        raise ValueError(f"{label}: no header and no data (expected a header such as 'torque [N m],twist [rad]', "
                         "then one sample per line)")
    best = None
    for delimiter in DELIMITERS:
        layout = _layout(content, delimiter)
        if layout is not None and (best is None or layout[1] > best[1][1]):
            best = delimiter, layout
    if best is None:
        header_only = len(content) == 1
        what = ("a header and no data rows" if header_only else
                "no line of numbers under a line of names with as many fields")
        raise ValueError(f"{label}: {what} (first line {content[0][0]}: {shown_text(content[0][1])}; expected a "
                         "header such as 'torque [N m],twist [rad]' and one sample per line, separated by ',' ';' "
                         "tabs or blanks)")
    delimiter, (start, count) = best
    header_line = content[start - 1][0] if start > 0 else None
    header = _fields(content[start - 1][1], delimiter, header=True) if start > 0 else None
    rows = []
    comma_seen = False
    # without quotes a line is its fields split at the separator (what csv.reader would give, ~10x faster)
    plain = delimiter != " " and not any('"' in line for _, line in content[start:])
    for n, line in content[start:]:
        fields = [field.strip() for field in line.split(delimiter)] if plain else _fields(line, delimiter)
        if fields is None or len(fields) != count:
            got = "an unbalanced quote" if fields is None else f"{len(fields)} field(s)"
            raise ValueError(f"{label} line {n}: {got}, the {'header' if header else 'first line'} has {count} "
                             f"(separator {DELIMITER_NAMES[delimiter]}): {shown_text(line)}")
        comma_seen = comma_seen or (delimiter != "," and any("," in f for f in fields))
        rows.append((n, fields))
    skipped = (header_line if header_line is not None else content[start][0]) - 1
    return TextTable(label=label, path=path, sha256=hashlib.sha256(data).hexdigest(), encoding=used,
                     delimiter=delimiter, decimal_mark="," if comma_seen else ".", skipped_lines=skipped,
                     header_line=header_line, header=header, rows=rows)
