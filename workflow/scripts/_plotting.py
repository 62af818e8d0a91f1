"""Figure output for the workflow: vector PDF plus PNG preview, written through the one writer.

Matplotlib chooses a non-interactive backend by itself when there is no display; this module
does not change the backend of an interactive session that imports it.
"""

from __future__ import annotations

import argparse
import json
import os

import matplotlib.pyplot as plt

from torsional_contact.provenance import atomic_path

__all__ = ["use_style", "save_figure", "figure_parser", "method_options", "load_data", "method_label", "plt"]


def use_style(style_path=None) -> None:
    """Apply the project's matplotlib style file (an input of every figure rule)."""
    if style_path:
        plt.style.use(os.fspath(style_path))


def save_figure(fig, pdf_path, png_path=None, dpi=150) -> None:
    """Save ``fig`` as PDF (and PNG), with the generating script in the metadata.

    ``savefig`` writes a temporary file, which ``io.output.atomic_path`` renames onto a regular
    file (or a symbolic link's target) or copies into a FIFO or device; a directory or a missing
    directory is refused with ``io.output.OutputError`` naming --pdf or --png.
    """
    try:
        with atomic_path(pdf_path, label="--pdf") as tmp:
            fig.savefig(tmp, format="pdf", metadata={"Creator": "torsional_contact workflow"})
        if png_path:
            with atomic_path(png_path, label="--png") as tmp:
                fig.savefig(tmp, format="png", dpi=dpi)
    finally:
        plt.close(fig)


def figure_parser(doc: str, data: bool = False, quantities=None) -> argparse.ArgumentParser:
    """Command line of a figure script: --style, --pdf, --png; --data for scripts that plot a JSON;
    for scripts that solve themselves, --quantity (one of ``quantities``), --method and --n-terms.

    Every option is required: the rule sets each value from the configuration."""
    parser = argparse.ArgumentParser(description=doc.strip().splitlines()[0])
    if data:
        parser.add_argument("--data", required=True, help="JSON written by the workflow")
    if quantities is not None:
        parser.add_argument("--quantity", choices=sorted(quantities), required=True)
        parser.add_argument("--method", required=True, help="solve()'s method")
        parser.add_argument("--n-terms", type=int, required=True,
                            help="N of a weak form (ignored by a method whose interface values are exact)")
    parser.add_argument("--style", required=True, help="matplotlib style file")
    parser.add_argument("--pdf", required=True)
    parser.add_argument("--png", required=True)
    return parser


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
