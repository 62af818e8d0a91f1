"""One lab record written as each export a laboratory may have (the fixture of the lab-file tests).

The record is the synthetic loop of ``notebooks/data/lab_loop.csv`` (time s, torque N m, twist
mrad), read once with the standard library only (not with the reader under test).  ``write_variants``
writes it as: plain CSV; ``;`` with decimal commas; Windows-1252 with ``°`` and ``·``; metadata
lines above the header; ``Angle [deg]``; a German export (``Zeit;Drehmoment [N·m];Winkel [°]``);
the unit spellings ``[Deg]``, ``[DEG]``, ``[RAD]``, ``[N-m]``; a UTF-8 byte-order mark; tabs;
blanks; CRLF line ends; and headers whose names need ``--torque-column``/``--twist-column``.
Numbers are written with 17 significant digits, so that every variant holds the same doubles up
to one rounding of a unit conversion (deg <-> rad: a relative 2e-16).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RECORD = ROOT / "notebooks" / "data" / "lab_loop.csv"


def record() -> tuple[list[float], list[float], list[float]]:
    """(time s, torque N m, twist rad) of the record, parsed with the standard library."""
    lines = [line for line in RECORD.read_text(encoding="utf-8").splitlines() if line and not line.startswith("#")]
    assert lines[0] == "time [s],torque [N m],twist [mrad]", lines[0]
    rows = [[float(x) for x in line.split(",")] for line in lines[1:]]
    return [r[0] for r in rows], [r[1] for r in rows], [r[2] * 1e-3 for r in rows]


@dataclass
class Variant:
    """An export: its text, its encoding, the options it needs, and the twist's factor to rad."""

    name: str
    header: list[str]
    delimiter: str = ","
    decimal_comma: bool = False
    encoding: str = "utf-8"
    twist_scale: float = 1.0  # written twist = twist [rad] / twist_scale
    torque_scale: float = 1.0
    metadata: list[str] = field(default_factory=list)
    newline: str = "\n"
    bom: bool = False
    options: list[str] = field(default_factory=list)  # what makes it read, if anything

    def text(self, time, torque, twist) -> str:
        def number(x):
            text = repr(float(x))
            return text.replace(".", ",") if self.decimal_comma else text
        rows = [self.delimiter.join(number(v) for v in (t, q / self.torque_scale, w / self.twist_scale))
                for t, q, w in zip(time, torque, twist, strict=True)]
        return self.newline.join([*self.metadata, self.delimiter.join(self.header), *rows]) + self.newline


DEG = math.pi / 180
#: The variants, by name.
VARIANTS = {v.name: v for v in [
    Variant("plain", ["time [s]", "torque [N m]", "twist [rad]"]),
    Variant("semicolon_decimal_comma", ["time [s]", "torque [N m]", "twist [rad]"], delimiter=";",
            decimal_comma=True),
    Variant("windows_1252", ["time [s]", "torque [N·m]", "twist [°]"], encoding="cp1252", twist_scale=DEG),
    Variant("metadata_lines", ["time [s]", "torque [N m]", "twist [rad]"],
            metadata=["Rig: torsion 3, load cell 20 N m", "Date: 2025-03-12 14:05", "Operator: A. B.", ""]),
    Variant("angle_deg", ["time [s]", "torque [N m]", "Angle [deg]"], twist_scale=DEG),
    Variant("german", ["Zeit [s]", "Drehmoment [N·m]", "Winkel [°]"], delimiter=";", decimal_comma=True,
            encoding="cp1252", twist_scale=DEG, newline="\r\n",
            metadata=["Prüfstand: Torsion 3", "Datum: 12.03.2025", "Bediener: Müller"]),
    Variant("Deg", ["time [s]", "torque [N m]", "twist [Deg]"], twist_scale=DEG),
    Variant("DEG", ["time [s]", "torque [N m]", "twist [DEG]"], twist_scale=DEG),
    Variant("RAD", ["time [s]", "torque [N m]", "twist [RAD]"]),
    Variant("N-m", ["time [s]", "torque [N-m]", "twist [rad]"]),
    Variant("kNm_mrad", ["time [s]", "torque [kNm]", "rotation [mrad]"], torque_scale=1e3, twist_scale=1e-3),
    Variant("bom", ["time [s]", "torque [N m]", "twist [rad]"], bom=True),
    Variant("tab", ["time [s]", "torque [N m]", "twist [rad]"], delimiter="\t"),
    Variant("blanks", ["time [s]", "torque [N m]", "twist [rad]"], delimiter="   "),
    Variant("crlf", ["time [s]", "torque [N m]", "twist [rad]"], newline="\r\n"),
    Variant("named_columns", ["t [s]", "T_meas [N m]", "phi_enc [rad]"], delimiter=";", decimal_comma=True,
            options=["--torque-column", "T_meas", "--twist-column", "phi_enc"]),
]}


def write_variant(directory: Path, name: str) -> Path:
    """Write the variant ``name`` of the record into ``directory``; returns its path."""
    variant = VARIANTS[name]
    data = variant.text(*record()).encode(variant.encoding)
    if variant.bom:
        data = b"\xef\xbb\xbf" + data
    path = Path(directory) / f"{name}.csv"
    path.write_bytes(data)
    return path
