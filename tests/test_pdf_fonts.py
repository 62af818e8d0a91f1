"""The printed-font-size check (tests/pdf_fonts.py) on PDFs made here: it must see what a reader sees.

A matplotlib figure with text of known sizes, included by a PDF page at a known scale, must be measured at
the printed sizes (font size times scale), and text below the minimum must be reported unless it is a
script next to full-size text.  The built papers are checked by tests/test_workflow.py.
"""

import pytest

pymupdf = pytest.importorskip("pymupdf")
pytest.importorskip("matplotlib")

from pdf_fonts import spans, too_small  # noqa: E402


def _figure(path, items, width=4.0):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(width, 2.0))
    for x, y, text, size in items:
        fig.text(x, y, text, fontsize=size)
    fig.savefig(path, format="pdf")
    plt.close(fig)


def _included(figure, path, scale):
    """A page that shows ``figure`` scaled by ``scale`` (as \\includegraphics[width=...] does)."""
    with pymupdf.open(figure) as source:
        rect = source[0].rect
        with pymupdf.open() as page_doc:
            page = page_doc.new_page(width=rect.width * scale + 20, height=rect.height * scale + 20)
            page.show_pdf_page(pymupdf.Rect(10, 10, 10 + rect.width * scale, 10 + rect.height * scale), source, 0)
            page_doc.save(path)


def test_sizes_are_measured_as_printed_after_scaling(tmp_path):
    _figure(tmp_path / "fig.pdf", [(0.1, 0.5, "Torque", 8.0)])
    _included(tmp_path / "fig.pdf", tmp_path / "page.pdf", 6.3 / 7.2)
    (span,) = spans(tmp_path / "page.pdf")
    assert span.text == "Torque"
    assert abs(span.size - 8.0 * 6.3 / 7.2) < 0.01  # 7.0 pt: the figure shrunk to the text width


def test_text_below_the_minimum_is_reported_and_text_at_it_is_not(tmp_path):
    _figure(tmp_path / "fig.pdf", [(0.1, 0.8, "legend entry", 6.0), (0.1, 0.3, "axis label", 7.0)])
    offenders = too_small(tmp_path / "fig.pdf")
    assert [s.text for s in offenders] == ["legend entry"]
    _included(tmp_path / "fig.pdf", tmp_path / "page.pdf", 0.9)  # 7 pt shrunk to 6.3 pt: now both fail
    assert sorted(s.text for s in too_small(tmp_path / "page.pdf")) == ["axis label", "legend entry"]


def test_a_script_next_to_full_size_text_passes_and_alone_fails(tmp_path):
    _figure(tmp_path / "fig.pdf", [(0.1, 0.5, r"$T^{*}_{\max}$", 8.0), (0.7, 0.5, "x", 5.0)])
    offenders = too_small(tmp_path / "fig.pdf")
    assert [s.text for s in offenders] == ["x"], offenders  # the 5.6-pt scripts of T stay with it
