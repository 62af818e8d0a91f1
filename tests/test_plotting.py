"""The workflow's figure helper (workflow/scripts/_plotting.py) draws what plain matplotlib draws.

The helper makes figures without pyplot, lets all renderers of one output type share the layouts
of math strings (matplotlib caches them per renderer) and embeds the PDF's TrueType subsets without
the OpenType layout tables.  The check is independent of the helper: the same figure (log axes,
whose tick labels are math strings, and math in labels, title and legend) is drawn once by plain
pyplot and ``savefig`` in one process and once through the helper in another; the PNG must be
byte-identical, and so must every stream of the PDF but the font programs (page content, widths,
character-to-glyph maps, ToUnicode maps; SOURCE_DATE_EPOCH fixes the PDF's dates), whose glyphs
must have the outlines and advance widths of plain matplotlib's.
"""

import io
import os
import re
import subprocess
import sys
import zlib
from pathlib import Path

from fontTools.ttLib import TTFont

ROOT = Path(__file__).resolve().parents[1]
STYLE = ROOT / "workflow" / "styles" / "paper.mplstyle"

DRAW = r"""
import sys
import numpy as np

def draw(fig, axes):
    x = np.logspace(-3, 2, 40)
    for ax, power in zip(axes, (2, 3)):
        ax.loglog(x, x**power, "o-", label=rf"$\epsilon^{power}$")
        ax.set_xlabel(r"$\Delta T^*/2 - 1$")
        ax.set_ylabel(r"energy per cycle $W\mu/((fp_0)^2a^3)$")
        ax.legend(title=r"loops $[T^*_{\min}, T^*_{\max}]$")
    fig.suptitle(r"$\sigma_{\theta z}/f p_0$ and plain text")
    fig.tight_layout(rect=(0, 0.05, 1, 1))
"""

PLAIN = DRAW + r"""
import matplotlib
matplotlib.use("agg")
import matplotlib.pyplot as plt
plt.style.use(sys.argv[1])
fig, axes = plt.subplots(1, 2, figsize=(6.3, 2.9))
draw(fig, axes)
fig.savefig(sys.argv[2], format="pdf", metadata={"Creator": "torsional_contact workflow"})
fig.savefig(sys.argv[3], format="png", dpi=150)
"""

HELPER = DRAW + r"""
sys.path.insert(0, sys.argv[4])
from _plotting import save_figure, subplots, use_style
use_style(sys.argv[1])
fig, axes = subplots(1, 2, figsize=(6.3, 2.9))
draw(fig, axes)
save_figure(fig, sys.argv[2], sys.argv[3])
"""


def _render(code, tmp_path, name):
    pdf, png = tmp_path / f"{name}.pdf", tmp_path / f"{name}.png"
    env = dict(os.environ, SOURCE_DATE_EPOCH="0", MPLBACKEND="agg")
    subprocess.run([sys.executable, "-c", code, str(STYLE), str(pdf), str(png), str(ROOT / "workflow" / "scripts")],
                   check=True, env=env, cwd=tmp_path)
    return pdf.read_bytes(), png.read_bytes()


TRUETYPE = b"\x00\x01\x00\x00"  # the first bytes of a TrueType font program
LAYOUT_TABLES = {"GSUB", "GPOS", "GDEF", "JSTF", "BASE", "MATH", "kern"}


def _streams(pdf: bytes):
    """(font programs, other streams) of a PDF as matplotlib writes it: every stream Flate-compressed."""
    streams = [zlib.decompress(data) for data in re.findall(rb"\nstream\n(.*?)\nendstream", pdf, re.S)]
    return ([TTFont(io.BytesIO(s)) for s in streams if s.startswith(TRUETYPE)],
            [s for s in streams if not s.startswith(TRUETYPE)])


def _glyphs(font):
    """{glyph name: (outline bytes, advance width)} of a TrueType font."""
    glyf = font["glyf"]
    return {name: (glyf[name].compile(glyf), font["hmtx"][name][0]) for name in font.getGlyphOrder()}


def test_helper_draws_what_plain_matplotlib_draws(tmp_path):
    plain_pdf, plain_png = _render(PLAIN, tmp_path, "plain")
    helper_pdf, helper_png = _render(HELPER, tmp_path, "helper")
    assert plain_png.startswith(b"\x89PNG") and plain_pdf.startswith(b"%PDF")
    assert helper_png == plain_png
    plain_fonts, plain_streams = _streams(plain_pdf)
    helper_fonts, helper_streams = _streams(helper_pdf)
    assert helper_streams == plain_streams and len(helper_streams) > 10
    assert len(helper_fonts) == len(plain_fonts) >= 2  # upright and italic (math) DejaVu Sans
    for plain, helper in zip(plain_fonts, helper_fonts, strict=True):
        assert LAYOUT_TABLES & set(plain.keys()) and not LAYOUT_TABLES & set(helper.keys())
        assert set(helper.keys()) == set(plain.keys()) - LAYOUT_TABLES
        assert helper["name"].getDebugName(6) == plain["name"].getDebugName(6)
        plain_glyphs, helper_glyphs = _glyphs(plain), _glyphs(helper)
        # plain matplotlib's subset may hold glyphs reachable only through substitutions (ligatures, math
        # variants), which the PDF never names: the CID-to-glyph maps among the streams above are the same
        assert len(helper_glyphs) > 4 and helper_glyphs.items() <= plain_glyphs.items()
        assert helper.getBestCmap().items() <= plain.getBestCmap().items()


def test_math_strings_are_laid_out_once_per_output_type_dpi_and_font(tmp_path):
    """Through the helper, the PDF's two renderers (bounding-box dry run and drawing) and the PNG's
    two share their math layouts: each string is parsed at most once per (output type, dpi, font)."""
    code = DRAW + r"""
sys.path.insert(0, sys.argv[4])
import collections, functools
from matplotlib.mathtext import MathTextParser
original = MathTextParser._parse_cached.__wrapped__
parses = collections.Counter()
def counting(self, s, dpi, prop, *rest):
    parses[(self._output_type, s, dpi, prop)] += 1
    return original(self, s, dpi, prop, *rest)
MathTextParser._parse_cached = functools.lru_cache(50)(counting)  # as matplotlib caches it: per parser
import _plotting
shared = MathTextParser._parse_cached
requests = collections.Counter()
def counting_requests(self, s, dpi, prop, *rest):
    requests[(self._output_type, s, dpi, prop)] += 1
    return shared(self, s, dpi, prop, *rest)
MathTextParser._parse_cached = counting_requests
fig, axes = _plotting.subplots(1, 2, figsize=(6.3, 2.9))
draw(fig, axes)
_plotting.save_figure(fig, sys.argv[2], sys.argv[3])
print(len(parses), max(parses.values()), sum(requests.values()), len(requests))
"""
    env = dict(os.environ, SOURCE_DATE_EPOCH="0", MPLBACKEND="agg")
    run = subprocess.run([sys.executable, "-c", code, str(STYLE), str(tmp_path / "f.pdf"), str(tmp_path / "f.png"),
                          str(ROOT / "workflow" / "scripts")], check=True, env=env, cwd=tmp_path,
                         capture_output=True, text=True)
    distinct, most_parses_of_one, requests, distinct_requested = map(int, run.stdout.split())
    assert distinct == distinct_requested > 20  # tick labels, axis labels, legends, title, at 3 dpi
    assert most_parses_of_one == 1  # each parsed once
    assert requests >= 2 * distinct  # though every one was asked for by at least two renderers
