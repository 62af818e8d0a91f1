"""Figure output for the workflow: vector PDF plus PNG preview, written through the one writer.

Figures are made with ``subplots`` here, on matplotlib's Agg canvas, without pyplot: a script
has no interactive session, and pyplot's import and figure registry cost a tenth of a CPU-second
per job.  This module does not change the backend of an interactive session that imports it.
Two matplotlib internals are wrapped, each only where the wrapped function exists: math strings are
laid out once per output type (``_share_mathtext_layouts``), and the PDF's embedded font subsets leave
out the OpenType layout tables that only a text shaper reads (``_embed_fonts_without_layout_tables``).
"""

from __future__ import annotations

import argparse
import functools
import json
import os

import matplotlib.style
from matplotlib import rcParams
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from torsional_contact.provenance import atomic_path

__all__ = ["use_style", "subplots", "rcParams", "save_figure", "figure_parser", "method_options", "load_data",
           "method_label"]


def _share_mathtext_layouts() -> None:
    """Lay out each math string once per output type, dpi and font, not once per renderer.

    Matplotlib caches ``MathTextParser._parse_cached`` per parser *instance*, and every renderer
    makes its own parser: saving one figure as PDF and PNG with ``bbox_inches="tight"`` draws it
    with four renderers (a dry run for the bounding box and the real draw, per format), so every
    tick label of a log axis went through the math parser (pyparsing, several ms each) twice per
    format.  The parse depends on the instance only through its output type ("vector" or
    "raster"): the result is keyed on that instead, and is the same object matplotlib would have
    computed.  Without the wrapped method (another matplotlib), nothing changes.
    """
    from matplotlib.mathtext import MathTextParser

    parse = getattr(MathTextParser._parse_cached, "__wrapped__", None)
    if parse is None or getattr(MathTextParser, "_shared_by_output_type", False):
        return
    parsers = {}  # one parser per output type stands for all

    @functools.lru_cache(maxsize=1024)
    def parse_by_output_type(output_type, *key):
        return parse(parsers[output_type], *key)

    def _parse_cached(self, *key):
        parsers.setdefault(self._output_type, self)
        return parse_by_output_type(self._output_type, *key)

    MathTextParser._parse_cached = _parse_cached
    MathTextParser._shared_by_output_type = True


_share_mathtext_layouts()

#: OpenType tables a text-shaping or math-layout engine reads (substitutions, positioning and their glyph
#: classes, justification, baselines, math constants, legacy kerning pairs): a PDF viewer does not, it draws
#: the glyphs a PDF names at the positions the PDF gives, and matplotlib lays the text out from the full font.
LAYOUT_TABLES = ("GSUB", "GPOS", "GDEF", "JSTF", "BASE", "MATH", "kern")


def without_layout_tables(font):
    """``font`` (a lazily read ``fontTools.ttLib.TTFont``) without its ``LAYOUT_TABLES``, unread: deleting a
    table of a lazy font does not decompile it.  Returns the same object."""
    for tag in LAYOUT_TABLES:
        if tag in font:
            del font[tag]
    return font


class _SubsettingWithoutLayout:
    """``fontTools.subset`` as matplotlib's font embedding sees it, except that ``load_font`` drops the layout
    tables before the subsetter reads them (it decompiles the layout tables of every font it loads, even
    those it is told to drop: about 50 ms of the 80 ms a DejaVu font costs per PDF)."""

    def __init__(self, subsetting):
        self._subsetting = subsetting

    def __getattr__(self, name):
        return getattr(self._subsetting, name)

    def load_font(self, *args, **kwargs):
        return without_layout_tables(self._subsetting.load_font(*args, **kwargs))


def _embed_fonts_without_layout_tables() -> None:
    """Embed the PDF's TrueType subsets (pdf.fonttype 42) without the layout tables.

    Matplotlib subsets every font it embeds with ``fontTools.subset`` (``get_glyphs_subset`` of
    ``backends._backend_pdf_ps``), keeping the layout tables of the glyphs used; the glyph outlines,
    metrics, character map, names and hinting of the subset stay as they were.  Without that function
    or its ``subset`` module (another matplotlib), nothing changes.
    """
    from matplotlib.backends import _backend_pdf_ps

    subsetting = getattr(_backend_pdf_ps, "subset", None)
    if (not hasattr(_backend_pdf_ps, "get_glyphs_subset") or not hasattr(subsetting, "load_font")
            or isinstance(subsetting, _SubsettingWithoutLayout)):
        return
    _backend_pdf_ps.subset = _SubsettingWithoutLayout(subsetting)


def use_style(style_path=None) -> None:
    """Apply the project's matplotlib style file (an input of every figure rule)."""
    if style_path:
        matplotlib.style.use(os.fspath(style_path))


def subplots(nrows=1, ncols=1, **kwargs):
    """``(figure, axes)`` as ``matplotlib.pyplot.subplots`` makes them (the same arguments; the keywords
    of ``Figure``, e.g. ``figsize``, go to the figure, the others to ``Figure.subplots``), on an Agg
    canvas as pyplot's non-interactive backend gives it, but not registered with pyplot."""
    figure_keywords = {key: kwargs.pop(key) for key in ("figsize", "dpi", "facecolor", "edgecolor", "frameon",
                                                        "layout") if key in kwargs}
    figure = Figure(**figure_keywords)
    FigureCanvasAgg(figure)
    return figure, figure.subplots(nrows, ncols, **kwargs)


def save_figure(fig, pdf_path, png_path=None, dpi=150) -> None:
    """Save ``fig`` as PDF (and PNG), with the generating script in the metadata; the PDF's fonts are
    embedded without their layout tables (``_embed_fonts_without_layout_tables``).

    ``savefig`` writes a temporary file, which ``output.atomic_path`` renames onto a regular
    file (or a symbolic link's target) or copies into a FIFO or device; a directory or a missing
    directory is refused with ``output.OutputError`` naming --pdf or --png.
    """
    _embed_fonts_without_layout_tables()  # here, not on import: the PDF backend imports fontTools' subsetter
    with atomic_path(pdf_path, label="--pdf") as tmp:
        fig.savefig(tmp, format="pdf", metadata={"Creator": "torsional_contact workflow"})
    if png_path:
        with atomic_path(png_path, label="--png") as tmp:
            fig.savefig(tmp, format="png", dpi=dpi)


def figure_parser(doc: str, data: bool = False, quantities=None) -> argparse.ArgumentParser:
    """Command line of a figure script: --style, --pdf, --png; --data for scripts that plot a JSON;
    for scripts that solve themselves, --quantity (one or more of ``quantities``: one figure each,
    from the same solutions), --method and --n-terms; then --pdf and --png name one file per
    quantity, in the same order (``figure_files``).

    Every option is required: the rule sets each value from the configuration."""
    parser = argparse.ArgumentParser(description=doc.strip().splitlines()[0])
    several = "+" if quantities is not None else None
    if data:
        parser.add_argument("--data", required=True, help="JSON written by the workflow")
    if quantities is not None:
        parser.add_argument("--quantity", choices=sorted(quantities), nargs="+", required=True,
                            help="one figure per quantity")
        parser.add_argument("--method", required=True, help="solve()'s method")
        parser.add_argument("--n-terms", type=int, required=True,
                            help="N of a weak form (ignored by a method whose interface values are exact)")
    parser.add_argument("--style", required=True, help="matplotlib style file")
    parser.add_argument("--pdf", required=True, nargs=several, help="one per --quantity, in order" if several else None)
    parser.add_argument("--png", required=True, nargs=several, help="one per --quantity, in order" if several else None)
    return parser


def figure_files(parser: argparse.ArgumentParser, args) -> list:
    """[(quantity, pdf, png)] of a script with --quantity: one PDF and one PNG per quantity, no quantity twice
    (else the parser's error names the option)."""
    if len(set(args.quantity)) != len(args.quantity):
        parser.error(f"--quantity: each quantity once, got {' '.join(args.quantity)}")
    for option, paths in (("--pdf", args.pdf), ("--png", args.png)):
        if len(paths) != len(args.quantity):
            parser.error(f"{option}: one file per --quantity ({len(args.quantity)}), got {len(paths)}")
    if len(set(args.pdf) | set(args.png)) != 2 * len(args.quantity):
        parser.error("--pdf, --png: every file a different path")
    return list(zip(args.quantity, args.pdf, args.png, strict=True))


def _methods():
    """The method table (imported here: the solvers' import chain costs about half a CPU-second at the start of
    the figure scripts that only plot data)."""
    from torsional_contact.backends import METHODS

    return METHODS


def method_options(args) -> dict:
    """``method`` and ``n_terms`` for ``solve`` from a figure's --method and --n-terms: N only for a
    truncated method (a weak form); the others choose their Dini terms per call (``n_terms=None``)."""
    truncated = _methods()[args.method].truncated
    return {"method": args.method, "n_terms": args.n_terms if truncated else None}


def load_data(path) -> dict:
    """The JSON a data rule wrote."""
    with open(path, encoding="utf-8") as handle:
        return json.load(handle)


#: How figures name the methods (the manuscript's names, not the API's ``method=`` values).
METHOD_LABELS = {"fast": "Abel-Fredholm", "complete": "complete weak form", "published": "printed eq. (38)"}


def method_label(solution) -> str:
    """The method of a ``Solution`` as figures name it, with N for the weak forms."""
    name = METHOD_LABELS.get(solution.method, solution.method)
    truncated = _methods()[solution.method].truncated
    return f"{name}, N = {solution.n_terms}" if truncated and solution.n_terms is not None else name
