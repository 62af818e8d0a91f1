"""Printed font sizes of the text in a PDF, as placed on the page (PyMuPDF; no poppler needed).

PyMuPDF reports each span of text with the size it has on the page: the font size times the scale of
every transformation above it, so a figure drawn 7.2 in wide and included at 6.3 in prints its 8-pt
labels at 7 pt, and that is what is measured.  The rule for legibility at print size:

* every span of text is at least ``minimum`` points (7 pt: TeX's points, 1/72.27 in, the unit in which the
  papers' fonts are set; PDF coordinates are in PostScript points, 1/72 in, in which TeX's 7-pt font
  measures 6.974), except
* a sub- or superscript (a span of at least ``SCRIPT_FRACTION`` of the minimum that lies next to a span
  of full size, within one line height of it): math typesetting sets scripts at 70 % of their base (TeX's
  \\scriptstyle of 10 pt is 7 pt, matplotlib's mathtext 70 %), and a script is read with its base.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

#: A script may be this fraction of the minimum size (70 % scripts of a base at the minimum, with rounding).
SCRIPT_FRACTION = 0.68
#: Sizes are compared with this slack (pt): PDF coordinates carry rounding of the writer and the scaling.
SLACK = 0.01
#: A TeX point in PostScript points (PDF units).
TEX_POINT = 72.0 / 72.27


@dataclass(frozen=True)
class Span:
    page: int
    size: float
    font: str
    text: str
    bbox: tuple[float, float, float, float]


def spans(pdf: Path) -> list[Span]:
    """Every non-blank span of text of ``pdf`` with its printed size (pt), font and bounding box."""
    import pymupdf

    found = []
    with pymupdf.open(pdf) as document:
        for number, page in enumerate(document, start=1):
            for block in page.get_text("dict")["blocks"]:
                for line in block.get("lines", []):
                    for span in line["spans"]:
                        if span["text"].strip():
                            found.append(Span(number, float(span["size"]), span["font"], span["text"],
                                              tuple(span["bbox"])))
    return found


def _near(small: Span, big: Span) -> bool:
    """``small`` touches ``big`` grown by one line height (its size) on every side, on the same page."""
    if small.page != big.page:
        return False
    x0, y0, x1, y1 = big.bbox
    grow = big.size
    a0, b0, a1, b1 = small.bbox
    return a0 <= x1 + grow and a1 >= x0 - grow and b0 <= y1 + grow and b1 >= y0 - grow


def too_small(pdf: Path, minimum: float = 7.0) -> list[Span]:
    """The spans of ``pdf`` below ``minimum`` TeX points that are not scripts of a full-size neighbour."""
    minimum *= TEX_POINT
    every = spans(pdf)
    full = [s for s in every if s.size >= minimum - SLACK]
    offenders = []
    for span in every:
        if span.size >= minimum - SLACK:
            continue
        script = span.size >= SCRIPT_FRACTION * minimum - SLACK and any(_near(span, big) for big in full)
        if not script:
            offenders.append(span)
    return offenders
