"""Write notebooks/data/lab_export.csv: the record of lab_loop.csv as a European rig's software exports it
(run by hand; the file is committed).

The same samples as ``notebooks/data/lab_loop.csv`` (time s, torque N m, twist mrad, read with the
standard library), written the way a spreadsheet set to a German locale saves them: metadata lines
above the header (rig, date, operator, specimen), ``;`` between fields, decimal commas, and columns
whose names are the rig's own (``Zeit [s];Moment M_t [N·m];Drehwinkel phi [°]``, the twist in
degrees).  The README reads it from the command line and from Python; the tests check that it gives
the friction of lab_loop.csv.

    python workflow/scripts/make_lab_export.py --source notebooks/data/lab_loop.csv --csv notebooks/data/lab_export.csv
"""

import argparse
import math

from torsional_contact.provenance import write_text

HEADER = "Zeit [s];Moment M_t [N·m];Drehwinkel phi [°]"
METADATA = ["Prüfstand: Torsion 3 (Messverstärker 20 N·m)", "Datum: 12.03.2025 14:05", "Bediener: A. Muster",
            "Probe: Zylinder D = 10 mm, Normalkraft 1 kN", ""]


def decimal_comma(value: float) -> str:
    """17 significant digits (the double itself), with a decimal comma."""
    return repr(float(value)).replace(".", ",")


def export(source_text: str) -> str:
    """The text of the export (CRLF line ends, as the rig's software writes them)."""
    lines = [line for line in source_text.splitlines() if line and not line.startswith("#")]
    if lines[0] != "time [s],torque [N m],twist [mrad]":
        raise ValueError(f"unexpected header {lines[0]!r}")
    rows = []
    for line in lines[1:]:
        time, torque, twist_mrad = (float(x) for x in line.split(","))
        rows.append(";".join(decimal_comma(v) for v in (time, torque, math.degrees(twist_mrad * 1e-3))))
    return "\r\n".join([*METADATA, HEADER, *rows]) + "\r\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--source", required=True)
    parser.add_argument("--csv", required=True)
    args = parser.parse_args()
    with open(args.source, encoding="utf-8") as handle:
        text = export(handle.read())
    write_text(args.csv, text, label="--csv", inputs=(("--source", args.source),))


if __name__ == "__main__":
    main()
