"""The workflow's figure helper (workflow/scripts/_plotting.py) draws what plain matplotlib draws.

The helper makes figures without pyplot and lets all renderers of one output type share the layouts
of math strings (matplotlib caches them per renderer).  The check is independent of the helper:
the same figure (log axes, whose tick labels are math strings, and math in labels, title and
legend) is drawn once by plain pyplot and ``savefig`` in one process and once through the helper
in another; the PDF and the PNG must be byte-identical (SOURCE_DATE_EPOCH fixes the PDF's dates).
"""

import os
import subprocess
import sys
from pathlib import Path

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


def test_helper_draws_the_same_bytes_as_plain_matplotlib(tmp_path):
    plain_pdf, plain_png = _render(PLAIN, tmp_path, "plain")
    helper_pdf, helper_png = _render(HELPER, tmp_path, "helper")
    assert plain_png.startswith(b"\x89PNG") and plain_pdf.startswith(b"%PDF")
    assert helper_png == plain_png
    assert helper_pdf == plain_pdf


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
